// The path's one encoding (docs/defeats.md, "One encoding per path"): its
// solvers and invariant candidates, made once; the demand runs of a set on
// the runtime; a proof re-checked in a fresh context. A set's test under
// assumptions is space_test.cpp.
#include "defeats/space.hpp"

#include "checker/check/recheck.hpp"
#include "checker/engines/invariants.hpp"
#include "checker/replay.hpp"
#include "defeats/space_solvers.hpp"
#include "properties/evaluator.hpp"

namespace cemv::defeats {

using Set = std::vector<int>;

void ActionSpace::Solvers::base_frames(int k) {
  while (static_cast<int>(base_bad.size()) <= k) {
    const int t = static_cast<int>(base_bad.size());
    const std::string at = "@" + std::to_string(t);
    z3::expr held = ctx.bool_const(("defeats.base.held" + at).c_str());
    base.add(held == (t == 0 ? u->at(frame, 0) : so_far.back() && u->at(frame, t)));
    z3::expr bad = ctx.bool_const(("defeats.base.violated" + at).c_str());
    base.add(z3::implies(bad, held && !u->at(good(), t)));
    base.add(u->at(trans, t));
    so_far.push_back(held);
    base_bad.push_back(bad);
  }
}

void ActionSpace::Solvers::step_frames(int k) {
  while (static_cast<int>(step_bad.size()) <= k) {
    const int t = static_cast<int>(step_bad.size());
    const std::string at = "@" + std::to_string(t);
    z3::expr on = ctx.bool_const(("defeats.step.cycle" + at).c_str());
    step.add(z3::implies(on, u->at(frame, t)));
    for (std::size_t j = 0; j < cands.size(); ++j) step.add(z3::implies(on && lits[j], u->at(cands[j], t)));
    z3::expr g = ctx.bool_const(("defeats.step.good" + at).c_str());
    z3::expr b = ctx.bool_const(("defeats.step.violated" + at).c_str());
    step.add(z3::implies(g, u->at(good(), t)));
    step.add(z3::implies(b, !u->at(good(), t)));
    step.add(u->at(trans, t));
    step_on.push_back(on);
    step_good.push_back(g);
    step_bad.push_back(b);
  }
}

namespace {

// The candidates the initial state satisfies (initiation does not depend on
// the actions: the assumptions constrain cycles, not the initial state).
std::vector<z3::expr> initiated(const checker::SafetyProblem& p, std::vector<z3::expr> cands, encoder::Unroller& u,
                                Meter& meter, const checker::Limits& limits) {
  z3::context& ctx = p.ts->ctx();
  z3::solver s(ctx);
  s.add(u.at(p.ts->init_formula(), 0));
  for (int round = 0; !cands.empty(); ++round) {
    z3::expr_vector some_false(ctx);
    for (const auto& c : cands) some_false.push_back(!u.at(c, 0));
    z3::expr r = ctx.bool_const(("defeats.init.round." + std::to_string(round)).c_str());
    s.add(z3::implies(r, z3::mk_or(some_false)));
    z3::expr_vector a(ctx);
    a.push_back(r);
    const z3::check_result cr = check_within(s, meter, a);
    if (cr == z3::unsat) break;
    if (cr == z3::unknown) throw checker::Stopped{unknown_reason(s.reason_unknown(), limits, meter)};
    z3::model m = s.get_model();
    std::vector<z3::expr> keep;
    for (const auto& c : cands)
      if (m.eval(u.at(c, 0), true).is_true()) keep.push_back(c);
    cands = std::move(keep);
    s.add(!r);
  }
  return cands;
}

}  // namespace

ActionSpace::ActionSpace(const model::Matrix& m, const PathDefeats& pd, const std::vector<Run>& demand_runs)
    : m_(m), pd_(pd), demand_runs_(demand_runs), s_(std::make_unique<Solvers>(m, pd)) {
  Solvers& s = *s_;
  const checker::SafetyProblem& p = s.built.problem.problem;
  s.u = std::make_unique<encoder::Unroller>(*p.ts);
  z3::expr frame = p.ts->constraint_formula() && p.assumption;
  for (std::size_t i = 0; i < s.built.keep.size(); ++i) {
    z3::expr x = s.ctx.bool_const(("defeats.exclude." + std::to_string(i + 1)).c_str());
    s.action_of.emplace(x.id(), static_cast<int>(i));
    s.exclude.push_back(x);
    frame = frame && z3::implies(x, s.built.keep[i]);
  }
  s.frame = frame;
  s.trans = p.ts->trans_formula();
  s.base.add(s.u->at(p.ts->init_formula(), 0));
  s.bmc_depth = static_cast<int>(std::min<long long>(*pd.requirement + kBmcMargin, kMaxBmcDepth));
  s.bmc_depth = std::max(s.bmc_depth, kMaxInductionK + 1);
  // The invariant candidates: the encoder's lemmas and the mined relations
  // (engines/invariants.hpp), mined once for the path with every action
  // allowed; each test keeps its inductive subset (Houdini).
  // Each state variable at its initial value: what freezes the state of an
  // action that never occurs (a soft bypass never commanded, a simulation
  // never switched on), which the checker's constant propagation gives a
  // question that excludes it outright.
  std::vector<z3::expr> cands;
  for (const auto& v : p.ts->statevars())
    if (v.has_init && (v.init.is_numeral() || v.init.is_true() || v.init.is_false())) cands.push_back(v.var == v.init);
  for (const auto& l : p.ts->lemmas()) cands.push_back(l.term);
  checker::MiningOptions mining;
  mining.bool_implications = true;
  for (const auto& c : checker::mine_candidates(p, mining)) cands.push_back(c);
  for (const auto& c : mined_without_actions(s.builder, *p.ts)) cands.push_back(c);
  Meter meter(s.ctx, s.probe, 0);
  checker::Limits unbounded;
  s.cands = initiated(p, std::move(cands), *s.u, meter, unbounded);
  s.houdini.add(s.u->at(s.frame && s.trans, 0));
  for (std::size_t j = 0; j < s.cands.size(); ++j) {
    z3::expr l = s.ctx.bool_const(("defeats.cand." + std::to_string(j)).c_str());
    s.lits.push_back(l);
    s.cand_of.emplace(l.id(), j);
    s.houdini.add(z3::implies(l, s.u->at(s.cands[j], 0)));
    s.cands_next.push_back(s.u->at(s.cands[j], 1));
  }
}

ActionSpace::~ActionSpace() = default;

namespace {

// What the demand runs with the set's actions taken show on the runtime,
// judged by the concrete evaluator on the requirement with exactly `allowed`
// allowed: the actions a violating run takes before its violation, or none.
std::optional<RunDefeat> run_defeat(const model::Matrix& m, const PathDefeats& pd, const Builder& b,
                                    const Set& allowed, const std::vector<Run>& demand_runs) {
  const properties::Property p = b.property(allowed);
  const properties::Evaluator judge(m);
  for (const Run& r : defeat_runs(m, pd.path, pd.actions, allowed, demand_runs)) {
    const checker::ConcreteTrace run = checker::run_on_runtime(m, r);
    properties::Trace trace;
    for (std::size_t i = 0; i < run.inputs.size(); ++i) trace.push_back({run.inputs[i], run.observables[i]});
    const properties::Evaluation e = judge.evaluate(p, {}, trace);
    if (e.holds || !e.cycle) continue;
    RunDefeat d;
    d.violation_cycle = static_cast<int>(*e.cycle);
    for (int a : allowed) {
      const std::vector<bool> kept = judge.values(b.exclusion(a), trace);
      for (std::size_t c = 0; c <= *e.cycle && c < kept.size(); ++c)
        if (!kept[c]) {
          d.used.push_back(a);
          break;
        }
    }
    return d;
  }
  return std::nullopt;
}

}  // namespace

std::optional<RunDefeat> ActionSpace::run(const Set& allowed) const {
  return run_defeat(m_, pd_, s_->builder, allowed, demand_runs_);
}

void ActionSpace::recheck(const Test& t, const checker::Limits& limits) const {
  z3::context ctx;
  Built fresh = s_->builder.build(ctx);
  checker::SafetyProblem p = fresh.problem.problem;
  for (std::size_t i = 0; i < fresh.keep.size(); ++i)
    if (!in(t.covered, static_cast<int>(i))) p.assumption = p.assumption && fresh.keep[i];
  checker::check::recheck_proof(p, t.proof, &limits);
}

}  // namespace cemv::defeats
