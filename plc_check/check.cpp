// One output tag decided and every run replayed on both sides (docs/plc.md
// "Relations", "Counterexamples").
#include "plc_check/check.hpp"

#include <map>
#include <memory>
#include <stdexcept>

#include "checker/check/recheck.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/reduce.hpp"
#include "checker/replay.hpp"
#include "checker/round_values.hpp"
#include "checker/shrink.hpp"
#include "model/vocabulary.hpp"
#include "plc_check/correspondence.hpp"
#include "plc_check/shared_proof.hpp"

namespace cemv::plc_check {

namespace {

using checker::InternalError;
using checker::ProverResult;
using checker::Verdict;

// The value an input of the run had: its value in the trace, 0 when the
// engines' reduction left it out (nothing the question reads depends on it).
checker::Value trace_value(const checker::Trace& t, std::size_t cycle, const std::string& name) {
  for (std::size_t i = 0; i < t.input_names.size(); ++i)
    if (t.input_names[i] == name) return t.cycles.at(cycle).inputs.at(i);
  return {};
}

plc::Value literal_of(plc::Type type, const checker::Value& v) {
  plc::Value l;
  l.type = type;
  if (type == plc::Type::Real) l.real = v.f;
  else if (type == plc::Type::Bool) l.integer = v.i != 0;
  else l.integer = v.i;
  return l;
}

// A program input the map holds at `v`.
plc::Value literal_of(plc::Type type, double v) {
  plc::Value l;
  l.type = type;
  if (type == plc::Type::Real) l.real = static_cast<float>(v);
  else if (type == plc::Type::Bool) l.integer = v != 0.0;
  else if (type == plc::Type::Int) l.integer = static_cast<std::int16_t>(static_cast<std::int64_t>(v));
  else l.integer = static_cast<std::int32_t>(static_cast<std::int64_t>(v));
  return l;
}

int observable_index(const model::Matrix& m, const std::string& key) {
  const auto obs = model::observables(m);
  for (std::size_t i = 0; i < obs.size(); ++i)
    if (obs[i].key == key) return static_cast<int>(i);
  throw std::logic_error("the matrix has no observable " + key);
}

bool related(Relation r, bool ett, int matrix, int program) {
  if (r == Relation::Equal) return matrix == program;
  const int safe = ett ? 1 : 0;
  return matrix != safe || program == safe;
}

class Replay {
 public:
  Replay(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou, const ResolvedMap& map,
         const OutputQuestion& q, Relation relation)
      : m_(m), program_(program), pou_(pou), map_(map), q_(q), relation_(relation) {}

  // The run of `t` on both sides; the difference, or an InternalError.
  Difference run(const ProductProblem& p, const checker::Trace& t) {
    Difference d;
    d.matrix_inputs = checker::cycle_inputs(t, *p.matrix, m_);
    for (const auto& x : p.extras) {
      if (!x.tag) continue;
      for (std::size_t c = 0; c < t.length(); ++c) {
        const checker::Value v = trace_value(t, c, x.name);
        auto& tv = d.matrix_inputs[c].tags.at(*x.tag);
        if (x.bad) tv.bad_quality = v.i != 0;
        else tv.value = v.is_float ? v.f : static_cast<float>(v.i);
      }
    }
    for (std::size_t c = 0; c < t.length(); ++c) {
      std::map<std::string, plc::Value> in;
      for (const auto& b : p.program_inputs)
        in[b.variable] = b.held ? literal_of(b.type, *b.held)
                                : literal_of(b.type, trace_value(t, c, b.term.decl().name().str()));
      d.program_inputs.push_back(std::move(in));
    }
    d.runtime = checker::run_on_runtime(m_, d.matrix_inputs);
    const int key = observable_index(m_, "effect[" + std::to_string(q_.effect) + "].tag[" + std::to_string(q_.position) + "]");
    plc::Interpreter interp(program_, pou_.name);
    d.scan = -1;
    for (std::size_t c = 0; c < t.length(); ++c) {
      interp.step(d.program_inputs[c], map_.scan_ms);
      d.matrix_values.push_back(d.runtime.observables.at(c).at(key));
      d.program_values.push_back(interp.value(q_.variable).integer != 0 ? 1 : 0);
      if (!related(relation_, q_.ett, d.matrix_values.back(), d.program_values.back())) {
        d.scan = static_cast<int>(c);
        d.assigned_at = interp.last_assignment(q_.variable);
        break;
      }
    }
    if (d.scan < 0)
      throw InternalError("plc-check " + q_.tag + ": the solver's run of " + std::to_string(t.length()) +
                          " scans does not break the relation on the matrix's runtime and the program's "
                          "interpreter (the encodings disagree with them)");
    const std::size_t n = static_cast<std::size_t>(d.scan) + 1;
    d.matrix_inputs.resize(n);
    d.program_inputs.resize(n);
    d.runtime.inputs.resize(n);
    d.runtime.observables.resize(n);
    return d;
  }

 private:
  const model::Matrix& m_;
  const plc::Program& program_;
  const plc::Pou& pou_;
  const ResolvedMap& map_;
  const OutputQuestion& q_;
  Relation relation_;
};

}  // namespace

const char* to_string(OutputVerdict v) {
  switch (v) {
    case OutputVerdict::Related: return "related";
    case OutputVerdict::Differs: return "differs";
    default: return "unknown";
  }
}

std::vector<OutputQuestion> questions(const model::Matrix& m, const ResolvedMap& map) {
  std::vector<OutputQuestion> out;
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    for (std::size_t j = 0; j < e.tags.size(); ++j) {
      OutputQuestion q;
      q.effect = e.id;
      q.position = static_cast<int>(j + 1);
      q.tag = e.tags[j].name;
      q.ett = e.tags[j].ett;
      for (const auto& b : map.map.outputs)
        if (model::tag_key(b.tag) == model::tag_key(q.tag) && (b.effect == 0 || b.effect == e.id)) q.variable = b.variable;
      out.push_back(q);
    }
  }
  return out;
}

namespace {

// A shortest run to `depth` on the reduced product, whose every scan also
// keeps `invariant` (true in every reachable state, so no run is lost).
// The run an assessor reads: every input the difference does not need put
// back at rest (the matrix's scenario defaults, good quality, no command), on
// the reduced problem by the concrete pass of checker/shrink.hpp (the
// solver's pass costs about 0.4 s an output here and changed nothing on the
// tank's seeded errors); then lifted to the product as built, its analog
// values made round numbers (checker/round_values.hpp), and replayed there.
checker::Trace readable_run(const checker::OwnedProblem& original, const checker::OwnedProblem& reduced,
                            const checker::Trace& run, const model::Matrix& m, const CheckOptions& o) {
  const auto rest = at_rest(m).rest;
  const checker::Trace rested = checker::rest_inputs_concretely(reduced.problem, run, rest, o.limits);
  // The inputs the reduction left out play no part; lifted, they read 0 (a
  // level below its low limit): at rest instead, on the product as built.
  const checker::Trace lifted =
      checker::rest_inputs_concretely(original.problem, checker::lift_trace(original.problem, rested), rest, o.limits);
  checker::Trace t = checker::round_values(original.problem, lifted);
  checker::check::replay_counterexample(original.problem, t, &o.limits);
  return t;
}

std::optional<checker::Trace> shortest_run(const checker::OwnedProblem& original, const checker::OwnedProblem& reduced,
                                           const std::vector<z3::expr>& invariant, int depth, const model::Matrix& m,
                                           const CheckOptions& o) {
  checker::SafetyProblem p = reduced.problem;
  for (const auto& c : invariant) p.assumption = p.assumption && c;
  const ProverResult r = checker::Bmc().prove(p, o.limits.with_work(o.work).with_depth(depth));
  if (r.verdict != Verdict::Falsified) return std::nullopt;
  return readable_run(original, reduced, r.cex, m, o);
}

}  // namespace

OutputResult check_output(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                          const ResolvedMap& map, const OutputQuestion& q, const CheckOptions& options) {
  OutputResult out;
  out.question = q;
  // The output's group at once first (the outputs whose cones overlap):
  // most programs that compute the matrix are proved there, a shared cone's
  // proof is not repeated.
  try {
    const SharedProof all = options.by_groups ? shared_proof(m, program, pou, map, options, q) : SharedProof{};
    if (all.proved) {
      out.verdict = OutputVerdict::Related;
      out.method = "correspondence invariants";
      out.k = all.k;
      return out;
    }
  } catch (const checker::Interrupted&) {
    out.reason = "time limit";
    return out;
  }
  const checker::ProblemFactory make = product_factory(m, program, pou, map, {q}, options.relation);
  Replay replay(m, program, pou, map, q, options.relation);
  auto differs = [&](const checker::OwnedProblem& original, const checker::Trace& t, const std::string& method) {
    out.verdict = OutputVerdict::Differs;
    out.method = method;
    out.k = static_cast<int>(t.length());
    out.difference = replay.run(*std::static_pointer_cast<ProductProblem>(original.owner), t);
    return out;
  };
  try {
    z3::context ctx;
    const checker::OwnedProblem original = make(ctx);
    const checker::OwnedProblem reduced = checker::reduce(original);
    // A short search first: most hand-coding errors show in the first scans.
    if (auto t = shortest_run(original, reduced, {}, options.first_depth, m, options)) return differs(original, *t, "bmc");
    // Seeded runs: a difference that needs a delay to run out, found without
    // a solver; otherwise the states that filter the candidates.
    const SamplingOptions so = at_rest(m);
    const Samples s = sample(reduced.problem, so);
    if (s.violation) return differs(original, readable_run(original, reduced, *s.violation, m, options), "simulation");
    // The proof from the correspondence of the two states (correspondence.hpp),
    // re-checked in a fresh context on the problem built again.
    const Correspondence c = prove_by_correspondence(reduced.problem, s, options.limits.with_work(options.work), so);
    if (c.result.verdict == Verdict::Proved) {
      checker::check::recheck_proof(checker::reducing(make), c.result, &options.limits);
      out.verdict = OutputVerdict::Related;
      out.method = "correspondence invariants";
      out.k = c.result.k;
      return out;
    }
    // The shortest run within the longest delays, each scan keeping what
    // Houdini proved of the two states.
    if (auto t = shortest_run(original, reduced, c.invariant, options.bmc_depth, m, options))
      return differs(original, *t, "bmc");
  } catch (const checker::Interrupted&) {
    out.reason = "time limit";
    return out;
  }
  checker::PortfolioOptions po;
  po.engine_work = options.work;
  po.preferred = at_rest(m).rest;
  const ProverResult r = checker::Portfolio(make, po).run(options.limits);
  out.method = r.method_text();
  out.k = r.k;
  if (r.verdict == Verdict::Proved) {
    out.verdict = OutputVerdict::Related;
  } else if (r.verdict == Verdict::Unknown) {
    out.reason = r.reason_text();
  } else {
    z3::context ctx;
    const checker::OwnedProblem original = make(ctx);
    const checker::Trace t = checker::round_values(original.problem, r.cex);
    checker::check::replay_counterexample(original.problem, t, &options.limits);
    return differs(original, t, r.method_text());
  }
  return out;
}

}  // namespace cemv::plc_check
