// Macro steps of held inputs (accelerated BMC, checker/engines/accelerated_bmc.hpp,
// and testgen's sweep of timer objectives, testgen/sweep.hpp). A macro step is
// either one cycle, or a stretch of n >= 2 cycles with the inputs held, in
// which every Int state variable advances by a fixed 0 or 1 per cycle and
// every other state variable stays put: the timers' saturating counters below
// their bound. The stretch's end state is then start + n * delta, with n a
// solver variable; its first and last cycles are checked against the
// transition relation. Between them it is an approximation, so every answer
// is re-simulated cycle by cycle on the encoder's Evaluator (first_violation).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <z3++.h>

#include "checker/limits.hpp"
#include "checker/prover.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

// One macro step of the unrolling: its start state and inputs live in the
// Unroller's copies at index j; `length(j)` is its number of cycles.
class MacroUnrolling {
 public:
  explicit MacroUnrolling(const SafetyProblem& p);
  z3::expr length(int j);
  // Macro step j: from state@j with inputs@j to state@(j+1).
  z3::expr step(int j);
  z3::expr init();
  // The problem's `good` false in the last cycle, the one after step j - 1.
  z3::expr violation(int j);
  encoder::Unroller& unroller() { return u_; }

 private:
  std::vector<z3::expr> nexts_and_facts(const std::vector<z3::expr>& state, int j);
  const SafetyProblem& p_;
  const encoder::TransitionSystem& ts_;
  z3::context& ctx_;
  encoder::Unroller u_;
  z3::expr_vector from_;
};

// The inputs of each macro step and its length (the last one's is 1), read
// from a model of an unrolling of `steps` macro steps and the last cycle.
struct MacroRun {
  std::vector<std::vector<Value>> inputs;
  std::vector<std::int64_t> lengths;
};
MacroRun macro_run(MacroUnrolling& m, const encoder::TransitionSystem& ts, const z3::model& model, int steps);

// Where the macro run first violates the property when run cycle by cycle on
// the Evaluator (0-based), if it does; nullopt when it is spurious (it breaks
// a constraint, or never violates). Holds nothing per cycle; stops when
// interrupted.
std::optional<std::int64_t> first_violation(const SafetyProblem& p, const MacroRun& run, const Limits& limits);

// The macro run's first `cycles` cycles, each with its inputs and the state
// at its start (for display and the re-check).
Trace expand(const SafetyProblem& p, const MacroRun& run, std::int64_t cycles);

}  // namespace cemv::checker
