// BMC over macro steps, for counterexamples too long to unroll (an
// 18,000-cycle override timer). A macro step is either one cycle, or a stretch
// of n >= 2 cycles with the inputs held, in which every Int state variable
// advances by a fixed 0 or 1 per cycle and every other state variable stays
// put: the timers' saturating counters below their bound. The stretch's end
// state is then start + n * delta, with n a solver variable; its first and last
// cycles are checked against the transition relation. Between them the check
// is an approximation (a comparison of a counter with a constant could flip
// and flip back), so each answer is expanded into cycles and re-simulated on
// the encoder's Evaluator: only a run that really violates the property there
// is reported, and a spurious one is blocked and the search goes on.
#pragma once

#include "checker/prover.hpp"

namespace cemv::checker {

class AcceleratedBmc : public Prover {
 public:
  static constexpr int kMaxMacroSteps = 8;
  static constexpr int kMaxRefinements = 8;
  Method method() const override { return Method::AcceleratedBmc; }
  // Falsified with a confirmed counterexample of at most kMaxMacroSteps
  // macro steps (and Limits::max_depth of them); never Proved.
  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override;
};

}  // namespace cemv::checker
