// A set's test on the path's one encoding (docs/defeats.md, "A test of a
// set S"): its demand runs, Houdini and k-induction under the assumptions
// that exclude the other actions (the unsat cores growing the set the proof
// covers), then BMC.
#include <stdexcept>

#include "checker/engines/invariants.hpp"
#include "defeats/space.hpp"
#include "defeats/space_solvers.hpp"

namespace cemv::defeats {

namespace {

using Set = std::vector<int>;

// One test's checks on the path's solvers, within its budget of work.
class SetTest {
 public:
  SetTest(ActionSpace::Solvers& s, const Set& allowed, const checker::Limits& limits)
      : s_(s), allowed_(allowed), limits_(limits), meter_(s.ctx, s.probe, limits.work), watchdog_(s.ctx, limits),
        needed_(s.exclude.size(), false) {}

  Test run(std::optional<int> proof_depth) {
    try {
      std::optional<std::vector<std::size_t>> alive = houdini();
      if (!alive) return unknown(s_.houdini);
      if (std::optional<Test> t = induction(*alive, proof_depth.value_or(kMaxInductionK))) return *t;
      if (proof_depth) return stopped(checker::UnknownReason::BoundReached);
      return bmc();
    } catch (const checker::Stopped& e) {
      return stopped(e.reason);
    } catch (const z3::exception& e) {
      return stopped(unknown_reason(e.msg(), limits_, meter_));
    }
  }

 private:
  // The literals that exclude the actions outside the set; a fresh vector
  // each check: copies of a z3::expr_vector share their elements.
  z3::expr_vector excluded() const {
    z3::expr_vector v(s_.ctx);
    for (std::size_t i = 0; i < s_.exclude.size(); ++i)
      if (!in(allowed_, static_cast<int>(i))) v.push_back(s_.exclude[i]);
    return v;
  }

  // The exclusions an unsat core names (its other literals are returned).
  // Read once per check: Z3 builds the core when asked.
  z3::expr_vector note_core(z3::solver& solver) {
    const z3::expr_vector core = solver.unsat_core();
    for (unsigned i = 0; i < core.size(); ++i)
      if (auto it = s_.action_of.find(core[i].id()); it != s_.action_of.end())
        needed_[static_cast<std::size_t>(it->second)] = true;
    return core;
  }

  z3::expr round() {
    z3::expr r = s_.ctx.bool_const(("defeats.houdini.round." + std::to_string(s_.rounds++)).c_str());
    return r;
  }

  // Houdini: the largest inductive subset of the candidates under these
  // exclusions, from what the empty set keeps (a superset of it); none when
  // a check is left unknown.
  std::optional<std::vector<std::size_t>> houdini() {
    std::vector<std::size_t> alive;
    if (s_.start_known) alive = s_.start;
    else for (std::size_t j = 0; j < s_.cands.size(); ++j) alive.push_back(j);
    for (;;) {
      if (limits_.interrupted()) throw checker::Stopped{checker::UnknownReason::TimeLimit};
      z3::expr_vector a = excluded();
      z3::expr_vector some_false(s_.ctx);
      for (std::size_t j : alive) {
        a.push_back(s_.lits[j]);
        some_false.push_back(!s_.cands_next[j]);
      }
      const z3::expr r = round();
      s_.houdini.add(z3::implies(r, z3::mk_or(some_false)));
      a.push_back(r);
      const z3::check_result cr = alive.empty() ? z3::unsat : check_within(s_.houdini, meter_, a);
      if (cr == z3::unknown) return std::nullopt;
      if (cr == z3::unsat) {
        s_.houdini.add(!r);
        break;
      }
      z3::model model = s_.houdini.get_model();
      std::vector<std::size_t> keep;
      for (std::size_t j : alive)
        if (model.eval(s_.cands_next[j], true).is_true()) keep.push_back(j);
      alive = std::move(keep);
      s_.houdini.add(!r);
    }
    if (allowed_.empty() && !s_.start_known) {
      s_.start = alive;
      s_.start_known = true;
    }
    return alive;
  }

  // The candidates the step used, closed under what their consecution
  // needs: only the exclusions this smaller invariant rests on count, so a
  // candidate kept by Houdini that the proof does not need (a relation
  // between the timers of an action the set excludes) does not hold the
  // grown set back. False when a check is left unknown.
  bool close_invariant(const std::vector<std::size_t>& alive, std::vector<bool>& inv) {
    for (;;) {
      z3::expr_vector some_false(s_.ctx);
      for (std::size_t j : alive)
        if (inv[j]) some_false.push_back(!s_.cands_next[j]);
      if (some_false.empty()) return true;
      const z3::expr r = round();
      s_.houdini.add(z3::implies(r, z3::mk_or(some_false)));
      z3::expr_vector a = excluded();
      for (std::size_t j : alive) a.push_back(s_.lits[j]);
      a.push_back(r);
      const z3::check_result cr = check_within(s_.houdini, meter_, a);
      if (cr != z3::unsat) {
        s_.houdini.add(!r);
        if (cr == z3::sat) throw std::logic_error("cemv defeats: Houdini's invariant is not inductive");
        return false;
      }
      bool grew = false;
      const z3::expr_vector core = s_.houdini.unsat_core();
      for (unsigned i = 0; i < core.size(); ++i) {
        const z3::expr e = core[i];
        if (auto it = s_.action_of.find(e.id()); it != s_.action_of.end())
          needed_[static_cast<std::size_t>(it->second)] = true;
        if (auto it = s_.cand_of.find(e.id()); it != s_.cand_of.end() && !inv[it->second]) {
          inv[it->second] = true;
          grew = true;
        }
      }
      s_.houdini.add(!r);
      if (!grew) return true;
    }
  }

  // k-induction relative to the invariant, the base case in the same loop:
  // the test's answer, or none when no k up to `depth` decides it.
  std::optional<Test> induction(const std::vector<std::size_t>& alive, int depth) {
    for (int k = 0; k <= depth; ++k) {
      s_.base_frames(k);
      z3::expr_vector a = excluded();
      a.push_back(s_.base_bad[static_cast<std::size_t>(k)]);
      z3::check_result cr = check_within(s_.base, meter_, a);
      if (cr == z3::sat) return defeated(s_.base.get_model(), k, checker::Method::Bmc);
      if (cr == z3::unknown) return unknown(s_.base);
      note_core(s_.base);
      s_.step_frames(k);
      z3::expr_vector b = excluded();
      for (std::size_t j : alive) b.push_back(s_.lits[j]);
      for (int c = 0; c <= k; ++c) b.push_back(s_.step_on[static_cast<std::size_t>(c)]);
      for (int c = 0; c < k; ++c) b.push_back(s_.step_good[static_cast<std::size_t>(c)]);
      b.push_back(s_.step_bad[static_cast<std::size_t>(k)]);
      cr = check_within(s_.step, meter_, b);
      if (cr == z3::unknown) return unknown(s_.step);
      if (cr == z3::unsat) return proved(alive, note_core(s_.step), k);
    }
    return std::nullopt;
  }

  // A proof at k: the invariant the step's core used, closed, and the set
  // grown by every exclusion no core needed.
  Test proved(const std::vector<std::size_t>& alive, const z3::expr_vector& core, int k) {
    std::vector<bool> in_invariant(s_.cands.size(), false);
    for (unsigned i = 0; i < core.size(); ++i)
      if (auto it = s_.cand_of.find(core[i].id()); it != s_.cand_of.end()) in_invariant[it->second] = true;
    if (!close_invariant(alive, in_invariant)) return unknown(s_.houdini);
    Test t;
    t.answer = Test::Answer::Holds;
    for (std::size_t i = 0; i < needed_.size(); ++i)
      if (!needed_[i]) t.covered.push_back(static_cast<int>(i));
    t.proof.verdict = checker::Verdict::Proved;
    t.proof.k = k;
    for (std::size_t j : alive)
      if (in_invariant[j]) t.proof.invariant.clauses.push_back(checker::to_smtlib(s_.cands[j]));
    t.proof.method = !t.proof.invariant.clauses.empty() && k <= 1 ? checker::Method::InvariantsInduction
                                                                  : checker::Method::KInduction;
    t.method = t.proof.method_text();
    t.work = meter_.spent();
    return t;
  }

  // Not proved: a counterexample up to T + a margin cycles.
  Test bmc() {
    s_.base_frames(s_.bmc_depth);
    if (!s_.any_made) {
      s_.any_made = true;
      z3::expr_vector bad(s_.ctx);
      for (int c = 0; c <= s_.bmc_depth; ++c) bad.push_back(s_.base_bad[static_cast<std::size_t>(c)]);
      s_.any_violation = s_.ctx.bool_const("defeats.base.any");
      s_.base.add(z3::implies(s_.any_violation, z3::mk_or(bad)));
    }
    z3::expr_vector a = excluded();
    a.push_back(s_.any_violation);
    const z3::check_result cr = check_within(s_.base, meter_, a);
    if (cr == z3::unknown) return unknown(s_.base);
    if (cr == z3::unsat) return stopped(checker::UnknownReason::BoundReached);
    const z3::model model = s_.base.get_model();
    int last = 0;
    while (last < s_.bmc_depth && !model.eval(s_.base_bad[static_cast<std::size_t>(last)], true).is_true()) ++last;
    return defeated(model, last, checker::Method::Bmc);
  }

  // A counterexample ending in cycle `last`: the actions it takes.
  Test defeated(const z3::model& model, int last, checker::Method method) {
    Test t;
    t.answer = Test::Answer::Defeats;
    for (int a : allowed_)
      for (int c = 0; c <= last; ++c)
        if (model.eval(s_.u->at(s_.built.keep[static_cast<std::size_t>(a)], c), true).is_false()) {
          t.used.push_back(a);
          break;
        }
    t.method = checker::to_string(method);
    t.work = meter_.spent();
    return t;
  }

  Test unknown(z3::solver& solver) { return stopped(unknown_reason(solver.reason_unknown(), limits_, meter_)); }

  Test stopped(checker::UnknownReason reason) {
    Test t;
    t.answer = Test::Answer::Unknown;
    t.reason = checker::to_string(reason);
    t.work = meter_.spent();
    return t;
  }

  ActionSpace::Solvers& s_;
  const Set& allowed_;
  const checker::Limits& limits_;
  Meter meter_;
  checker::Watchdog watchdog_;
  std::vector<bool> needed_;  // exclusions some unsat core used
};

}  // namespace

Test ActionSpace::test(const Set& allowed, const checker::Limits& limits, std::optional<int> proof_depth) {
  // The demand runs of the set, then (a full test) of each set of one action
  // fewer: a subset that defeats shows that the set does (allowing more
  // actions only adds runs), in milliseconds of the runtime where the
  // solver's BMC over a long T costs millions of work units.
  std::optional<RunDefeat> d = run(allowed);
  for (std::size_t i = 0; !proof_depth && !d && allowed.size() > 1 && i < allowed.size(); ++i) {
    Set fewer = allowed;
    fewer.erase(fewer.begin() + static_cast<std::ptrdiff_t>(i));
    d = run(fewer);
  }
  if (d) {
    Test t;
    t.answer = Test::Answer::Defeats;
    t.used = d->used;
    t.method = checker::to_string(checker::Method::DirectedRun);
    return t;
  }
  return SetTest(*s_, allowed, limits).run(proof_depth);
}

}  // namespace cemv::defeats
