// The concrete evaluator: every operator on hand-made input columns (checked
// against values worked out from the definitions in docs/properties.md), and
// whole properties on runtime traces of the examples.
#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

const model::Matrix& tank() {
  static const model::Matrix m = formats::load_matrix(CEMV_SOURCE_DIR "/examples/tank-overfill/matrix.json");
  return m;
}

// A trace in which the Boolean input tags A = HS_100_BYP and B = HS_101_RST
// follow the given 0/1 strings, and LT_100A the given analog values (only the
// inputs matter for these expressions; the observables are all 0).
Trace columns(const std::string& a, const std::string& b, std::vector<float> level = {}) {
  const auto& m = tank();
  model::InputTable inputs(m);
  Trace t(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    t[k].input.tags.resize(inputs.size());
    t[k].input.tags[*inputs.find("HS_100_BYP")].value = a[k] == '1';
    t[k].input.tags[*inputs.find("HS_101_RST")].value = b[k] == '1';
    if (k < level.size()) t[k].input.tags[*inputs.find("LT_100A")].value = level[k];
    t[k].observables.assign(model::observables(m).size(), 0);
  }
  return t;
}

std::string eval(const std::string& expr, const Trace& t) {
  PropertyFile f = parse_properties("property p { always " + expr + " }", tank(), "t.props");
  std::string out;
  for (bool v : Evaluator(tank()).values(f.properties[0].body, t)) out += v ? '1' : '0';
  return out;
}

TEST(PropertiesEvaluator, PastTimeOperatorsFollowTheirDefinitions) {
  Trace t = columns("1101110001", "0010000100");
  EXPECT_EQ(eval("HS_100_BYP", t), "1101110001");
  EXPECT_EQ(eval("prev(HS_100_BYP)", t), "0110111000");  // false in the first cycle
  EXPECT_EQ(eval("rose(HS_100_BYP)", t), "1001000001");  // a value true in cycle 0 rose
  EXPECT_EQ(eval("fell(HS_100_BYP)", t), "0010001000");
  // held(e, N): e in every cycle of [k-N, k]; false while k < N.
  EXPECT_EQ(eval("held(HS_100_BYP, 0 cycles)", t), "1101110001");
  EXPECT_EQ(eval("held(HS_100_BYP, 1 cycle)", t), "0100110000");
  EXPECT_EQ(eval("held(HS_100_BYP, 2 cycles)", t), "0000010000");
  EXPECT_EQ(eval("held(HS_100_BYP, 200 ms)", t), "0000010000");
  // within(e, N): e in some cycle of [max(0, k-N), k].
  EXPECT_EQ(eval("within(HS_100_BYP, 1 cycles)", t), "1111111001");
  EXPECT_EQ(eval("within(HS_100_BYP, 3 cycles)", t), "1111111111");
  EXPECT_EQ(eval("within(HS_101_RST, 150 ms)", t), "0011100111");  // 150 ms -> 2 cycles
  // since(a, b): b at some j <= k and a in every cycle of (j, k].
  EXPECT_EQ(eval("since(HS_100_BYP, HS_101_RST)", t), "0011110100");
  EXPECT_EQ(eval("since(not HS_100_BYP, HS_100_BYP)", t), "1111111111");
  EXPECT_EQ(eval("since(false, HS_101_RST)", t), "0010000100");
}

TEST(PropertiesEvaluator, ConnectivesCountAndFloatComparisons) {
  Trace t = columns("0011", "0101", {89.9f, 90.0f, 90.000001f, -1.0f});
  EXPECT_EQ(eval("HS_100_BYP and HS_101_RST", t), "0001");
  EXPECT_EQ(eval("HS_100_BYP or HS_101_RST", t), "0111");
  EXPECT_EQ(eval("HS_100_BYP implies HS_101_RST", t), "1101");
  EXPECT_EQ(eval("HS_100_BYP iff HS_101_RST", t), "1001");
  EXPECT_EQ(eval("count(HS_100_BYP, HS_101_RST, true) >= 2", t), "0111");
  EXPECT_EQ(eval("count(HS_100_BYP, HS_101_RST) == 1", t), "0110");
  EXPECT_EQ(eval("LT_100A >= 90.0", t), "0110");
  // 90.000001 is 90.0 in single precision: the constant rounds like the runtime's REAL.
  EXPECT_EQ(eval("LT_100A > 90.0", t), "0000");
  EXPECT_EQ(eval("LT_100A < 90.000001", t), "1001");
  EXPECT_EQ(eval("90 <= LT_100A", t), "0110");
}

TEST(PropertiesEvaluator, CommandsQualityAndAssumptions) {
  Trace t = columns("0000", "0000");
  model::InputTable inputs(tank());
  t[1].input.commands.push_back({model::CommandOp::SoftBypassTag, 1, 0, 2, 0, true, "", 0.0f});
  t[2].input.commands.push_back({model::CommandOp::SimulateTag, 0, 0, 0, 0, true, "lt_100a", 95.0f});
  t[3].input.tags[*inputs.find("LT_100B")].bad_quality = true;
  EXPECT_EQ(eval("issued(soft_bypass_tag)", t), "0100");
  EXPECT_EQ(eval("issued(soft_bypass_tag, cause = 1, tag = 2, on = true)", t), "0100");
  EXPECT_EQ(eval("issued(soft_bypass_tag, tag = 3)", t), "0000");
  EXPECT_EQ(eval("issued(soft_bypass_tag, on = false)", t), "0000");
  EXPECT_EQ(eval("issued(simulate_tag, tag = LT_100A)", t), "0010");
  EXPECT_EQ(eval("bad(LT_100B)", t), "0001");
  EXPECT_EQ(eval("good(LT_100B)", t), "1110");

  // Assumptions cut the judged part of the trace at their first failure.
  PropertyFile f = parse_properties(R"(
assume not bad(LT_100B)
property inv { always not issued(simulate_tag) }
property reach { reachable bad(LT_100B) }
property own { assume not issued(soft_bypass_tag)  never issued(simulate_tag) }
)", tank(), "t.props");
  auto r = Evaluator(tank()).evaluate(f, t);
  EXPECT_FALSE(r[0].holds);
  EXPECT_EQ(r[0].cycle, 2u);
  EXPECT_EQ(r[0].judged, 3u);
  EXPECT_FALSE(r[0].assumptions_held);
  EXPECT_FALSE(r[1].holds);  // the witness lies beyond the assumption's failure
  EXPECT_FALSE(r[1].cycle);
  EXPECT_TRUE(r[2].holds);   // judged on cycle 0 only
  EXPECT_EQ(r[2].judged, 1u);
}

TEST(PropertiesEvaluator, ResponseWindowsAndVacuity) {
  Trace t = columns("0100100000", "0001000010");
  auto check = [&](const std::string& text) {
    PropertyFile f = parse_properties(text, tank(), "t.props");
    return Evaluator(tank()).evaluate(f.properties.at(0), f.assumptions, t);
  };
  // Triggers at 1 and 4; responses at 3 and 8.
  auto r = check("property p { whenever HS_100_BYP then HS_101_RST within 2 cycles }");
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.trigger_cycle, 4u);
  EXPECT_EQ(r.cycle, 6u);  // definite once the window [4, 6] has passed
  EXPECT_TRUE(r.antecedent_met);
  r = check("property p { whenever HS_100_BYP then HS_101_RST within 4 cycles }");
  EXPECT_TRUE(r.holds);
  r = check("property p { whenever HS_100_BYP then HS_101_RST within 1 cycles }");
  EXPECT_EQ(r.trigger_cycle, 1u);
  EXPECT_EQ(r.cycle, 2u);
  // A window running past the end of the trace is not a violation (yet).
  t = columns("0000000010", "0000000000");
  r = check("property p { whenever HS_100_BYP then HS_101_RST within 2 cycles }");
  EXPECT_TRUE(r.holds);
  r = check("property p { whenever HS_100_BYP then HS_101_RST within 0 cycles }");
  EXPECT_EQ(r.cycle, 8u);
  // Vacuity information: the antecedent of an implication never met.
  r = check("property p { always HS_101_RST implies HS_100_BYP }");
  EXPECT_TRUE(r.holds);
  EXPECT_FALSE(r.antecedent_met);
}

// Properties on the runtime's trace of the tank example's first scenario
// (docs/scenario.md; the cycle numbers are those its README walks through).
TEST(PropertiesEvaluator, TankOverfillScenarioTrace) {
  const auto& m = tank();
  Trace t = testing::run_scenario(m, CEMV_SOURCE_DIR "/examples/tank-overfill/scenario-1-overfill-trip.json");
  ASSERT_GT(t.size(), 25u);
  PropertyFile f = parse_properties(R"(
property never_active { never effect[1].active }
property trips { reachable effect[CLOSE_XV101].active and not XV_101 }
property on_delay { always rose(cause[1].active) implies held(cause[1].trip_requested, 2 s) }
property fast { whenever rose(cause[1].trip_requested) then cause[1].active within 1900 ms }
property slow { whenever rose(cause[1].trip_requested) then cause[1].active within 2 s }
property stored { always fell(effect[1].latched) implies within(HS_101_RST, 0 ms) }
property degraded { reachable cause[1].voting == 1oo2 and cause[1].degraded }
)", m, "t.props");
  auto r = Evaluator(m).evaluate(f, t);
  std::optional<std::size_t> first_active;
  std::vector<bool> active = Evaluator(m).values(f.properties[0].body, t);
  for (std::size_t k = 0; k < t.size() && !first_active; ++k)
    if (active[k]) first_active = k;
  ASSERT_TRUE(first_active);
  EXPECT_FALSE(r[0].holds);
  EXPECT_EQ(r[0].cycle, first_active);
  EXPECT_TRUE(r[1].holds);
  EXPECT_EQ(r[1].cycle, first_active);
  EXPECT_TRUE(r[2].holds) << "cause 1 became active without 2 s of trip request";
  EXPECT_TRUE(r[2].antecedent_met);
  EXPECT_FALSE(r[3].holds) << "the on-delay is 20 cycles, not 19";
  EXPECT_EQ(*r[3].cycle - *r[3].trigger_cycle, 19u);
  EXPECT_TRUE(r[4].holds);
  EXPECT_TRUE(r[4].antecedent_met);
  EXPECT_TRUE(r[5].holds);
  EXPECT_TRUE(r[5].antecedent_met) << "the scenario resets the stored effect";
  EXPECT_TRUE(r[6].holds);
}

}  // namespace
}  // namespace cemv::properties
