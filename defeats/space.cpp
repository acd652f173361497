#include "defeats/space.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "checker/check/recheck.hpp"
#include "checker/engines/invariants.hpp"
#include "checker/engines/solving.hpp"
#include "checker/reduce.hpp"
#include "checker/replay.hpp"
#include "encoder/encode.hpp"
#include "encoder/unroller.hpp"
#include "formats/diagnostics.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "response/property.hpp"

namespace cemv::defeats {

namespace {

using Set = std::vector<int>;

// The induction depth and the BMC depth past the requirement's T of a test:
// a defeat's counterexample is a demand held T + 1 cycles after the few
// cycles that take the actions (a timed soft bypass, an override).
constexpr int kMaxInductionK = 24;
constexpr int kBmcMargin = 12;
constexpr int kMaxBmcDepth = 200;

bool in(const Set& s, int i) { return std::binary_search(s.begin(), s.end(), i); }

// The work a test spends against its budget, as checker::WorkMeter counts it
// (Z3's `rlimit count`, the context's resource limit armed to what is left
// before each check), read through one solver of the `skip` tactic that
// lives as long as the path: checker::resource_count makes a default solver
// for each reading, a third of this enumeration's time when every set is a
// few short checks.
class Meter {
 public:
  Meter(z3::context& ctx, z3::solver& probe, checker::Work budget)
      : ctx_(ctx), probe_(probe), budget_(budget), start_(count()) {}
  ~Meter() { Z3_update_param_value(ctx_, "rlimit", "0"); }
  Meter(const Meter&) = delete;
  Meter& operator=(const Meter&) = delete;
  bool arm() {
    if (budget_ == 0) {
      Z3_update_param_value(ctx_, "rlimit", "0");
      return true;
    }
    const checker::Work used = spent();
    if (used >= budget_) return false;
    checker::Work left = budget_ - used;
    if (left > 4000000000ULL) left = 4000000000ULL;  // Z3's limit is an unsigned int
    Z3_update_param_value(ctx_, "rlimit", std::to_string(left).c_str());
    return true;
  }
  checker::Work spent() const { return count() - start_; }
  bool exhausted() const { return budget_ != 0 && spent() >= budget_; }

 private:
  checker::Work count() const {
    const z3::stats st = probe_.statistics();
    for (unsigned i = 0; i < st.size(); ++i)
      if (st.key(i) == "rlimit count")
        return st.is_uint(i) ? st.uint_value(i) : static_cast<checker::Work>(st.double_value(i));
    return 0;
  }
  z3::context& ctx_;
  z3::solver& probe_;
  checker::Work budget_;
  checker::Work start_;
};

z3::check_result check_within(z3::solver& s, Meter& meter, const z3::expr_vector& assumptions) {
  if (!meter.arm()) return z3::unknown;
  return s.check(assumptions);
}

checker::UnknownReason unknown_reason(const std::string& z3_reason, const checker::Limits& limits,
                                      const Meter& meter) {
  if (limits.interrupted()) return checker::UnknownReason::TimeLimit;
  if (meter.exhausted()) return checker::UnknownReason::WorkLimit;
  return checker::unknown_reason(z3_reason, limits);
}

// The requirement with every action excluded, parsed once: its property's
// assumptions are the exclusions, one per action and in the actions' order
// (response::requirement_property_text states no other).
properties::PropertyFile requirement_file(const model::Matrix& m, const PathDefeats& pd) {
  std::vector<std::string> excluded;
  for (const auto& a : pd.actions) excluded.push_back(a.excluded_term());
  const std::string name = "defeat." + pd.path.key() + ".space";
  const std::string text = response::requirement_property_text(m, pd.path, *pd.requirement, name, excluded);
  properties::PropertyFile f;
  try {
    f = properties::parse_properties(text, m, "cemv-defeats:" + name);
  } catch (const formats::LoadError& e) {
    std::string what;
    for (const auto& i : e.issues()) what += "\n" + i.str();
    throw std::logic_error("cemv defeats wrote a property the parser refuses:" + what + "\n" + text);
  }
  if (f.properties.size() != 1 || !f.assumptions.empty() ||
      f.properties[0].assumptions.size() != pd.actions.size())
    throw std::logic_error("cemv defeats: the requirement's assumptions are not its actions' exclusions");
  return f;
}

z3::expr in_range(const encoder::Encoding& enc, const z3::expr& var) {
  z3::context& ctx = var.ctx();
  const float range = std::numeric_limits<float>::max();
  return z3::expr(ctx, Z3_mk_fpa_geq(ctx, var, enc.ts.float_const(-range))) &&
         z3::expr(ctx, Z3_mk_fpa_leq(ctx, var, enc.ts.float_const(range)));
}

}  // namespace

// The path's problem in one context: the requirement with no action
// excluded, and each action's exclusion (`not TERM`) as a term of one cycle,
// reduced together (checker/reduce.hpp) so that the terms keep their cone.
struct Built {
  checker::OwnedProblem problem;
  std::vector<z3::expr> keep;  // keep[i]: action i does not occur in the cycle
};

class Builder {
 public:
  Builder(const model::Matrix& m, const PathDefeats& pd) : m_(m), file_(requirement_file(m, pd)) {
    const properties::Property& all = file_.properties[0];
    roots_ = properties::property_roots(all, {}, m);
    free_ = all;
    free_.assumptions.clear();
    for (std::size_t i = 0; i < all.assumptions.size(); ++i) {
      properties::Property x;
      x.name = all.name + ".x" + std::to_string(i + 1);
      x.kind = properties::PropertyKind::Invariant;
      x.body = all.assumptions[i].expr;
      exclusions_.push_back(std::move(x));
    }
  }

  // `none`: the problem with every action excluded, reduced as the checker
  // reduces a question (the commands it excludes constants), no terms kept.
  Built build(z3::context& ctx, bool none = false) const {
    std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m_, roots_);
    const properties::Monitor mon = properties::compile_monitor(*enc, free_, {});
    std::vector<z3::expr> keep;
    for (const auto& x : exclusions_) keep.push_back(properties::compile_monitor(*enc, x, {}).good);
    z3::expr assumption = mon.assumption;
    for (const auto& in : enc->ts.inputvars())
      if (in.var.is_fpa()) assumption = assumption && in_range(*enc, in.var);
    if (none)
      for (const auto& k : keep) assumption = assumption && k;
    checker::OwnedProblem original{enc, checker::SafetyProblem{&enc->ts, mon.good, assumption}};
    if (none) return Built{checker::reduce(original), {}};
    checker::OwnedProblem reduced = checker::reduce_with(original, keep);
    return Built{std::move(reduced), std::move(keep)};
  }

  // The requirement with the actions of `allowed` allowed, for the runtime's judge.
  properties::Property property(const Set& allowed) const {
    properties::Property p = file_.properties[0];
    p.assumptions.clear();
    for (std::size_t i = 0; i < file_.properties[0].assumptions.size(); ++i)
      if (!in(allowed, static_cast<int>(i))) p.assumptions.push_back(file_.properties[0].assumptions[i]);
    return p;
  }
  const properties::Expr& exclusion(int i) const { return exclusions_[static_cast<std::size_t>(i)].body; }

 private:
  const model::Matrix& m_;
  properties::PropertyFile file_;
  std::vector<model::Node> roots_;
  properties::Property free_;
  std::vector<properties::Property> exclusions_;
};

struct ActionSpace::Solvers {
  explicit Solvers(const model::Matrix& m, const PathDefeats& pd)
      : builder(m, pd), built(builder.build(ctx)), frame(ctx), trans(ctx), base(ctx), step(ctx), houdini(ctx),
        probe(z3::tactic(ctx, "skip").mk_solver()),
        any_violation(ctx) {}

  Builder builder;
  z3::context ctx;
  Built built;
  std::unique_ptr<encoder::Unroller> u;
  std::vector<z3::expr> exclude;  // exclude[i]: the literal assuming action i never occurs
  std::unordered_map<unsigned, int> action_of;  // literal id -> action
  std::unordered_map<unsigned, std::size_t> cand_of;  // literal id -> candidate
  z3::expr frame, trans;          // one cycle: constraints, assumption, guarded exclusions; the transition
  z3::solver base, step, houdini;
  z3::solver probe;  // reads the work spent (Meter)
  z3::expr any_violation;         // base: a violation in some cycle up to bmc_depth
  int bmc_depth = 0;
  bool any_made = false;
  std::vector<z3::expr> so_far, base_bad, step_on, step_good, step_bad;
  std::vector<z3::expr> cands, lits;  // initiated invariant candidates and their literals
  std::vector<z3::expr> cands_next;   // each candidate in cycle 1 of Houdini's unrolling (made once:
                                      // an unrolling substitutes every variable)
  std::vector<std::size_t> start;     // Houdini's start: what the empty set keeps (its largest fixpoint)
  bool start_known = false;
  int rounds = 0;

  const encoder::TransitionSystem& ts() const { return *built.problem.problem.ts; }
  const z3::expr& good() const { return built.problem.problem.good; }

  // The base case unrolls from the initial state. A violation in cycle t
  // counts when the assumptions held in cycles 0..t (`so_far[t]`), never
  // asking anything of later cycles: the assumption of a later cycle can be
  // unsatisfiable in some states (an override that has become active).
  void base_frames(int k) {
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
  // The inductive step's cycles, each behind a literal of its own: a step of
  // k assumes the cycles 0..k and nothing of those after.
  void step_frames(int k) {
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
};

namespace {

// The relations that hold while no action occurs (a monitor's counter and
// the on-delay it waits for): mined on the problem with every action
// excluded, which the checker reduces to a system whose commands are
// constants, and read back over this system's variables; a candidate over a
// variable that reduction removed, or gave another sort, is left out.
std::vector<z3::expr> mined_without_actions(const Builder& b, const encoder::TransitionSystem& ts) {
  std::vector<std::string> texts;
  {
    z3::context ctx;
    const Built none = b.build(ctx, true);
    checker::MiningOptions mining;
    mining.bool_implications = true;
    for (const auto& c : checker::mine_candidates(none.problem.problem, mining)) texts.push_back(checker::to_smtlib(c));
  }
  std::vector<z3::expr> out;
  for (const auto& t : texts) {
    try {
      out.push_back(checker::from_smtlib(ts, t));
    } catch (const z3::exception&) {
    }
  }
  return out;
}

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

void ActionSpace::recheck(const Test& t, const checker::Limits& limits) const {
  z3::context ctx;
  Built fresh = s_->builder.build(ctx);
  checker::SafetyProblem p = fresh.problem.problem;
  for (std::size_t i = 0; i < fresh.keep.size(); ++i)
    if (!in(t.covered, static_cast<int>(i))) p.assumption = p.assumption && fresh.keep[i];
  checker::check::recheck_proof(p, t.proof, &limits);
}

}  // namespace cemv::defeats
