// The runtime's explanations (runtime/explain.hpp): for every observable that
// changed in a cycle, the rule of docs/semantics.md the blocks applied; and
// the simulation permission of O.8. Each case is a short run built by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "runtime/runtime.hpp"

namespace cemv_test {
long allocation_count();
}

namespace {

using namespace cemv;
using model::CommandOp;
using model::IntersectionType;

// One cause (input IN, de-energize-to-trip) on one effect (output OUT) of
// type `t`, with a reset/override tag RST and a 2-cycle override when asked.
model::Matrix one_cell(IntersectionType t, bool reset_tag) {
  model::Matrix m;
  m.name = "T";
  m.cycle_ms = 100;
  model::Cause c;
  c.id = 1;
  c.name = "LIMIT";
  c.tags.push_back(model::CauseTag{"IN", false, true});
  c.bypass_tag = "BYP";
  m.causes.push_back(c);
  model::Effect e;
  e.id = 1;
  e.name = "STOP";
  e.tags.push_back(model::EffectTag{"OUT", false});
  if (reset_tag) e.reset_tag = "RST";
  if (t == IntersectionType::V || t == IntersectionType::R) e.override_time = model::Override{2, 0};  // 20 cycles
  m.effects.push_back(e);
  m.intersections.push_back({1, 1, t, std::nullopt, ""});
  return m;
}

// Runs frames of (IN, RST, BYP) and collects "cycle key before->after: why" lines.
struct ExplainedRun {
  model::Matrix m;
  runtime::Runtime rt;
  std::vector<model::Observable> obs;
  model::CycleInput in;
  explicit ExplainedRun(const model::Matrix& matrix) : m(matrix), rt(m), obs(model::observables(m)), in(rt.default_input()) {
    rt.explain(true);
  }
  std::vector<std::string> step(float input, float reset = 0, float bypass = 0,
                                std::vector<model::Command> commands = {}) {
    in.tags[*rt.inputs().find("IN")].value = input;
    if (auto i = rt.inputs().find("RST")) in.tags[*i].value = reset;
    in.tags[*rt.inputs().find("BYP")].value = bypass;
    in.commands = std::move(commands);
    rt.step(in);
    std::vector<std::string> out;
    for (const auto& e : rt.explanations())
      out.push_back(obs[e.observable].key + " " + std::to_string(e.before) + "->" + std::to_string(e.after) + ": " +
                    e.why);
    return out;
  }
};

std::string find(const std::vector<std::string>& lines, const std::string& key) {
  for (const auto& l : lines)
    if (l.rfind(key + " ", 0) == 0) return l;
  return "";
}

TEST(RuntimeExplain, ATripIsExplainedFromTheVotingToTheOutput) {
  ExplainedRun r(one_cell(IntersectionType::N, false));
  // Cycle 1: only the output moves, from the start-up 0 to its untripped 1.
  EXPECT_EQ(r.step(1), std::vector<std::string>{
                           "effect[1].tag[1] 0->1: output OUT = 1: the effect's output state is OFF "
                           "(de-energize-to-trip; every output reads 0 before the first cycle, T.3, E.9)"});
  EXPECT_TRUE(r.step(1).empty());  // nothing changes: nothing to explain
  auto why = r.step(0);
  EXPECT_EQ(find(why, "cause[1].active"),
            "cause[1].active 0->1: trip requested: IN = FALSE (tripped): 1 of 1 voting tags tripped, 1 needed "
            "(de-energize-to-trip: trips when FALSE) (C.3, C.4)");
  EXPECT_EQ(find(why, "effect[1].active"),
            "effect[1].active 0->1: N request: cause 1 LIMIT is active on its N intersection (E.2, E.6)");
  EXPECT_NE(find(why, "effect[1].tag[1]").find("the effect's output state turned ON: output OUT = 0"),
            std::string::npos);
  why = r.step(0, 0, 1);  // the bypass tag
  EXPECT_EQ(find(why, "cause[1].bypassed"), "cause[1].bypassed 0->1: bypass tag BYP is TRUE (C.8)");
  EXPECT_EQ(find(why, "cause[1].active"), "cause[1].active 1->0: bypassed: bypass tag BYP is TRUE (C.8)");
  EXPECT_EQ(find(why, "effect[1].active"),
            "effect[1].active 1->0: no request left: no linked cause is active (E.2, E.6)");
}

// The LSST counterexample (examples/lsst-tma, req4): an R latch cleared
// without a reset when its cause goes away during an override (E.5).
TEST(RuntimeExplain, AnRLatchClearedByTheOverrideNamesE5) {
  ExplainedRun r(one_cell(IntersectionType::R, true));
  r.step(1);
  auto why = r.step(0, 1);  // tripped, and the switch rises: the override starts
  EXPECT_EQ(find(why, "effect[1].latched"),
            "effect[1].latched 0->1: R latch set: cause 1 LIMIT is active on its R intersection (E.5)");
  EXPECT_EQ(find(why, "effect[1].override_active"),
            "effect[1].override_active 0->1: override started by the rising edge of the reset/override tag RST "
            "while a V/R trip was requested (E.3 step 2)");
  why = r.step(1, 0);
  EXPECT_EQ(find(why, "effect[1].latched"),
            "effect[1].latched 1->0: R latch cleared without a reset: its R request fell while an override was "
            "running (E.5; 13.2.1 (4))");
  EXPECT_EQ(find(why, "effect[1].override_active"),
            "effect[1].override_active 1->0: override ended: no V or R request is left (E.3 step 1c)");
}

// A toggle that finds no override to start or stop is a reset (E.3 step 2, E.4).
TEST(RuntimeExplain, AToggleWithNothingToOverrideActsAsAReset) {
  ExplainedRun r(one_cell(IntersectionType::R, true));
  r.step(1);
  r.step(0);  // R latch set
  r.step(1);  // the cause goes: the latch holds
  auto why = r.step(1, 1);
  EXPECT_EQ(find(why, "effect[1].latched"),
            "effect[1].latched 1->0: the override toggle (the rising edge of the reset/override tag RST) found no "
            "override to start or stop and acted as a reset, which cleared the R latch (E.3 step 2, E.4)");
  EXPECT_NE(find(why, "effect[1].active").find("(E.3 step 2, E.4) (E.6)"), std::string::npos);
}

// An override that ends at its maximum time and restarts in the same cycle
// keeps its value; the step is still explained (examples/lsst-tma, req7).
TEST(RuntimeExplain, AnOverrideRestartedAtItsTimeoutIsExplained) {
  ExplainedRun r(one_cell(IntersectionType::V, true));
  r.step(1);
  r.step(0, 1);  // override starts in cycle 2
  for (int i = 0; i < 19; ++i) EXPECT_TRUE(find(r.step(0, 0), "effect[1].override_active").empty());
  auto why = r.step(0, 1);  // cycle 22: 20 cycles elapsed, and the switch rises again
  EXPECT_EQ(find(why, "effect[1].override_active"),
            "effect[1].override_active 1->1: override ended: its maximum time of 2 s expired, alarm "
            "override_failed_timeout (E.3 step 1a); in the same cycle a new override started (E.3 step 2)");
}

TEST(RuntimeExplain, OperatorCommandsAreNamed) {
  model::Matrix m = one_cell(IntersectionType::S, false);
  ExplainedRun r(m);
  r.step(1);
  r.step(0);
  r.step(1);  // latched, cause gone
  model::Command reset;
  reset.op = CommandOp::ResetEffect;
  reset.effect = 1;
  auto why = r.step(1, 0, 0, {reset});
  EXPECT_EQ(find(why, "effect[1].latched"),
            "effect[1].latched 1->0: reset_effect accepted with no S/R request left: latch cleared (O.2, E.4)");
}

TEST(RuntimeExplain, OffByDefaultAndWhenSwitchedOff) {
  model::Matrix m = one_cell(IntersectionType::N, false);
  runtime::Runtime rt(m);
  model::CycleInput in = rt.default_input();
  in.tags[*rt.inputs().find("IN")].value = 0;
  rt.step(in);
  EXPECT_TRUE(rt.explanations().empty());
  rt.explain(true);
  in.tags[*rt.inputs().find("IN")].value = 1;
  rt.step(in);
  EXPECT_FALSE(rt.explanations().empty());
  rt.explain(false);
  EXPECT_TRUE(rt.explanations().empty());
  // Off, a cycle allocates nothing (the bench_runtime target, and
  // Runtime.NoHeapAllocationInsideStep on a richer matrix).
  const long before = cemv_test::allocation_count();
  for (int i = 0; i < 20; ++i) {
    in.tags[0].value = static_cast<float>(i % 2);
    rt.step(in);
  }
  EXPECT_EQ(cemv_test::allocation_count() - before, 0);
}

// O.8: a tag whose simulation is not allowed refuses simulate_tag, whatever the value.
TEST(RuntimeSimulation, ATagThatMayNotBeSimulatedRefusesTheCommand) {
  model::Matrix m = one_cell(IntersectionType::N, false);
  m.causes[0].tags[0].simulation_allowed = false;
  runtime::Runtime rt(m);
  model::CycleInput in = rt.default_input();
  model::Command sim;
  sim.op = CommandOp::SimulateTag;
  sim.tag_name = "in";  // tag names compare case-insensitively (6.1.4)
  sim.value = 0;
  in.commands = {sim};
  rt.step(in);
  EXPECT_EQ(rt.commands_refused(), 1);
  model::Observable active{"cause[1].active", model::FieldType::Bool, model::Node::Kind::Cause, 1, "active", 0};
  EXPECT_EQ(rt.value(active), 0);  // the plant's TRUE, not the simulated FALSE
  // The output tag still may be simulated.
  sim.tag_name = "OUT";
  in.commands = {sim};
  rt.step(in);
  EXPECT_EQ(rt.commands_refused(), 0);
  EXPECT_EQ(rt.output("OUT").value(), false);
}

}  // namespace
