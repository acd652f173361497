// A trace judged on the encoding's own Evaluator, for the passes that make a
// counterexample readable (shrink.cpp, round_values.cpp): does it still
// violate `good` in its last cycle, and in no earlier one, with the
// constraints and the assumption in every cycle? A replay costs microseconds
// a cycle, a solver call on the unrolling a good part of a second. Internal
// to checker/.
#pragma once

#include <optional>
#include <vector>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

class ConcreteJudge {
 public:
  // Throws std::logic_error when the evaluator does not interpret an
  // operator of the problem.
  explicit ConcreteJudge(const SafetyProblem& p) : enc_(p.ts->ctx()) {
    enc_.ts = *p.ts;
    enc_.ts.name_term("judge.good", p.good);
    enc_.ts.name_term("judge.facts", p.assumption && p.ts->constraint_formula());
    ev_.emplace(enc_);
  }

  bool violates(const Trace& t) {
    ev_->reset();
    for (std::size_t k = 0; k < t.cycles.size(); ++k) {
      step(t.cycles[k]);
      if (!ev_->value("judge.facts")) return false;
      if ((ev_->value("judge.good") != 0) != (k + 1 < t.cycles.size())) return false;
    }
    return !t.cycles.empty();
  }

  // Each cycle's states (before its inputs, as lift_trace records them) for
  // a trace whose inputs changed.
  void record_states(Trace& t) {
    if (t.state_names.empty()) return;
    ev_->reset();
    for (auto& cycle : t.cycles) {
      for (std::size_t s = 0; s < cycle.state.size(); ++s) {
        cycle.state[s].i = ev_->state()[s].i;
        cycle.state[s].f = ev_->state()[s].f;
      }
      step(cycle);
    }
  }

 private:
  void step(const Trace::Cycle& cycle) {
    in_.clear();
    for (const auto& v : cycle.inputs) in_.push_back({v.i, v.f});
    ev_->step_raw(in_);
  }

  encoder::Encoding enc_;
  std::optional<encoder::Evaluator> ev_;
  std::vector<encoder::Evaluator::Value> in_;
};

}  // namespace cemv::checker
