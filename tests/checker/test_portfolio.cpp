// The portfolio: the engines one after another, each within its budget of
// work; the answer is the same on every run and every machine, re-checked,
// and the wall clock only interrupts.
#include <gtest/gtest.h>

#include <chrono>

#include "checker/engines/portfolio.hpp"
#include "tests/checker/problems.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

Limits depth(int d) {
  Limits l;
  l.max_depth = d;
  return l;
}

ProverResult decide(const fixtures::NamedProblem& p, PortfolioOptions o = {}) {
  return Portfolio(p.make, std::move(o)).run(depth(40));
}

std::size_t nonzero_inputs(const Trace& t) {
  std::size_t n = 0;
  for (const auto& c : t.cycles)
    for (const auto& v : c.inputs) n += v.i != 0 || v.f != 0.0f;
  return n;
}

// Its speed is a benchmark figure (cemv_checker_measure), not asserted here.
TEST(Portfolio, ProvesTheHippsOverrideBoundWithoutUnrolling) {
  // invariants+induction proves it on the reduced problem in one
  // strengthened step (the monitor's counter related to the override
  // timer): no unrolling to 18,000 cycles.
  ProverResult r = decide(fixtures::override_instance_monitor(18000, Verdict::Proved));
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  EXPECT_EQ(r.method, Method::InvariantsInduction);
  EXPECT_LE(r.k, 1);
}

TEST(Portfolio, ProvesTheHippsOverrideBoundByInvariantsWhenThatIsTheEngine) {
  PortfolioOptions o;
  o.engines = {Method::InvariantsInduction, Method::Bmc};
  ProverResult r = decide(fixtures::override_instance_monitor(18000, Verdict::Proved), o);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  EXPECT_EQ(r.method, Method::InvariantsInduction);
  EXPECT_EQ(r.k, 0);
  bool relates_monitor_and_timer = false;
  for (const auto& c : r.invariant.clauses)
    relates_monitor_and_timer = relates_monitor_and_timer || (c.find("monitor.override_held") != std::string::npos &&
                                                              c.find("override.elapsed") != std::string::npos);
  EXPECT_TRUE(relates_monitor_and_timer) << r.invariant.text();
}

TEST(Portfolio, RefutesTheBoundOneCycleTooTightWithALongCounterexample) {
  ProverResult r = decide(fixtures::override_instance_monitor(17999, Verdict::Falsified));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  EXPECT_EQ(r.method, Method::AcceleratedBmc);
  EXPECT_GE(r.cex.length(), 18001u);
}

TEST(Portfolio, ReportsBmcsShortestCounterexampleWithOnlyTheInputsItNeeds) {
  ProverResult r = decide(fixtures::guarded_counter(2));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  EXPECT_EQ(r.method, Method::Bmc);
  EXPECT_EQ(r.cex.length(), 4u);
  // `start` in cycle 0 is all the counter needs.
  EXPECT_EQ(r.cex.input(0, "start").i, 1);
  EXPECT_EQ(nonzero_inputs(r.cex), 1u);
}

TEST(Portfolio, SameProblemSameAnswer) {
  auto tank = fixtures::example_term("tank-overfill", {model::Node{model::Node::Kind::Effect, 1}},
                                     "effect[1].active", true, Verdict::Falsified, 1);
  ProverResult a = decide(tank), b = decide(tank);
  ASSERT_EQ(a.verdict, Verdict::Falsified);
  EXPECT_EQ(a.method, b.method);
  ASSERT_EQ(a.cex.length(), b.cex.length());
  for (std::size_t c = 0; c < a.cex.length(); ++c) {
    EXPECT_EQ(a.cex.cycles[c].inputs, b.cex.cycles[c].inputs) << "cycle " << c;
    EXPECT_EQ(a.cex.cycles[c].state, b.cex.cycles[c].state) << "cycle " << c;
  }
  auto proof = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult p = decide(proof), q = decide(proof);
  ASSERT_EQ(p.verdict, Verdict::Proved);
  EXPECT_EQ(p.method, q.method);
  EXPECT_EQ(p.k, q.k);
  EXPECT_EQ(p.invariant.clauses, q.invariant.clauses);
}

// Nothing decides: every engine stops at its budget of work, and the answer
// is the same unknown every time, with the reason and what each engine
// reached.
TEST(Portfolio, StopsAtItsBudgetsWhenNothingDecides) {
  PortfolioOptions o;
  o.engine_work = kMega / 2;
  o.quick_work = kMega / 4;
  ProverResult r = decide(fixtures::edge_counter(), o);
  ProverResult again = decide(fixtures::edge_counter(), o);
  EXPECT_EQ(r.verdict, Verdict::Unknown);
  EXPECT_NE(r.reason, UnknownReason::TimeLimit);
  EXPECT_EQ(r.engines, again.engines);
  EXPECT_EQ(r.work, again.work);
  EXPECT_NE(r.engines.find("pdr"), std::string::npos) << r.engines;
}

// The wall clock only interrupts: an interrupted question is unknown with
// reason "time limit", whatever an engine had, and ends on time.
TEST(Portfolio, TheWallClockOnlyInterrupts) {
  Limits l = depth(40);
  l.deadline = Clock::now() + std::chrono::milliseconds(300);
  PortfolioOptions o;
  o.engine_work = 0;  // no budget of its own: only the clock ends it
  o.quick_work = 0;
  auto t0 = Clock::now();
  ProverResult r = Portfolio(fixtures::edge_counter().make, o).run(l);
  double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  EXPECT_EQ(r.verdict, Verdict::Unknown);
  EXPECT_EQ(r.reason, UnknownReason::TimeLimit);
  EXPECT_LT(seconds, 3.0);  // 0.3 s; the margin is for a loaded 2-core machine
  CancelToken cancel;
  cancel.cancel();
  Limits c = depth(40);
  c.cancel = &cancel;
  ProverResult cut = decide(fixtures::guarded_counter(2));
  ProverResult none = Portfolio(fixtures::guarded_counter(2).make).run(c);
  EXPECT_EQ(cut.verdict, Verdict::Falsified);
  EXPECT_EQ(none.verdict, Verdict::Unknown);
  EXPECT_EQ(none.reason, UnknownReason::TimeLimit);
}

// The quick attempt (k-induction without mined invariants) answers what it
// can; without it the engines after it give the same verdict, a shortest
// counterexample from an engine that unrolls depth by depth.
TEST(Portfolio, QuickAttemptAndTheEnginesAgree) {
  for (int quick_k : {1, -1}) {
    PortfolioOptions o;
    o.quick_k = quick_k;
    const auto bug = fixtures::guarded_counter(2);
    ProverResult r = decide(bug, o);
    ASSERT_EQ(r.verdict, Verdict::Falsified) << "quick_k " << quick_k;
    EXPECT_EQ(r.cex.length(), 4u) << "quick_k " << quick_k;
    const auto proof = fixtures::override_instance_monitor(18000, Verdict::Proved);
    ProverResult p = decide(proof, o);
    ASSERT_EQ(p.verdict, Verdict::Proved) << "quick_k " << quick_k;
    EXPECT_EQ(p.method, Method::InvariantsInduction) << "quick_k " << quick_k;
  }
}

// BMC in the quick attempt finds a counterexample deeper than quick_k.
TEST(Portfolio, QuickBmcFindsADeeperCounterexample) {
  PortfolioOptions o;
  o.engines = {Method::KInduction};  // nothing else could find it
  o.max_k = 1;
  o.quick_bmc_depth = 8;
  const auto bug = fixtures::saturating_counter(10, 5);  // six cycles of `go`
  ProverResult r = decide(bug, o);
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  EXPECT_EQ(r.method, Method::Bmc);
  o.quick_bmc_depth = 0;
  EXPECT_EQ(decide(bug, o).verdict, Verdict::Unknown);
}

// On a wide problem the wide engines are asked instead, in their order: PDR's
// proof, or the shortest counterexample BMC finds after PDR. Every problem is
// wide here (wide_states = 0).
TEST(Portfolio, WideEnginesAnswerOnAWideProblem) {
  PortfolioOptions o;
  o.quick_k = -1;
  o.wide_states = 0;
  o.wide_engines = {Method::Pdr, Method::Bmc};
  const auto bug = fixtures::guarded_counter(2);
  ProverResult r = decide(bug, o);
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  EXPECT_EQ(r.cex.length(), 4u);
  const auto fine = fixtures::guarded_counter(3);
  ProverResult p = decide(fine, o);
  ASSERT_EQ(p.verdict, Verdict::Proved) << p.reason_text();
  EXPECT_EQ(p.method, Method::Pdr);
}

// k-induction-plain: no mined invariant, only the encoder's lemmas (this
// hand-made system has none): it proves the guarded counter by induction
// over a simple path alone, where k-induction proves it strengthened by what
// its miner found.
TEST(Portfolio, PlainKInductionMinesNothing) {
  const auto proof = fixtures::guarded_counter(3);
  z3::context ctx;
  const OwnedProblem owned = proof.make(ctx);
  ProverResult mined = make_prover(Method::KInduction, 10)->prove(owned.problem, Limits{});
  ProverResult plain = make_prover(Method::KInductionPlain, 10)->prove(owned.problem, Limits{});
  ASSERT_EQ(mined.verdict, Verdict::Proved) << mined.reason_text();
  ASSERT_EQ(plain.verdict, Verdict::Proved) << plain.reason_text();
  EXPECT_FALSE(mined.invariant.clauses.empty());
  EXPECT_TRUE(plain.invariant.clauses.empty()) << plain.invariant.text();
  EXPECT_EQ(plain.method, Method::KInductionPlain);
}

TEST(Portfolio, RejectsAMethodThatIsNoEngine) {
  PortfolioOptions o;
  o.engines = {Method::Bmc, Method::DirectedRun};
  Portfolio portfolio(fixtures::guarded_counter(3).make, o);
  EXPECT_THROW(portfolio.run(depth(5)), std::invalid_argument);
}

// One engine's budget of work: a budget too small for the proof leaves it
// unknown ("work limit"), the same budget always gives the same figure.
TEST(Portfolio, AnEnginesBudgetIsWork) {
  const auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  z3::context ctx;
  const OwnedProblem owned = p.make(ctx);
  ProverResult tiny = make_prover(Method::InvariantsInduction)->prove(owned.problem, Limits{}.with_work(1000));
  EXPECT_EQ(tiny.verdict, Verdict::Unknown);
  EXPECT_EQ(tiny.reason, UnknownReason::WorkLimit);
  z3::context c1, c2;
  const OwnedProblem o1 = p.make(c1), o2 = p.make(c2);
  ProverResult a = make_prover(Method::InvariantsInduction)->prove(o1.problem, Limits{}.with_work(50 * kMega));
  ProverResult b = make_prover(Method::InvariantsInduction)->prove(o2.problem, Limits{}.with_work(50 * kMega));
  ASSERT_EQ(a.verdict, Verdict::Proved) << a.reason_text();
  EXPECT_EQ(a.work, b.work);
  EXPECT_GT(a.work, 0u);
}

}  // namespace
