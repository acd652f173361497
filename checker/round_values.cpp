#include "checker/round_values.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

namespace {

// Does the trace violate `good` in its last cycle and in no earlier one,
// with the constraints and the assumption in every cycle?
class Judge {
 public:
  explicit Judge(const SafetyProblem& p) : enc_(p.ts->ctx()) {
    enc_.ts = *p.ts;
    enc_.ts.name_term("round.good", p.good);
    enc_.ts.name_term("round.facts", p.assumption && p.ts->constraint_formula());
    ev_.emplace(enc_);
  }
  bool violates(const Trace& t) {
    ev_->reset();
    std::vector<encoder::Evaluator::Value> in;
    for (std::size_t k = 0; k < t.cycles.size(); ++k) {
      in.clear();
      for (const auto& v : t.cycles[k].inputs) in.push_back({v.i, v.f});
      ev_->step_raw(in);
      if (!ev_->value("round.facts")) return false;
      if ((ev_->value("round.good") != 0) != (k + 1 < t.cycles.size())) return false;
    }
    return !t.cycles.empty();
  }
  // The states of `t` (each cycle's, before its inputs), as lift_trace
  // records them, for a trace whose inputs changed.
  void record_states(Trace& t) {
    if (t.state_names.empty()) return;
    ev_->reset();
    std::vector<encoder::Evaluator::Value> in;
    for (auto& cycle : t.cycles) {
      for (std::size_t s = 0; s < cycle.state.size(); ++s) {
        cycle.state[s].i = ev_->state()[s].i;
        cycle.state[s].f = ev_->state()[s].f;
      }
      in.clear();
      for (const auto& v : cycle.inputs) in.push_back({v.i, v.f});
      ev_->step_raw(in);
    }
  }

 private:
  encoder::Encoding enc_;
  std::optional<encoder::Evaluator> ev_;
};

// Rounder numbers near `v`, roundest first: for 0-3 decimals, the two
// neighbours at that many decimals, nearer first. `v` itself ends the list
// once a candidate equals it (nothing rounder than v at that precision).
std::vector<float> rounder_numbers(float v) {
  std::vector<float> out;
  if (!std::isfinite(v)) return out;
  for (int decimals = 0; decimals <= 3; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    const double lo = std::floor(static_cast<double>(v) * scale) / scale;
    const double hi = std::ceil(static_cast<double>(v) * scale) / scale;
    const double near = std::fabs(lo - v) <= std::fabs(hi - v) ? lo : hi;
    const double far = near == lo ? hi : lo;
    for (double c : {near, far}) {
      const float f = static_cast<float>(c);
      if (f == v) return out;
      if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    }
  }
  return out;
}

}  // namespace

Trace round_values(const SafetyProblem& problem, const Trace& cex) {
  Trace t = cex;
  try {
    Judge judge(problem);
    if (!judge.violates(t)) return cex;
    const std::size_t n = t.cycles.size();
    for (std::size_t i = 0; i < t.input_names.size(); ++i) {
      for (std::size_t lo = 0; lo < n;) {
        const Value held = t.cycles[lo].inputs[i];
        std::size_t hi = lo + 1;
        while (hi < n && t.cycles[hi].inputs[i] == held) ++hi;
        if (held.is_float)
          for (float c : rounder_numbers(held.f)) {
            Trace trial = t;
            for (std::size_t k = lo; k < hi; ++k) trial.cycles[k].inputs[i].f = c;
            if (!judge.violates(trial)) continue;
            t = std::move(trial);
            break;
          }
        lo = hi;
      }
    }
    judge.record_states(t);
  } catch (const std::logic_error&) {
    return cex;  // an operator the evaluator does not interpret
  }
  return t;
}

}  // namespace cemv::checker
