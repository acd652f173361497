// Timer boundaries of every time function, at the exact cycle of expiry and one
// cycle before (docs/semantics.md T.2): a timer started in cycle k has
// elapsed n*cycle_ms in cycle k+n and expires in the first cycle where elapsed
// >= duration. All timers here are 2000 ms (prealarms 1000 ms) at 100 ms cycles,
// so they expire in cycle k+20 (prealarms k+10). Cycles are counted from 1.
#include <gtest/gtest.h>

#include "test_sim.hpp"

namespace cemv::testing {
namespace {

Cause timed_cause(TimeMode mode, std::uint32_t ms = 2000) {
  Cause c = make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt);
  c.time = {mode, ms};
  return c;
}
constexpr float kTrip = 0.0f, kOk = 1.0f;  // DTT

// Runs until `sim` has run `cycle` cycles.
void run_to(Sim& sim, std::uint64_t cycle) {
  ASSERT_LE(sim.cycle(), cycle);
  sim.step(static_cast<int>(cycle - sim.cycle()));
}

// 13.1.1 ON delay: "The input tag must stay tripped throughout the ON delay time".
TEST(TimerBoundary, OnDelayActiveAtKPlus20NotBefore) {
  Sim sim(make_matrix({timed_cause(TimeMode::OnDelay)}, {make_effect(1)}, {link(1, 1)}));
  sim.step();  // cycle 1 healthy
  sim.set("T1_1", kTrip);
  run_to(sim, 2);  // k = 2
  EXPECT_TRUE(sim.b("cause[1].trip_requested"));
  EXPECT_TRUE(sim.b("cause[1].timer_running"));
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 21);  // k+19
  EXPECT_FALSE(sim.b("cause[1].active"));
  EXPECT_TRUE(sim.b("cause[1].timer_running"));
  EXPECT_EQ(sim.out("Y1_1"), 1);
  run_to(sim, 22);  // k+20
  EXPECT_TRUE(sim.b("cause[1].active"));
  EXPECT_FALSE(sim.b("cause[1].timer_running"));
  EXPECT_EQ(sim.out("Y1_1"), 0);
}

// 13.1.1 (2): "ON delay canceled by change of the input tag": a new trip starts
// the full delay again.
TEST(TimerBoundary, OnDelayRestartsAfterCancel) {
  Sim sim(make_matrix({timed_cause(TimeMode::OnDelay)}, {make_effect(1)}, {link(1, 1)}));
  sim.step();
  sim.set("T1_1", kTrip);
  run_to(sim, 12);  // tripped in cycles 2..12
  sim.set("T1_1", kOk);
  run_to(sim, 13);
  EXPECT_FALSE(sim.b("cause[1].timer_running"));
  sim.set("T1_1", kTrip);
  run_to(sim, 33);  // k = 14, k+19 = 33
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 34);
  EXPECT_TRUE(sim.b("cause[1].active"));
}

// Start-up: a condition holding in the first cycle starts the timer in cycle 1.
TEST(TimerBoundary, OnDelayFromStartUp) {
  Sim sim(make_matrix({timed_cause(TimeMode::OnDelay)}, {make_effect(1)}, {link(1, 1)}));
  sim.set("T1_1", kTrip);
  run_to(sim, 20);
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 21);
  EXPECT_TRUE(sim.b("cause[1].active"));
}

// 13.1.1 OFF delay: condition first unmet in cycle k: active through k+19,
// inactive in k+20.
TEST(TimerBoundary, OffDelayInactiveAtKPlus20) {
  Sim sim(make_matrix({timed_cause(TimeMode::OffDelay)}, {make_effect(1)}, {link(1, 1)}));
  sim.set("T1_1", kTrip);
  sim.step();
  EXPECT_TRUE(sim.b("cause[1].active"));  // no delay on activation
  run_to(sim, 5);
  sim.set("T1_1", kOk);
  run_to(sim, 6);  // k = 6
  EXPECT_FALSE(sim.b("cause[1].trip_requested"));
  EXPECT_TRUE(sim.b("cause[1].active"));
  EXPECT_TRUE(sim.b("cause[1].timer_running"));
  run_to(sim, 25);  // k+19
  EXPECT_TRUE(sim.b("cause[1].active"));
  run_to(sim, 26);  // k+20
  EXPECT_FALSE(sim.b("cause[1].active"));
  EXPECT_FALSE(sim.b("cause[1].timer_running"));
}

// 13.1.1 (2): "The timer of the OFF delay is canceled when the input tag
// becomes FALSE again"; the next release runs the full delay.
TEST(TimerBoundary, OffDelayCanceledByRetrip) {
  Sim sim(make_matrix({timed_cause(TimeMode::OffDelay)}, {make_effect(1)}, {link(1, 1)}));
  sim.set("T1_1", kTrip);
  run_to(sim, 2);
  sim.set("T1_1", kOk);
  run_to(sim, 12);  // released in 3..12
  sim.set("T1_1", kTrip);
  run_to(sim, 13);
  EXPECT_TRUE(sim.b("cause[1].active"));
  EXPECT_FALSE(sim.b("cause[1].timer_running"));
  sim.set("T1_1", kOk);
  run_to(sim, 33);  // k = 14, k+19 = 33
  EXPECT_TRUE(sim.b("cause[1].active"));
  run_to(sim, 34);
  EXPECT_FALSE(sim.b("cause[1].active"));
}

// 13.1.1 Timed cause: active k..k+19 whatever the input does, inactive from
// k+20, and again only on a new rising edge of the condition.
TEST(TimerBoundary, TimedCauseRunsItsTimeRegardlessOfInput) {
  Sim sim(make_matrix({timed_cause(TimeMode::Timed)}, {make_effect(1)}, {link(1, 1)}));
  sim.step();
  sim.set("T1_1", kTrip);
  run_to(sim, 2);  // k = 2
  EXPECT_TRUE(sim.b("cause[1].active"));
  sim.set("T1_1", kOk);  // a one-cycle pulse is enough
  run_to(sim, 21);       // k+19
  EXPECT_TRUE(sim.b("cause[1].active"));
  EXPECT_TRUE(sim.b("cause[1].timer_running"));
  run_to(sim, 22);  // k+20
  EXPECT_FALSE(sim.b("cause[1].active"));
}

TEST(TimerBoundary, TimedCauseNeedsANewRisingEdge) {
  Sim sim(make_matrix({timed_cause(TimeMode::Timed)}, {make_effect(1)}, {link(1, 1)}));
  sim.step();
  sim.set("T1_1", kTrip);
  run_to(sim, 21);  // held tripped from k = 2
  EXPECT_TRUE(sim.b("cause[1].active"));
  run_to(sim, 22);
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 40);  // still held: no restart
  EXPECT_FALSE(sim.b("cause[1].active"));
  sim.set("T1_1", kOk);
  run_to(sim, 41);
  sim.set("T1_1", kTrip);
  run_to(sim, 42);  // new edge, k' = 42
  EXPECT_TRUE(sim.b("cause[1].active"));
  run_to(sim, 61);
  EXPECT_TRUE(sim.b("cause[1].active"));
  run_to(sim, 62);
  EXPECT_FALSE(sim.b("cause[1].active"));
}

// 6.4.5 / 13.2.2 output delay: the effect is active at once, its output tag
// follows in k+20.
TEST(TimerBoundary, OutputDelayChangesTheTagAtKPlus20) {
  Effect e = make_effect(1);
  e.output_delay_ms = 2000;
  Sim sim(make_matrix({make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt)}, {e}, {link(1, 1)}));
  sim.step();
  sim.set("T1_1", kTrip);
  run_to(sim, 2);  // k = 2
  EXPECT_TRUE(sim.b("effect[1].active"));
  EXPECT_TRUE(sim.b("effect[1].output_delay_running"));
  EXPECT_EQ(sim.out("Y1_1"), 1);
  run_to(sim, 21);  // k+19
  EXPECT_EQ(sim.out("Y1_1"), 1);
  EXPECT_EQ(sim.get("effect[1].tag[1]"), 1);
  EXPECT_TRUE(sim.b("effect[1].output_delay_running"));
  run_to(sim, 22);  // k+20
  EXPECT_EQ(sim.out("Y1_1"), 0);
  EXPECT_EQ(sim.get("effect[1].tag[1]"), 0);
  EXPECT_FALSE(sim.b("effect[1].output_delay_running"));
  // "returns at once when it goes inactive"
  sim.set("T1_1", kOk);
  run_to(sim, 23);
  EXPECT_FALSE(sim.b("effect[1].active"));
  EXPECT_EQ(sim.out("Y1_1"), 1);
}

// 6.4.5: in the first cycle after start-up the output delay does not apply.
TEST(TimerBoundary, OutputDelayNotAppliedInTheFirstCycle) {
  Effect e = make_effect(1);
  e.output_delay_ms = 2000;
  Sim sim(make_matrix({make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt)}, {e}, {link(1, 1)}));
  sim.set("T1_1", kTrip);
  sim.step();
  EXPECT_TRUE(sim.b("effect[1].active"));
  EXPECT_EQ(sim.out("Y1_1"), 0);
}

Matrix override_matrix(IntersectionType t) {
  Effect e = make_effect(1);
  e.override_time = Override{2, 1};  // max 2 s, prealarm 1 s
  return make_matrix({make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt)}, {e}, {link(1, 1, t)});
}

// 13.2.1 V: "The timer is automatically stopped as soon as the maximum
// override time has been reached" with the time-out alarm (3); the prealarm
// follows the same convention at 1 s.
TEST(TimerBoundary, OverrideTimeAndPrealarm) {
  for (auto type : {IntersectionType::V, IntersectionType::R}) {
    SCOPED_TRACE(to_string(type));
    Sim sim(override_matrix(type));
    sim.step();
    sim.set("T1_1", kTrip);
    run_to(sim, 2);
    EXPECT_TRUE(sim.b("effect[1].active"));
    sim.cmd(command(CommandOp::OverrideEffect, 0, 1));
    run_to(sim, 3);  // override starts, k = 3
    EXPECT_TRUE(sim.b("effect[1].override_active"));
    EXPECT_FALSE(sim.b("effect[1].active"));
    EXPECT_EQ(sim.out("Y1_1"), 1);
    run_to(sim, 12);  // k+9
    EXPECT_FALSE(sim.b("effect[1].override_prealarm"));
    run_to(sim, 13);  // k+10
    EXPECT_TRUE(sim.b("effect[1].override_prealarm"));
    run_to(sim, 22);  // k+19
    EXPECT_TRUE(sim.b("effect[1].override_active"));
    EXPECT_FALSE(sim.b("effect[1].active"));
    EXPECT_FALSE(sim.b("effect[1].override_failed_timeout"));
    run_to(sim, 23);  // k+20
    EXPECT_FALSE(sim.b("effect[1].override_active"));
    EXPECT_TRUE(sim.b("effect[1].override_failed_timeout"));
    EXPECT_TRUE(sim.b("effect[1].active"));
    EXPECT_EQ(sim.out("Y1_1"), 0);
  }
}

// 6.3.6 / 13.1.3: a timed soft bypass "is then removed automatically when the
// configured time has elapsed", with the bypass-timeout alarm; prealarm at 1 s.
TEST(TimerBoundary, TimedSoftBypassOfACauseAndPrealarm) {
  Cause c = make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt);
  c.soft_bypass = {true, 2, 1};
  Sim sim(make_matrix({c}, {make_effect(1)}, {link(1, 1)}));
  sim.set("T1_1", kTrip);
  sim.step();
  EXPECT_TRUE(sim.b("cause[1].active"));
  sim.cmd(command(CommandOp::SoftBypassCause, 1, 0, 0, true));
  run_to(sim, 2);  // k = 2
  EXPECT_TRUE(sim.b("cause[1].soft_bypassed"));
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 11);  // k+9
  EXPECT_FALSE(sim.b("cause[1].bypass_prealarm"));
  run_to(sim, 12);  // k+10
  EXPECT_TRUE(sim.b("cause[1].bypass_prealarm"));
  run_to(sim, 21);  // k+19
  EXPECT_TRUE(sim.b("cause[1].soft_bypassed"));
  EXPECT_FALSE(sim.b("cause[1].active"));
  EXPECT_FALSE(sim.b("cause[1].bypass_timeout"));
  run_to(sim, 22);  // k+20
  EXPECT_FALSE(sim.b("cause[1].soft_bypassed"));
  EXPECT_TRUE(sim.b("cause[1].bypass_timeout"));
  EXPECT_TRUE(sim.b("cause[1].active"));
}

// The timers count whole cycles of cycle_ms: at 50 ms cycles a 2000 ms ON
// delay takes 40 cycles.
TEST(TimerBoundary, DurationsScaleWithCycleTime) {
  Matrix m = make_matrix({timed_cause(TimeMode::OnDelay)}, {make_effect(1)}, {link(1, 1)}, 50);
  Sim sim(m);
  sim.step();
  sim.set("T1_1", kTrip);
  run_to(sim, 41);  // k = 2, k+39
  EXPECT_FALSE(sim.b("cause[1].active"));
  run_to(sim, 42);
  EXPECT_TRUE(sim.b("cause[1].active"));
}

}  // namespace
}  // namespace cemv::testing
