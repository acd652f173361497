// The four printers of `cemv check` results on one hand-built CheckResult that
// holds every verdict, a standard property, and names with characters that
// XML and JSON must escape. Golden files under golden/ pin the exact bytes;
// run with CEMV_UPDATE_GOLDEN=1 to rewrite them after an intended change (and
// review the diff).
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "reports/check_report.hpp"

using cemv::checker::CheckResult;
using cemv::checker::PropertyResult;
using cemv::checker::PropertyVerdict;
using cemv::reports::CheckFormat;

namespace {

PropertyResult property(std::string name, std::string kind, int line, PropertyVerdict v) {
  PropertyResult p;
  p.name = std::move(name);
  p.kind = std::move(kind);
  p.file = "examples/tank-overfill/requirements.props";
  p.line = line;
  p.column = 10;
  p.verdict = v;
  return p;
}

CheckResult sample(double seconds_scale = 1.0) {
  CheckResult r;
  r.matrix_name = "TANK_T100";
  r.matrix_signature = "3f0c9a1b2d4e5f60718293a4b5c6d7e8f90a1b2c3d4e5f60718293a4b5c6d7e8";
  r.tool_version = "0.1.0";
  r.property_files = {"examples/tank-overfill/requirements.props"};
  r.shard = "2/3";

  PropertyResult proved = property("req1.overfill_closes_xv101", "response", 12, PropertyVerdict::Proved);
  proved.description = "2oo3 high level for 2 s closes XV_101 within 500 ms";
  proved.method = "k-induction";
  proved.depth = 3;
  proved.notes = {"500 ms is 5 cycles of 100 ms"};
  proved.support = {{"intersection[1,1]", "cause 1 -> effect 1 (N)"},
                    {"cause[1].voting", "2oo3"}};
  proved.support_minimal = true;
  proved.invariant = "(<= effect[1].timer 5)";
  proved.matters = {"cause[1].active", "effect[1].active", "effect[1].tag[1]"};
  proved.seconds = 0.25 * seconds_scale;
  r.properties.push_back(proved);

  PropertyResult falsified = property("req5.stored_holds", "invariant", 30, PropertyVerdict::Falsified);
  falsified.description = "effect 1 stays active while a cause is active";
  falsified.method = "bmc";
  falsified.depth = 4;
  falsified.violation_cycle = 3;
  falsified.scenario_file = "out/req5.stored_holds.scenario.json";
  falsified.diagram_file = "out/req5.stored_holds.svg";
  falsified.vcd_file = "out/req5.stored_holds.vcd";
  falsified.timing_table =
      "timing (cycle:value at the first cycle and at each change; cycle n is t = (n-1)*100 ms):\n"
      "  LT_100A           1:0  3:95\n"
      "  effect[1].active  1:0  3:1  4:0\n";
  falsified.matters = {"effect[1].active", "cause[1].active"};
  falsified.explanation = {{3, "LT_100A", "0", "95", "an input of the run (the plant or the operator's switch)"},
                           {3, "effect[1].active", "0", "1", "N request: cause 1 LT100_HH is active on its N intersection (E.2, E.6)"},
                           {4, "effect[1].active", "1", "0", "no request left: no linked cause is active (E.2, E.6)"}};
  falsified.seconds = 0.031 * seconds_scale;
  r.properties.push_back(falsified);

  PropertyResult reach = property("req7.effect1_trips", "reachable", 40, PropertyVerdict::Reachable);
  reach.method = "bmc";
  reach.depth = 2;
  reach.violation_cycle = 1;
  reach.scenario_file = "out/req7.effect1_trips.scenario.json";
  reach.diagram_file = "out/req7.effect1_trips.svg";
  reach.vcd_file = "out/req7.effect1_trips.vcd";
  reach.timing_table = "timing:\n  effect[1].active  1:0  2:1\n";
  reach.matters = {"effect[1].active"};
  reach.seconds = 0.01 * seconds_scale;
  r.properties.push_back(reach);

  PropertyResult dead = property("req7.effect9_resets", "reachable", 41, PropertyVerdict::Unreachable);
  dead.method = "pdr";
  dead.depth = 1;
  dead.matters = {"effect[9].reset_required"};
  dead.seconds = 0.5 * seconds_scale;
  r.properties.push_back(dead);

  PropertyResult vac = property("req9.when_never", "response", 50, PropertyVerdict::Vacuous);
  vac.reason = "the trigger can never hold";
  vac.matters = {"cause[2].active", "effect[2].active"};
  vac.seconds = 0.02 * seconds_scale;
  r.properties.push_back(vac);

  PropertyResult unknown = property("req4.override_1800s", "invariant", 60, PropertyVerdict::Unknown);
  unknown.reason = "time limit";
  unknown.matters = {"effect[4].override_active"};
  unknown.seconds = 10.0 * seconds_scale;
  r.properties.push_back(unknown);

  // A generated property (no file) whose text needs escaping everywhere:
  // markup, quotes, a control character and a byte that is not UTF-8.
  PropertyResult odd;
  odd.name = "std.effect[3] <a & \"b\"> 'c'";
  odd.kind = "invariant";
  odd.description = std::string("tab\there, bell\x07, bad byte \xff, newline\nend");
  odd.verdict = PropertyVerdict::Falsified;
  odd.method = "bmc";
  odd.depth = 1;
  odd.violation_cycle = 0;
  odd.timing_table = "  x <&> 1:0\n";
  odd.seconds = 0.001 * seconds_scale;
  r.properties.push_back(odd);

  r.standard = false;
  return r;
}

const cemv::reports::CheckReportInputs kInputs{"examples/tank-overfill/matrix.json"};

std::string golden_path(const std::string& name) { return std::string(CEMV_GOLDEN_DIR) + "/" + name; }

void expect_golden(const std::string& actual, const std::string& name) {
  std::string path = golden_path(name);
  if (std::getenv("CEMV_UPDATE_GOLDEN")) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  std::ifstream f(path, std::ios::binary);
  ASSERT_TRUE(f) << "missing golden file " << path;
  std::stringstream s;
  s << f.rdbuf();
  EXPECT_EQ(actual, s.str()) << "differs from " << path;
}

std::string render(const CheckResult& r, CheckFormat f) {
  return cemv::reports::check_report(r, kInputs, f);
}

}  // namespace

TEST(CheckPrinters, TextGolden) { expect_golden(render(sample(), CheckFormat::Text), "check.txt"); }
TEST(CheckPrinters, JsonGolden) { expect_golden(render(sample(), CheckFormat::Json), "check.json"); }
TEST(CheckPrinters, JunitGolden) { expect_golden(render(sample(), CheckFormat::Junit), "check.junit.xml"); }
TEST(CheckPrinters, SarifGolden) { expect_golden(render(sample(), CheckFormat::Sarif), "check.sarif"); }

// Only the text report shows times: the machine formats are byte-identical
// whatever the run took.
TEST(CheckPrinters, MachineFormatsHaveNoTimes) {
  for (CheckFormat f : {CheckFormat::Json, CheckFormat::Junit, CheckFormat::Sarif})
    EXPECT_EQ(render(sample(1.0), f), render(sample(3.7), f));
  EXPECT_NE(render(sample(1.0), CheckFormat::Text), render(sample(3.7), CheckFormat::Text));
}

TEST(CheckPrinters, JsonSummaryCountsEveryVerdict) {
  auto j = nlohmann::json::parse(render(sample(), CheckFormat::Json));
  EXPECT_EQ(j["format"], "cemv-result/1");
  EXPECT_EQ(j["summary"]["properties"], 7);
  EXPECT_EQ(j["summary"]["falsified"], 2);
  EXPECT_EQ(j["summary"]["proved"], 1);
  EXPECT_EQ(j["summary"]["unknown"], 1);
  EXPECT_EQ(j["properties"][1]["violation_cycle"], 3);
  EXPECT_TRUE(j["properties"][0]["violation_cycle"].is_null());
  EXPECT_EQ(j["properties"][0]["elements"], nlohmann::json({"cause[1]", "effect[1]"}));
}

TEST(CheckPrinters, InterruptedRunSaysSo) {
  CheckResult r = sample();
  r.interrupted = true;
  EXPECT_EQ(nlohmann::json::parse(render(r, CheckFormat::Json))["interrupted"], true);
  EXPECT_NE(render(r, CheckFormat::Text).find("INTERRUPTED"), std::string::npos);
}

TEST(CheckPrinters, FormatNames) {
  EXPECT_EQ(cemv::reports::check_format_from_string("sarif"), CheckFormat::Sarif);
  EXPECT_EQ(cemv::reports::check_format_from_string("junit"), CheckFormat::Junit);
  EXPECT_FALSE(cemv::reports::check_format_from_string("xml").has_value());
}

// `cemv check --out DIR` writes NAME.svg and NAME.vcd beside each scenario:
// every format names them for the property they belong to, and only there.
TEST(CheckPrinters, EveryFormatNamesTheDiagramFiles) {
  const CheckResult r = sample();
  auto j = nlohmann::json::parse(render(r, CheckFormat::Json));
  EXPECT_EQ(j["properties"][1]["diagram"], "out/req5.stored_holds.svg");
  EXPECT_EQ(j["properties"][1]["waveforms"], "out/req5.stored_holds.vcd");
  EXPECT_EQ(j["properties"][2]["diagram"], "out/req7.effect1_trips.svg");
  EXPECT_TRUE(j["properties"][0]["diagram"].is_null());
  EXPECT_TRUE(j["properties"][0]["waveforms"].is_null());

  const std::string junit = render(r, CheckFormat::Junit);
  for (const char* f : {"diagram: out/req5.stored_holds.svg", "waveforms: out/req5.stored_holds.vcd",
                        "diagram: out/req7.effect1_trips.svg", "waveforms: out/req7.effect1_trips.vcd"})
    EXPECT_NE(junit.find(f), std::string::npos) << f;

  auto s = nlohmann::json::parse(render(r, CheckFormat::Sarif));
  const auto& results = s["runs"][0]["results"];
  const nlohmann::json* req5 = nullptr;
  for (const auto& res : results)
    if (res["properties"]["property"] == "req5.stored_holds") req5 = &res;
  ASSERT_NE(req5, nullptr);
  std::string message = (*req5)["message"]["text"];
  EXPECT_NE(message.find("out/req5.stored_holds.svg"), std::string::npos);
  EXPECT_NE(message.find("out/req5.stored_holds.vcd"), std::string::npos);
  std::vector<std::string> uris;
  for (const auto& a : (*req5)["attachments"]) uris.push_back(a["artifactLocation"]["uri"]);
  EXPECT_EQ(uris, (std::vector<std::string>{"out/req5.stored_holds.scenario.json", "out/req5.stored_holds.svg",
                                            "out/req5.stored_holds.vcd"}));
  // A finding without a run (unknown) has no attachments.
  for (const auto& res : results) {
    if (res["properties"]["verdict"] == "unknown") {
      EXPECT_FALSE(res.contains("attachments"));
    }
  }
}

// A matrix text as a file holds it: the lines of its elements are what the
// SARIF related locations and a standard property's place point at.
const char* kMatrixText = R"({
  "causes": [
    {
      "id": 1
    }
  ],
  "effects": [
    {
      "id": 1
    }
  ],
  "format": "cemv-matrix/1",
  "intersections": [
    {
      "cause": 1,
      "effect": 1
    },
    {
      "cause": 2,
      "effect": 1
    }
  ],
  "name": "TANK_T100"
}
)";

// A counterexample's cells become related locations at their lines in the
// matrix file (line 18 is the object of intersection 2/1); a falsified
// property with none gets the elements it reads (effect 1 at line 8).
TEST(CheckPrinters, SarifRelatedLocationsAtTheMatrixLines) {
  CheckResult r = sample();
  r.properties[1].counterexample_support = {"intersection[2,1]"};
  const cemv::reports::CheckReportInputs in{"examples/tank-overfill/matrix.json", kMatrixText};
  auto s = nlohmann::json::parse(cemv::reports::check_report(r, in, CheckFormat::Sarif));
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& res : s["runs"][0]["results"]) by_name[res["properties"]["property"]] = res;
  const auto& cells = by_name["req5.stored_holds"]["relatedLocations"];
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0]["physicalLocation"]["artifactLocation"]["uri"], "examples/tank-overfill/matrix.json");
  EXPECT_EQ(cells[0]["physicalLocation"]["region"]["startLine"], 18);
  EXPECT_NE(cells[0]["message"]["text"].get<std::string>().find("intersection[2,1]"), std::string::npos);
  // The result itself stays at the property's line in its file.
  EXPECT_EQ(by_name["req5.stored_holds"]["locations"][0]["physicalLocation"]["region"]["startLine"], 30);
  // No cells: the elements it reads (the standard property "odd" reads none).
  r.properties[1].counterexample_support.clear();
  s = nlohmann::json::parse(cemv::reports::check_report(r, in, CheckFormat::Sarif));
  for (const auto& res : s["runs"][0]["results"]) {
    if (res["properties"]["property"] == "req5.stored_holds") {
      ASSERT_EQ(res["relatedLocations"].size(), 2u);  // effect[1], cause[1]
      EXPECT_EQ(res["relatedLocations"][0]["physicalLocation"]["region"]["startLine"], 8);
      EXPECT_EQ(res["relatedLocations"][1]["physicalLocation"]["region"]["startLine"], 3);
    }
  }
  // Only falsified properties get them.
  for (const auto& res : s["runs"][0]["results"]) {
    if (res["properties"]["verdict"] != "falsified") {
      EXPECT_FALSE(res.contains("relatedLocations"));
    }
  }
  // The documentation, relative to the repository: no invented host.
  const auto& driver = s["runs"][0]["tool"]["driver"];
  EXPECT_EQ(driver["informationUri"], "README.md");
  for (const auto& rule : driver["rules"]) EXPECT_EQ(rule["helpUri"], "docs/checker.md");
}

// --expect / --baseline: an expected negative verdict is a note in text, no
// failing test in JUnit, a suppressed result in SARIF; a verdict not as
// expected is an error, a failing test and a result, whatever the verdict.
TEST(CheckPrinters, ExpectedVerdictsInEveryFormat) {
  CheckResult r = sample();
  r.properties[1].expected = "falsified";  // req5.stored_holds: falsified, as expected
  r.properties[1].expected_from = "# expect:";
  r.properties[0].expected = "falsified";  // req1: proved, expected falsified
  r.properties[0].expected_from = "baseline base.json";
  const std::string text = render(r, CheckFormat::Text);
  EXPECT_NE(text.find("requirements.props:30:10: note: property 'req5.stored_holds' falsified at cycle 4 "
                      "(found by bmc) (as expected)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("requirements.props:12:10: error: property 'req1.overfill_closes_xv101' proved by "
                      "k-induction (k = 3), expected falsified (baseline base.json)"),
            std::string::npos)
      << text;
  const std::string junit = render(r, CheckFormat::Junit);
  EXPECT_NE(junit.find("failures=\"4\""), std::string::npos);  // req1, unreachable, vacuous, odd; not req5
  EXPECT_NE(junit.find("<failure type=\"proved\""), std::string::npos);
  auto s = nlohmann::json::parse(render(r, CheckFormat::Sarif));
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& res : s["runs"][0]["results"]) by_name[res["properties"]["property"]] = res;
  EXPECT_EQ(by_name["req5.stored_holds"]["suppressions"][0]["kind"], "inSource");
  EXPECT_EQ(by_name["req1.overfill_closes_xv101"]["ruleId"], "CEMV-NOT-AS-EXPECTED");
  EXPECT_FALSE(by_name["req1.overfill_closes_xv101"].contains("suppressions"));
  auto j = nlohmann::json::parse(render(r, CheckFormat::Json));
  EXPECT_EQ(j["properties"][1]["expected"], "falsified");
  EXPECT_TRUE(j["properties"][2]["expected"].is_null());
  // The lines -q prints: every property that did not pass, or not as expected.
  const std::string quiet = cemv::reports::check_findings(r, kInputs);
  EXPECT_EQ(std::count(quiet.begin(), quiet.end(), '\n'), 6) << quiet;  // all but the reachable one
}
