#include "testgen/search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>

#include "checker/engines/accelerated_bmc.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/context_pool.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/property_problem.hpp"
#include "checker/random_runs.hpp"
#include "checker/replay.hpp"
#include "checker/shrink.hpp"
#include "encoder/encode.hpp"

namespace cemv::testgen::detail {

namespace {

using checker::Limits;
using checker::OwnedProblem;
using checker::ProverResult;
using checker::Verdict;

// Longest trace BMC unrolls cycle by cycle; beyond it only accelerated BMC
// (macro steps of held inputs) is asked.
constexpr int kMaxUnrolled = 400;
constexpr float kAnalogRange = 1e9f;
constexpr int kLongHorizon = 8;

std::string name_of(const z3::expr& v) { return v.decl().name().str(); }

// Values an engineer would set on an analog input (checker/random_runs.hpp):
// a search restricted to them is fast and its steps read like a test sheet;
// only when it fails are all floats allowed.
std::vector<float> engineer_values(const model::Matrix& m, const model::InputTag& tag, float hold) {
  return checker::analog_test_values(m, tag, hold);
}

// The goal's problem: its cone, analog values a transmitter can deliver
// (within +/- 1e9: a field test sets no value near the float range's end,
// whose shortest text some readers round beyond it), with `engineer` only
// the values an engineer sets, and after a prefix the state it leaves.
checker::ProblemFactory problem(const model::Matrix& m, const Goal& g, const std::vector<model::CycleInput>& prefix,
                                bool engineer) {
  checker::ProblemOptions o;
  o.sliced = !g.roots.empty();
  o.roots = g.roots;
  o.analog_range = kAnalogRange;
  o.prefix = prefix.empty() ? nullptr : &prefix;  // the caller's, alive while the factory is used
  if (engineer) {
    const model::CycleInput hold = prefix.empty() ? model::default_cycle_input(m) : prefix.back();
    const model::InputTable table(m);
    o.analog_values.resize(table.size());
    for (std::size_t i = 0; i < table.size(); ++i)
      if (table.tags()[i].kind == model::TagKind::Analog)
        o.analog_values[i] = engineer_values(m, table.tags()[i], hold.tags[i].value);
  }
  return checker::property_problem(m, *g.file, *g.property, o);
}

}  // namespace

// Inputs keep their value unless the objective needs otherwise: the end of
// the prefix (held), or the plant at rest (scenario defaults, good quality);
// no operator command.
checker::PreferredValue held_inputs(const encoder::Encoding& enc, const model::CycleInput& hold) {
  auto values = std::make_shared<std::unordered_map<std::string, checker::Value>>();
  for (std::size_t i = 0; i < enc.tag_value.size() && i < hold.tags.size(); ++i) {
    if (enc.tag_value[i]) {
      checker::Value v;
      if (enc.tag_value[i]->is_fpa()) {
        v.is_float = true;
        v.f = hold.tags[i].value;
      } else {
        v.i = hold.tags[i].value != 0.0f ? 1 : 0;
      }
      (*values)[name_of(*enc.tag_value[i])] = v;
    }
    if (enc.tag_bad[i]) {
      checker::Value b;
      b.i = hold.tags[i].bad_quality ? 1 : 0;
      (*values)[name_of(*enc.tag_bad[i])] = b;
    }
  }
  for (const auto& c : enc.commands) (*values)[name_of(c.var)] = checker::Value{};
  return [values](const std::string& input) -> std::optional<checker::Value> {
    auto it = values->find(input);
    if (it == values->end()) return std::nullopt;
    return it->second;
  };
}

std::vector<model::CycleInput> witness_inputs(const checker::Trace& t, const encoder::Encoding& enc,
                                             const model::Matrix& m, const model::CycleInput& hold) {
  std::vector<model::CycleInput> cycles = checker::cycle_inputs(t, enc, m);
  // Tags outside the cone keep what the test last gave them (cycle_inputs
  // sets them to the defaults, which nothing encoded reads).
  for (auto& in : cycles)
    for (std::size_t i = 0; i < in.tags.size() && i < enc.tag_value.size(); ++i) {
      if (in.tags[i].value == 0.0f) in.tags[i].value = 0.0f;  // -0 reads as 0 in every comparison (C.3)
      if (!enc.tag_value[i]) in.tags[i].value = hold.tags[i].value;
      if (!enc.tag_bad[i]) in.tags[i].bad_quality = hold.tags[i].bad_quality;
    }
  return cycles;
}

SearchResult Searcher::find(const Goal& g, const std::vector<model::CycleInput>& prefix, checker::Work budget) const {
  // First with the values an engineer sets (fast, readable), then any float.
  SearchResult first = find_once(g, prefix, budget / 2, true);
  if (first.kind == SearchResult::Kind::Found) return first;
  SearchResult second = find_once(g, prefix, budget / 2, false);
  if (second.kind != SearchResult::Kind::Found) second.reason = first.reason + "; " + second.reason;
  return second;
}

SearchResult Searcher::find_once(const Goal& g, const std::vector<model::CycleInput>& prefix, checker::Work budget,
                                 bool engineer) const {
  SearchResult out;
  checker::PooledContext ctx;
  OwnedProblem op = problem(m_, g, prefix, engineer)(ctx);
  const auto& enc = *std::static_pointer_cast<encoder::Encoding>(op.owner);
  const int depth = g.horizon + options_.max_depth;
  Limits limits;
  limits.cancel = options_.cancel;
  ProverResult r;
  checker::Work spent = 0;
  // A witness that needs a timer to run (a horizon of many cycles) holds its
  // inputs for most of them: accelerated BMC's macro steps find it at once,
  // where plain BMC unrolls every cycle of the analog arithmetic.
  if (g.horizon >= kLongHorizon) {
    const checker::Work mine = depth <= kMaxUnrolled ? budget / 2 : budget;
    r = checker::AcceleratedBmc{}.prove(op.problem,
                                         limits.with_work(mine).with_depth(checker::AcceleratedBmc::kMaxMacroSteps));
    spent = r.work;
    // Macro steps may hold inputs far longer than the objective needs (any
    // n satisfies a saturated timer): such a run is no field test, and every
    // later replay of the test would pay for it. Plain BMC then decides.
    if (r.verdict == Verdict::Falsified &&
        static_cast<int>(r.cex.length()) > std::max(2 * g.horizon, g.horizon + options_.max_depth)) {
      r = ProverResult{};
      r.method = checker::Method::AcceleratedBmc;
      r.reason = checker::UnknownReason::BoundReached;
      r.detail = "witness longer than the objective needs";
    }
  }
  if (r.verdict != Verdict::Falsified && depth <= kMaxUnrolled && spent < budget)
    r = checker::Bmc{}.prove(op.problem, limits.with_work(budget - spent).with_depth(depth));
  checker::stop_if_interrupted(limits);
  // A witness has at least one cycle (after a prefix too: the objective is
  // reached by what the search adds); an empty one is an engine's error.
  if (r.verdict == Verdict::Falsified && r.cex.length() == 0)
    throw checker::InternalError("objective search: " + r.method_text() + " answered reachable without a witness");
  if (r.verdict != Verdict::Falsified) {
    out.reason = (r.reason == checker::UnknownReason::None ? std::string("not found") : r.reason_text()) + " (" +
                 r.method_text() + ", depth " + std::to_string(r.k) + ")";
    return out;
  }
  const model::CycleInput hold = prefix.empty() ? model::default_cycle_input(m_) : prefix.back();
  checker::Trace readable =
      checker::shrink_trace(op.problem, r.cex, held_inputs(enc, hold), limits.with_work(options_.shrink_work));
  checker::stop_if_interrupted(limits);
  out.cycles = witness_inputs(readable, enc, m_, hold);
  out.kind = SearchResult::Kind::Found;
  out.method = r.method_text();
  return out;
}

SearchResult Searcher::prove_unreachable(const Goal& g) const {
  SearchResult out;
  checker::PortfolioOptions po;
  po.engines = {checker::Method::InvariantsInduction, checker::Method::KInduction, checker::Method::Pdr};
  po.engine_work = options_.proof_work;
  po.quick_work = options_.proof_work;
  po.max_k = 4;
  Limits limits;
  limits.cancel = options_.cancel;
  ProverResult r = checker::Portfolio(problem(m_, g, {}, false), po).run(limits);
  checker::stop_if_interrupted(limits);
  if (r.verdict == Verdict::Proved) {
    out.kind = SearchResult::Kind::Infeasible;
    out.method = r.method_text();
    out.reason = "proved unreachable by " + r.method_text() + (r.k > 0 ? " (k = " + std::to_string(r.k) + ")" : "");
    if (!r.invariant.clauses.empty() && r.invariant.clauses.size() <= 4)
      out.reason += "; invariant: " + r.invariant.text();
    while (!out.reason.empty() && out.reason.back() == '\n') out.reason.pop_back();
  } else {
    out.reason = "no proof (" + r.reason_text() + ")";
  }
  return out;
}

}  // namespace cemv::testgen::detail
