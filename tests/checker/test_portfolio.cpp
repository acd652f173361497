// The portfolio: the engines race in their own contexts, yet the answer is
// the deterministic one (BMC's shortest counterexample, the preferred proof),
// re-checked, and on time.
#include <gtest/gtest.h>

#include <chrono>

#include "checker/engines/portfolio.hpp"
#include "tests/checker/problems.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

ProverResult race(const fixtures::NamedProblem& p, std::chrono::milliseconds budget = std::chrono::seconds(30)) {
  Portfolio portfolio(p.make);
  return portfolio.run(Limits::within(budget, 40));
}

std::size_t nonzero_inputs(const Trace& t) {
  std::size_t n = 0;
  for (const auto& c : t.cycles)
    for (const auto& v : c.inputs) n += v.i != 0 || v.f != 0.0f;
  return n;
}

// Its speed is a benchmark figure (cemv_checker_measure), not asserted here.
TEST(Portfolio, ProvesTheHippsOverrideBoundWithoutUnrolling) {
  // k-induction, first in the preference order, proves it on the reduced
  // problem with the encoder's range lemmas: no unrolling to 18,000 cycles.
  ProverResult r = race(fixtures::override_instance_monitor(18000, Verdict::Proved));
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason;
  EXPECT_EQ(r.method, "k-induction");
  EXPECT_LE(r.k, 1);
}

TEST(Portfolio, ProvesTheHippsOverrideBoundByInvariantsWhenThatIsTheEngine) {
  PortfolioOptions o;
  o.engines = {"invariants+induction", "bmc"};
  o.tiers = {{"invariants+induction", "bmc"}};
  const auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult r = Portfolio(p.make, o).run(Limits::within(std::chrono::seconds(30), 40));
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason;
  EXPECT_EQ(r.method, "invariants+induction");
  EXPECT_EQ(r.k, 0);
  bool relates_monitor_and_timer = false;
  for (const auto& c : r.invariant.clauses)
    relates_monitor_and_timer = relates_monitor_and_timer || (c.find("monitor.override_held") != std::string::npos &&
                                                              c.find("override.elapsed") != std::string::npos);
  EXPECT_TRUE(relates_monitor_and_timer) << r.invariant.text();
}

TEST(Portfolio, RefutesTheBoundOneCycleTooTightWithALongCounterexample) {
  ProverResult r = race(fixtures::override_instance_monitor(17999, Verdict::Falsified));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason;
  EXPECT_EQ(r.method, "accelerated-bmc");
  EXPECT_GE(r.cex.length(), 18001u);
}

TEST(Portfolio, ReportsBmcsShortestCounterexampleWithOnlyTheInputsItNeeds) {
  ProverResult r = race(fixtures::guarded_counter(2));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason;
  EXPECT_EQ(r.method, "bmc");
  EXPECT_EQ(r.cex.length(), 4u);
  // `start` in cycle 0 is all the counter needs.
  EXPECT_EQ(r.cex.input(0, "start").i, 1);
  EXPECT_EQ(nonzero_inputs(r.cex), 1u);
}

TEST(Portfolio, SameProblemSameAnswer) {
  auto tank = fixtures::example_term("tank-overfill", {model::Node{model::Node::Kind::Effect, 1}},
                                     "effect[1].active", true, Verdict::Falsified, 1);
  ProverResult a = race(tank), b = race(tank);
  ASSERT_EQ(a.verdict, Verdict::Falsified);
  EXPECT_EQ(a.method, b.method);
  ASSERT_EQ(a.cex.length(), b.cex.length());
  for (std::size_t c = 0; c < a.cex.length(); ++c) {
    EXPECT_EQ(a.cex.cycles[c].inputs, b.cex.cycles[c].inputs) << "cycle " << c;
    EXPECT_EQ(a.cex.cycles[c].state, b.cex.cycles[c].state) << "cycle " << c;
  }
  auto proof = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult p = race(proof), q = race(proof);
  ASSERT_EQ(p.verdict, Verdict::Proved);
  EXPECT_EQ(p.method, q.method);
  EXPECT_EQ(p.k, q.k);
  EXPECT_EQ(p.invariant.clauses, q.invariant.clauses);
}

TEST(Portfolio, EndsOnTimeWhenNothingDecides) {
  auto t0 = std::chrono::steady_clock::now();
  ProverResult r = race(fixtures::edge_counter(), std::chrono::milliseconds(1500));
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.verdict, Verdict::Unknown);
  EXPECT_EQ(r.reason, "time limit");
  EXPECT_LT(seconds, 4.0);  // 1.5 s budget; the margin is for a loaded 2-core machine
}

// The quick attempt (k-induction without mined invariants, in the calling
// thread) answers what it can with the answer the race would give.
TEST(Portfolio, QuickAttemptGivesTheRacesAnswer) {
  for (int quick_k : {1, -1}) {
    PortfolioOptions o;
    o.quick_k = quick_k;
    const auto bug = fixtures::guarded_counter(2);
    ProverResult r = Portfolio(bug.make, o).run(Limits::within(std::chrono::seconds(30), 40));
    ASSERT_EQ(r.verdict, Verdict::Falsified) << "quick_k " << quick_k;
    EXPECT_EQ(r.method, "bmc") << "quick_k " << quick_k;
    EXPECT_EQ(r.cex.length(), 4u) << "quick_k " << quick_k;
    const auto proof = fixtures::override_instance_monitor(18000, Verdict::Proved);
    ProverResult p = Portfolio(proof.make, o).run(Limits::within(std::chrono::seconds(30), 40));
    ASSERT_EQ(p.verdict, Verdict::Proved) << "quick_k " << quick_k;
    EXPECT_EQ(p.method, "k-induction") << "quick_k " << quick_k;
  }
}

// BMC in the quick attempt finds a counterexample deeper than quick_k.
TEST(Portfolio, QuickBmcFindsADeeperCounterexample) {
  PortfolioOptions o;
  o.engines = {"k-induction"};  // nothing else could find it
  o.tiers = {{"k-induction"}};
  o.max_k = 1;
  o.quick_bmc_depth = 8;
  const auto bug = fixtures::saturating_counter(10, 5);  // six cycles of `go`
  ProverResult r = Portfolio(bug.make, o).run(Limits::within(std::chrono::seconds(30), 40));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason;
  EXPECT_EQ(r.method, "bmc");
  o.quick_bmc_depth = 0;
  EXPECT_EQ(Portfolio(bug.make, o).run(Limits::within(std::chrono::seconds(30), 40)).verdict, Verdict::Unknown);
}

// On a wide problem with race_wide, the wide engines race: PDR's proof, or
// BMC's shortest counterexample, whichever the problem has. Every problem is
// wide here (in_order_max_states = 0).
TEST(Portfolio, WideEnginesRaceWhenAskedTo) {
  PortfolioOptions o;
  o.quick_k = -1;
  o.in_order_max_states = 0;
  o.wide_engines = {"pdr", "bmc"};
  o.race_wide = true;
  const auto bug = fixtures::guarded_counter(2);
  ProverResult r = Portfolio(bug.make, o).run(Limits::within(std::chrono::seconds(30), 40));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason;
  EXPECT_EQ(r.method, "bmc");  // the shortest counterexample, whoever found one first
  EXPECT_EQ(r.cex.length(), 4u);
  const auto fine = fixtures::guarded_counter(3);
  ProverResult p = Portfolio(fine.make, o).run(Limits::within(std::chrono::seconds(30), 40));
  ASSERT_EQ(p.verdict, Verdict::Proved) << p.reason;
  EXPECT_EQ(p.method, "pdr");
}

// k-induction-plain: no mined invariant, only the encoder's lemmas (this
// hand-made system has none): it proves the guarded counter by induction
// over a simple path alone, where k-induction proves it strengthened by what
// its miner found.
TEST(Portfolio, PlainKInductionMinesNothing) {
  const auto proof = fixtures::guarded_counter(3);
  z3::context ctx;
  const OwnedProblem owned = proof.make(ctx);
  ProverResult mined = make_prover("k-induction", 10)->prove(owned.problem, Limits::within(std::chrono::seconds(30)));
  ProverResult plain =
      make_prover("k-induction-plain", 10)->prove(owned.problem, Limits::within(std::chrono::seconds(30)));
  ASSERT_EQ(mined.verdict, Verdict::Proved) << mined.reason;
  ASSERT_EQ(plain.verdict, Verdict::Proved) << plain.reason;
  EXPECT_FALSE(mined.invariant.clauses.empty());
  EXPECT_TRUE(plain.invariant.clauses.empty()) << plain.invariant.text();
  EXPECT_EQ(plain.method, "k-induction");
}

TEST(Portfolio, RejectsAnUnknownEngine) {
  PortfolioOptions o;
  o.engines = {"bmc", "magic"};
  Portfolio portfolio(fixtures::guarded_counter(2).make, o);
  EXPECT_THROW(portfolio.run(Limits::within(std::chrono::seconds(5))), std::invalid_argument);
}

}  // namespace
