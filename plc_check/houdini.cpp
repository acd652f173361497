// Houdini on a product's Bool and Int state (houdini.hpp).
#include "plc_check/houdini.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_set>

#include "checker/engines/invariants.hpp"
#include "encoder/unroller.hpp"
#include "plc_check/cones.hpp"

namespace cemv::plc_check {

namespace {

bool has_floats(const encoder::TransitionSystem& ts) {
  for (const auto& v : ts.statevars())
    if (v.var.is_fpa()) return true;
  for (const auto& v : ts.inputvars())
    if (v.var.is_fpa()) return true;
  return false;
}

// A candidate, its copy at the cycle that decides it (0 for initiation, 1 for
// consecution) and its activation literal in cycle 0 (consecution only).
struct Candidate {
  z3::expr term;
  z3::expr decided;
  std::optional<z3::expr> literal;
};

// Drops, in order, the candidates false in a model until the check is unsat;
// each round's "some candidate is false" behind a fresh literal.
void drop_until_unsat(z3::solver& s, std::vector<Candidate>& cands, const checker::Limits& limits,
                      checker::WorkMeter& meter) {
  z3::context& ctx = s.ctx();
  for (int round = 0; !cands.empty(); ++round) {
    if (limits.interrupted()) throw checker::Stopped{checker::UnknownReason::TimeLimit};
    z3::expr_vector some_false(ctx);
    for (const auto& c : cands) some_false.push_back(!c.decided);
    const z3::expr this_round = ctx.bool_const(("plc.houdini.round." + std::to_string(round)).c_str());
    s.add(z3::implies(this_round, z3::mk_or(some_false)));
    z3::expr_vector assume(ctx);
    assume.push_back(this_round);
    for (const auto& c : cands)
      if (c.literal) assume.push_back(*c.literal);
    const z3::check_result r = checker::check_within(s, meter, assume);
    if (r == z3::unsat) return;
    if (r == z3::unknown) throw checker::Stopped{checker::unknown_reason(s.reason_unknown(), limits, meter)};
    const z3::model m = s.get_model();
    std::vector<Candidate> keep;
    for (auto& c : cands)
      if (m.eval(c.decided, true).is_true()) keep.push_back(std::move(c));
    s.add(!this_round);
    cands = std::move(keep);
  }
}

// The conjuncts of `e`.
std::vector<z3::expr> conjuncts(const z3::expr& e) {
  std::vector<z3::expr> out;
  std::vector<z3::expr> todo{e};
  while (!todo.empty()) {
    const z3::expr t = todo.back();
    todo.pop_back();
    if (t.is_app() && t.decl().decl_kind() == Z3_OP_AND) {
      for (unsigned i = t.num_args(); i-- > 0;) todo.push_back(t.arg(i));
    } else {
      out.push_back(t);
    }
  }
  return out;
}

}  // namespace

std::vector<z3::expr> product_houdini(const checker::SafetyProblem& p, std::vector<z3::expr> candidates,
                                      const checker::Limits& limits, checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  if (has_floats(ts)) return checker::houdini(p, std::move(candidates), limits, meter);
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  checker::Watchdog watchdog(ctx, limits);
  std::vector<Candidate> cands;
  for (const auto& c : candidates) cands.push_back(Candidate{c, u.at(c, 0), std::nullopt});
  {
    z3::solver s(ctx, "QF_LIA");
    s.add(u.at(ts.init_formula(), 0));
    drop_until_unsat(s, cands, limits, meter);
  }
  z3::solver s(ctx, "QF_LIA");
  s.add(u.at(ts.constraint_formula() && p.assumption && ts.trans_formula(), 0));
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const z3::expr l = ctx.bool_const(("plc.houdini.cand." + std::to_string(i)).c_str());
    s.add(z3::implies(l, cands[i].decided));
    cands[i].literal = l;
    cands[i].decided = u.at(cands[i].term, 1);
  }
  drop_until_unsat(s, cands, limits, meter);
  std::vector<z3::expr> kept;
  for (const auto& c : cands) kept.push_back(c.term);
  return kept;
}

std::vector<z3::expr> product_houdini_by_cones(const checker::SafetyProblem& p,
                                               const std::vector<std::vector<z3::expr>>& candidates,
                                               const std::vector<std::vector<std::size_t>>& cones,
                                               const checker::Limits& limits, checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  if (has_floats(ts)) {
    std::vector<z3::expr> all;
    std::unordered_set<unsigned> ids;
    for (const auto& cs : candidates)
      for (const auto& c : cs)
        if (ids.insert(c.id()).second) all.push_back(c);
    return checker::houdini(p, std::move(all), limits, meter);
  }
  z3::context& ctx = ts.ctx();
  encoder::Unroller u(ts);
  checker::Watchdog watchdog(ctx, limits);
  std::unordered_set<unsigned> asked;  // kept or dropped by an earlier cone
  std::vector<z3::expr> kept;
  std::vector<z3::expr> kept_at_0;  // each unrolled once, not once per later cone
  std::vector<std::vector<std::size_t>> kept_vars;  // the state variables each reads
  TermReads reads(ts);
  std::vector<std::pair<z3::expr, std::vector<std::size_t>>> cone_facts;  // in cycle 0, with the state read
  for (const auto& f : conjuncts(ts.constraint_formula() && p.assumption)) cone_facts.push_back({u.at(f, 0), reads.of(f)});
  for (std::size_t i = 0; i < cones.size() && i < candidates.size(); ++i) {
    std::vector<bool> in(ts.statevars().size(), false);
    for (std::size_t v : cones[i]) in[v] = true;
    std::vector<Candidate> cands;
    for (const auto& c : candidates[i])
      if (asked.insert(c.id()).second) cands.push_back(Candidate{c, u.at(c, 0), std::nullopt});
    if (cands.empty()) continue;
    z3::expr_vector init(ctx), trans(ctx);
    for (std::size_t v : cones[i]) {
      const auto& s = ts.statevars()[v];
      init.push_back(s.var == s.init);
      trans.push_back(s.next_var == s.next);
    }
    {
      z3::solver s(ctx, "QF_LIA");
      s.add(u.at(z3::mk_and(init), 0));
      drop_until_unsat(s, cands, limits, meter);
    }
    // Only the facts over this cone's state (the constraints and the
    // assumption on its inputs, what earlier cones kept of its variables):
    // the others speak of variables its transitions do not read, and
    // leaving a fact out only weakens what the cone may assume, so what it
    // keeps is inductive still. Each round's query is then the cone's size,
    // not the product's (a later cone of a generated 16 x 16 program
    // assumed 3,646 invariants, most of other cones).
    auto within = [&](const std::vector<std::size_t>& vars) {
      return std::all_of(vars.begin(), vars.end(), [&](std::size_t v) { return in[v]; });
    };
    z3::expr_vector facts(ctx);
    for (const auto& f : cone_facts)
      if (within(f.second)) facts.push_back(f.first);
    for (std::size_t k = 0; k < kept_at_0.size(); ++k)
      if (within(kept_vars[k])) facts.push_back(kept_at_0[k]);
    z3::solver s(ctx, "QF_LIA");
    s.add(u.at(z3::mk_and(trans), 0));
    s.add(facts);
    for (std::size_t j = 0; j < cands.size(); ++j) {
      const z3::expr l = ctx.bool_const(("plc.houdini.cone." + std::to_string(i) + "." + std::to_string(j)).c_str());
      s.add(z3::implies(l, cands[j].decided));
      cands[j].literal = l;
      cands[j].decided = u.at(cands[j].term, 1);
    }
    drop_until_unsat(s, cands, limits, meter);
    for (const auto& c : cands) {
      kept.push_back(c.term);
      kept_at_0.push_back(u.at(c.term, 0));
      kept_vars.push_back(reads.of(c.term));
    }
  }
  return kept;
}

}  // namespace cemv::plc_check
