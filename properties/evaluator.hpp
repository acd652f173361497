// The concrete evaluator of the property language: decides properties on one
// finite runtime trace, straight from the definitions of docs/properties.md
// ("Semantics"), looking back over the whole trace. It is the independent
// judge of counterexamples found by the symbolic monitor (properties/monitor.*),
// with which it shares no code.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// One scan cycle of a trace: what the runtime consumed and the observables
// after the scan (runtime::Runtime::snapshot, model::observables order:
// Bool 0/1, Int as is, Voting as the model::Voting enumerator).
struct TraceCycle {
  model::CycleInput input;
  std::vector<int> observables;
};
using Trace = std::vector<TraceCycle>;  // index 0 = the first cycle after start-up

struct Evaluation {
  std::string name;
  PropertyKind kind = PropertyKind::Invariant;
  // Invariant / Never / Response: no violation inside the judged part of the
  // trace. Reachable: a witness inside it.
  bool holds = true;
  // Invariant / Never: the first violating cycle. Response: the cycle where the
  // first violation becomes definite (trigger cycle + within_cycles).
  // Reachable: the first witness. 0-based trace indices.
  std::optional<std::size_t> cycle;
  std::optional<std::size_t> trigger_cycle;  // Response: the trigger of that violation
  // The judged part of the trace is cycles [0, judged): every assumption
  // (file and property) held in each of them. A trace whose assumptions fail
  // early is judged on its prefix only; `assumptions_held` says whether they
  // held throughout.
  std::size_t judged = 0;
  bool assumptions_held = true;
  // Whether the antecedent (Response: the trigger; Invariant of `a implies b`
  // and Never of `a and b`: a) held in some judged cycle. A property that holds
  // with an antecedent never met says nothing about this trace.
  bool antecedent_met = false;
};

class Evaluator {
 public:
  // The matrix fixes the observable order (model::observables) and the input tags.
  explicit Evaluator(const model::Matrix& m);

  Evaluation evaluate(const Property& p, const std::vector<Assumption>& file_assumptions, const Trace& t) const;
  std::vector<Evaluation> evaluate(const PropertyFile& f, const Trace& t) const;

  // The value of a Boolean expression in every cycle of the trace.
  std::vector<bool> values(const Expr& e, const Trace& t) const;

 private:
  std::vector<model::Observable> observables_;
};

}  // namespace cemv::properties
