// Unit tests of the reference runtime against the fixed decisions of
// docs/semantics.md (the paragraphs marked "fixed"), through the public API only. Paragraph numbers refer to
// docs/semantics.md. Matrices are built in C++ so that each test shows exactly
// the options it exercises.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"
#include "runtime/runtime.hpp"

// The allocation counter of test_runtime_unit_alloc.cpp.
namespace cemv_test {
long allocation_count();
}

namespace {

using namespace cemv;
using model::CauseFunction;
using model::Command;
using model::CommandOp;
using model::IntersectionType;
using model::Voting;

// ---- building matrices ------------------------------------------------------

model::Cause discrete_cause(int id, std::vector<std::string> tags,
                            CauseFunction f = CauseFunction::Normal) {
  model::Cause c;
  c.id = id;
  c.name = "C" + std::to_string(id);
  c.function = f;
  for (auto& t : tags) c.tags.push_back(model::CauseTag{t, false, true});
  return c;
}

model::Cause analog_cause(int id, std::vector<std::string> tags, CauseFunction f, float limit,
                          float hysteresis, model::LimitType type = model::LimitType::High) {
  model::Cause c = discrete_cause(id, std::move(tags), f);
  c.input = model::InputKind::Analog;
  model::AnalogParams a;
  a.limit_type = type;
  a.limit = limit;
  a.hysteresis = hysteresis;
  c.analog = a;
  return c;
}

model::Effect effect(int id, std::vector<std::string> tags) {
  model::Effect e;
  e.id = id;
  e.name = "E" + std::to_string(id);
  for (auto& t : tags) e.tags.push_back(model::EffectTag{t, false});
  return e;
}

model::Intersection cell(int cause, int effect, IntersectionType t = IntersectionType::N,
                         std::optional<int> xoon = std::nullopt) {
  model::Intersection x;
  x.cause = cause;
  x.effect = effect;
  x.type = t;
  x.xoon = xoon;
  return x;
}

model::Matrix matrix(std::vector<model::Cause> causes, std::vector<model::Effect> effects = {},
                     std::vector<model::Intersection> cells = {}) {
  model::Matrix m;
  m.name = "T";
  m.cycle_ms = 100;
  m.causes = std::move(causes);
  m.effects = std::move(effects);
  m.intersections = std::move(cells);
  m.sort_by_id();
  return m;
}

// ---- driving the runtime -------------------------------------------------------

class Plant {
 public:
  explicit Plant(const model::Matrix& m) : rt_(m), in_(rt_.default_input()) {}

  void set(const std::string& tag, float value, bool bad = false) {
    auto idx = rt_.inputs().find(tag);
    ASSERT_TRUE(idx.has_value()) << "no input tag " << tag;
    in_.tags[*idx] = model::TagValue{value, bad};
  }
  void command(Command c) { in_.commands.push_back(std::move(c)); }
  // Runs n cycles; commands apply to the first of them only.
  void run(int n = 1) {
    for (int i = 0; i < n; ++i) {
      rt_.step(in_);
      last_refused_ = rt_.commands_refused();
      in_.commands.clear();
    }
  }
  int cause(int id, const char* field) const { return rt_.value(obs(model::Node::Kind::Cause, id, field)); }
  int effect(int id, const char* field) const {
    return rt_.value(obs(model::Node::Kind::Effect, id, field));
  }
  bool active(int cause_id) const { return cause(cause_id, "active") != 0; }
  bool effect_active(int id) const { return effect(id, "active") != 0; }
  bool out(const std::string& tag) const { return rt_.output(tag).value(); }
  int refused() const { return last_refused_; }
  std::uint64_t cycle() const { return rt_.cycles_run(); }
  runtime::Runtime& rt() { return rt_; }
  model::CycleInput& input() { return in_; }

 private:
  static model::Observable obs(model::Node::Kind kind, int id, const char* field) {
    model::Observable o;
    o.kind = kind;
    o.id = id;
    o.field = field;
    o.key = field;
    return o;
  }
  runtime::Runtime rt_;
  model::CycleInput in_;
  int last_refused_ = 0;
};

Command cmd(CommandOp op) {
  Command c;
  c.op = op;
  return c;
}
Command cause_cmd(CommandOp op, int cause, bool on = true, int tag = 0) {
  Command c = cmd(op);
  c.cause = cause;
  c.on = on;
  c.tag = tag;
  return c;
}
Command effect_cmd(CommandOp op, int effect, bool on = true) {
  Command c = cmd(op);
  c.effect = effect;
  c.on = on;
  return c;
}
Command simulate(const std::string& tag, float value) {
  Command c = cmd(CommandOp::SimulateTag);
  c.tag_name = tag;
  c.value = value;
  return c;
}

// ---- T.2 / C.6 timers -----------------------------------------------------------

model::Matrix timed_cause(model::TimeMode mode, std::uint32_t ms) {
  model::Cause c = discrete_cause(1, {"A"});
  c.time = {mode, ms};
  return matrix({c});
}

TEST(Timers, OnDelayActiveAtKPlus20NotBefore) {
  Plant p(timed_cause(model::TimeMode::OnDelay, 2000));
  p.run(3);
  p.set("A", 0);  // DTT: tripped; condition first met in cycle k = 4
  p.run();
  EXPECT_EQ(p.cycle(), 4u);
  EXPECT_TRUE(p.cause(1, "trip_requested"));
  EXPECT_TRUE(p.cause(1, "timer_running"));
  EXPECT_FALSE(p.active(1));
  p.run(18);  // k + 18
  EXPECT_FALSE(p.active(1));
  p.run();  // k + 19
  EXPECT_FALSE(p.active(1));
  EXPECT_TRUE(p.cause(1, "timer_running"));
  p.run();  // k + 20
  EXPECT_TRUE(p.active(1));
  EXPECT_FALSE(p.cause(1, "timer_running"));
}

TEST(Timers, OnDelayIsCancelledByTheCondition) {
  Plant p(timed_cause(model::TimeMode::OnDelay, 2000));
  p.set("A", 0);
  p.run(10);
  p.set("A", 1);  // interrupted: the timer restarts at the next trip
  p.run();
  EXPECT_FALSE(p.cause(1, "timer_running"));
  p.set("A", 0);
  p.run(20);  // started again 20 cycles ago: elapsed 19 cycles
  EXPECT_FALSE(p.active(1));
  p.run();
  EXPECT_TRUE(p.active(1));
}

TEST(Timers, OnDelayStartsInTheFirstCycle) {
  Plant p(timed_cause(model::TimeMode::OnDelay, 2000));
  p.set("A", 0);
  p.run(20);  // cycles 1..20: elapsed 19
  EXPECT_FALSE(p.active(1));
  p.run();  // cycle 21 = 1 + 20
  EXPECT_TRUE(p.active(1));
}

TEST(Timers, DurationsRoundUpToWholeCycles) {
  Plant p(timed_cause(model::TimeMode::OnDelay, 150));  // ceil(150 / 100) = 2 cycles
  p.set("A", 0);
  p.run(2);
  EXPECT_FALSE(p.active(1));
  p.run();
  EXPECT_TRUE(p.active(1));
}

TEST(Timers, OffDelayActiveThroughKPlus19) {
  Plant p(timed_cause(model::TimeMode::OffDelay, 2000));
  p.set("A", 0);
  p.run(5);
  EXPECT_TRUE(p.active(1));
  p.set("A", 1);  // condition first unmet in cycle k
  p.run();
  EXPECT_TRUE(p.active(1));
  EXPECT_TRUE(p.cause(1, "timer_running"));
  EXPECT_FALSE(p.cause(1, "trip_requested"));
  p.run(19);  // k + 19
  EXPECT_TRUE(p.active(1));
  p.run();  // k + 20
  EXPECT_FALSE(p.active(1));
  EXPECT_FALSE(p.cause(1, "timer_running"));
}

TEST(Timers, OffDelayIsCancelledWhenTheConditionReturns) {
  Plant p(timed_cause(model::TimeMode::OffDelay, 2000));
  p.set("A", 0);
  p.run();
  p.set("A", 1);
  p.run(10);
  p.set("A", 0);
  p.run();
  EXPECT_FALSE(p.cause(1, "timer_running"));
  p.set("A", 1);
  p.run(20);  // a fresh off delay: elapsed 19
  EXPECT_TRUE(p.active(1));
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Timers, OffDelayDoesNotHoldACauseThatWasNeverActive) {
  Plant p(timed_cause(model::TimeMode::OffDelay, 2000));
  p.run(3);
  EXPECT_FALSE(p.active(1));
  EXPECT_FALSE(p.cause(1, "timer_running"));
}

TEST(Timers, TimedCauseRunsForItsDurationWhateverTheInput) {
  Plant p(timed_cause(model::TimeMode::Timed, 2000));
  p.run(2);
  p.set("A", 0);  // rising edge in cycle k
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 1);  // the input returns at once: no effect on the timed cause
  p.run(10);
  p.set("A", 0);  // a new edge while running is ignored
  p.run(9);       // k + 19
  EXPECT_TRUE(p.active(1));
  EXPECT_TRUE(p.cause(1, "timer_running"));
  p.run();  // k + 20: inactive although the condition holds
  EXPECT_FALSE(p.active(1));
  p.run(30);  // held condition: no new edge, stays inactive
  EXPECT_FALSE(p.active(1));
  p.set("A", 1);
  p.run();
  p.set("A", 0);  // new rising edge: starts again
  p.run();
  EXPECT_TRUE(p.active(1));
}

// ---- C.4 voting and hysteresis ---------------------------------------------------

TEST(Hysteresis, TwoOutOfThreeHighExampleOfC4) {
  Plant p(matrix({analog_cause(1, {"A", "B", "C"}, CauseFunction::TwoOoThree, 90.0f, 5.0f)}));
  p.set("A", 95);
  p.set("B", 95);
  p.set("C", 87);
  p.run();
  EXPECT_TRUE(p.active(1));
  EXPECT_EQ(p.cause(1, "tripped_tags"), 2);
  EXPECT_FALSE(p.cause(1, "hysteresis_active"));
  p.set("B", 84);
  p.run();
  EXPECT_TRUE(p.active(1));  // two tags >= 85
  EXPECT_EQ(p.cause(1, "tripped_tags"), 2);
  EXPECT_TRUE(p.cause(1, "hysteresis_active"));
  p.set("C", 80);
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_FALSE(p.cause(1, "hysteresis_active"));
}

TEST(Hysteresis, ThresholdsAreComparedInclusively) {
  Plant p(matrix({analog_cause(1, {"A"}, CauseFunction::Normal, 90.0f, 5.0f)}));
  p.set("A", 89.99f);
  p.run();
  EXPECT_FALSE(p.active(1));
  p.set("A", 90.0f);  // value >= limit trips
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 85.0f);  // value >= limit - hysteresis holds
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 84.99f);
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Hysteresis, LowLimit) {
  Plant p(matrix({analog_cause(1, {"A"}, CauseFunction::Normal, 10.0f, 2.0f, model::LimitType::Low)}));
  p.set("A", 10.0f);
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 12.0f);
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 12.01f);
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Hysteresis, AndOfTwoHighGoesInactiveWhenOneUndershoots_Erratum) {
  Plant p(matrix({analog_cause(1, {"A", "B"}, CauseFunction::And, 90.0f, 5.0f)}));
  p.set("A", 95);
  p.set("B", 95);
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("B", 80);  // one of the two below limit - hysteresis
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Hysteresis, OrOfTwoHighStaysUntilBothUndershoot) {
  Plant p(matrix({analog_cause(1, {"A", "B"}, CauseFunction::Or, 90.0f, 5.0f)}));
  p.set("A", 95);
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 86);
  p.run();
  EXPECT_TRUE(p.active(1));
  p.set("A", 80);
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Voting, DiscreteFunctionsAndEtt) {
  model::Cause c = discrete_cause(1, {"A", "B", "C"}, CauseFunction::TwoOoThree);
  c.tags[2].ett = true;  // C trips on TRUE
  Plant p(matrix({c}));
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::TwoOoThree));
  p.set("A", 0);
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_EQ(p.cause(1, "tripped_tags"), 1);
  p.set("C", 1);
  p.run();
  EXPECT_TRUE(p.active(1));
  EXPECT_EQ(p.cause(1, "tripped_tags"), 2);
}

// ---- C.3 / C.4 bad quality and degraded voting -----------------------------------

TEST(DegradedVoting, TwoOutOfThreeMinusOneIsOneOutOfTwo) {
  model::Cause c = discrete_cause(1, {"A", "B", "C"}, CauseFunction::TwoOoThree);
  c.bad_quality = model::BadQuality::Degrade;
  Plant p(matrix({c}));
  p.set("C", 1, true);  // bad quality: taken out
  p.run();
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::OneOoTwo));
  EXPECT_TRUE(p.cause(1, "degraded"));
  EXPECT_FALSE(p.active(1));
  p.set("B", 0);
  p.run();
  EXPECT_TRUE(p.active(1));
  EXPECT_EQ(p.cause(1, "tripped_tags"), 1);
  p.set("B", 0, true);  // two taken out: 1oo1 on A
  p.run();
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::OneOoOne));
  EXPECT_FALSE(p.active(1));
  p.set("A", 1, true);  // all taken out, for bad quality: (1oo1) trips
  p.run();
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::OneOoOne));
  EXPECT_TRUE(p.active(1));
}

TEST(DegradedVoting, AllSoftBypassedIsBypassAndInactive) {
  model::Cause c = discrete_cause(1, {"A", "B"}, CauseFunction::Or);
  Plant p(matrix({c}));
  p.set("A", 0);
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 1));
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::OneOoOne));
  EXPECT_FALSE(p.active(1));  // the tripped tag is out of the voting
  EXPECT_EQ(p.cause(1, "tripped_tags"), 0);
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 2));
  p.run();
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::Bypass));
  EXPECT_TRUE(p.cause(1, "degraded"));
  EXPECT_FALSE(p.active(1));
}

TEST(DegradedVoting, AndOfThreeErrataOfB5Table2) {
  model::Cause c = discrete_cause(1, {"A", "B", "C"}, CauseFunction::And);
  c.bad_quality = model::BadQuality::Degrade;
  // Case 5: not tripped, tripped, tripped -> 3oo3, inactive (erratum).
  {
    Plant p(matrix({c}));
    p.set("B", 0);
    p.set("C", 0);
    p.run();
    EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::ThreeOoThree));
    EXPECT_FALSE(p.active(1));
  }
  // Case 6: not tripped, tripped, bad quality -> 2oo2, inactive (erratum).
  {
    Plant p(matrix({c}));
    p.set("B", 0);
    p.set("C", 1, true);
    p.run();
    EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::TwoOoTwo));
    EXPECT_FALSE(p.active(1));
  }
  // Case 7: not tripped, tripped, bypass -> 2oo2, inactive (erratum).
  {
    Plant p(matrix({c}));
    p.set("B", 0);
    p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 3));
    p.run();
    EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::TwoOoTwo));
    EXPECT_FALSE(p.active(1));
  }
  // Case 12: tripped, tripped, bad quality -> 2oo2, active (as printed).
  {
    Plant p(matrix({c}));
    p.set("A", 0);
    p.set("B", 0);
    p.set("C", 1, true);
    p.run();
    EXPECT_TRUE(p.active(1));
  }
}

TEST(BadQuality, TripAndIgnore) {
  model::Cause trip = discrete_cause(1, {"A"});
  model::Cause ignore = discrete_cause(2, {"B"});
  ignore.bad_quality = model::BadQuality::Ignore;
  Plant p(matrix({trip, ignore}));
  p.set("A", 1, true);
  p.set("B", 1, true);
  p.run();
  EXPECT_TRUE(p.active(1));   // trip: a bad tag counts as tripped
  EXPECT_FALSE(p.active(2));  // ignore: the value as delivered
  EXPECT_FALSE(p.cause(1, "degraded"));
  p.set("B", 0, true);  // a substitute value 0 trips a DTT tag even with ignore
  p.run();
  EXPECT_TRUE(p.active(2));
}

// ---- C.7 acknowledgement ------------------------------------------------------------

model::Matrix ack_matrix() {
  model::Cause c = discrete_cause(1, {"A"});
  c.auto_ack = false;
  c.bypass_tag = "BYP";
  return matrix({c});
}

TEST(Acknowledgement, LatchHoldsUntilAckAfterTheTripIsGone) {
  Plant p(ack_matrix());
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.active(1));
  EXPECT_TRUE(p.cause(1, "ack_required"));
  p.command(cause_cmd(CommandOp::AckCause, 1));  // trip still requested: ignored
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_TRUE(p.active(1));
  p.set("A", 1);
  p.run();  // trip gone; the earlier ack was not remembered
  EXPECT_TRUE(p.active(1));
  EXPECT_FALSE(p.cause(1, "trip_requested"));
  p.command(cause_cmd(CommandOp::AckCause, 1));
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_FALSE(p.cause(1, "ack_required"));
}

TEST(Acknowledgement, LatchPersistsThroughBypass) {
  Plant p(ack_matrix());
  p.set("A", 0);
  p.run();
  p.set("BYP", 1);
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_TRUE(p.cause(1, "bypassed"));
  p.set("A", 1);
  p.run();
  p.set("BYP", 0);
  p.run();
  EXPECT_TRUE(p.active(1));  // bypass acknowledged nothing
}

TEST(Acknowledgement, NotSetWhileBypassed) {
  Plant p(ack_matrix());
  p.set("BYP", 1);
  p.set("A", 0);
  p.run();
  EXPECT_FALSE(p.cause(1, "ack_required"));
  p.set("A", 1);
  p.run();
  p.set("BYP", 0);
  p.run();
  EXPECT_FALSE(p.active(1));
}

TEST(Acknowledgement, RefusedWithAutoAckOrOffDelay) {
  model::Cause a = discrete_cause(1, {"A"});  // auto_ack true
  model::Cause b = discrete_cause(2, {"B"});
  b.auto_ack = false;
  b.time = {model::TimeMode::OffDelay, 500};  // auto_ack has no effect
  Plant p(matrix({a, b}));
  p.command(cause_cmd(CommandOp::AckCause, 1));
  p.command(cause_cmd(CommandOp::AckCause, 2));
  p.set("B", 0);
  p.run();
  EXPECT_EQ(p.refused(), 2);
  EXPECT_FALSE(p.cause(2, "ack_required"));
  p.set("B", 1);
  p.run(5);  // off delay 5 cycles: active through +4
  EXPECT_TRUE(p.active(2));
  p.run();
  EXPECT_FALSE(p.active(2));  // no acknowledgement needed
}

// ---- C.8 bypass, inhibit ---------------------------------------------------------------

TEST(CauseBypass, InhibitAndTimedSoftBypass) {
  model::Cause c = discrete_cause(1, {"A"});
  c.inhibit_tag = "INH";
  c.soft_bypass = {true, 2, 1};  // 2 s = 20 cycles, prealarm 1 s = 10 cycles
  Plant p(matrix({c}));
  p.set("A", 0);
  p.set("INH", 1);
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_TRUE(p.cause(1, "inhibited"));
  p.set("INH", 0);
  p.command(cause_cmd(CommandOp::SoftBypassCause, 1, true));  // started in cycle s
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_TRUE(p.cause(1, "soft_bypassed"));
  EXPECT_TRUE(p.cause(1, "bypassed"));
  p.run(9);  // s + 9
  EXPECT_FALSE(p.cause(1, "bypass_prealarm"));
  p.run();  // s + 10
  EXPECT_TRUE(p.cause(1, "bypass_prealarm"));
  p.run(9);  // s + 19
  EXPECT_TRUE(p.cause(1, "soft_bypassed"));
  EXPECT_FALSE(p.active(1));
  p.run();  // s + 20: removed, alarm
  EXPECT_FALSE(p.cause(1, "soft_bypassed"));
  EXPECT_TRUE(p.cause(1, "bypass_timeout"));
  EXPECT_FALSE(p.cause(1, "bypass_prealarm"));
  EXPECT_TRUE(p.active(1));
  p.run(3);
  EXPECT_TRUE(p.cause(1, "bypass_timeout"));
  p.command(cause_cmd(CommandOp::ClearAlarms, 1));
  p.run();
  EXPECT_FALSE(p.cause(1, "bypass_timeout"));
}

TEST(CauseBypass, SoftBypassRefusedWhenNotAllowed) {
  model::Cause c = discrete_cause(1, {"A", "B"}, CauseFunction::Or);
  c.soft_bypass.allowed = false;
  c.tags[1].soft_bypass_allowed = false;
  Plant p(matrix({c}));
  p.command(cause_cmd(CommandOp::SoftBypassCause, 1, true));
  p.command(cause_cmd(CommandOp::SoftBypassCause, 1, false));
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 2));
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 3));  // no third tag
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 1));  // allowed
  p.run();
  EXPECT_EQ(p.refused(), 4);
  EXPECT_FALSE(p.cause(1, "soft_bypassed"));
  EXPECT_TRUE(p.cause(1, "degraded"));
}

// ---- C.5 delta and prewarning ----------------------------------------------------------

TEST(AnalogStatus, DeltaAlarmWithHysteresisAndPrewarning) {
  model::Cause c = analog_cause(1, {"A", "B"}, CauseFunction::Or, 90.0f, 2.0f);
  c.analog->delta = 5.0f;
  c.analog->prewarning = 80.0f;
  Plant p(matrix({c}));
  p.set("A", 50);
  p.set("B", 55);
  p.run();
  EXPECT_TRUE(p.cause(1, "delta_alarm"));
  EXPECT_FALSE(p.cause(1, "prewarning"));
  p.set("B", 53);  // 3 is not < 5 - 2: stays
  p.run();
  EXPECT_TRUE(p.cause(1, "delta_alarm"));
  p.set("B", 52.5f);
  p.run();
  EXPECT_FALSE(p.cause(1, "delta_alarm"));
  p.set("B", 80);
  p.run();
  EXPECT_TRUE(p.cause(1, "prewarning"));
  EXPECT_FALSE(p.active(1));  // status only
  EXPECT_TRUE(p.cause(1, "delta_alarm"));
}

// ---- C.11 first out --------------------------------------------------------------------

TEST(FirstOut, LowestIdAmongThoseThatBecameActiveTogether) {
  std::vector<model::Cause> cs;
  for (int id = 1; id <= 3; ++id) {
    cs.push_back(discrete_cause(id, {"T" + std::to_string(id)}));
    cs.back().first_out_group = 4;
  }
  Plant p(matrix(cs));
  p.run();
  p.set("T3", 0);
  p.set("T2", 0);
  p.run();
  EXPECT_TRUE(p.cause(2, "first_out"));
  EXPECT_FALSE(p.cause(3, "first_out"));
  p.set("T1", 0);
  p.run();
  EXPECT_FALSE(p.cause(1, "first_out"));
  Command clear = cmd(CommandOp::ClearFirstOut);
  clear.group = 4;
  p.command(clear);
  p.run();
  EXPECT_FALSE(p.cause(2, "first_out"));
  EXPECT_FALSE(p.cause(1, "first_out"));  // still active, did not become active
  p.set("T3", 1);
  p.run();
  p.set("T3", 0);
  p.run();
  EXPECT_TRUE(p.cause(3, "first_out"));
}

TEST(FirstOut, FirstCycleCounts) {
  model::Cause c = discrete_cause(1, {"A"});
  c.first_out_group = 1;
  Plant p(matrix({c}));
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.cause(1, "first_out"));
}

// ---- E.2 XooN ------------------------------------------------------------------------------

TEST(Effects, XooNAssignmentAndDirectIntersection) {
  std::vector<model::Cause> cs;
  for (int id = 1; id <= 4; ++id) cs.push_back(discrete_cause(id, {"T" + std::to_string(id)}));
  Plant p(matrix(cs, {effect(1, {"Y"})},
                 {cell(1, 1, IntersectionType::N, 2), cell(2, 1, IntersectionType::N, 2),
                  cell(3, 1, IntersectionType::N, 2), cell(4, 1)}));
  p.run();
  EXPECT_TRUE(p.out("Y"));  // DTT: 1 while inactive
  p.set("T1", 0);
  p.run();
  EXPECT_FALSE(p.effect_active(1));  // 1 of 3
  p.set("T3", 0);
  p.run();
  EXPECT_TRUE(p.effect_active(1));  // 2 of 3
  EXPECT_FALSE(p.out("Y"));
  p.set("T1", 1);
  p.set("T3", 1);
  p.set("T4", 0);  // the intersection outside the XooN acts alone
  p.run();
  EXPECT_TRUE(p.effect_active(1));
}

// ---- E.4 / E.5 S and R latches -----------------------------------------------------------

TEST(Effects, StoredLatchResetByRisingEdgeOnly) {
  model::Effect e = effect(1, {"Y"});
  e.reset_tag = "RST";
  Plant p(matrix({discrete_cause(1, {"A"})}, {e}, {cell(1, 1, IntersectionType::S)}));
  p.set("A", 0);
  p.set("RST", 1);  // held during start-up: no edge
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  EXPECT_TRUE(p.effect(1, "latched"));
  p.set("A", 1);
  p.run();
  EXPECT_TRUE(p.effect_active(1));  // RST still TRUE: no edge, no reset
  EXPECT_TRUE(p.effect(1, "ok_to_reset"));
  p.set("RST", 0);
  p.run();
  p.set("RST", 1);
  p.run();
  EXPECT_FALSE(p.effect_active(1));
  EXPECT_FALSE(p.effect(1, "latched"));
}

TEST(Effects, ResetHasNoEffectWhileTheCauseIsActive) {
  Plant p(matrix({discrete_cause(1, {"A"})}, {effect(1, {"Y"})}, {cell(1, 1, IntersectionType::S)}));
  p.set("A", 0);
  p.run();
  p.command(effect_cmd(CommandOp::ResetEffect, 1));
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_FALSE(p.effect(1, "ok_to_reset"));
  p.set("A", 1);
  p.run();
  EXPECT_TRUE(p.effect_active(1));  // the earlier reset was not remembered
  p.command(effect_cmd(CommandOp::ResetEffect, 1));
  p.run();
  EXPECT_FALSE(p.effect_active(1));
}

TEST(Effects, OperatorResetRefusedWithResetTagOrWithoutLatch) {
  model::Effect tagged = effect(1, {"Y1"});
  tagged.reset_tag = "RST";
  Plant p(matrix({discrete_cause(1, {"A"})}, {tagged, effect(2, {"Y2"})},
                 {cell(1, 1, IntersectionType::S), cell(1, 2, IntersectionType::N)}));
  p.command(effect_cmd(CommandOp::ResetEffect, 1));
  p.command(effect_cmd(CommandOp::ResetEffect, 2));
  p.command(effect_cmd(CommandOp::ResetEffect, 99));
  p.run();
  EXPECT_EQ(p.refused(), 3);
}

// ---- E.3 override -------------------------------------------------------------------------

model::Matrix override_matrix(IntersectionType type) {
  model::Effect e = effect(1, {"Y"});
  e.override_time = model::Override{10, 8};  // 100 cycles, prealarm at 80
  e.bypass_tag = "EBYP";
  return matrix({discrete_cause(1, {"A"}), discrete_cause(2, {"B"})}, {e},
                {cell(1, 1, type), cell(2, 1, IntersectionType::N)});
}

TEST(Override, StartPrealarmTimeoutAndClear) {
  Plant p(override_matrix(IntersectionType::V));
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));  // started in cycle s
  p.run();
  EXPECT_TRUE(p.effect(1, "override_active"));
  EXPECT_FALSE(p.effect_active(1));
  EXPECT_TRUE(p.out("Y"));
  p.run(79);  // s + 79
  EXPECT_FALSE(p.effect(1, "override_prealarm"));
  p.run();  // s + 80
  EXPECT_TRUE(p.effect(1, "override_prealarm"));
  p.run(19);  // s + 99
  EXPECT_TRUE(p.effect(1, "override_active"));
  p.run();  // s + 100: timeout
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect(1, "override_failed_timeout"));
  EXPECT_TRUE(p.effect_active(1));
  p.command(effect_cmd(CommandOp::ClearAlarms, 1));
  p.run();
  EXPECT_FALSE(p.effect(1, "override_failed_timeout"));
}

TEST(Override, NewCauseEndsItWithAlarm) {
  Plant p(override_matrix(IntersectionType::V));
  p.set("A", 0);
  p.run();
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run(5);
  EXPECT_TRUE(p.effect(1, "override_active"));
  p.set("B", 0);  // a linked cause that was not active at the start
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect(1, "override_failed_cause"));
  EXPECT_TRUE(p.effect_active(1));
}

TEST(Override, EndsWhenTheCauseGoesAndStopToggles) {
  Plant p(override_matrix(IntersectionType::V));
  p.set("A", 0);
  p.run();
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  p.command(effect_cmd(CommandOp::StopOverride, 1));
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect_active(1));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  EXPECT_TRUE(p.effect(1, "override_active"));
  p.set("A", 1);
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_FALSE(p.effect(1, "override_failed_timeout"));
  EXPECT_FALSE(p.effect(1, "override_failed_cause"));
  EXPECT_FALSE(p.effect_active(1));
}

TEST(Override, CannotStartWhileBypassedOrWithoutRequest) {
  Plant p(override_matrix(IntersectionType::V));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));  // no request: nothing to override
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  p.set("A", 0);
  p.set("EBYP", 1);
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect(1, "bypassed"));
}

TEST(Override, ResettableLatchNeedsNoResetWhenTheCauseGoesDuringOverride) {
  Plant p(override_matrix(IntersectionType::R));
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.effect(1, "latched"));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  EXPECT_FALSE(p.effect_active(1));
  p.set("A", 1);
  p.run();
  EXPECT_FALSE(p.effect(1, "latched"));
  EXPECT_FALSE(p.effect_active(1));
  EXPECT_FALSE(p.effect(1, "override_active"));
}

TEST(Override, ResettableLatchClearedWhenGroupDeactivationAndCauseEndCoincide) {
  // E.5: `was_running` is the state at the end of the previous cycle.
  model::Matrix m = override_matrix(IntersectionType::R);
  m.group_deactivation = model::GroupDeactivation{"EN_GDM", "SET_GDM"};
  Plant p(m);
  p.set("A", 0);
  p.set("EN_GDM", 1);
  p.run();
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  EXPECT_TRUE(p.effect(1, "override_active"));
  p.set("A", 1);
  p.set("SET_GDM", 1);
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_FALSE(p.effect(1, "latched"));
  EXPECT_FALSE(p.effect_active(1));
}

TEST(Override, ResettableLatchWithoutOverrideNeedsReset) {
  Plant p(override_matrix(IntersectionType::R));
  p.set("A", 0);
  p.run();
  p.set("A", 1);
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  EXPECT_TRUE(p.effect(1, "ok_to_reset"));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));  // nothing to override: a reset
  p.run();
  EXPECT_FALSE(p.effect_active(1));
}

TEST(Override, ResetTagEdgeTogglesOverride) {
  model::Matrix m = override_matrix(IntersectionType::V);
  m.effects[0].reset_tag = "RST";
  Plant p(m);
  p.set("A", 0);
  p.run();
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));  // refused: a reset tag is configured
  p.set("RST", 1);
  p.run();
  EXPECT_EQ(p.refused(), 1);
  EXPECT_TRUE(p.effect(1, "override_active"));
  p.set("RST", 0);
  p.run();
  p.set("RST", 1);
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect_active(1));
}

// ---- E.7 output delay ------------------------------------------------------------------------

model::Matrix delayed_matrix() {
  model::Effect e = effect(1, {"Y"});
  e.output_delay_ms = 1000;  // 10 cycles
  e.bypass_tag = "EBYP";
  return matrix({discrete_cause(1, {"A"})}, {e}, {cell(1, 1)});
}

TEST(OutputDelay, NotAppliedInTheFirstCycle) {
  Plant p(delayed_matrix());
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  EXPECT_FALSE(p.out("Y"));
  EXPECT_FALSE(p.effect(1, "output_delay_running"));
}

TEST(OutputDelay, OutputsFollowAfterTheDelayAndReturnAtOnce) {
  Plant p(delayed_matrix());
  p.run(2);
  p.set("A", 0);  // active in cycle k
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  EXPECT_TRUE(p.out("Y"));
  EXPECT_TRUE(p.effect(1, "output_delay_running"));
  p.run(9);  // k + 9
  EXPECT_TRUE(p.out("Y"));
  p.run();  // k + 10
  EXPECT_FALSE(p.out("Y"));
  EXPECT_FALSE(p.effect(1, "output_delay_running"));
  p.set("A", 1);
  p.run();
  EXPECT_TRUE(p.out("Y"));
}

TEST(OutputDelay, BypassRestartsTheDelay) {
  Plant p(delayed_matrix());
  p.run();
  p.set("A", 0);
  p.run(5);
  p.set("EBYP", 1);
  p.run();
  EXPECT_FALSE(p.effect_active(1));
  p.set("EBYP", 0);  // active again in cycle j: a fresh delay
  p.run();
  EXPECT_TRUE(p.effect(1, "output_delay_running"));
  p.run(9);
  EXPECT_TRUE(p.out("Y"));
  p.run();
  EXPECT_FALSE(p.out("Y"));
}

TEST(OutputDelay, StoredEffectCannotBeResetWhileTheDelayRuns) {
  model::Matrix m = delayed_matrix();
  m.intersections[0].type = IntersectionType::S;
  Plant p(m);
  p.run();
  p.set("A", 0);
  p.run();
  p.set("A", 1);
  p.run();
  p.command(effect_cmd(CommandOp::ResetEffect, 1));
  p.run();
  EXPECT_TRUE(p.effect_active(1));  // delay still running
  p.run(8);                         // delay expires
  EXPECT_FALSE(p.effect(1, "output_delay_running"));
  EXPECT_FALSE(p.out("Y"));
  p.command(effect_cmd(CommandOp::ResetEffect, 1));
  p.run();
  EXPECT_FALSE(p.effect_active(1));
  EXPECT_TRUE(p.out("Y"));
}

// ---- E.8 / E.9 pass-through and mask -----------------------------------------------------------

struct PassMaskRow {
  bool pass_through;
  bool mask_configured;
  bool ett;
  bool effect_active;
  bool process;
  bool mask;
  bool expected;
};

// Printed in ctest's test list: a readable case, not the struct's raw bytes
// (which hold addresses and differ between runs).
void PrintTo(const PassMaskRow& r, std::ostream* os) {
  *os << "pass_through=" << r.pass_through << " mask=" << r.mask_configured << " ett=" << r.ett
      << " active=" << r.effect_active << " process=" << r.process << " mask_tag=" << r.mask;
}

class PassThroughMask : public ::testing::TestWithParam<PassMaskRow> {};

TEST_P(PassThroughMask, OutputValue) {
  const PassMaskRow r = GetParam();
  model::Effect e = effect(1, {"Y"});
  e.tags[0].ett = r.ett;
  model::ProcessData pd;
  pd.tag = "PV";
  pd.pass_through = r.pass_through;
  if (r.mask_configured) pd.mask_tag = "MASK";
  e.process_data = pd;
  Plant p(matrix({discrete_cause(1, {"A"})}, {e}, {cell(1, 1)}));
  p.set("A", r.effect_active ? 0 : 1);
  p.set("PV", r.process ? 1 : 0);
  if (r.mask_configured) p.set("MASK", r.mask ? 1 : 0);
  p.run();
  EXPECT_EQ(p.out("Y"), r.expected);
  EXPECT_EQ(p.effect(1, "masked") != 0, r.mask_configured && r.mask);
  EXPECT_EQ(p.effect(1, "pass_through_active") != 0, r.pass_through && !r.effect_active);
}

// Columns: pass, mask cfg, ett, active, process value, mask tag -> output.
INSTANTIATE_TEST_SUITE_P(
    Table13_2_5, PassThroughMask,
    ::testing::Values(
        // neither: the effect logic (DTT 0 active / 1 inactive; ETT opposite)
        PassMaskRow{false, false, false, false, false, false, true},
        PassMaskRow{false, false, false, true, true, false, false},
        PassMaskRow{false, false, true, true, false, false, true},
        // pass-through only: inactive -> process value, active -> safe value
        PassMaskRow{true, false, false, false, false, false, false},
        PassMaskRow{true, false, false, false, true, false, true},
        PassMaskRow{true, false, false, true, true, false, false},
        PassMaskRow{true, false, true, false, true, false, false},  // ETT inverts
        PassMaskRow{true, false, true, true, true, false, true},
        // mask only: mask -> process value, else logic
        PassMaskRow{false, true, false, true, true, true, true},
        PassMaskRow{false, true, false, false, false, true, false},
        PassMaskRow{false, true, false, true, true, false, false},
        PassMaskRow{false, true, false, false, false, false, true},
        PassMaskRow{false, true, true, false, true, true, false},
        // both: inactive -> process value; active -> mask ? process : safe
        PassMaskRow{true, true, false, false, false, false, false},
        PassMaskRow{true, true, false, false, true, true, true},
        PassMaskRow{true, true, false, true, true, true, true},
        PassMaskRow{true, true, false, true, true, false, false},
        PassMaskRow{true, true, true, true, true, false, true},
        PassMaskRow{true, true, true, true, false, true, true}));

// ---- I.3 / I.4 internal references -------------------------------------------------------------

TEST(References, CurrentValueDownstreamPreviousValueOnACycle) {
  // Cause 1 holds itself through Effect[1] (a cycle: read one cycle late);
  // cause 3 reads the output tag Effect[1][1] of the same cycle.
  model::Cause self = discrete_cause(1, {"Effect[1]"});
  self.tags[0].ett = true;
  model::Cause start = discrete_cause(2, {"START"});
  model::Cause follower = discrete_cause(3, {"Effect[1][1]"});  // DTT: trips when output is 0
  Plant p(matrix({self, start, follower}, {effect(1, {"Y"})}, {cell(1, 1), cell(2, 1)}));
  p.run();
  EXPECT_FALSE(p.active(1));
  EXPECT_FALSE(p.active(3));
  p.set("START", 0);
  p.run();
  EXPECT_TRUE(p.effect_active(1));
  EXPECT_TRUE(p.active(3));   // same cycle
  EXPECT_FALSE(p.active(1));  // previous cycle's Effect[1]
  p.set("START", 1);
  p.run();
  EXPECT_TRUE(p.active(1));  // now it holds the effect by itself
  EXPECT_TRUE(p.effect_active(1));
  p.run(3);
  EXPECT_TRUE(p.active(1));
}

TEST(References, CauseReferenceAsBypassTag) {
  model::Cause master = discrete_cause(1, {"M"});
  master.tags[0].ett = true;
  model::Cause slave = discrete_cause(2, {"A"});
  slave.bypass_tag = "Cause[1]";
  Plant p(matrix({master, slave}));
  p.set("A", 0);
  p.run();
  EXPECT_TRUE(p.active(2));
  p.set("M", 1);
  p.run();
  EXPECT_FALSE(p.active(2));
  EXPECT_TRUE(p.cause(2, "bypassed"));
}

// ---- M.2 / M.3 / O.* matrix level ---------------------------------------------------------------

TEST(SecureWrite, CommandsRefusedWhileEnableIsFalse) {
  model::Matrix m = matrix({discrete_cause(1, {"A"})});
  m.secure_write = model::SecureWrite{"EN_SWC"};
  Plant p(m);
  p.command(cause_cmd(CommandOp::SoftBypassCause, 1, true));
  p.run();
  EXPECT_EQ(p.refused(), 1);
  EXPECT_FALSE(p.cause(1, "soft_bypassed"));
  p.set("EN_SWC", 1);
  p.command(cause_cmd(CommandOp::SoftBypassCause, 1, true));
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_TRUE(p.cause(1, "soft_bypassed"));
}

model::Matrix maintenance_matrix() {
  model::Cause c = discrete_cause(1, {"A", "B", "C"}, CauseFunction::TwoOoThree);
  model::Effect e = effect(1, {"Y"});
  e.soft_bypass_allowed = true;
  e.override_time = model::Override{100, 0};
  model::Matrix m = matrix({c, discrete_cause(2, {"D"})}, {e},
                           {cell(1, 1), cell(2, 1, IntersectionType::V)});
  m.group_deactivation = model::GroupDeactivation{"EN_GDM", "SET_GDM"};
  return m;
}

TEST(GroupDeactivation, RisingEdgeWhileEnabledEndsAllMaintenance) {
  Plant p(maintenance_matrix());
  p.set("SET_GDM", 1);  // held at start-up: no edge
  p.set("EN_GDM", 1);
  p.set("D", 0);
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 1));
  p.command(simulate("B", 0));
  p.command(effect_cmd(CommandOp::SoftBypassEffect, 1, true));
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_TRUE(p.effect(1, "soft_bypassed"));
  EXPECT_TRUE(p.cause(1, "degraded"));
  EXPECT_TRUE(p.active(1));  // 1oo2 with simulated B tripped
  p.command(effect_cmd(CommandOp::SoftBypassEffect, 1, false));
  p.command(effect_cmd(CommandOp::OverrideEffect, 1));
  p.run();
  EXPECT_FALSE(p.effect(1, "soft_bypassed"));
  EXPECT_TRUE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.effect_active(1));  // cause 1 via N is not overridden
  p.set("SET_GDM", 0);
  p.run();
  p.set("EN_GDM", 0);
  p.set("SET_GDM", 1);  // edge without enable: nothing
  p.run();
  EXPECT_TRUE(p.effect(1, "override_active"));
  EXPECT_TRUE(p.cause(1, "degraded"));
  p.set("SET_GDM", 0);
  p.run();
  p.set("EN_GDM", 1);
  p.set("SET_GDM", 1);
  p.run();
  EXPECT_FALSE(p.effect(1, "override_active"));
  EXPECT_FALSE(p.effect(1, "override_failed_timeout"));
  EXPECT_FALSE(p.cause(1, "degraded"));
  EXPECT_FALSE(p.active(1));  // simulation of B ended: B back to its input value
}

TEST(Maintenance, MutuallyLockedAllowsOneTagAtATime) {
  model::Matrix m = maintenance_matrix();
  m.causes[0].mutually_locked_maintenance = true;
  Plant p(m);
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 1));
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 2));  // refused
  p.command(simulate("C", 0));                                 // refused
  p.command(simulate("A", 0));                                 // the same tag: allowed
  p.run();
  EXPECT_EQ(p.refused(), 2);
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, false, 1));
  p.command(cmd(CommandOp::StopSimulation));
  p.command(cause_cmd(CommandOp::SoftBypassTag, 1, true, 2));
  p.run();
  EXPECT_EQ(p.refused(), 0);
  EXPECT_EQ(p.cause(1, "voting"), static_cast<int>(Voting::OneOoTwo));
}

TEST(Simulation, InputValueAndQualityAndOutputForcing) {
  model::Cause c = discrete_cause(1, {"A"});
  Plant p(matrix({c}, {effect(1, {"Y"})}, {cell(1, 1)}));
  p.set("A", 1, true);  // bad quality trips
  p.run();
  EXPECT_TRUE(p.active(1));
  p.command(simulate("a", 1));  // case-insensitive; good quality
  p.run();
  EXPECT_FALSE(p.active(1));
  p.command(simulate("Y", 0));
  p.run();
  EXPECT_FALSE(p.out("Y"));
  EXPECT_FALSE(p.effect_active(1));
  Command stop = cmd(CommandOp::StopSimulation);
  stop.tag_name = "Y";
  p.command(stop);
  p.command(simulate("NOPE", 1));  // not a cause or effect tag
  p.run();
  EXPECT_EQ(p.refused(), 1);
  EXPECT_TRUE(p.out("Y"));
}

// ---- whole-runtime properties -----------------------------------------------------------------------

model::Matrix rich_matrix() {
  model::Matrix m = maintenance_matrix();
  m.causes[0].first_out_group = 1;
  m.causes[1].first_out_group = 1;
  m.causes[0].time = {model::TimeMode::OnDelay, 300};
  m.effects[0].output_delay_ms = 200;
  m.effects[0].process_data = model::ProcessData{"PV", true, "MASK"};
  m.secure_write = model::SecureWrite{"EN_SWC"};
  return m;
}

TEST(Runtime, NoHeapAllocationInsideStep) {
  Plant p(rich_matrix());
  p.set("EN_SWC", 1);
  p.run();
  std::vector<Command> script = {cause_cmd(CommandOp::SoftBypassTag, 1, true, 1), simulate("B", 0),
                                 effect_cmd(CommandOp::OverrideEffect, 1),
                                 cause_cmd(CommandOp::ClearAlarms, 1)};
  model::CycleInput& in = p.input();
  in.commands.reserve(8);
  const std::size_t d = *p.rt().inputs().find("D");
  long before = cemv_test::allocation_count();
  for (int i = 0; i < 50; ++i) {
    in.commands.clear();
    if (i < static_cast<int>(script.size())) in.commands.push_back(script[i]);
    in.tags[d].value = (i / 7) % 2 ? 0.0f : 1.0f;
    p.rt().step(in);
  }
  // push_back of a Command copies its std::string (short, within SSO).
  EXPECT_EQ(cemv_test::allocation_count() - before, 0);
  // The counter does count: building a runtime allocates.
  long at_construction = cemv_test::allocation_count();
  runtime::Runtime another(rich_matrix());
  EXPECT_GT(cemv_test::allocation_count(), at_construction);
}

TEST(Runtime, DeterministicSnapshotsInObservableOrder) {
  model::Matrix m = rich_matrix();
  Plant a(m), b(m);
  std::vector<int> sa, sb;
  for (int i = 0; i < 40; ++i) {
    for (Plant* p : {&a, &b}) {
      p->set("EN_SWC", 1);
      p->set("A", i % 3 ? 1 : 0);
      p->set("B", i % 5 ? 1 : 0);
      p->set("D", i % 11 < 5 ? 0 : 1);
      if (i == 10) p->command(effect_cmd(CommandOp::OverrideEffect, 1));
      p->run();
    }
    a.rt().snapshot(sa);
    b.rt().snapshot(sb);
    ASSERT_EQ(sa, sb);
  }
  auto obs = model::observables(m);
  ASSERT_EQ(sa.size(), obs.size());
  for (std::size_t i = 0; i < obs.size(); ++i) EXPECT_EQ(sa[i], a.rt().value(obs[i])) << obs[i].key;
}

TEST(Runtime, DefaultInputIsNonTripped) {
  model::Cause high = analog_cause(1, {"H"}, CauseFunction::Normal, 90.0f, 2.0f);
  model::Cause low = analog_cause(2, {"L"}, CauseFunction::Normal, 10.0f, 2.0f, model::LimitType::Low);
  model::Cause ett = discrete_cause(3, {"E"});
  ett.tags[0].ett = true;
  ett.bypass_tag = "BYP";
  Plant p(matrix({high, low, ett, discrete_cause(4, {"D"})}));
  const auto in = p.rt().default_input();
  auto value = [&](const char* tag) { return in.tags[*p.rt().inputs().find(tag)].value; };
  EXPECT_EQ(value("H"), 87.0f);
  EXPECT_EQ(value("L"), 13.0f);
  EXPECT_EQ(value("E"), 0.0f);
  EXPECT_EQ(value("D"), 1.0f);
  EXPECT_EQ(value("BYP"), 0.0f);
  p.run();
  for (int id = 1; id <= 4; ++id) EXPECT_FALSE(p.active(id)) << id;
}

TEST(Runtime, CommentElementsAreNotProcessed) {
  model::Cause comment = discrete_cause(2, {"X"}, CauseFunction::Comment);
  Plant p(matrix({discrete_cause(1, {"A"}), comment}, {effect(1, {"Y"})},
                 {cell(1, 1, IntersectionType::Note), cell(2, 1)}));
  p.set("A", 0);
  p.run();
  EXPECT_FALSE(p.effect_active(1));  // '*' is for note only
  EXPECT_FALSE(p.rt().inputs().find("X").has_value());
  EXPECT_EQ(model::observables(p.rt().matrix()).size(),
            model::cause_fields().size() + model::effect_fields().size() + 1);
}

}  // namespace
