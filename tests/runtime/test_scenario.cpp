// cemv-scenario/1 (docs/scenario.md): parsing against a matrix, defaults and
// the expansion into cycles. The matrix is built in code so these tests need
// neither the matrix loader nor the runtime, except the last one, which checks
// that the runtime's own defaults agree with the scenario defaults.
#include <limits>

#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "test_sim.hpp"

namespace cemv::testing {
namespace {

Matrix tank() {
  Cause c = make_cause(1, CauseFunction::TwoOoThree, 3, Kind::AnalogHigh, BadQuality::Degrade, "LT_100");
  c.name = "LT100_HH";
  c.tags[0].name = "LT_100A";
  c.tags[1].name = "LT_100B";
  c.tags[2].name = "LT_100C";
  c.bypass_tag = "HS_100_BYP";
  c.first_out_group = 1;
  Cause low = make_cause(2, CauseFunction::Normal, 1, Kind::AnalogLow);
  Cause ett = make_cause(3, CauseFunction::Or, 2, Kind::DiscreteEtt);
  Cause dtt = make_cause(4, CauseFunction::Normal, 1, Kind::DiscreteDtt);
  Effect e = make_effect(1);
  e.name = "CLOSE_INLET";
  e.tags[0].name = "XV_101";
  e.reset_tag = "HS_101_RST";
  e.override_time = Override{600, 540};
  Effect e2 = make_effect(2, 2);
  return make_matrix({c, low, ett, dtt}, {e, e2},
                     {link(1, 1, IntersectionType::R), link(2, 2), link(3, 2), link(4, 2)});
}

std::string first_issue(const std::string& text, const Matrix& m = tank()) {
  try {
    parse_scenario(text, m);
  } catch (const LoadError& e) {
    return e.issues().empty() ? "" : e.issues()[0].str();
  }
  return "(accepted)";
}

TEST(ScenarioDefaults, NonTrippedValuesOfS1) {
  Matrix m = tank();
  InputTable t(m);
  CycleInput in = default_cycle_input(m);
  ASSERT_EQ(in.tags.size(), t.size());
  auto v = [&](const char* name) { return in.tags[*t.find(name)]; };
  EXPECT_EQ(v("LT_100A").value, 84.0f);  // high: 90 - 5 - 1
  EXPECT_EQ(v("T2_1").value, 16.0f);     // low: 10 + 5 + 1
  EXPECT_EQ(v("T3_1").value, 0.0f);      // ETT discrete: FALSE
  EXPECT_EQ(v("T4_1").value, 1.0f);      // DTT discrete: TRUE
  EXPECT_EQ(v("HS_100_BYP").value, 0.0f);
  EXPECT_EQ(v("HS_101_RST").value, 0.0f);
  for (const auto& tv : in.tags) EXPECT_FALSE(tv.bad_quality);
  EXPECT_TRUE(in.commands.empty());
}

TEST(ScenarioParse, TheExampleOfTheFormat) {
  Matrix m = tank();
  const char* text = R"({
    "format": "cemv-scenario/1",
    "initial": {"LT_100A": 50.0, "HS_100_BYP": false},
    "steps": [
      {"inputs": {"LT_100A": 95.0, "LT_100B": {"value": 95.0, "quality": "bad"}},
       "commands": [{"op": "soft_bypass_tag", "cause": 1, "tag": 2, "on": true}],
       "cycles": 1,
       "expect": {"cause[1].active": true, "cause[1].voting": "1oo2",
                  "effect[CLOSE_INLET].active": true, "XV_101": false}},
      {"ms": 2000, "expect": {"cause[LT100_HH].tripped_tags": 1, "effect[2].tag[2]": true}}
    ]})";
  Scenario sc = parse_scenario(text, m);
  ASSERT_EQ(sc.steps.size(), 2u);
  EXPECT_EQ(sc.initial.size(), 2u);
  const auto& s0 = sc.steps[0];
  ASSERT_EQ(s0.commands.size(), 1u);
  EXPECT_EQ(s0.commands[0].op, CommandOp::SoftBypassTag);
  EXPECT_EQ(s0.commands[0].cause, 1);
  EXPECT_EQ(s0.commands[0].tag, 2);
  ASSERT_EQ(s0.expect.size(), 4u);
  // Keys keep JSON (sorted) order; each resolves to the canonical observable.
  std::map<std::string, const Expectation*> by_key;
  for (const auto& x : s0.expect) by_key[x.key] = &x;
  EXPECT_EQ(by_key.at("cause[1].voting")->expected, static_cast<int>(Voting::OneOoTwo));
  EXPECT_EQ(by_key.at("effect[CLOSE_INLET].active")->target.observable.key, "effect[1].active");
  EXPECT_EQ(by_key.at("XV_101")->target.kind, ExpectTarget::Kind::OutputTag);
  EXPECT_EQ(by_key.at("XV_101")->target.observable.key, "effect[1].tag[1]");
  EXPECT_EQ(sc.steps[1].cycles, 20u);
  EXPECT_EQ(sc.steps[1].expect[0].target.observable.key, "cause[1].tripped_tags");

  ExpandedScenario ex = expand_scenario(sc, m);
  ASSERT_EQ(ex.cycles.size(), 21u);
  InputTable t(m);
  std::size_t a = *t.find("LT_100A"), b = *t.find("LT_100B"), c = *t.find("LT_100C");
  EXPECT_EQ(ex.cycles[0].tags[a].value, 95.0f);
  EXPECT_TRUE(ex.cycles[0].tags[b].bad_quality);
  EXPECT_EQ(ex.cycles[0].tags[c].value, 84.0f);
  EXPECT_EQ(ex.cycles[0].commands.size(), 1u);
  EXPECT_TRUE(ex.cycles[1].commands.empty());      // commands only in a step's first cycle
  EXPECT_EQ(ex.cycles[20].tags[a].value, 95.0f);   // values persist
  EXPECT_TRUE(ex.cycles[20].tags[b].bad_quality);
  ASSERT_EQ(ex.checks.size(), 2u);
  EXPECT_EQ(ex.checks[0].cycle, 0u);
  EXPECT_EQ(ex.checks[1].cycle, 20u);
  EXPECT_EQ(ex.step_of_cycle[20], 1u);
}

TEST(ScenarioParse, InitialValuesApplyBeforeTheFirstStep) {
  Matrix m = tank();
  Scenario sc = parse_scenario(
      R"({"format":"cemv-scenario/1","initial":{"lt_100c":{"quality":"bad"}},"steps":[{}]})", m);
  ExpandedScenario ex = expand_scenario(sc, m);
  InputTable t(m);
  ASSERT_EQ(ex.cycles.size(), 1u);
  EXPECT_TRUE(ex.cycles[0].tags[*t.find("LT_100C")].bad_quality);
  EXPECT_EQ(ex.cycles[0].tags[*t.find("LT_100C")].value, 84.0f);  // value kept
}

TEST(ScenarioParse, ReadsTheShortestTextOfTheLargestFloats) {
  // 3.4028235e+38 is a little above FLT_MAX as a double yet rounds to it;
  // the checker writes it in counterexamples, so it must read back.
  Matrix m = tank();
  Scenario sc = parse_scenario(
      R"({"format":"cemv-scenario/1","steps":[{"inputs":{"LT_100A":-3.4028235e+38,"LT_100B":3.4028235e+38}}]})", m);
  ExpandedScenario ex = expand_scenario(sc, m);
  InputTable t(m);
  EXPECT_EQ(ex.cycles[0].tags[*t.find("LT_100A")].value, -std::numeric_limits<float>::max());
  EXPECT_EQ(ex.cycles[0].tags[*t.find("LT_100B")].value, std::numeric_limits<float>::max());
}

struct Rejection {
  const char* name;
  const char* steps;  // the "steps" array
  const char* message;
};

// Printed in ctest's test list: a readable case, not the struct's raw bytes
// (which hold addresses and differ between runs).
void PrintTo(const Rejection& r, std::ostream* os) { *os << r.name; }

class ScenarioRejects : public ::testing::TestWithParam<Rejection> {};

TEST_P(ScenarioRejects, NamesTheBadItem) {
  std::string text = std::string(R"({"format":"cemv-scenario/1","steps":)") + GetParam().steps + "}";
  EXPECT_EQ(first_issue(text), GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Items, ScenarioRejects,
    ::testing::Values(
        Rejection{"TagTypo", R"([{"inputs":{"LT_10OA":95}}])",
                  "steps[0].inputs: unknown tag 'LT_10OA' (did you mean 'LT_100A'?)"},
        Rejection{"OutputAsInput", R"([{"inputs":{"XV_101":true}}])",
                  "steps[0].inputs: 'XV_101' is an output tag; outputs cannot be set as inputs (use "
                  "the simulate_tag command to force one)"},
        Rejection{"BoolForAnalog", R"([{"inputs":{"LT_100A":true}}])",
                  "steps[0].inputs.LT_100A: tag 'LT_100A' is analog: the value must be a number, not "
                  "a boolean"},
        Rejection{"NumberForBool", R"([{"inputs":{"HS_100_BYP":1}}])",
                  "steps[0].inputs.HS_100_BYP: tag 'HS_100_BYP' is Boolean: the value must be true or "
                  "false, not an integer"},
        Rejection{"BadQualityWord", R"([{"inputs":{"LT_100A":{"value":1,"quality":"poor"}}}])",
                  "steps[0].inputs.LT_100A.quality: must be \"good\" or \"bad\", not \"poor\""},
        Rejection{"UnknownCommand", R"([{},{"commands":[{"op":"ack_casue","cause":1}]}])",
                  "steps[1].commands[0].op: unknown command 'ack_casue' (did you mean 'ack_cause'?)"},
        Rejection{"CommandMissingField", R"([{"commands":[{"op":"soft_bypass_cause","cause":1}]}])",
                  "steps[0].commands[0]: command 'soft_bypass_cause' needs \"on\""},
        Rejection{"CommandUnknownField", R"([{"commands":[{"op":"ack_cause","cause":1,"effect":1}]}])",
                  "steps[0].commands[0].effect: unknown key"},
        Rejection{"CommandUnknownCause", R"([{"commands":[{"op":"ack_cause","cause":9}]}])",
                  "steps[0].commands[0].cause: no cause with id 9"},
        Rejection{"TagIndexOutOfRange", R"([{"commands":[{"op":"soft_bypass_tag","cause":2,"tag":2,"on":true}]}])",
                  "steps[0].commands[0].tag: cause 2 has 1 input tag(s); the tag index is 1-1"},
        Rejection{"SimulateUnknownTag", R"([{"commands":[{"op":"simulate_tag","tag":"XV_1O1","value":true}]}])",
                  "steps[0].commands[0].tag: unknown tag 'XV_1O1' (did you mean 'XV_101'?)"},
        Rejection{"ClearAlarmsNeedsOne", R"([{"commands":[{"op":"clear_alarms"}]}])",
                  "steps[0].commands[0]: command 'clear_alarms' needs exactly one of \"cause\" and "
                  "\"effect\""},
        Rejection{"ExpectUnknownField", R"([{"expect":{"cause[1].actve":true}}])",
                  "steps[0].expect.cause[1].actve: unknown cause field 'actve' (did you mean "
                  "'active'?)"},
        Rejection{"ExpectUnknownCauseName", R"([{"expect":{"cause[LT100_H].active":true}}])",
                  "steps[0].expect.cause[LT100_H].active: no cause named 'LT100_H' (did you mean "
                  "'LT100_HH'?)"},
        Rejection{"ExpectUnknownKey", R"([{"expect":{"XV_102":true}}])",
                  "steps[0].expect.XV_102: unknown expectation key 'XV_102': not an output tag, nor "
                  "cause[..].FIELD / effect[..].FIELD (did you mean 'XV_101'?)"},
        Rejection{"ExpectTagIndex", R"([{"expect":{"effect[1].tag[2]":true}}])",
                  "steps[0].expect.effect[1].tag[2]: effect 1 has 1 output tag(s); tag[k] takes k = "
                  "1-1"},
        Rejection{"ExpectWrongType", R"([{"expect":{"cause[1].voting":"2oo4"}}])",
                  "steps[0].expect.cause[1].voting: expects a voting: \"1oo1\", \"1oo2\", \"2oo2\", "
                  "\"1oo3\", \"2oo3\", \"3oo3\" or \"bypass\", not \"2oo4\""},
        Rejection{"MsNotMultiple", R"([{"ms":150}])",
                  "steps[0].ms: 150 is not a multiple of cycle_ms (100)"},
        Rejection{"CyclesAndMs", R"([{"ms":100,"cycles":1}])",
                  "steps[0]: give either \"cycles\" or \"ms\", not both"},
        Rejection{"ZeroCycles", R"([{"cycles":0}])", "steps[0].cycles: must be 1-1000000, not 0"},
        Rejection{"TooManyCycles", R"([{"cycles":600000},{"cycles":600000}])",
                  "steps[1]: the scenario exceeds 1000000 cycles in total"},
        Rejection{"StepUnknownKey", R"([{"expekt":{}}])",
                  "steps[0].expekt: unknown key (did you mean 'expect'?)"},
        Rejection{"NoSteps", R"([])", "steps: empty; a scenario has at least one step"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(ScenarioParse, RejectsBadFramesAndSyntax) {
  EXPECT_EQ(first_issue(R"({"format":"cemv-scenario/2","steps":[{}]})"),
            "format: expected \"cemv-scenario/1\", got \"cemv-scenario/2\"");
  EXPECT_EQ(first_issue(R"({"format":"cemv-scenario/1","steps":[{}],"initail":{}})"),
            "initail: unknown key (did you mean 'initial'?)");
  EXPECT_EQ(first_issue("{\"format\":\"cemv-scenario/1\",\n \"steps\": [}"),
            first_issue("{\"format\":\"cemv-scenario/1\",\n \"steps\": [}"));
  EXPECT_NE(first_issue("{\"format\":\"cemv-scenario/1\",\n \"steps\": [}").find("line 2"),
            std::string::npos);
  std::string deep(200, '[');
  EXPECT_NE(first_issue(deep).find("nesting deeper than 64 levels"), std::string::npos);
  EXPECT_EQ(first_issue("[1]"), "a scenario is a JSON object, not an array");
}

TEST(ScenarioParse, ReportsEveryProblemNotJustTheFirst) {
  try {
    parse_scenario(R"({"format":"cemv-scenario/1","steps":[{"inputs":{"A":1,"B":2},"ms":7}]})", tank());
    FAIL() << "accepted";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().size(), 3u);
  }
}

TEST(ScenarioParse, CommentOnlyElementsHaveNoStatus) {
  Matrix m = tank();
  Cause c = make_cause(5, CauseFunction::Comment, 1, Kind::DiscreteDtt);
  m.causes.push_back(c);
  EXPECT_EQ(first_issue(R"({"format":"cemv-scenario/1","steps":[{"expect":{"cause[5].active":false}}]})", m),
            "steps[0].expect.cause[5].active: cause 5 is comment-only and is not processed");
}

}  // namespace
}  // namespace cemv::testing

namespace cemv::testing {
namespace {

// The expansion holds one frame per cycle: a long scenario on a wide matrix is
// refused with a message instead of exhausting memory.
TEST(ScenarioParse, RefusesExpansionsTooLargeForMemory) {
  Matrix m;
  m.name = "WIDE";
  for (int i = 1; i <= 40; ++i) m.causes.push_back(make_cause(i, CauseFunction::Or, 3, Kind::DiscreteDtt));
  EXPECT_EQ(InputTable(m).size(), 120u);
  std::string msg = first_issue(R"({"format":"cemv-scenario/1","steps":[{"cycles":300000}]})", m);
  EXPECT_EQ(msg, "steps[0]: the scenario is too long for this matrix: 300000 cycles x 120 input tags "
                 "exceed 32000000 input values");
  EXPECT_EQ(first_issue(R"({"format":"cemv-scenario/1","steps":[{"cycles":200000}]})", m), "(accepted)");
}

}  // namespace
}  // namespace cemv::testing
