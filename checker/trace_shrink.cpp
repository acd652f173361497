#include "checker/trace_shrink.hpp"

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"

namespace cemv::checker {

namespace {

// The cycles of a trace as stretches of equal inputs.
struct Stretch {
  std::vector<Value> inputs;
  std::size_t cycles = 0;
};

std::vector<Stretch> stretches_of(const Trace& t) {
  std::vector<Stretch> out;
  for (const auto& c : t.cycles) {
    if (!out.empty() && out.back().inputs == c.inputs) ++out.back().cycles;
    else out.push_back(Stretch{c.inputs, 1});
  }
  return out;
}

class Replayer {
 public:
  Replayer(const SafetyProblem& p) : enc_(p.ts->ctx()) {
    enc_.ts = *p.ts;
    enc_.ts.name_term("checker.good", p.good);
    enc_.ts.name_term("checker.facts", p.ts->constraint_formula() && p.assumption);
  }

  // The run of these stretches up to its first violation, or nothing.
  std::optional<Trace> run(const std::vector<Stretch>& stretches, const Trace& names) {
    encoder::Evaluator ev(enc_);
    Trace t;
    t.input_names = names.input_names;
    t.state_names = names.state_names;
    for (const auto& s : stretches) {
      std::vector<encoder::Evaluator::Value> in(s.inputs.size());
      for (std::size_t i = 0; i < in.size(); ++i) {
        in[i].i = s.inputs[i].i;
        in[i].f = s.inputs[i].f;
      }
      for (std::size_t c = 0; c < s.cycles; ++c) {
        Trace::Cycle cycle;
        cycle.inputs = s.inputs;
        for (std::size_t v = 0; v < enc_.ts.statevars().size(); ++v)
          cycle.state.push_back(Value{enc_.ts.statevars()[v].var.is_fpa(), ev.state()[v].i, ev.state()[v].f});
        ev.step_raw(in);
        t.cycles.push_back(std::move(cycle));
        if (!ev.value("checker.facts")) return std::nullopt;
        if (!ev.value("checker.good")) return t;
      }
    }
    return std::nullopt;
  }

 private:
  encoder::Encoding enc_;
};

}  // namespace

Trace shrink_counterexample(const SafetyProblem& problem, const Trace& cex, std::size_t max_steps) {
  std::vector<Stretch> stretches = stretches_of(cex);
  const std::size_t inputs = cex.input_names.size();
  if (cex.length() * stretches.size() * inputs > max_steps) return cex;
  Replayer replay(problem);
  Trace best = cex;
  try {
    if (!replay.run(stretches, cex)) return cex;  // not a counterexample of this problem: leave it to the re-check
    for (std::size_t s = 0; s < stretches.size(); ++s)
      for (std::size_t i = 0; i < inputs; ++i) {
        Value& v = stretches[s].inputs[i];
        if (v.i == 0 && v.f == 0.0f) continue;
        const Value kept = v;
        v = Value{kept.is_float, 0, 0.0f};
        if (auto t = replay.run(stretches, cex)) {
          best = std::move(*t);
          stretches = stretches_of(best);  // shorter or merged: continue on the new stretches
          if (s >= stretches.size()) return best;
        } else {
          v = kept;
        }
      }
  } catch (const std::logic_error&) {
    return cex;  // an operator the Evaluator does not interpret
  }
  return best;
}

}  // namespace cemv::checker
