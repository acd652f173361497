// A set's test on the path's one encoding (docs/defeats.md, "A test of a
// set S"): its demand runs, Houdini and k-induction under the assumptions
// that exclude the other actions (the unsat cores growing the set the proof
// covers), then BMC.
#include <stdexcept>

#include "checker/engines/invariants.hpp"
#include "defeats/space.hpp"
#include "defeats/space_solvers.hpp"

namespace cemv::defeats {

using Set = std::vector<int>;

Test ActionSpace::test(const Set& allowed, const checker::Limits& limits, std::optional<int> proof_depth) {
  const bool search = !proof_depth;
  Test t;
  // The demand runs of the set, then of each set of one action fewer: a
  // subset that defeats shows that the set does (allowing more actions only
  // adds runs), in milliseconds of the runtime where the solver's BMC over
  // a long T costs millions of work units.
  std::optional<RunDefeat> d = run(allowed);
  for (std::size_t i = 0; search && !d && allowed.size() > 1 && i < allowed.size(); ++i) {
    Set fewer = allowed;
    fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
    d = run(fewer);
  }
  if (d) {
    t.answer = Test::Answer::Defeats;
    t.used = d->used;
    t.method = checker::to_string(checker::Method::DirectedRun);
    return t;
  }
  Solvers& s = *s_;
  Meter meter(s.ctx, s.probe, limits.work);
  checker::Watchdog watchdog(s.ctx, limits);
  // A fresh vector each check: copies of a z3::expr_vector share their elements.
  auto excluded = [&] {
    z3::expr_vector v(s.ctx);
    for (std::size_t i = 0; i < s.exclude.size(); ++i)
      if (!in(allowed, static_cast<int>(i))) v.push_back(s.exclude[i]);
    return v;
  };
  std::vector<bool> needed(s.exclude.size(), false);  // exclusions some unsat core used
  // The exclusions an unsat core names (its other literals are returned).
  // Read once per check: Z3 builds the core when asked.
  auto note_core = [&](z3::solver& solver) {
    const z3::expr_vector core = solver.unsat_core();
    for (unsigned i = 0; i < core.size(); ++i)
      if (auto it = s.action_of.find(core[i].id()); it != s.action_of.end())
        needed[static_cast<std::size_t>(it->second)] = true;
    return core;
  };
  // The candidates the step used, closed under what their consecution
  // needs: only the exclusions this smaller invariant rests on count, so a
  // candidate kept by Houdini that the proof does not need (a relation
  // between the timers of an action the set excludes) does not hold the
  // grown set back. False when a check is left unknown.
  auto close_invariant = [&](const std::vector<std::size_t>& alive, std::vector<bool>& inv, std::vector<bool>& need,
                             Meter& meter_) {
    for (;;) {
      z3::expr_vector some_false(s.ctx);
      for (std::size_t j : alive)
        if (inv[j]) some_false.push_back(!s.cands_next[j]);
      if (some_false.empty()) return true;
      z3::expr round = s.ctx.bool_const(("defeats.houdini.round." + std::to_string(s.rounds++)).c_str());
      s.houdini.add(z3::implies(round, z3::mk_or(some_false)));
      z3::expr_vector a = excluded();
      for (std::size_t j : alive) a.push_back(s.lits[j]);
      a.push_back(round);
      const z3::check_result cr = check_within(s.houdini, meter_, a);
      if (cr != z3::unsat) {
        s.houdini.add(!round);
        if (cr == z3::sat) throw std::logic_error("cemv defeats: Houdini's invariant is not inductive");
        return false;
      }
      bool grew = false;
      const z3::expr_vector core = s.houdini.unsat_core();
      for (unsigned i = 0; i < core.size(); ++i) {
        const z3::expr e = core[i];
        if (auto it = s.action_of.find(e.id()); it != s.action_of.end()) need[static_cast<std::size_t>(it->second)] = true;
        if (auto it = s.cand_of.find(e.id()); it != s.cand_of.end() && !inv[it->second]) {
          inv[it->second] = true;
          grew = true;
        }
      }
      s.houdini.add(!round);
      if (!grew) return true;
    }
  };
  auto unknown = [&](z3::solver& solver) {
    t.answer = Test::Answer::Unknown;
    t.reason = checker::to_string(unknown_reason(solver.reason_unknown(), limits, meter));
    t.work = meter.spent();
    return t;
  };
  auto defeated = [&](const z3::model& model, int last, checker::Method method) {
    t.answer = Test::Answer::Defeats;
    for (int a : allowed)
      for (int c = 0; c <= last; ++c)
        if (model.eval(s.u->at(s.built.keep[static_cast<std::size_t>(a)], c), true).is_false()) {
          t.used.push_back(a);
          break;
        }
    t.method = checker::to_string(method);
    t.work = meter.spent();
    return t;
  };
  try {
    // Houdini: the largest inductive subset of the candidates under these
    // exclusions, from what the empty set keeps (a superset of it).
    std::vector<std::size_t> alive;
    if (s.start_known) alive = s.start;
    else for (std::size_t j = 0; j < s.cands.size(); ++j) alive.push_back(j);
    for (;;) {
      if (limits.interrupted()) throw checker::Stopped{checker::UnknownReason::TimeLimit};
      z3::expr_vector a = excluded();
      z3::expr_vector some_false(s.ctx);
      for (std::size_t j : alive) {
        a.push_back(s.lits[j]);
        some_false.push_back(!s.cands_next[j]);
      }
      z3::expr round = s.ctx.bool_const(("defeats.houdini.round." + std::to_string(s.rounds++)).c_str());
      s.houdini.add(z3::implies(round, z3::mk_or(some_false)));
      a.push_back(round);
      const z3::check_result cr = alive.empty() ? z3::unsat : check_within(s.houdini, meter, a);
      if (cr == z3::unknown) return unknown(s.houdini);
      if (cr == z3::unsat) {
        s.houdini.add(!round);
        break;
      }
      z3::model model = s.houdini.get_model();
      std::vector<std::size_t> keep;
      for (std::size_t j : alive)
        if (model.eval(s.cands_next[j], true).is_true()) keep.push_back(j);
      alive = std::move(keep);
      s.houdini.add(!round);
    }
    if (allowed.empty() && !s.start_known) {
      s.start = alive;
      s.start_known = true;
    }
    // k-induction relative to the invariant, the base case in the same loop.
    for (int k = 0; k <= proof_depth.value_or(kMaxInductionK); ++k) {
      s.base_frames(k);
      z3::expr_vector a = excluded();
      a.push_back(s.base_bad[static_cast<std::size_t>(k)]);
      z3::check_result cr = check_within(s.base, meter, a);
      if (cr == z3::sat) return defeated(s.base.get_model(), k, checker::Method::Bmc);
      if (cr == z3::unknown) return unknown(s.base);
      note_core(s.base);
      s.step_frames(k);
      z3::expr_vector b = excluded();
      for (std::size_t j : alive) b.push_back(s.lits[j]);
      for (int c = 0; c <= k; ++c) b.push_back(s.step_on[static_cast<std::size_t>(c)]);
      for (int c = 0; c < k; ++c) b.push_back(s.step_good[static_cast<std::size_t>(c)]);
      b.push_back(s.step_bad[static_cast<std::size_t>(k)]);
      cr = check_within(s.step, meter, b);
      if (cr == z3::unknown) return unknown(s.step);
      if (cr == z3::unsat) {
        const z3::expr_vector core = note_core(s.step);
        std::vector<bool> in_invariant(s.cands.size(), false);
        for (unsigned i = 0; i < core.size(); ++i)
          if (auto it = s.cand_of.find(core[i].id()); it != s.cand_of.end()) in_invariant[it->second] = true;
        if (!close_invariant(alive, in_invariant, needed, meter)) return unknown(s.houdini);
        t.answer = Test::Answer::Holds;
        for (std::size_t i = 0; i < needed.size(); ++i)
          if (!needed[i]) t.covered.push_back(static_cast<int>(i));
        t.proof.verdict = checker::Verdict::Proved;
        t.proof.k = k;
        for (std::size_t j : alive)
          if (in_invariant[j]) t.proof.invariant.clauses.push_back(checker::to_smtlib(s.cands[j]));
        t.proof.method = !t.proof.invariant.clauses.empty() && k <= 1 ? checker::Method::InvariantsInduction
                                                                      : checker::Method::KInduction;
        t.method = t.proof.method_text();
        t.work = meter.spent();
        return t;
      }
    }
    // Not proved: a counterexample up to T + a margin cycles.
    if (!search) {
      t.answer = Test::Answer::Unknown;
      t.reason = checker::to_string(checker::UnknownReason::BoundReached);
      t.work = meter.spent();
      return t;
    }
    s.base_frames(s.bmc_depth);
    if (!s.any_made) {
      s.any_made = true;
      z3::expr_vector bad(s.ctx);
      for (int c = 0; c <= s.bmc_depth; ++c) bad.push_back(s.base_bad[static_cast<std::size_t>(c)]);
      s.any_violation = s.ctx.bool_const("defeats.base.any");
      s.base.add(z3::implies(s.any_violation, z3::mk_or(bad)));
    }
    z3::expr_vector a = excluded();
    a.push_back(s.any_violation);
    const z3::check_result cr = check_within(s.base, meter, a);
    if (cr == z3::unknown) return unknown(s.base);
    if (cr == z3::sat) {
      const z3::model model = s.base.get_model();
      int last = 0;
      while (last < s.bmc_depth && !model.eval(s.base_bad[static_cast<std::size_t>(last)], true).is_true()) ++last;
      return defeated(model, last, checker::Method::Bmc);
    }
    t.answer = Test::Answer::Unknown;
    t.reason = checker::to_string(checker::UnknownReason::BoundReached);
    t.work = meter.spent();
    return t;
  } catch (const checker::Stopped& e) {
    t.answer = Test::Answer::Unknown;
    t.reason = checker::to_string(e.reason);
    t.work = meter.spent();
    return t;
  } catch (const z3::exception& e) {
    t.answer = Test::Answer::Unknown;
    t.reason = checker::to_string(unknown_reason(e.msg(), limits, meter));
    t.work = meter.spent();
    return t;
  }
}

}  // namespace cemv::defeats
