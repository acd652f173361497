#include "checker/engines/kinduction.hpp"

#include <algorithm>
#include <unordered_set>

#include "checker/engines/invariants.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/unroller.hpp"

namespace cemv::checker {

namespace {

// The state vectors of cycles i and j differ in at least one variable.
z3::expr states_differ(const encoder::TransitionSystem& ts, encoder::Unroller& u, int i, int j) {
  z3::expr_vector parts(ts.ctx());
  for (const auto& s : ts.statevars()) parts.push_back(u.var_at(s.var, i) != u.var_at(s.var, j));
  return parts.empty() ? ts.ctx().bool_val(false) : z3::mk_or(parts);
}

// The first pair of equal states among cycles 0..k of the model, if any.
std::optional<std::pair<int, int>> repeated_state(const encoder::TransitionSystem& ts,
                                                  encoder::Unroller& u, const z3::model& m, int k) {
  std::vector<std::vector<Value>> states;
  for (int c = 0; c <= k; ++c) {
    std::vector<Value> v;
    for (const auto& s : ts.statevars()) v.push_back(value_in(m, u.var_at(s.var, c)));
    states.push_back(std::move(v));
  }
  for (int j = 1; j <= k; ++j)
    for (int i = 0; i < j; ++i)
      if (states[i] == states[j]) return std::make_pair(i, j);
  return std::nullopt;
}

}  // namespace

std::vector<z3::expr> KInduction::strengthening(const SafetyProblem& problem, const Limits& limits,
                                               WorkMeter& meter) const {
  std::vector<z3::expr> candidates;
  std::unordered_set<unsigned> seen;
  auto add = [&](const z3::expr& e) {
    if (seen.insert(e.id()).second) candidates.push_back(e);
  };
  if (options_.use_lemmas)
    for (const auto& l : problem.ts->lemmas()) add(l.term);
  if (options_.mine_invariants) {
    MiningOptions mining;
    mining.bool_implications = options_.bool_implications;
    mining.limits = &limits;
    for (const auto& c : mine_candidates(problem, mining)) add(c);
  }
  if (candidates.empty()) return candidates;
  return houdini(problem, std::move(candidates), limits, meter);
}

ProverResult KInduction::prove(const SafetyProblem& problem, const Limits& limits) {
  const auto start = Clock::now();
  const auto& ts = *problem.ts;
  z3::context& ctx = ts.ctx();
  ProverResult r;
  r.method = options_.method;
  // One budget for the strengthening and the induction: the meter counts
  // the context's work from here, Houdini's checks included.
  WorkMeter meter(ctx, limits);
  auto finish = [&](Verdict v, int k, UnknownReason reason) {
    r.verdict = v;
    r.k = k;
    r.reason = reason;
    r.work = meter.spent();
    r.seconds = seconds_since(start);
    return r;
  };
  try {
    std::vector<z3::expr> inv = strengthening(problem, limits, meter);
    if (limits.interrupted()) return finish(Verdict::Unknown, 0, UnknownReason::TimeLimit);
    for (const auto& c : inv) r.invariant.clauses.push_back(to_smtlib(c));
    z3::expr S = ctx.bool_val(true);
    if (!inv.empty()) {
      z3::expr_vector parts(ctx);
      for (const auto& c : inv) parts.push_back(c);
      S = z3::mk_and(parts);
    }
    encoder::Unroller u(ts);
    Watchdog watchdog(ctx, limits);
    z3::solver base = make_solver(ctx, limits.solvers), step = make_solver(ctx, limits.solvers);
    const z3::expr facts = ts.constraint_formula() && problem.assumption;
    const z3::expr trans = ts.trans_formula();
    const int max_k = options_.max_k < 0 ? limits.max_depth : std::min(options_.max_k, limits.max_depth);
    base.add(u.at(ts.init_formula(), 0));
    step.add(u.at(S, 0));
    for (int k = 0; k <= max_k; ++k) {
      if (limits.interrupted()) return finish(Verdict::Unknown, k, UnknownReason::TimeLimit);
      // Base case: no violation in cycle k (cycles before it were checked).
      base.add(u.at(facts, k));
      z3::expr bad = ctx.bool_const(("kind.base.violated@" + std::to_string(k)).c_str());
      base.add(z3::implies(bad, !u.at(problem.good, k)));
      z3::expr_vector assume(ctx);
      assume.push_back(bad);
      z3::check_result cr = check_within(base, meter, assume);
      if (cr == z3::sat) {
        r.cex = trace_from_model(ts, u, base.get_model(), k);
        r.invariant = {};
        return finish(Verdict::Falsified, k, UnknownReason::None);
      }
      if (cr == z3::unknown)
        return finish(Verdict::Unknown, k, unknown_reason(base.reason_unknown(), limits, meter, &r.detail));
      base.add(u.at(problem.good, k));
      base.add(u.at(trans, k));

      // Inductive step: k cycles keeping S and good, then a violation.
      step.add(u.at(facts, k));
      z3::expr step_bad = ctx.bool_const(("kind.step.violated@" + std::to_string(k)).c_str());
      step.add(z3::implies(step_bad, !u.at(problem.good, k)));
      for (;;) {
        z3::expr_vector a(ctx);
        a.push_back(step_bad);
        cr = check_within(step, meter, a);
        if (cr == z3::unsat) return finish(Verdict::Proved, k, UnknownReason::None);
        if (cr == z3::unknown)
          return finish(Verdict::Unknown, k, unknown_reason(step.reason_unknown(), limits, meter, &r.detail));
        if (!options_.simple_path) break;
        auto pair = repeated_state(ts, u, step.get_model(), k);
        if (!pair) break;
        step.add(states_differ(ts, u, pair->first, pair->second));
        r.simple_path = true;
      }
      step.add(u.at(problem.good, k));
      step.add(u.at(trans, k));
      step.add(u.at(S, k + 1));
    }
    return finish(Verdict::Unknown, max_k, UnknownReason::BoundReached);
  } catch (const Stopped& e) {
    return finish(Verdict::Unknown, 0, e.reason);
  } catch (const z3::exception& e) {
    return finish(Verdict::Unknown, 0, unknown_reason(e.msg(), limits, meter, &r.detail));
  }
}

}  // namespace cemv::checker
