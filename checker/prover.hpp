// The one interface every proof engine implements (Pono's engines/ pattern):
// a safety problem over a transition system goes in, a verdict with its
// evidence comes out. Evidence is context-independent (names and numbers,
// SMT-LIB text), so a fresh solver in a fresh Z3 context can re-check it
// (checker/check/) and a portfolio can move it between threads.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <z3++.h>

#include "checker/limits.hpp"
#include "checker/names.hpp"
#include "encoder/transition_system.hpp"

namespace cemv::checker {

// `good` must hold in every cycle of every run in which `assumption` held in
// every cycle so far. Both are terms over the state and input variables of one
// cycle (docs/encoding.md, "Timing convention").
struct SafetyProblem {
  const encoder::TransitionSystem* ts = nullptr;
  z3::expr good;
  z3::expr assumption;
};

// A problem together with whatever owns its transition system: what a
// portfolio's factory builds once per thread, in that thread's own context.
struct OwnedProblem {
  std::shared_ptr<void> owner;
  SafetyProblem problem;
};
using ProblemFactory = std::function<OwnedProblem(z3::context&)>;

// A concrete value of one variable in one cycle.
struct Value {
  bool is_float = false;
  std::int64_t i = 0;  // Bool 0/1 or Int
  float f = 0.0f;      // Float32
  bool operator==(const Value&) const = default;
  std::string text() const;
};

// A counterexample: cycle 0 starts in the initial state; `good` is false in the
// last cycle and `assumption` holds in every cycle.
struct Trace {
  std::vector<std::string> input_names;  // TransitionSystem::inputvars() order
  std::vector<std::string> state_names;  // TransitionSystem::statevars() order
  struct Cycle {
    std::vector<Value> inputs;
    std::vector<Value> state;  // at the start of the cycle, for display
  };
  std::vector<Cycle> cycles;

  std::size_t length() const { return cycles.size(); }
  // The value of input `name` in `cycle`; throws std::out_of_range.
  Value input(std::size_t cycle, const std::string& name) const;
  Value state(std::size_t cycle, const std::string& name) const;
};

// A state invariant as SMT-LIB text over the state variable names: each
// clause is one SMT-LIB term; the invariant is their conjunction.
struct Invariant {
  std::vector<std::string> clauses;
  std::string text() const;    // one clause a line
  std::string smtlib() const;  // (and ...) as one term
};

enum class Verdict { Proved, Falsified, Unknown };
std::string to_string(Verdict v);

// Evidence of Proved: `invariant` (inductive on its own) holds in every
// reachable state, and `good` is k-inductive relative to it: no violation in
// cycles 0..k-1, and k cycles that keep the invariant and `good` are followed
// by a cycle that keeps `good` (k = 0: the invariant implies `good`).
// `simple_path`: the inductive step needs the k+1 states to be distinct.
struct ProverResult {
  Verdict verdict = Verdict::Unknown;
  Method method = Method::None;
  bool localized = false;  // found on the localization (checker/localize.hpp), checked on the whole
  int k = 0;
  bool simple_path = false;
  Invariant invariant;
  Trace cex;
  UnknownReason reason = UnknownReason::None;
  std::string detail;  // SolverGaveUp, CannotRun: the solver's or the evaluator's words
  // Unknown from a portfolio: what each engine answered ("k-induction: bound
  // reached at k = 10; ..."), for a reader who asks why nothing decided.
  std::string engines;
  Work work = 0;          // resource units spent (deterministic)
  double seconds = 0.0;   // wall time (never in a deterministic output)

  std::string method_text() const { return checker::method_text(method, localized); }
  // The reason as printed: the reason's words, and the detail after a colon.
  std::string reason_text() const;
};

class Prover {
 public:
  virtual ~Prover() = default;
  virtual Method method() const = 0;
  virtual ProverResult prove(const SafetyProblem& problem, const Limits& limits) = 0;
};

// A re-check of an answer failed: the engine, the encoder or Z3 is wrong.
// Never reported as a verdict (exit 4).
class InternalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cemv::checker
