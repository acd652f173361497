// Every load issue names its place (formats/diagnostics.hpp): the file, then
// the line and column when there is one, as compilers write it.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "model/validate.hpp"

namespace cemv::formats {
namespace {

namespace fs = std::filesystem;
const fs::path kScenarios = fs::path(CEMV_SOURCE_DIR) / "tests" / "scenarios";

model::Matrix ch13() { return load_matrix(kScenarios / "matrices" / "ch13_causes.json"); }

// The messages of the issues a scenario text gets, as the CLI prints them.
std::vector<std::string> scenario_messages(const std::string& text, const model::Matrix& m = ch13()) {
  std::vector<std::string> out;
  try {
    parse_scenario(text, m, "s.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const LoadError& e) {
    for (const auto& i : e.issues()) out.push_back(i.message());
  }
  return out;
}

TEST(IssueMessage, EveryFormOfPlace) {
  EXPECT_EQ((LoadIssue{"causes[0].id", "bad", "m.json", 3, 7}).message(), "m.json:3:7: error: causes[0].id: bad");
  EXPECT_EQ((LoadIssue{"line 3, column 7", "bad", "m.json", 3, 7}).message(), "m.json:3:7: error: bad");
  EXPECT_EQ((LoadIssue{"m.json", "cannot open", "m.json"}).message(), "m.json: error: cannot open");
  EXPECT_EQ((LoadIssue{"format", "missing", "m.json"}).message(), "m.json: error: format: missing");
  // The CSV reader's places carry their file.
  EXPECT_EQ((LoadIssue{"g.csv: line 4, column 2", "odd"}).message(), "g.csv:4:2: error: odd");
  EXPECT_EQ((LoadIssue{"g.csv: line 4, columns 3-5", "odd"}).message("warning"), "g.csv:4: warning: columns 3-5: odd");
  // The property parser's.
  EXPECT_EQ((LoadIssue{"p.props:2:1", "unknown kind"}).message(), "p.props:2:1: error: unknown kind");
  EXPECT_EQ((LoadIssue{"", "nothing to say where"}).message(), "error: nothing to say where");
}

TEST(IssueMessage, InFileNamesOnlyIssuesWithoutAFile) {
  LoadError e({{"causes[0]", "a"}, {"x.csv: line 2", "b"}, {"p", "c", "other.json"}});
  LoadError placed = e.in_file("m.json");
  EXPECT_EQ(placed.issues()[0].message(), "m.json: error: causes[0]: a");
  EXPECT_EQ(placed.issues()[1].message(), "x.csv:2: error: b");
  EXPECT_EQ(placed.issues()[2].message(), "other.json: error: p: c");
}

TEST(JsonPositions, PathsAsTheLoadersSpellThem) {
  const std::string text = "{\n  \"a\": [1, {\"b c\": 2, \"d\": 3}],\n  \"e\": {\"f\": true, \"f\": false}\n}\n";
  JsonPositions p(text);
  auto at = [&](const std::string& path, bool last = false) {
    auto o = p.find(path, last);
    return o ? line_and_column(text, *o) : std::pair<std::size_t, std::size_t>{0, 0};
  };
  EXPECT_EQ(at("a"), (std::pair<std::size_t, std::size_t>{2, 3}));
  EXPECT_EQ(at("a[1]"), (std::pair<std::size_t, std::size_t>{2, 12}));
  EXPECT_EQ(at("a[1]['b c']"), (std::pair<std::size_t, std::size_t>{2, 13}));
  EXPECT_EQ(at("e.f"), (std::pair<std::size_t, std::size_t>{3, 9}));
  EXPECT_EQ(at("e.f", true), (std::pair<std::size_t, std::size_t>{3, 20}));
  // A missing member is placed at the closest enclosing path.
  auto enclosing = p.find_enclosing("a[1].missing");
  ASSERT_TRUE(enclosing);
  EXPECT_EQ(line_and_column(text, *enclosing), (std::pair<std::size_t, std::size_t>{2, 12}));
  EXPECT_FALSE(p.find_enclosing("nowhere"));
}

TEST(ScenarioJson, GuardedParserGivesCemvsOwnMessagesWithPositions) {
  EXPECT_EQ(scenario_messages("{\"format\": \"cemv-scenario/1\",\n \"steps\": [{\"cycles\": 1e999}]}").at(0),
            "s.json:2:23: error: number '1e999' is out of range (overflows a double)");
  EXPECT_EQ(scenario_messages("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"inputs\": {\"I1\": NaN}}]}").at(0),
            "s.json:1:59: error: 'NaN' is not a JSON number (JSON has no NaN or Infinity)");
  EXPECT_EQ(scenario_messages("{\"format\": \"cemv-scenario/1\",\n \"steps\": [{\"cycles\": 1,\n \"cycles\": 2}]}").at(0),
            "s.json:3:2: error: steps[0].cycles: duplicate key (a key may appear once per object)");
  EXPECT_EQ(scenario_messages("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"x\": \"\xff\"}]}").at(0),
            "s.json:1:48: error: invalid UTF-8: byte 0xFF does not belong here (a scenario is UTF-8 text; "
            "save it as UTF-8)");
  EXPECT_EQ(scenario_messages("").at(0), "s.json: error: file is empty (expected a cemv-scenario/1 JSON object)");
  // No library text: no "[json.exception".
  for (const auto& m : scenario_messages("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"cycles\": 1,}]}"))
    EXPECT_EQ(m.find("json.exception"), std::string::npos) << m;
}

TEST(ScenarioJson, ObjectsMayHaveMoreMembersThanAMatrixObject) {
  std::string inputs;
  for (int i = 0; i < 300; ++i) inputs += (i ? ", " : "") + std::string("\"X") + std::to_string(i) + "\": true";
  auto messages = scenario_messages("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"inputs\": {" + inputs + "}}]}");
  // Refused for the unknown tags, not for the size of the object.
  EXPECT_NE(messages.at(0).find("none of the scenario's 300 tags is in matrix CH13_CAUSES"), std::string::npos)
      << messages.at(0);
}

TEST(ScenarioJson, PathIssuesArePlaced) {
  auto m = scenario_messages("{\"format\": \"cemv-scenario/1\",\n \"steps\": [\n  {\"ms\": 250}]}");
  EXPECT_EQ(m.at(0), "s.json:3:4: error: steps[0].ms: 250 is not a multiple of cycle_ms (100)");
}

TEST(ScenarioHint, MostlyUnknownTagsSuggestAnotherMatrix) {
  auto all = scenario_messages(
      R"({"format": "cemv-scenario/1", "steps": [{"inputs": {"A1": true, "A2": true, "A3": true}}]})");
  EXPECT_EQ(all.at(0), "s.json: error: none of the scenario's 3 tags is in matrix CH13_CAUSES; is it the scenario "
                       "of another matrix?");
  auto most = scenario_messages(
      R"({"format": "cemv-scenario/1", "steps": [{"inputs": {"I1": true, "A2": true, "A3": true}}]})");
  EXPECT_EQ(most.at(0), "s.json: error: 2 of the scenario's 3 tags are not in matrix CH13_CAUSES; is it the "
                        "scenario of another matrix?");
  // A typo among known tags is only a typo.
  auto typo = scenario_messages(
      R"({"format": "cemv-scenario/1", "steps": [{"inputs": {"I1": true, "I2": true, "I33": true}}]})");
  EXPECT_EQ(typo.size(), 1u);
  EXPECT_NE(typo.at(0).find("unknown tag 'I33'"), std::string::npos);
}

TEST(ElementOffset, FindingsArePlacedAtTheirElement) {
  const std::string text = read_text_file(kScenarios / "matrices" / "matrix_with_x.json");
  JsonPositions p(text);
  auto at = [&](const std::string& element) {
    auto o = element_offset(p, element);
    return o ? line_and_column(text, *o) : std::pair<std::size_t, std::size_t>{0, 0};
  };
  EXPECT_EQ(at("matrix"), (std::pair<std::size_t, std::size_t>{1, 1}));
  EXPECT_NE(at("cause[1]").first, 0u);
  EXPECT_NE(at("intersection cause[1]/effect[1]").first, 0u);
  EXPECT_EQ(at("cause[99]").first, 0u);
  // load_valid_matrix's refusal lines carry them.
  try {
    load_valid_matrix(kScenarios / "matrices" / "matrix_with_x.json", "simulated");
    FAIL() << "accepted";
  } catch (const LoadError& e) {
    ASSERT_GE(e.issues().size(), 2u);
    EXPECT_EQ(e.issues()[1].line, at("intersection cause[1]/effect[1]").first);
  }
}

}  // namespace
}  // namespace cemv::formats
