// The property language's parser: every atom and operator resolves to the
// AST node docs/properties.md says it does.
#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"

namespace cemv::properties {
namespace {

using Kind = Expr::Kind;

model::Matrix tank() { return formats::load_matrix(CEMV_SOURCE_DIR "/examples/tank-overfill/matrix.json"); }

Expr body_of(const std::string& expr, const model::Matrix& m) {
  PropertyFile f = parse_properties("property p { always " + expr + " }", m, "t.props");
  return f.properties.at(0).body;
}

TEST(PropertiesParser, FileWithKindsAssumptionsExpectAndDescription) {
  auto m = tank();
  PropertyFile f = parse_properties(R"(# file comment
assume not HS_100_BYP

# expect: proved
property req.one "the first one" {
  assume not cause[1].bypassed
  always effect[1].active implies not XV_101
}
property two { never effect[CLOSE_XV101].override_active }
# expect: reachable
property three { reachable effect[2].active }
# expect: falsified
property four {
  whenever cause[LT100_HH].active then effect[1].active within 500 ms
  assume good(LT_100A)
}
)", m, "t.props");
  EXPECT_EQ(f.file_name, "t.props");
  ASSERT_EQ(f.assumptions.size(), 1u);
  EXPECT_EQ(f.assumptions[0].expr.kind, Kind::Not);
  EXPECT_EQ(f.assumptions[0].loc.line, 2);
  EXPECT_EQ(f.assumptions[0].loc.column, 8);
  ASSERT_EQ(f.properties.size(), 4u);
  const Property& p = f.properties[0];
  EXPECT_EQ(p.name, "req.one");
  EXPECT_EQ(p.description, "the first one");
  EXPECT_EQ(p.kind, PropertyKind::Invariant);
  EXPECT_EQ(p.expect, "proved");
  EXPECT_EQ(p.loc.line, 5);
  EXPECT_EQ(p.loc.column, 10);
  ASSERT_EQ(p.assumptions.size(), 1u);
  EXPECT_EQ(p.body.kind, Kind::Implies);
  EXPECT_EQ(p.body.args[0].observable.key, "effect[1].active");
  EXPECT_EQ(p.body.args[1].kind, Kind::Not);
  EXPECT_EQ(p.body.args[1].args[0].observable.key, "effect[1].tag[1]");
  EXPECT_EQ(f.properties[1].kind, PropertyKind::Never);
  EXPECT_EQ(f.properties[1].expect, "");
  EXPECT_EQ(f.properties[1].body.observable.key, "effect[1].override_active");
  EXPECT_EQ(f.properties[2].kind, PropertyKind::Reachable);
  EXPECT_EQ(f.properties[2].expect, "reachable");
  const Property& r = f.properties[3];
  EXPECT_EQ(r.kind, PropertyKind::Response);
  EXPECT_EQ(r.expect, "falsified");
  EXPECT_EQ(r.trigger.observable.key, "cause[1].active");
  EXPECT_EQ(r.within_cycles, 5);
  EXPECT_TRUE(r.notes.empty());
  ASSERT_EQ(r.assumptions.size(), 1u);
  EXPECT_EQ(r.assumptions[0].expr.kind, Kind::Not);
  EXPECT_EQ(r.assumptions[0].expr.args[0].kind, Kind::InputBad);
}

TEST(PropertiesParser, InputTagsAnalogAndBoolComparisons) {
  auto m = tank();
  model::InputTable inputs(m);
  Expr e = body_of("LT_100A >= 90.0", m);
  ASSERT_EQ(e.kind, Kind::Compare);
  EXPECT_EQ(e.cmp, CompareOp::Ge);
  EXPECT_EQ(e.args[0].kind, Kind::InputValue);
  EXPECT_EQ(e.args[0].type, ExprType::Float);
  EXPECT_EQ(e.args[0].input, *inputs.find("LT_100A"));
  EXPECT_EQ(e.args[1].kind, Kind::FloatConst);
  EXPECT_EQ(e.args[1].float_value, 90.0f);
  // A number on the left, single-precision rounding of the constant.
  e = body_of("0.1 < lt_100b", m);
  EXPECT_EQ(e.args[0].float_value, 0.1f);
  EXPECT_EQ(e.args[1].input, *inputs.find("LT_100B"));
  // A Boolean input tag is a Boolean atom.
  e = body_of("HS_100_ESD", m);
  EXPECT_EQ(e.kind, Kind::InputValue);
  EXPECT_EQ(e.type, ExprType::Bool);
  // Quality.
  e = body_of("bad(LT_102) or good(\"LT_100C\")", m);
  ASSERT_EQ(e.kind, Kind::Or);
  EXPECT_EQ(e.args[0].kind, Kind::InputBad);
  EXPECT_EQ(e.args[1].kind, Kind::Not);
  EXPECT_EQ(e.args[1].args[0].input, *inputs.find("LT_100C"));
  // Bool == Bool is iff; != is its negation.
  e = body_of("effect[1].active == XV_101", m);
  EXPECT_EQ(e.kind, Kind::Iff);
  e = body_of("effect[1].active != false", m);
  EXPECT_EQ(e.kind, Kind::Not);
  EXPECT_EQ(e.args[0].kind, Kind::Iff);
}

TEST(PropertiesParser, IntAndVotingFields) {
  auto m = tank();
  Expr e = body_of("cause[1].tripped_tags >= 2", m);
  EXPECT_EQ(e.args[0].type, ExprType::Int);
  EXPECT_EQ(e.args[1].kind, Kind::IntConst);
  EXPECT_EQ(e.args[1].int_value, 2);
  e = body_of("cause[1].voting == 1oo2", m);
  EXPECT_EQ(e.args[1].type, ExprType::Voting);
  EXPECT_EQ(e.args[1].int_value, static_cast<int>(model::Voting::OneOoTwo));
  e = body_of("cause[1].voting != bypass", m);
  EXPECT_EQ(e.cmp, CompareOp::Ne);
  EXPECT_EQ(e.args[1].int_value, static_cast<int>(model::Voting::Bypass));
  e = body_of("cause[1].tripped_tags < cause[2].tripped_tags", m);
  EXPECT_EQ(e.args[1].kind, Kind::Observable);
}

TEST(PropertiesParser, PastTimeOperatorsAndDurationRounding) {
  auto m = tank();
  Expr e = body_of("prev(effect[1].latched) and not effect[1].latched", m);
  EXPECT_EQ(e.args[0].kind, Kind::Prev);
  e = body_of("rose(cause[1].active) or fell(cause[2].active)", m);
  EXPECT_EQ(e.args[0].kind, Kind::Rose);
  EXPECT_EQ(e.args[1].kind, Kind::Fell);
  e = body_of("held(cause[1].trip_requested, 2 s)", m);
  EXPECT_EQ(e.kind, Kind::Held);
  EXPECT_EQ(e.cycles, 20);
  e = body_of("within(cause[1].active, 2.5s)", m);
  EXPECT_EQ(e.kind, Kind::Within);
  EXPECT_EQ(e.cycles, 25);
  e = body_of("held(cause[1].active, 3 cycles)", m);
  EXPECT_EQ(e.cycles, 3);
  e = body_of("since(not effect[1].active, issued(reset_effect, effect = 1))", m);
  EXPECT_EQ(e.kind, Kind::Since);
  EXPECT_EQ(e.args[1].kind, Kind::CommandIssued);
  PropertyFile f = parse_properties("property p { always held(cause[1].active, 250 ms) }", m, "t.props");
  EXPECT_EQ(f.properties[0].body.cycles, 3);
  ASSERT_EQ(f.properties[0].notes.size(), 1u);
  EXPECT_EQ(f.properties[0].notes[0], "line 1: 250 ms rounded up to 3 cycles of 100 ms (300 ms), as the runtime rounds timers");
}

// Minutes and hours, as the checklist writes long times (issue: durations
// accept min and h): whole milliseconds, rounded to cycles like the others.
TEST(PropertiesParser, DurationsInMinutesAndHours) {
  auto m = tank();  // 100 ms cycles
  EXPECT_EQ(body_of("held(cause[1].active, 10 min)", m).cycles, 6000);
  EXPECT_EQ(body_of("held(cause[1].active, 1.5 min)", m).cycles, 900);
  EXPECT_EQ(body_of("held(cause[1].active, 2min)", m).cycles, 1200);
  EXPECT_EQ(body_of("held(cause[1].active, 0.5 h)", m).cycles, 18000);
  EXPECT_EQ(body_of("held(cause[1].active, 1h)", m).cycles, 36000);
  EXPECT_EQ(body_of("held(cause[1].active, 0.001 min)", m).cycles, 1);  // 60 ms, rounded up
  EXPECT_EQ(body_of("held(cause[1].active, 1 h)", m).cycles, body_of("held(cause[1].active, 3600 s)", m).cycles);
}

TEST(PropertiesParser, CommandPatterns) {
  auto m = tank();
  Expr e = body_of("issued(soft_bypass_tag, cause = LT100_HH, tag = 2, on = true)", m);
  ASSERT_EQ(e.kind, Kind::CommandIssued);
  EXPECT_EQ(e.command.op, model::CommandOp::SoftBypassTag);
  EXPECT_EQ(e.command.cause, 1);
  EXPECT_EQ(e.command.tag, 2);
  EXPECT_EQ(e.command.on, true);
  EXPECT_FALSE(e.command.effect);
  e = body_of("issued(simulate_tag, tag = lt_100a)", m);
  EXPECT_EQ(e.command.tag_name, "LT_100A");
  e = body_of("issued(ack_cause)", m);
  EXPECT_FALSE(e.command.cause);
}

TEST(PropertiesParser, AggregatesExpandOverSets) {
  auto m = tank();
  model::InputTable inputs(m);
  Expr e = body_of("count(t in cause[1].tags: good(t) and t >= 90.0) >= 2", m);
  ASSERT_EQ(e.kind, Kind::Compare);
  const Expr& c = e.args[0];
  ASSERT_EQ(c.kind, Kind::Count);
  EXPECT_EQ(c.type, ExprType::Int);
  ASSERT_EQ(c.args.size(), 3u);
  EXPECT_EQ(c.args[2].args[1].args[0].input, *inputs.find("LT_100C"));
  e = body_of("any(c in sif[2].causes: c.active)", m);
  ASSERT_EQ(e.kind, Kind::Or);
  ASSERT_EQ(e.args.size(), 2u);  // causes 3 and 4
  EXPECT_EQ(e.args[1].observable.key, "cause[4].active");
  e = body_of("all(x in effects: any(c in x.causes: issued(soft_bypass_cause, cause = c)) or x.tag[1])", m);
  ASSERT_EQ(e.kind, Kind::And);
  ASSERT_EQ(e.args.size(), 3u);
  EXPECT_EQ(e.args[2].args[0].args.size(), 2u);  // effect 3 has causes 3 and 4
  e = body_of("all(t in effect[1].tags: not t)", m);
  EXPECT_EQ(e.args[0].args[0].observable.key, "effect[1].tag[1]");
  e = body_of("count(cause[1].active, cause[2].active, cause[3].active) <= 1", m);
  EXPECT_EQ(e.args[0].args.size(), 3u);
}

TEST(PropertiesParser, PrecedenceOfConnectives) {
  auto m = tank();
  // not > and > or > implies (right) > iff
  Expr e = body_of("not HS_100_BYP and HS_101_RST or HS_100_ESD implies XV_101 implies P_101_RUN iff P_102_RUN", m);
  ASSERT_EQ(e.kind, Kind::Iff);
  const Expr& imp = e.args[0];
  ASSERT_EQ(imp.kind, Kind::Implies);
  EXPECT_EQ(imp.args[0].kind, Kind::Or);
  EXPECT_EQ(imp.args[0].args[0].kind, Kind::And);
  EXPECT_EQ(imp.args[0].args[0].args[0].kind, Kind::Not);
  EXPECT_EQ(imp.args[1].kind, Kind::Implies);
  e = body_of("(HS_100_BYP -> XV_101) <-> true", m);
  EXPECT_EQ(e.kind, Kind::Iff);
  EXPECT_EQ(e.args[0].kind, Kind::Implies);
}

}  // namespace
}  // namespace cemv::properties

// Traps (docs/properties.md, "Traps"): what parses but rarely means what was meant.
namespace cemv::properties {
namespace {

TEST(PropertiesTraps, ExcludingOneOfTheTwoOverrideCommandsWarns) {
  auto m = tank();
  PropertyFile f = parse_properties(
      "assume not issued(override_effect, effect = 2)\n"
      "property p { always effect[2].active implies not effect[2].override_active }\n"
      "property q { assume not issued(stop_override, effect = 2)\n"
      "             always effect[2].active implies not effect[2].override_active }\n",
      m, "t.props");
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_EQ(f.warnings[0],
            "t.props:1:12: warning: the assumption excludes override_effect but not stop_override, the same button "
            "(docs/semantics.md E.3, O.3: either command toggles the override): an override can still start or "
            "stop; exclude both, e.g. `not issued(override_effect, effect = 2) and not issued(stop_override, "
            "effect = 2)`");
  // p carries the warning in its notes; q excludes both commands and carries none.
  ASSERT_FALSE(f.properties[0].notes.empty());
  EXPECT_EQ(f.properties[0].notes.back().rfind("warning: line 1: the assumption excludes override_effect", 0), 0u);
  for (const auto& n : f.properties[1].notes) EXPECT_EQ(n.find("warning"), std::string::npos) << n;
}

TEST(PropertiesTraps, ExcludingTheCommandsOfAnEffectWithAResetTagWarns) {
  auto m = tank();  // effect 1 has the reset tag HS_101_RST
  PropertyFile f = parse_properties(
      "property p { assume not issued(override_effect, effect = 1) and not issued(stop_override, effect = 1)\n"
      "             always effect[1].latched implies effect[1].active }\n",
      m, "t.props");
  ASSERT_EQ(f.warnings.size(), 2u);
  EXPECT_NE(f.warnings[0].find("which has the reset tag HS_101_RST: the effect refuses override commands"),
            std::string::npos)
      << f.warnings[0];
  EXPECT_NE(f.warnings[0].find("assume `not rose(HS_101_RST)`"), std::string::npos);
}

TEST(PropertiesTraps, PositiveUseIsNoTrap) {
  auto m = tank();
  PropertyFile f = parse_properties(
      "property p { whenever issued(override_effect, effect = 2) then true within 1 cycles }\n"
      "property q { assume not issued(override_effect) and not issued(stop_override) always true }\n",
      m, "t.props");
  EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
}

// Names are unique across the files of a run and the standard set
// (docs/properties.md): two rows with opposite verdicts, one scenario file.
TEST(PropertiesNames, ARepeatAcrossFilesIsAnErrorAtTheRepeat) {
  auto m = tank();
  std::vector<PropertyFile> files = {parse_properties("property req1 { always true }\n", m, "a.props"),
                                     parse_properties("\nproperty req1 { always true }\n", m, "b.props")};
  try {
    check_distinct_names(files);
    FAIL() << "accepted";
  } catch (const formats::LoadError& e) {
    EXPECT_EQ(e.issues().front().message(),
              "b.props:2:10: error: property 'req1' is already defined at a.props:1:10; every property of one run "
              "needs its own name (the reports and the counterexample files are named after it)");
  }
  files[1] = parse_properties("property REQ1 { always true }\n", m, "b.props");
  try {
    check_distinct_names(files);
    FAIL() << "names that differ only in case accepted";
  } catch (const formats::LoadError& e) {
    EXPECT_NE(e.issues().front().what.find("differs only in case"), std::string::npos);
  }
  files[1] = parse_properties("property std.reachable.e1 { always true }\n", m, "b.props");
  files.push_back(standard_properties(m));
  try {
    check_distinct_names(files);
    FAIL() << "a standard name accepted";
  } catch (const formats::LoadError& e) {
    EXPECT_EQ(e.issues().front().message(),
              "b.props:1:10: error: property 'std.reachable.e1' is also the name of a standard property "
              "(--standard); rename it: the standard set's names are fixed");
  }
  files[1] = parse_properties("property req2 { always true }\n", m, "b.props");
  EXPECT_NO_THROW(check_distinct_names(files));
}

TEST(PropertiesEncoding, AFileThatIsNotUtf8IsRefusedAtItsByte) {
  auto m = tank();
  try {
    parse_properties("property p \"Azimut \xDC" "berdrehzahl\" { always true }\n", m, "t.props");
    FAIL() << "accepted";
  } catch (const formats::LoadError& e) {
    EXPECT_EQ(e.issues().front().message(), "t.props:1:20: error: this byte is not UTF-8; save the file as UTF-8");
  }
}

}  // namespace
}  // namespace cemv::properties
