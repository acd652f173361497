// The symbolic monitor (properties/monitor.*): every operator run through the
// encoder's Evaluator on concrete cycles against hand-computed values and
// against the cycle definitions of properties/ast.hpp on random sequences;
// counters checked to be exact; depths checked with a solver (BMC); the cone
// of influence checked on an example matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/unroller.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"

using namespace cemv;
using properties::Expr;
using properties::Property;
using properties::PropertyKind;
using Kind = Expr::Kind;

namespace {

// One cause reading one tag T1 (discrete DTT: tripped when T1 is 0, or
// analog high limit 90) and one effect with output tag OUT1.
model::Matrix one_cause(bool analog) {
  model::Matrix m;
  m.name = "T";
  m.cycle_ms = 100;
  model::Cause c;
  c.id = 1;
  c.name = "C1";
  c.input = analog ? model::InputKind::Analog : model::InputKind::Discrete;
  c.tags.push_back({"T1", false, true});
  if (analog) c.analog = model::AnalogParams{model::LimitType::High, 90.0f, 5.0f, std::nullopt, 0.0f, ""};
  c.bypass_tag = "BY1";
  m.causes.push_back(c);
  model::Effect e;
  e.id = 1;
  e.name = "E1";
  e.tags.push_back({"OUT1", false});
  m.effects.push_back(e);
  m.intersections.push_back({1, 1, model::IntersectionType::N, std::nullopt, ""});
  return m;
}

model::Observable observable(const model::Matrix& m, const std::string& key) {
  for (const auto& o : model::observables(m))
    if (o.key == key) return o;
  throw std::out_of_range(key);
}

Property invariant(Expr body) {
  Property p;
  p.name = "p";
  p.kind = PropertyKind::Invariant;
  p.body = std::move(body);
  return p;
}

// The discrete one-cause matrix with the monitor of one property compiled in
// and its terms named, driven cycle by cycle.
struct Harness {
  model::Matrix m;
  z3::context ctx;
  std::unique_ptr<encoder::Encoding> enc;
  properties::Monitor mon;
  std::unique_ptr<encoder::Evaluator> ev;

  Harness(model::Matrix matrix, const Property& p, const std::vector<properties::Assumption>& file = {})
      : m(std::move(matrix)),
        enc(encoder::encode(ctx, m, properties::property_roots(p, file, m))),
        mon(properties::compile_monitor(*enc, p, file)) {
    enc->ts.name_term("test.good", mon.good);
    enc->ts.name_term("test.assumption", mon.assumption);
    if (mon.antecedent) enc->ts.name_term("test.antecedent", *mon.antecedent);
    ev = std::make_unique<encoder::Evaluator>(*enc);
  }
  std::size_t index(const std::string& tag) const { return *enc->inputs.find(tag); }
  Expr value(const std::string& tag) const {
    return Expr::input_value(index(tag), enc->inputs.tags()[index(tag)].kind);
  }
  Expr bad(const std::string& tag) const { return Expr::input_bad(index(tag)); }
  // One cycle: T1 = v1 (with its quality), other tags at their defaults.
  int step(float v1, bool bad1 = false, std::vector<model::Command> cmds = {}) {
    model::CycleInput in;
    in.tags.resize(enc->inputs.size());
    in.tags[index("T1")] = {v1, bad1};
    in.commands = std::move(cmds);
    ev->step(in);
    return ev->value("test.good");
  }
  std::int64_t state(const std::string& name) const {
    const auto& sv = enc->ts.statevars();
    for (std::size_t i = 0; i < sv.size(); ++i)
      if (sv[i].name == name) return ev->state()[i].i;
    throw std::out_of_range(name);
  }
};

// Discrete T1 (DTT): the cause is active exactly when T1 reads 0.
Expr active(const model::Matrix& m) { return Expr::of_observable(observable(m, "cause[1].active")); }

// Drives `x` = cause[1].active through a sequence and returns the monitor's
// good value per cycle.
std::vector<int> run_on_active(const Expr& body_of_active, const std::vector<int>& x) {
  Harness h(one_cause(false), invariant(body_of_active));
  std::vector<int> out;
  for (int v : x) out.push_back(h.step(v ? 0.0f : 1.0f));
  return out;
}

Expr unary(Kind k, const Expr& a, int n = 0) { return Expr::unary(k, a, n); }

TEST(MonitorOperators, PrevIsFalseInTheFirstCycle) {
  auto m = one_cause(false);
  EXPECT_EQ(run_on_active(unary(Kind::Prev, active(m)), {1, 0, 1, 1, 0}),
            (std::vector<int>{0, 1, 0, 1, 1}));
}

TEST(MonitorOperators, RoseAndFell) {
  auto m = one_cause(false);
  std::vector<int> x = {1, 1, 0, 1, 0, 0, 1};
  EXPECT_EQ(run_on_active(unary(Kind::Rose, active(m)), x), (std::vector<int>{1, 0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(run_on_active(unary(Kind::Fell, active(m)), x), (std::vector<int>{0, 0, 1, 0, 1, 0, 0}));
}

TEST(MonitorOperators, HeldNeedsNPlusOneCycles) {
  auto m = one_cause(false);
  std::vector<int> x = {1, 1, 1, 0, 1, 1, 1, 1};
  EXPECT_EQ(run_on_active(unary(Kind::Held, active(m), 2), x), (std::vector<int>{0, 0, 1, 0, 0, 0, 1, 1}));
  EXPECT_EQ(run_on_active(unary(Kind::Held, active(m), 0), x), x);
}

TEST(MonitorOperators, WithinLooksNCyclesBack) {
  auto m = one_cause(false);
  std::vector<int> x = {0, 0, 1, 0, 0, 0, 1, 0};
  EXPECT_EQ(run_on_active(unary(Kind::Within, active(m), 2), x), (std::vector<int>{0, 0, 1, 1, 1, 0, 1, 1}));
  EXPECT_EQ(run_on_active(unary(Kind::Within, active(m), 0), x), x);
}

// The held counter is exactly the number of consecutive cycles held before
// this one, saturating at N: what lets invariants relate it to `*.elapsed`.
TEST(MonitorOperators, HeldCounterCountsConsecutiveCyclesExactly) {
  auto m = one_cause(false);
  Harness h(m, invariant(unary(Kind::Held, active(m), 3)));
  ASSERT_EQ(h.mon.state_vars.size(), 1u);
  const std::string counter = h.mon.state_vars[0];
  EXPECT_EQ(counter.rfind("monitor.", 0), 0u);
  std::vector<int> x = {1, 1, 0, 1, 1, 1, 1, 1, 0};
  std::vector<int> expect = {1, 2, 0, 1, 2, 3, 3, 3, 0};  // after each cycle
  for (std::size_t k = 0; k < x.size(); ++k) {
    h.step(x[k] ? 0.0f : 1.0f);
    EXPECT_EQ(h.state(counter), expect[k]) << k;
  }
}

TEST(MonitorOperators, SinceOverInputValueAndQuality) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  Expr a = probe.value("T1"), b = probe.bad("T1");
  Harness h(m, invariant(Expr::binary(Kind::Since, a, b)));
  std::vector<std::pair<int, int>> ab = {{0, 0}, {1, 1}, {1, 0}, {0, 0}, {1, 0}, {0, 1}, {1, 0}, {0, 0}};
  std::vector<int> expect = {0, 1, 1, 0, 0, 1, 1, 0};
  for (std::size_t k = 0; k < ab.size(); ++k)
    EXPECT_EQ(h.step(static_cast<float>(ab[k].first), ab[k].second), expect[k]) << k;
}

TEST(MonitorAtoms, CountAndIntObservables) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  using properties::CompareOp;
  // Bad quality trips the cause (the default bad_quality = trip).
  Expr cnt = Expr::nary(Kind::Count, {probe.value("T1"), probe.bad("T1"), active(m)});
  Harness h(m, invariant(Expr::compare(CompareOp::Ge, cnt, Expr::integer(2))));
  EXPECT_EQ(h.step(1.0f, false), 0);  // 1 + 0 + 0
  EXPECT_EQ(h.step(1.0f, true), 1);   // 1 + 1 + 1
  EXPECT_EQ(h.step(0.0f, false), 0);  // 0 + 0 + 1
  EXPECT_EQ(h.step(0.0f, true), 1);   // 0 + 1 + 1
  Expr tripped = Expr::of_observable(observable(m, "cause[1].tripped_tags"));
  Harness t(m, invariant(Expr::compare(CompareOp::Eq, tripped, Expr::integer(1))));
  EXPECT_EQ(t.step(1.0f), 0);
  EXPECT_EQ(t.step(0.0f), 1);
  Expr voting = Expr::of_observable(observable(m, "cause[1].voting"));
  Harness v(m, invariant(Expr::compare(CompareOp::Ne, voting, Expr::voting(model::Voting::OneOoOne))));
  EXPECT_EQ(v.step(1.0f), 0);
}

// An aggregate as large as the parser allows (100,000 terms) is one flat sum:
// the Evaluator and Z3 walk it without a 100,000-deep recursion.
TEST(MonitorAtoms, LargeCountIsOneFlatSum) {
  auto m = one_cause(false);
  std::vector<Expr> many(100000, active(m));
  Expr body = Expr::compare(properties::CompareOp::Ge, Expr::nary(Kind::Count, std::move(many)),
                            Expr::integer(100000));
  Harness h(m, invariant(body));
  EXPECT_EQ(h.step(0.0f), 1);
  EXPECT_EQ(h.step(1.0f), 0);
}

TEST(MonitorAtoms, FloatComparisonsInSinglePrecision) {
  auto m = one_cause(true);
  Harness probe(m, invariant(Expr::boolean(true)));
  Expr v = probe.value("T1");
  using properties::CompareOp;
  struct Case { CompareOp op; float c; float in; int expect; };
  std::vector<Case> cases = {
      {CompareOp::Ge, 90.0f, 90.0f, 1},  {CompareOp::Gt, 90.0f, 90.0f, 0},
      {CompareOp::Lt, 90.0f, 89.99f, 1}, {CompareOp::Le, 90.0f, 90.00001f, 0},
      {CompareOp::Eq, 0.1f, 0.1f, 1},    {CompareOp::Ne, 0.1f, 0.1f, 0},
      {CompareOp::Eq, 0.0f, -0.0f, 1},  // IEEE equality, not bit equality
  };
  for (const auto& c : cases) {
    Harness h(m, invariant(Expr::compare(c.op, v, Expr::real(c.c))));
    EXPECT_EQ(h.step(c.in), c.expect) << static_cast<int>(c.op) << " " << c.c << " " << c.in;
  }
  // The constant may come first.
  Harness h(m, invariant(Expr::compare(CompareOp::Gt, Expr::real(90.0f), v)));
  EXPECT_EQ(h.step(89.0f), 1);
  EXPECT_EQ(h.step(91.0f), 0);
}

TEST(MonitorAtoms, OutputTagAndBypassInput) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  // OUT1 is DTT: 0 while effect 1 is active.
  Harness h(m, invariant(Expr::of_observable(observable(m, "effect[1].tag[1]"))));
  EXPECT_EQ(h.step(1.0f), 1);
  EXPECT_EQ(h.step(0.0f), 0);
  Harness by(m, invariant(probe.value("BY1")));
  model::CycleInput in;
  in.tags.resize(by.enc->inputs.size());
  in.tags[by.index("BY1")].value = 1.0f;
  by.ev->step(in);
  EXPECT_EQ(by.ev->value("test.good"), 1);
}

TEST(MonitorAtoms, CommandPatterns) {
  auto m = one_cause(false);
  properties::CommandPattern any_sb{model::CommandOp::SoftBypassCause, 1, {}, {}, {}, {}, {}};
  properties::CommandPattern sb_off = any_sb;
  sb_off.on = false;
  // Effect 1 has no V or R intersection: override_effect is always refused
  // (O.3), so the encoder has no input for it; the monitor adds a free one,
  // so issuing it counts (ast.hpp: issued whether or not accepted).
  properties::CommandPattern ovr{model::CommandOp::OverrideEffect, {}, 1, {}, {}, {}, {}};
  model::Command on{model::CommandOp::SoftBypassCause, 1, 0, 0, 0, true, "", 0.0f};
  model::Command off = on;
  off.on = false;
  model::Command ovr_cmd{model::CommandOp::OverrideEffect, 0, 1, 0, 0, true, "", 0.0f};

  Harness any(m, invariant(Expr::issued(any_sb)));
  EXPECT_EQ(any.step(1.0f, false, {}), 0);
  EXPECT_EQ(any.step(1.0f, false, {on}), 1);
  EXPECT_EQ(any.step(1.0f, false, {off}), 1);
  Harness only_off(m, invariant(Expr::issued(sb_off)));
  EXPECT_EQ(only_off.step(1.0f, false, {on}), 0);
  EXPECT_EQ(only_off.step(1.0f, false, {off}), 1);
  Harness refused(m, invariant(Expr::issued(ovr)));
  EXPECT_EQ(refused.step(1.0f, false, {}), 0);
  EXPECT_EQ(refused.step(1.0f, false, {ovr_cmd}), 1);
  EXPECT_EQ(refused.ev->value("effect[1].override_active"), 0);  // and it changes nothing
  ASSERT_TRUE(refused.enc->ts.inputvar("cmd.override_effect[1]").has_value());
  EXPECT_NE(refused.enc->find_command(ovr_cmd), nullptr);
  // An open pattern covers every always-refused ack of the cone (cause 1
  // acknowledges automatically, O.1).
  properties::CommandPattern ack{model::CommandOp::AckCause, {}, {}, {}, {}, {}, {}};
  Harness any_ack(m, invariant(Expr::issued(ack)));
  model::Command ack1{model::CommandOp::AckCause, 1, 0, 0, 0, true, "", 0.0f};
  EXPECT_EQ(any_ack.step(1.0f, false, {ack1}), 1);
  // A simulation of the bypass tag BY1 (not simulatable, O.8) is issued too.
  properties::CommandPattern sim{model::CommandOp::SimulateTag, {}, {}, {}, {}, {}, std::string("BY1")};
  Harness simulated(m, invariant(Expr::issued(sim)));
  model::Command sim_by{model::CommandOp::SimulateTag, 0, 0, 0, 0, true, "by1", 1.0f};
  EXPECT_EQ(simulated.step(1.0f, false, {}), 0);
  EXPECT_EQ(simulated.step(1.0f, false, {sim_by}), 1);
}

// ---- Response -------------------------------------------------------------------

Property response(Expr trigger, Expr resp, int n) {
  Property p;
  p.name = "r";
  p.kind = PropertyKind::Response;
  p.trigger = std::move(trigger);
  p.response = std::move(resp);
  p.within_cycles = n;
  return p;
}

// Trigger = T1's value, response = T1's bad flag.
std::vector<int> run_response(int n, const std::vector<std::pair<int, int>>& tr) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  Harness h(m, response(probe.value("T1"), probe.bad("T1"), n));
  EXPECT_TRUE(h.mon.antecedent.has_value());
  std::vector<int> out;
  for (auto [t, r] : tr) out.push_back(h.step(static_cast<float>(t), r));
  return out;
}

TEST(MonitorResponse, ViolatedWhenTheWindowOfNPlusOneCyclesCloses) {
  EXPECT_EQ(run_response(2, {{1, 0}, {0, 0}, {0, 0}}), (std::vector<int>{1, 1, 0}));
  // Answered at the last cycle of the window, then a trigger answered at
  // once, then a trigger with no answer: violated two cycles later.
  EXPECT_EQ(run_response(2, {{1, 0}, {1, 0}, {0, 1}, {0, 0}, {1, 0}, {0, 0}, {0, 1},
                             {1, 1}, {1, 0}, {0, 0}, {0, 0}}),
            (std::vector<int>{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0}));
  // The oldest pending trigger decides: triggers at 0 and 1, no answer.
  EXPECT_EQ(run_response(1, {{1, 0}, {1, 0}, {0, 0}}), (std::vector<int>{1, 0, 0}));
  // N = 0: the response must come in the trigger's own cycle.
  EXPECT_EQ(run_response(0, {{1, 1}, {0, 0}, {1, 0}}), (std::vector<int>{1, 1, 0}));
}

// ---- Against the definitions of properties/ast.hpp on random sequences ------------

// Direct readings of the cycle semantics (ast.hpp), on whole finite sequences.
int ref_held(const std::vector<int>& a, int k, int n) {
  if (k < n) return 0;
  for (int j = k - n; j <= k; ++j)
    if (!a[j]) return 0;
  return 1;
}
int ref_within(const std::vector<int>& a, int k, int n) {
  for (int j = std::max(0, k - n); j <= k; ++j)
    if (a[j]) return 1;
  return 0;
}
int ref_since(const std::vector<int>& a, const std::vector<int>& b, int k) {
  for (int j = k; j >= 0; --j) {
    if (b[j]) return 1;
    if (!a[j]) return 0;
  }
  return 0;
}
// The first cycle at which some trigger's window [j, j+N] has ended without
// a response; -1 if none within the sequence.
int ref_first_violation(const std::vector<int>& t, const std::vector<int>& r, int n) {
  int len = static_cast<int>(t.size());
  for (int k = 0; k < len; ++k) {
    int j = k - n;
    if (j < 0 || !t[j]) continue;
    bool answered = false;
    for (int i = j; i <= k; ++i) answered = answered || r[i];
    if (!answered) return k;
  }
  return -1;
}

TEST(MonitorRandom, OperatorsMatchTheirDefinitions) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  Expr a = probe.value("T1"), b = probe.bad("T1");
  std::mt19937 rng(7);
  auto sequence = [&](int one_in) {
    std::vector<int> v;
    for (int k = 0; k < 40; ++k) v.push_back(static_cast<int>(rng() % one_in == 0));
    return v;
  };
  for (int n : {0, 1, 2, 5}) {
    Harness held(m, invariant(unary(Kind::Held, a, n)));
    Harness within(m, invariant(unary(Kind::Within, a, n)));
    Harness since(m, invariant(Expr::binary(Kind::Since, a, b)));
    Harness resp(m, response(a, b, n));
    for (int round = 0; round < 25; ++round) {
      std::vector<int> dense = sequence(1), sparse = sequence(6), quality = sequence(4);
      for (auto& d : dense) d = static_cast<int>(rng() % 5 != 0);  // long runs for held
      for (Harness* h : {&held, &within, &since, &resp}) h->ev->reset();
      int first = ref_first_violation(sparse, quality, n);
      for (int k = 0; k < 40; ++k) {
        auto f = [](int v) { return static_cast<float>(v); };
        EXPECT_EQ(held.step(f(dense[k]), quality[k]), ref_held(dense, k, n)) << n << " " << k;
        EXPECT_EQ(within.step(f(sparse[k]), quality[k]), ref_within(sparse, k, n)) << n << " " << k;
        EXPECT_EQ(since.step(f(dense[k]), quality[k]), ref_since(dense, quality, k)) << k;
        int good = resp.step(f(sparse[k]), quality[k]);
        // Exact up to and including the first violation.
        if (first < 0 || k <= first) {
          EXPECT_EQ(good, k == first ? 0 : 1) << n << " " << k;
        }
      }
    }
  }
}

// ---- Depths with a solver ------------------------------------------------------------

// Whether some cycle k < depth violates `good` on a path whose assumption
// holds in every cycle (BMC of depth `depth`).
bool falsifiable_within(Harness& h, int depth) {
  z3::solver s(h.ctx);
  encoder::Unroller u(h.enc->ts);
  s.add(u.path(depth));
  z3::expr_vector violated(h.ctx);
  for (int k = 0; k < depth; ++k) {
    s.add(u.at(h.mon.assumption, k));
    violated.push_back(!u.at(h.mon.good, k));
  }
  s.add(z3::mk_or(violated));
  return s.check() == z3::sat;
}

TEST(MonitorSolver, HeldIsFirstViolatedAtDepthNPlusOne) {
  auto m = one_cause(false);
  Property p = invariant(Expr::boolean(true));
  p.kind = PropertyKind::Never;
  p.body = unary(Kind::Held, active(m), 3);  // active in cycles 0..3
  Harness h(m, p);
  EXPECT_FALSE(falsifiable_within(h, 3));
  EXPECT_TRUE(falsifiable_within(h, 4));
}

TEST(MonitorSolver, ResponseIsFirstViolatedAtDepthNPlusOneAndAssumptionsCount) {
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  Property p = response(probe.value("T1"), probe.bad("T1"), 2);
  Harness h(m, p);
  EXPECT_FALSE(falsifiable_within(h, 2));
  EXPECT_TRUE(falsifiable_within(h, 3));
  // A file assumption that T1 is bad whenever it reads TRUE answers every trigger.
  properties::Assumption always_answered{"", Expr::binary(Kind::Implies, probe.value("T1"), probe.bad("T1")), {}};
  Harness assumed(m, p, {always_answered});
  EXPECT_FALSE(falsifiable_within(assumed, 6));
}

// A never-accepted command is still an operator action the solver may pick.
TEST(MonitorSolver, AlwaysRefusedCommandCanBeIssued) {
  auto m = one_cause(false);
  Property p = invariant(Expr::boolean(true));
  p.kind = PropertyKind::Never;
  p.body = Expr::issued({model::CommandOp::OverrideEffect, {}, 1, {}, {}, {}, {}});
  Harness h(m, p);
  EXPECT_TRUE(falsifiable_within(h, 1));
}

TEST(MonitorSolver, ReachableWitnessOfWithinAfterFell) {
  // Reachable: cause 1 fell, and in the previous cycle it had been active
  // within the last 2 cycles: the earliest witness is cycle 1 (active at 0).
  auto m = one_cause(false);
  Harness probe(m, invariant(Expr::boolean(true)));
  Property p = invariant(Expr::boolean(true));
  p.kind = PropertyKind::Reachable;
  p.body = Expr::nary(Kind::And, {unary(Kind::Fell, active(m)), unary(Kind::Prev, unary(Kind::Within, active(m), 2))});
  Harness h(m, p);
  EXPECT_FALSE(h.mon.antecedent.has_value());
  EXPECT_FALSE(falsifiable_within(h, 1));
  EXPECT_TRUE(falsifiable_within(h, 2));
}

// The held counter is exact, so a relational invariant ties it to the
// matrix's own override timer (E.3, docs/encoding.md T.2) at any length: here
// 1800 s = 18,000 cycles, proved by one induction step, no unrolling.
TEST(MonitorSolver, HeldCounterRelatesToTheOverrideTimerByInduction) {
  auto m = one_cause(false);
  m.intersections[0].type = model::IntersectionType::V;
  m.effects[0].override_time = model::Override{1800, 0};
  const int d = 18000;
  Property p = invariant(Expr::boolean(true));
  p.kind = PropertyKind::Never;
  p.body = unary(Kind::Held, Expr::of_observable(observable(m, "effect[1].override_active")), d);
  Harness h(m, p);
  const auto& ts = h.enc->ts;
  z3::expr running = *ts.statevar("effect[1].override");
  z3::expr elapsed = *ts.statevar("effect[1].override.elapsed");
  z3::expr held = *ts.statevar(h.mon.state_vars.at(0));
  z3::expr_vector parts(h.ctx);
  parts.push_back(running == (held > 0));
  parts.push_back(elapsed <= held);
  parts.push_back(z3::implies(!running, elapsed == 0));
  for (const auto& l : ts.lemmas()) parts.push_back(l.term);
  z3::expr inv = z3::mk_and(parts);
  encoder::Unroller u(ts);
  z3::solver base(h.ctx);
  base.add(u.at(ts.init_formula(), 0) && !u.at(inv, 0));
  EXPECT_EQ(base.check(), z3::unsat);
  z3::solver step(h.ctx);
  step.add(u.at(inv, 0) && u.at(ts.constraint_formula(), 0) && u.at(ts.trans_formula(), 0) &&
           !u.at(inv, 1));
  EXPECT_EQ(step.check(), z3::unsat);
  // The step query is not vacuous: with the same premises, a stronger
  // relation (the timer strictly behind the counter) can fail.
  z3::solver loose(h.ctx);
  loose.add(u.at(inv, 0) && u.at(ts.constraint_formula(), 0) && u.at(ts.trans_formula(), 0) &&
            !u.at(elapsed < held, 1));
  EXPECT_EQ(loose.check(), z3::sat);
}

// ---- Several monitors, shared state, cone of influence ----------------------------

TEST(MonitorSystem, SharedSubformulasAndSeveralProperties) {
  auto m = one_cause(false);
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  Expr x = active(m);
  // rose and fell of the same operand share one prev variable.
  auto first = properties::compile_monitor(
      *enc, invariant(Expr::binary(Kind::Or, unary(Kind::Rose, x), unary(Kind::Fell, x))), {});
  EXPECT_EQ(first.state_vars.size(), 1u);
  auto second = properties::compile_monitor(*enc, invariant(unary(Kind::Prev, x)), {});
  ASSERT_EQ(second.state_vars.size(), 1u);
  EXPECT_NE(second.state_vars[0], first.state_vars[0]);
  // Counters come with their range lemma.
  auto third = properties::compile_monitor(*enc, invariant(unary(Kind::Held, x, 4)), {});
  const auto& lemmas = enc->ts.lemmas();
  EXPECT_TRUE(std::any_of(lemmas.begin(), lemmas.end(), [&](const auto& l) {
    return l.name == third.state_vars[0] + ".range";
  }));
  // An implication's left side is the antecedent of an invariant.
  auto imp = properties::compile_monitor(*enc, invariant(Expr::binary(Kind::Implies, x, x)), {});
  ASSERT_TRUE(imp.antecedent.has_value());
  EXPECT_TRUE(z3::eq(*imp.antecedent, *enc->ts.term("cause[1].active")));
  // And the first conjunct of a never.
  Property never = invariant(Expr::nary(Kind::And, {Expr::of_observable(observable(m, "effect[1].active")), x}));
  never.kind = PropertyKind::Never;
  auto nev = properties::compile_monitor(*enc, never, {});
  ASSERT_TRUE(nev.antecedent.has_value());
  EXPECT_TRUE(z3::eq(*nev.antecedent, *enc->ts.term("effect[1].active")));
  never.body = x;
  EXPECT_FALSE(properties::compile_monitor(*enc, never, {}).antecedent.has_value());
}

TEST(MonitorCone, RootsCoverObservablesInputReadersAndCommandTargets) {
  auto m = formats::load_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/matrix.json");
  model::InputTable inputs(m);
  std::size_t lt_a = *inputs.find("LT_100A");
  std::size_t lt_102 = *inputs.find("LT_102");
  using Node = model::Node;
  Property p = invariant(Expr::binary(
      Kind::Implies, Expr::compare(properties::CompareOp::Ge, Expr::input_value(lt_a, model::TagKind::Analog), Expr::real(90.0f)),
      Expr::of_observable(observable(m, "effect[1].active"))));
  EXPECT_EQ(properties::property_roots(p, {}, m),
            (std::vector<Node>{{Node::Kind::Cause, 1}, {Node::Kind::Effect, 1}}));
  properties::CommandPattern reset{model::CommandOp::ResetEffect, {}, 2, {}, {}, {}, {}};
  const std::vector<Node> with_e2{{Node::Kind::Cause, 1}, {Node::Kind::Effect, 1}, {Node::Kind::Effect, 2}};
  const std::vector<Node> without_e2{{Node::Kind::Cause, 1}, {Node::Kind::Effect, 1}};
  auto assumed = [&](Expr e) { return properties::property_roots(p, {{"", std::move(e), {}}}, m); };
  Expr issued = Expr::issued(reset);
  // Assumed absent (negative in the assumption, also under held or an
  // implication's left side): its target need not be in the cone.
  EXPECT_EQ(assumed(Expr::unary(Kind::Not, issued)), without_e2);
  EXPECT_EQ(assumed(unary(Kind::Held, Expr::unary(Kind::Not, issued), 3)), without_e2);
  EXPECT_EQ(assumed(Expr::binary(Kind::Implies, issued, Expr::boolean(false))), without_e2);
  // Assumed present, or under rose (either direction), or in the judged
  // part: its target must be in the cone.
  EXPECT_EQ(assumed(issued), with_e2);
  EXPECT_EQ(assumed(Expr::unary(Kind::Not, unary(Kind::Rose, issued))), with_e2);
  Property judged = p;
  judged.body = Expr::binary(Kind::And, p.body, Expr::unary(Kind::Not, issued));
  EXPECT_EQ(properties::property_roots(judged, {}, m), with_e2);
  // An open target: every effect.
  reset.effect.reset();
  EXPECT_EQ(assumed(Expr::issued(reset)).size(), m.effects.size() + 1);

  // The cone of effect 3 lacks effect 1: compiling is an error, not a guess.
  z3::context ctx;
  auto small = encoder::encode(ctx, m, {{Node::Kind::Effect, 3}});
  EXPECT_THROW(properties::compile_monitor(*small, p, {}), std::logic_error);

  // A tag outside the cone becomes a free input the Evaluator feeds.
  auto enc = encoder::encode(ctx, m, properties::property_roots(p, {}, m));
  ASSERT_FALSE(enc->tag_value[lt_102].has_value());
  Property q = invariant(Expr::compare(properties::CompareOp::Lt, Expr::input_value(lt_102, model::TagKind::Analog),
                                       Expr::real(10.0f)));
  auto mon = properties::compile_monitor(*enc, q, {});
  ASSERT_TRUE(enc->tag_value[lt_102].has_value());
  enc->ts.name_term("test.good", mon.good);
  encoder::Evaluator ev(*enc);
  model::CycleInput in;
  in.tags.resize(inputs.size());
  in.tags[lt_102].value = 5.0f;
  ev.step(in);
  EXPECT_EQ(ev.value("test.good"), 1);
  in.tags[lt_102].value = 50.0f;
  ev.step(in);
  EXPECT_EQ(ev.value("test.good"), 0);
}

// ---- Parsed properties on the examples ------------------------------------------------

model::Matrix example(const std::string& name) {
  return formats::load_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json");
}

// A Float32 numeral of a model, through its IEEE bit pattern.
float float_of(const z3::expr& v) {
  z3::expr bits = z3::expr(v.ctx(), Z3_mk_fpa_to_ieee_bv(v.ctx(), v)).simplify();
  std::uint32_t u = bits.get_numeral_uint();
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

// Requirement 1's shape with short durations (held 300 ms = [k-3, k], within
// 200 ms = 2 cycles): cause 1's 2 s ON delay cannot close XV_101 in time, so
// the first violation is at cycle 3 + 2 = 5. The solver's trace, replayed on
// the encoder's Evaluator, violates `good` exactly there.
TEST(MonitorExamples, ParsedResponseOnTheTankFirstViolatedAtItsDeadline) {
  auto m = example("tank-overfill");
  auto file = properties::parse_properties(
      "property req1.short {\n"
      "  whenever held(count(t in cause[1].tags: good(t) and t >= 90.0) >= 2, 300 ms)\n"
      "  then not XV_101 within 200 ms\n"
      "}\n",
      m, "t.props");
  const Property& p = file.properties.at(0);
  ASSERT_EQ(p.within_cycles, 2);
  Harness h(m, p, file.assumptions);
  EXPECT_FALSE(falsifiable_within(h, 5));
  z3::solver s(h.ctx);
  encoder::Unroller u(h.enc->ts);
  s.add(u.path(6));
  for (int k = 0; k < 6; ++k) s.add(u.at(h.mon.assumption, k));
  s.add(!u.at(h.mon.good, 5));
  ASSERT_EQ(s.check(), z3::sat);
  z3::model model = s.get_model();
  const auto& inputs = h.enc->ts.inputvars();
  for (int k = 0; k < 6; ++k) {
    std::vector<encoder::Evaluator::Value> in(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      z3::expr v = model.eval(u.var_at(inputs[i].var, k), true);
      if (v.is_fpa()) in[i].f = float_of(v);
      else in[i].i = v.is_true() ? 1 : 0;
    }
    h.ev->step_raw(in);
    EXPECT_EQ(h.ev->value("test.good"), k < 5 ? 1 : 0) << k;
  }
}

// The standard properties of two examples, parsed and compiled: no invariant
// is violated within 4 cycles; on the tank (no trip there is delayed) every
// effect has a trip and a reset witness within 4 cycles.
TEST(MonitorExamples, StandardPropertiesWithinFourCycles) {
  for (const char* name : {"tank-overfill", "pipeline-hipps"}) {
    auto m = example(name);
    auto file = properties::standard_properties(m);
    ASSERT_FALSE(file.properties.empty());
    bool tank = std::string(name) == "tank-overfill";
    for (const auto& p : file.properties) {
      bool reachable = p.kind == PropertyKind::Reachable;
      if (reachable && !tank) continue;
      Harness h(m, p, file.assumptions);
      EXPECT_EQ(falsifiable_within(h, 4), reachable) << name << " " << p.name;
    }
  }
}

// Every requirement the examples state (examples/*/requirements.props)
// compiles on its own cone; within 3 cycles none expected `proved` is
// violated, and the tank's reachability goals have their witnesses.
TEST(MonitorExamples, RequirementFilesCompileAndHoldForThreeCycles) {
  for (const char* name : {"tank-overfill", "pipeline-hipps", "compressor", "burner-management"}) {
    auto m = example(name);
    auto file = properties::load_properties(
        std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/requirements.props", m);
    ASSERT_FALSE(file.properties.empty()) << name;
    for (const auto& p : file.properties) {
      Harness h(m, p, file.assumptions);
      bool violated = falsifiable_within(h, 3);
      if (p.expect == "proved") {
        EXPECT_FALSE(violated) << name << " " << p.name;
      }
      if (p.expect == "reachable" && std::string(name) == "tank-overfill") {
        EXPECT_TRUE(violated) << p.name;
      }
    }
  }
}

}  // namespace
