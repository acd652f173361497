#include "checker/cone_group.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <memory>
#include <set>

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"
#include "checker/engines/multi.hpp"
#include "checker/reduce.hpp"
#include "checker/replay.hpp"
#include "checker/translate.hpp"
#include "encoder/encode.hpp"
#include "model/graph.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "properties/print.hpp"
#include "properties/shape.hpp"

namespace cemv::checker {

namespace {

using properties::PropertyKind;

// Random runs per group, as the vacuity search of one property had them
// (checker/witness_pool.hpp): long enough for the cone's delays, short
// enough that a question no run answers costs little.
constexpr int kRuns = 8;
constexpr std::size_t kSegments = 16;
constexpr std::size_t kRunCycles = 600;
// The shallow unrolling of the covers and antecedents still open.
constexpr int kReachDepth = 8;
// A cone this small (state variables after the reduction) is unrolled before
// any random run.
constexpr std::size_t kSmallCone = 64;

properties::Trace as_property_trace(const ConcreteTrace& t) {
  properties::Trace trace;
  trace.reserve(t.inputs.size());
  for (std::size_t k = 0; k < t.inputs.size(); ++k) trace.push_back({t.inputs[k], t.observables[k]});
  return trace;
}

std::uint64_t seed_of(const std::string& name) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a: the same runs whatever else is checked
  for (char c : name) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return h;
}

bool is_cover(const GroupMember& g) { return g.property->kind == PropertyKind::Reachable; }

std::vector<std::string> space_tags(const RunSpace& space) {
  std::vector<std::string> out;
  for (const auto& t : space.tags) out.push_back(t.name);
  return out;
}

}  // namespace

ConeGroup::ConeGroup(const model::Matrix& m, std::vector<GroupMember> members, const CheckOptions& options)
    : m_(m), members_(std::move(members)), options_(options) {
  for (const auto& g : members_) roots_of_.push_back(properties::property_roots(*g.property, g.file->assumptions, m_));
}

GroupEncoding encode_group(z3::context& ctx, const model::Matrix& m, const std::vector<GroupMember>& members,
                           const CheckOptions& options, bool guard_cells, bool reduce) {
  std::vector<model::Node> roots;
  for (const auto& g : members)
    for (const auto& n : properties::property_roots(*g.property, g.file->assumptions, m)) roots.push_back(n);
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  GroupEncoding b;
  encoder::EncodeOptions eo;
  eo.guard_cells = guard_cells;
  b.enc = encoder::encode(ctx, m, roots, eo);
  if (options.modify_encoding) options.modify_encoding(*b.enc);
  std::vector<properties::Monitor> monitors;
  for (const auto& g : members) monitors.push_back(properties::compile_monitor(*b.enc, *g.property, g.file->assumptions));
  // Analog inputs over the finite floats, as checker/property_problem states
  // every property's problem.
  z3::expr assumption = monitors.front().assumption;
  const z3::expr max = b.enc->ts.float_const(std::numeric_limits<float>::max());
  const z3::expr min = b.enc->ts.float_const(-std::numeric_limits<float>::max());
  for (const auto& in : b.enc->ts.inputvars())
    if (in.var.is_fpa())
      assumption = assumption && z3::expr(ctx, Z3_mk_fpa_geq(ctx, in.var, min)) &&
                   z3::expr(ctx, Z3_mk_fpa_leq(ctx, in.var, max));
  std::vector<z3::expr> terms;
  for (const auto& mon : monitors) {
    terms.push_back(mon.good);
    b.original_goods.push_back(mon.good);
    b.shared.push_back(z3::eq(mon.assumption, monitors.front().assumption));
  }
  for (const auto& mon : monitors)
    if (mon.antecedent) terms.push_back(*mon.antecedent);
  b.original = OwnedProblem{b.enc, SafetyProblem{&b.enc->ts, ctx.bool_val(true), assumption}};
  if (!reduce) {
    for (const auto& mon : monitors) b.antecedents.push_back(mon.antecedent);
    return b;
  }
  b.reduced = reduce_with(*b.original, terms);
  std::size_t next = monitors.size();
  for (std::size_t i = 0; i < monitors.size(); ++i) {
    b.goods.push_back(terms[i]);
    b.antecedents.push_back(monitors[i].antecedent ? std::optional<z3::expr>(terms[next++]) : std::nullopt);
  }
  return b;
}

std::vector<EarlyAnswer> ConeGroup::decide(const Limits& limits) {
  std::vector<EarlyAnswer> out(members_.size());
  PooledContext ctx;
  // A caller's directed runs come first in each member's own checker, and
  // the group then only says what it knows of the cone: that needs no
  // reduction (on big_matrix's wide cones, a tenth of `cemv response`).
  const bool runs_first = !options_.directed_runs.empty() || options_.directed_runs_only;
  Built b = encode_group(ctx, m_, members_, options_, /*guard_cells=*/false, /*reduce=*/!runs_first);
  // What every member's own checker needs of the cone.
  ConeFacts facts;
  facts.preferred = plant_at_rest({{b.enc.get(), &m_}});
  std::vector<std::string> tags;
  for (std::size_t i = 0; i < b.enc->tag_value.size(); ++i)
    if (b.enc->tag_value[i] || b.enc->tag_bad[i]) tags.push_back(b.enc->inputs.tags()[i].name);
  std::vector<model::Command> commands;
  for (const auto& c : b.enc->commands) commands.push_back(c.command());
  facts.space = run_space(m_, nullptr, tags, commands);
  if (commands.empty()) facts.space.commands.clear();
  facts.space.trips = cause_trips(m_, tags);
  facts.space.rests = rests_of(m_, facts.space.trips);
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i].facts = facts;
    out[i].facts.has_antecedent = b.antecedents[i].has_value();
  }
  if (runs_first) return out;
  // On a small cone the shallow unrolling answers at once what the runs
  // would look for at length, and the runs take what it leaves. On a wide
  // one the runs go first, and the unrolling takes only the covers they
  // leave: for an antecedent, unrolling the whole group's cone costs more
  // than the member's own question, asked on the elements it names (a
  // localization, checker/localize.hpp).
  const bool small = b.reduced->problem.ts->statevars().size() <= kSmallCone;
  if (!small) random_runs(out, limits);
  prove(b, out, limits);
  reach(b, out, limits, /*antecedents=*/small);
  if (small) random_runs(out, limits);
  recheck(b, out, limits);
  return out;
}

void ConeGroup::random_runs(std::vector<EarlyAnswer>& out, const Limits& limits) const {
  const RunSpace& space = out.front().facts.space;
  if (space.tags.empty() && space.commands.empty()) return;
  const properties::Evaluator evaluator(m_);
  const model::CycleInput start = model::default_cycle_input(m_);
  auto judge = [&](std::size_t i, const properties::Trace& t) {
    return evaluator.evaluate(*members_[i].property, members_[i].file->assumptions, t);
  };
  // The cycle at which member i's run shows what it is kept for (a cover's
  // witness, a violation), or -1.
  auto shows = [&](std::size_t i, const properties::Evaluation& ev) -> long {
    const bool found = is_cover(members_[i]) ? ev.holds : !ev.holds;
    return found && ev.cycle ? static_cast<long>(*ev.cycle) : -1;
  };
  // What a member still waits for from the runs: a cover's witness, a
  // violation, or a witness that its antecedent can hold.
  auto settled = [&](std::size_t i) {
    return is_cover(members_[i]) ? !out[i].run.empty() : out[i].vacuity_witnessed;
  };
  auto all_settled = [&] {
    for (std::size_t i = 0; i < out.size(); ++i)
      if (!settled(i)) return false;
    return true;
  };
  auto try_run = [&](const Run& run) {
    stop_if_interrupted(limits);
    const properties::Trace trace = as_property_trace(run_on_runtime(m_, expand(m_, run, start)));
    for (std::size_t i = 0; i < members_.size(); ++i) {
      EarlyAnswer& a = out[i];
      if (settled(i)) continue;
      const properties::Evaluation ev = judge(i, trace);
      if (ev.judged >= 1 && (!a.facts.has_antecedent || ev.antecedent_met)) a.vacuity_witnessed = true;
      if (!a.run.empty() || a.proof || shows(i, ev) < 0) continue;
      // Kept shorter where it still shows it: a run people read.
      const Run shortest = minimise_run(run, [&](const Run& candidate) {
        return shows(i, judge(i, as_property_trace(run_on_runtime(m_, expand(m_, candidate, start)))));
      });
      a.run = expand(m_, shortest, start);
      a.run_method = Method::RandomRun;
    }
  };
  for (auto& a : out) a.runs_tried = true;
  // First the direct runs: each cause a member names tripped alone, then
  // all of them together (an XooN's X causes), held for the longest
  // duration that fits: what an intersection's antecedent and a cover of an
  // effect's activity most often need.
  const std::vector<std::string> tags = space_tags(space);
  const std::size_t hold = space.holds.empty() ? 1 : std::min(space.holds.back(), kRunCycles);
  std::set<std::vector<int>> tried;
  for (std::size_t i = 0; i < members_.size() && !all_settled(); ++i) {
    if (settled(i)) continue;
    std::vector<int> all;
    for (const auto& n : roots_of_[i])
      if (n.kind == model::Node::Kind::Cause) all.push_back(n.id);
    std::vector<std::vector<int>> sets;
    for (int c : all) sets.push_back({c});
    if (all.size() > 1) sets.push_back(all);
    for (const auto& set : sets) {
      if (settled(i) || !tried.insert(set).second) continue;
      RunSegment trips{{}, {}, hold};
      for (int id : set) {
        const std::vector<RunSegment::Change> trip = cause_trip(*m_.find_cause(id), tags);
        trips.changes.insert(trips.changes.end(), trip.begin(), trip.end());
      }
      if (!trips.changes.empty()) try_run({trips});
    }
  }
  // Then seeded random runs of the cone.
  RandomRuns gen(space, seed_of(members_.front().property->name));
  for (int r = 0; r < kRuns && !all_settled(); ++r) try_run(gen.next(kSegments, kRunCycles));
}

void ConeGroup::prove(Built& b, std::vector<EarlyAnswer>& out, const Limits& limits) const {
  MultiProblem p{b.reduced->problem.ts, b.goods, b.reduced->problem.assumption};
  std::vector<bool> open(members_.size());
  std::size_t count = 0;
  for (std::size_t i = 0; i < open.size(); ++i) {
    open[i] = b.shared[i] && !is_cover(members_[i]) && out[i].run.empty();
    count += open[i];
  }
  if (count == 0) return;
  std::vector<bool> strengthen(members_.size());
  for (std::size_t i = 0; i < strengthen.size(); ++i) strengthen[i] = !properties::counts_cycles(*members_[i].property);
  const std::vector<ProverResult> proofs =
      prove_each(p, open, strengthen, limits.with_work(options_.budgets.quick * count));
  stop_if_interrupted(limits);
  for (std::size_t i = 0; i < open.size(); ++i)
    if (open[i] && proofs[i].verdict == Verdict::Proved) out[i].proof = proofs[i];
}

void ConeGroup::reach(Built& b, std::vector<EarlyAnswer>& out, const Limits& limits, bool antecedents) const {
  // A cover's witness, or a witness that a proved member's antecedent (or,
  // without one, its assumptions) can hold: one unrolling for all of them.
  std::vector<z3::expr> targets;
  std::vector<bool> open(members_.size());
  std::vector<bool> for_vacuity(members_.size());
  std::size_t count = 0;
  z3::context& ctx = b.reduced->problem.ts->ctx();
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const bool cover = is_cover(members_[i]) && out[i].run.empty();
    for_vacuity[i] = antecedents && !is_cover(members_[i]) && out[i].proof && !out[i].vacuity_witnessed;
    open[i] = b.shared[i] && (cover || for_vacuity[i]);
    if (cover) targets.push_back(!b.goods[i]);
    else if (for_vacuity[i] && b.antecedents[i]) targets.push_back(*b.antecedents[i]);
    else targets.push_back(ctx.bool_val(true));
    count += open[i];
  }
  if (count == 0) return;
  const std::vector<ProverResult> found =
      reach_each(*b.reduced->problem.ts, targets, b.reduced->problem.assumption, open,
                 limits.with_work(options_.budgets.quick * count).with_depth(kReachDepth));
  stop_if_interrupted(limits);
  for (std::size_t i = 0; i < members_.size(); ++i) {
    if (!open[i] || found[i].verdict != Verdict::Falsified) continue;
    if (for_vacuity[i]) {
      out[i].vacuity_witnessed = true;
      continue;
    }
    const Trace lifted = lift_trace(b.original->problem, found[i].cex);
    out[i].run = cycle_inputs(lifted, *b.enc, m_);
    out[i].run_method = Method::Bmc;
  }
}

void ConeGroup::recheck(const Built& b, std::vector<EarlyAnswer>& out, const Limits& limits) const {
  bool any = false;
  for (const auto& a : out) any = any || a.proof.has_value();
  if (!any) return;
  // The group's reduced problem copied into a context that holds nothing of
  // the engines' (the same names: the invariants' text reads there), where
  // each proof's obligations are stated afresh for a new solver
  // (checker/translate.hpp).
  PooledContext ctx;
  std::vector<z3::expr> goods = b.goods;
  const OwnedProblem copy = translate(b.reduced->problem, ctx, &goods);
  for (std::size_t i = 0; i < out.size(); ++i)
    if (out[i].proof)
      check::recheck_proof(SafetyProblem{copy.problem.ts, goods[i], copy.problem.assumption}, *out[i].proof, &limits);
}

std::vector<std::vector<std::size_t>> cone_groups(const model::Matrix& m, const std::vector<GroupMember>& jobs) {
  const model::DependencyGraph graph(m);
  const model::InputTable inputs(m);
  std::map<std::tuple<const properties::PropertyFile*, std::vector<model::Node>, std::string>, std::size_t> index;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    const auto& g = jobs[j];
    std::vector<model::Node> cone = graph.feeders_of(properties::property_roots(*g.property, g.file->assumptions, m));
    std::sort(cone.begin(), cone.end());
    std::string assumptions;
    for (const auto& a : g.property->assumptions) assumptions += properties::to_text(a.expr, inputs) + "\n";
    auto [it, fresh] = index.emplace(std::make_tuple(g.file, std::move(cone), std::move(assumptions)), groups.size());
    if (fresh) groups.emplace_back();
    groups[it->second].push_back(j);
  }
  return groups;
}

}  // namespace cemv::checker
