// Houdini on a product's Bool and Int state (houdini.hpp).
#include "plc_check/houdini.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <unordered_set>

#include "checker/engines/invariants.hpp"
#include "checker/limits.hpp"
#include "encoder/unroller.hpp"
#include "plc_check/cones.hpp"
#include "plc_check/premise.hpp"

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

// A solver for the consecution queries. Each round wants a model that breaks
// many candidates: Z3's phase by occurrences (smt.phase_selection 6) leaves
// more of a round's candidates false than its cached phase does and ends the
// same Houdini in fewer rounds (the generated 128 x 128 x 1024 program's
// layers: 2,492 rounds against 4,183, about 28% less time; what is kept does
// not depend on the order of the drops).
z3::solver consecution_solver(z3::context& ctx) {
  z3::solver s = checker::linear_integer_solver(ctx);
  z3::params params(ctx);
  params.set("phase_selection", 6u);
  s.set(params);
  return s;
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
    z3::solver s = checker::linear_integer_solver(ctx);
    s.add(u.at(ts.init_formula(), 0));
    drop_until_unsat(s, cands, limits, meter);
  }
  z3::solver s = consecution_solver(ctx);
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

std::vector<z3::expr> product_houdini_by_layers(const checker::SafetyProblem& p,
                                                const std::vector<std::vector<z3::expr>>& candidates,
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
  TermReads reads(ts);
  std::vector<std::vector<std::size_t>> next_reads(ts.statevars().size());
  for (std::size_t v = 0; v < next_reads.size(); ++v) next_reads[v] = reads.of(ts.statevars()[v].next);
  std::unordered_set<unsigned> asked;  // kept or dropped by an earlier layer
  std::vector<z3::expr> kept;
  // Every fact in cycle 0 (the constraints and the assumption, then what the
  // layers keep), with the state variables it reads.
  std::vector<std::pair<z3::expr, std::vector<std::size_t>>> facts;
  std::vector<FactShape> shapes;
  for (const auto& f : conjuncts_of(ts.constraint_formula() && p.assumption)) {
    facts.push_back({u.at(f, 0), reads.of(f)});
    shapes.push_back(shape_of(facts.back().first));
  }
  std::vector<char> in(ts.statevars().size(), 0);
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    std::vector<Candidate> cands;
    std::set<std::size_t> stepped;  // the variables the candidates read
    for (const auto& c : candidates[i])
      if (asked.insert(c.id()).second) {
        cands.push_back(Candidate{c, u.at(c, 0), std::nullopt});
        for (std::size_t v : reads.of(c)) stepped.insert(v);
      }
    if (cands.empty()) continue;
    // The query holds the transitions of the variables the candidates read,
    // and the facts over those and what their next-state functions read:
    // no other variable decides a candidate in the next scan. Every fact
    // left out (and every other transition) only weakens what the query
    // assumes, so what is kept is inductive still; the query is the size
    // of a layer and its frontier, not of the cone below it.
    std::fill(in.begin(), in.end(), 0);
    z3::expr_vector init(ctx), trans(ctx);
    for (std::size_t v : stepped) {
      const auto& s = ts.statevars()[v];
      init.push_back(s.var == s.init);
      trans.push_back(s.next_var == s.next);
      in[v] = 1;
      for (std::size_t w : next_reads[v]) in[w] = 1;
    }
    {
      z3::solver s = checker::linear_integer_solver(ctx);
      s.add(u.at(z3::mk_and(init), 0));
      drop_until_unsat(s, cands, limits, meter);
    }
    std::vector<std::size_t> premise;
    for (std::size_t f = 0; f < facts.size(); ++f)
      if (std::all_of(facts[f].second.begin(), facts[f].second.end(), [&](std::size_t v) { return in[v] != 0; }))
        premise.push_back(f);
    z3::expr_vector assumed(ctx);
    for (std::size_t f : without_repeats(shapes, premise)) assumed.push_back(facts[f].first);
    z3::solver s = consecution_solver(ctx);
    s.add(u.at(z3::mk_and(trans), 0));
    s.add(assumed);
    for (std::size_t j = 0; j < cands.size(); ++j) {
      const z3::expr l = ctx.bool_const(("plc.houdini.layer." + std::to_string(i) + "." + std::to_string(j)).c_str());
      s.add(z3::implies(l, cands[j].decided));
      cands[j].literal = l;
      cands[j].decided = u.at(cands[j].term, 1);
    }
    drop_until_unsat(s, cands, limits, meter);
    for (const auto& c : cands) {
      kept.push_back(c.term);
      facts.push_back({u.at(c.term, 0), reads.of(c.term)});
      shapes.push_back(shape_of(facts.back().first));
    }
  }
  return kept;
}

}  // namespace cemv::plc_check
