#include "testgen/search.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_map>

#include "checker/engines/accelerated_bmc.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/random_runs.hpp"
#include "checker/replay.hpp"
#include "checker/shrink.hpp"
#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "properties/monitor.hpp"

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

// The goal's safety problem in `ctx`; with a prefix, the initial state is the
// state after the prefix (the encoding's own Evaluator runs it, monitor
// included, so the past-time operators see the whole test).
OwnedProblem build(z3::context& ctx, const model::Matrix& m, const Goal& g,
                   const std::vector<model::CycleInput>& prefix, bool engineer = false) {
  std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m, g.roots);
  properties::Monitor mon = properties::compile_monitor(*enc, *g.property, g.file->assumptions);
  // Analog values a transmitter can deliver: within +/- 1e9 (a field test sets
  // no value near the float range's end, whose shortest text some readers
  // round beyond it).
  z3::expr assumption = mon.assumption;
  const z3::expr max = enc->ts.float_const(kAnalogRange);
  const z3::expr min = enc->ts.float_const(-kAnalogRange);
  for (const auto& in : enc->ts.inputvars())
    if (in.var.is_fpa())
      assumption = assumption && z3::expr(ctx, Z3_mk_fpa_geq(ctx, in.var, min)) &&
                   z3::expr(ctx, Z3_mk_fpa_leq(ctx, in.var, max));
  if (engineer) {
    const model::CycleInput hold = prefix.empty() ? model::default_cycle_input(m) : prefix.back();
    for (std::size_t i = 0; i < enc->tag_value.size(); ++i) {
      if (!enc->tag_value[i] || !enc->tag_value[i]->is_fpa()) continue;
      z3::expr any = ctx.bool_val(false);
      for (float v : engineer_values(m, enc->inputs.tags()[i], hold.tags[i].value))
        any = any || z3::expr(ctx, Z3_mk_fpa_eq(ctx, *enc->tag_value[i], enc->ts.float_const(v)));
      assumption = assumption && any;
    }
  }
  if (!prefix.empty()) {
    encoder::Evaluator ev(*enc);
    for (const auto& in : prefix) ev.step(in);
    const auto state = ev.state();
    const auto& vars = enc->ts.statevars();
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const z3::expr& v = vars[i].var;
      z3::expr value = v.is_bool() ? ctx.bool_val(state[i].i != 0)
                       : v.is_int() ? ctx.int_val(static_cast<int64_t>(state[i].i))
                                    : enc->ts.float_const(state[i].f);
      enc->ts.set_init(v, value);
    }
  }
  return OwnedProblem{enc, checker::SafetyProblem{&enc->ts, mon.good, assumption}};
}

// Inputs keep their value unless the objective needs otherwise: the end of
// the prefix (held), or the plant at rest (scenario defaults, good quality);
// no operator command.
checker::PreferredValue preferred(const encoder::Encoding& enc, const model::CycleInput& hold) {
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

Limits within(double seconds, int depth) {
  return Limits::within(std::chrono::milliseconds(static_cast<long long>(seconds * 1000)), depth);
}

}  // namespace

SearchResult Searcher::find(const Goal& g, const std::vector<model::CycleInput>& prefix, double budget_s) const {
  // First with the values an engineer sets (fast, readable), then any float.
  SearchResult first = find_once(g, prefix, budget_s * 0.5, true);
  if (first.kind == SearchResult::Kind::Found) return first;
  SearchResult second = find_once(g, prefix, budget_s * 0.5, false);
  if (second.kind != SearchResult::Kind::Found) second.reason = first.reason + "; " + second.reason;
  return second;
}

SearchResult Searcher::find_once(const Goal& g, const std::vector<model::CycleInput>& prefix, double budget_s,
                                 bool engineer) const {
  SearchResult out;
  z3::context ctx;
  OwnedProblem op = build(ctx, m_, g, prefix, engineer);
  const auto& enc = *std::static_pointer_cast<encoder::Encoding>(op.owner);
  const int depth = g.horizon + options_.max_depth;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(static_cast<long long>(budget_s * 1000));
  ProverResult r;
  // A witness that needs a timer to run (a horizon of many cycles) holds its
  // inputs for most of them: accelerated BMC's macro steps find it at once,
  // where plain BMC unrolls every cycle of the analog arithmetic.
  if (g.horizon >= kLongHorizon) {
    Limits limits = within(budget_s, checker::AcceleratedBmc::kMaxMacroSteps);
    limits.deadline = depth <= kMaxUnrolled ? std::chrono::steady_clock::now() +
                                                  std::chrono::milliseconds(static_cast<long long>(budget_s * 500))
                                            : deadline;
    r = checker::AcceleratedBmc{}.prove(op.problem, limits);
    // Macro steps may hold inputs far longer than the objective needs (any
    // n satisfies a saturated timer): such a run is no field test, and every
    // later replay of the test would pay for it. Plain BMC then decides.
    if (r.verdict == Verdict::Falsified &&
        static_cast<int>(r.cex.length()) > std::max(2 * g.horizon, g.horizon + options_.max_depth)) {
      r = ProverResult{};
      r.method = "accelerated-bmc";
      r.reason = "witness longer than the objective needs";
    }
  }
  if (r.verdict != Verdict::Falsified && depth <= kMaxUnrolled) {
    Limits limits = within(budget_s, depth);
    limits.deadline = deadline;
    if (!limits.over()) r = checker::Bmc{}.prove(op.problem, limits);
  }
  // A witness has at least one cycle (after a prefix too: the objective is
  // reached by what the search adds); an empty one is an engine's error.
  if (r.verdict == Verdict::Falsified && r.cex.length() == 0)
    throw checker::InternalError("objective search: " + r.method + " answered reachable without a witness");
  if (r.verdict != Verdict::Falsified) {
    out.reason = (r.reason.empty() ? "not found" : r.reason) + " (" + r.method + ", depth " + std::to_string(r.k) + ")";
    return out;
  }
  const model::CycleInput hold = prefix.empty() ? model::default_cycle_input(m_) : prefix.back();
  checker::Trace readable = checker::shrink_trace(op.problem, r.cex, preferred(enc, hold), within(5.0, 0));
  out.cycles = checker::cycle_inputs(readable, enc, m_);
  // Tags outside the cone keep what the test last gave them (cycle_inputs
  // sets them to the defaults, which nothing encoded reads).
  for (auto& in : out.cycles)
    for (std::size_t i = 0; i < in.tags.size() && i < enc.tag_value.size(); ++i) {
      if (in.tags[i].value == 0.0f) in.tags[i].value = 0.0f;  // -0 reads as 0 in every comparison (C.3)
      if (!enc.tag_value[i]) in.tags[i].value = hold.tags[i].value;
      if (!enc.tag_bad[i]) in.tags[i].bad_quality = hold.tags[i].bad_quality;
    }
  out.kind = SearchResult::Kind::Found;
  out.method = r.method;
  return out;
}

SearchResult Searcher::prove_unreachable(const Goal& g) const {
  SearchResult out;
  const model::Matrix* m = &m_;
  Goal goal = g;
  checker::ProblemFactory factory = [m, goal](z3::context& ctx) { return build(ctx, *m, goal, {}); };
  checker::PortfolioOptions po;
  po.engines = {"invariants+induction", "k-induction", "pdr"};
  po.max_k = 4;
  ProverResult r = checker::Portfolio(factory, po).run(within(options_.proof_budget_s, 1000));
  if (r.verdict == Verdict::Proved) {
    out.kind = SearchResult::Kind::Infeasible;
    out.method = r.method;
    out.reason = "proved unreachable by " + r.method + (r.k > 0 ? " (k = " + std::to_string(r.k) + ")" : "");
    if (!r.invariant.clauses.empty() && r.invariant.clauses.size() <= 4)
      out.reason += "; invariant: " + r.invariant.text();
    while (!out.reason.empty() && out.reason.back() == '\n') out.reason.pop_back();
  } else {
    out.reason = "no proof (" + r.reason + ")";
  }
  return out;
}

}  // namespace cemv::testgen::detail
