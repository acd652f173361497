// One behaviour for the helpers every format shares (model/text.hpp,
// formats/diagnostics.hpp): the same typo gets the same hint in a matrix and
// in a scenario, names are quoted with control bytes escaped everywhere, and
// the scenario's `matrix` key, the refusal of an invalid matrix and the
// expectation loop behave as docs/scenario.md says.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "model/text.hpp"
#include "model/validate.hpp"

namespace cemv::formats {
namespace {

namespace fs = std::filesystem;

const fs::path kScenarios = fs::path(CEMV_SOURCE_DIR) / "tests" / "scenarios";

std::string read(const fs::path& p) { return read_text_file(p); }

model::Matrix ch13() { return load_matrix(kScenarios / "matrices" / "ch13_causes.json"); }

// The `what` of the first issue a matrix text with an unknown key in cause[0] gets.
std::string matrix_key_problem(const std::string& key) {
  std::string text = read(kScenarios / "matrices" / "ch13_causes.json");
  const std::string anchor = "{\"id\": 1, \"name\": \"ON_DELAY\",";
  auto at = text.find(anchor);
  EXPECT_NE(at, std::string::npos);
  text.insert(at + 1, "\"" + key + "\": \"x\", ");
  try {
    parse_matrix(text, "m.json");
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().at(0).where, "causes[0]." + key);
    return e.issues().at(0).what;
  }
  ADD_FAILURE() << "the matrix with key " << key << " loads";
  return "";
}

// The same for a scenario step.
std::string scenario_key_problem(const std::string& key) {
  try {
    parse_scenario("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"" + key + "\": \"x\"}]}", ch13());
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().at(0).where, "steps[0]." + key);
    return e.issues().at(0).what;
  }
  ADD_FAILURE() << "the scenario with key " << key << " loads";
  return "";
}

TEST(TypoHints, SameTypoSameHintInMatrixAndScenario) {
  // A swapped pair, a truncation, another case, and a word too far from any key.
  const std::vector<std::pair<std::string, std::string>> typos = {
      {"descripiton", "unknown key (did you mean 'description'?)"},
      {"desc", "unknown key (did you mean 'description'?)"},
      {"DESCRIPTION", "unknown key (did you mean 'description'?)"},
      {"descriptionxyzw", "unknown key"},
  };
  for (const auto& [typo, want] : typos) {
    EXPECT_EQ(matrix_key_problem(typo), want) << typo;
    EXPECT_EQ(scenario_key_problem(typo), want) << typo;
  }
}

TEST(TypoHints, OneRuleForTheDistance) {
  using model::did_you_mean;
  // Up to 3 letters one edit, up to 8 two, longer three; case does not count.
  EXPECT_EQ(did_you_mean("mx", std::vector<std::string>{"ms"}), " (did you mean 'ms'?)");
  EXPECT_EQ(did_you_mean("xy", std::vector<std::string>{"ms"}), "");
  EXPECT_EQ(did_you_mean("exepct", std::vector<std::string>{"expect"}), " (did you mean 'expect'?)");
  EXPECT_EQ(did_you_mean("ackcasue", std::vector<std::string>{"ack_cause"}), " (did you mean 'ack_cause'?)");
  EXPECT_EQ(did_you_mean("ON_DELAI", std::vector<std::string>{"on_delay"}), " (did you mean 'on_delay'?)");
  // Ties go to the first candidate.
  EXPECT_EQ(did_you_mean("ab", std::vector<std::string>{"ac", "ad"}), " (did you mean 'ac'?)");
}

TEST(Quoting, ControlBytesAreEscapedInEveryFormat) {
  EXPECT_EQ(model::in_quotes("A\x01" "B"), "'A\\x01B'");
  EXPECT_EQ(model::in_quotes(std::string(60, 'x')), "'" + std::string(48, 'x') + "...'");
  // A scenario naming an unknown tag with a control byte.
  try {
    parse_scenario("{\"format\": \"cemv-scenario/1\", \"steps\": [{\"inputs\": {\"I\\u0007\": true}}]}", ch13());
    ADD_FAILURE() << "loads";
  } catch (const LoadError& e) {
    EXPECT_NE(e.issues().at(0).what.find("unknown tag 'I\\x07'"), std::string::npos) << e.issues().at(0).what;
  }
}

// Found by fuzzing (docs/fuzzing.md): issues were placed by counting the line
// breaks before each one, quadratic in a file of many issues. LineIndex places
// them in one pass and must agree with line_and_column everywhere.
TEST(LineIndex, AgreesWithLineAndColumn) {
  const std::string text = "a\nbc\n\n{\n  \"x\": 1\n}";
  LineIndex lines(text);
  for (std::size_t i = 0; i <= text.size() + 2; ++i) {
    EXPECT_EQ(lines.line_and_column(i), line_and_column(text, i)) << "index " << i;
    EXPECT_EQ(lines.line_column(i), line_column(text, i)) << "index " << i;
  }
  LineIndex empty("");
  EXPECT_EQ(empty.line_and_column(0), (std::pair<std::size_t, std::size_t>{1, 1}));
}

// The guarded parse lists at most kMaxIssues bad numbers, then says it stopped.
TEST(GuardedJson, StopsListingBadNumbersAfterTheLimit) {
  std::string text = "[";
  for (int i = 0; i < 500; ++i) text += i == 0 ? "NaN" : ",\nNaN";
  text += "]";
  std::vector<LoadIssue> issues;
  EXPECT_FALSE(parse_guarded_json(text, "many.json", issues));
  ASSERT_EQ(issues.size(), kMaxIssues + 1);
  EXPECT_EQ(issues[1].line, 2u);
  EXPECT_EQ(issues.back().what, "too many problems; the rest are not listed");
}

TEST(ScenarioMatrixKey, ResolvedAgainstTheScenarioFolder) {
  auto p = scenario_matrix_path(kScenarios / "rejects" / "typo_tag.json");
  ASSERT_TRUE(p.has_value());
  EXPECT_EQ(*p, kScenarios / "rejects" / "../matrices/ch13_causes.json");
  EXPECT_TRUE(fs::exists(*p));
  // Parsed with the scenario (as written), and checked there too.
  auto sc = parse_scenario(R"({"format": "cemv-scenario/1", "matrix": "m.json", "steps": [{}]})", ch13());
  EXPECT_EQ(sc.matrix, "m.json");
  try {
    parse_scenario(R"({"format": "cemv-scenario/1", "matrix": "", "steps": [{}]})", ch13());
    ADD_FAILURE() << "an empty matrix path loads";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().at(0).where, "matrix");
  }
}

TEST(ScenarioMatrixKey, AbsentOrNotAString) {
  const fs::path dir = fs::temp_directory_path() / "cemv_test_diagnostics";
  fs::create_directories(dir);
  std::ofstream(dir / "none.json") << R"({"format": "cemv-scenario/1", "steps": [{}]})";
  std::ofstream(dir / "number.json") << R"({"format": "cemv-scenario/1", "matrix": 3, "steps": [{}]})";
  EXPECT_FALSE(scenario_matrix_path(dir / "none.json").has_value());
  EXPECT_THROW(scenario_matrix_path(dir / "number.json"), LoadError);
  EXPECT_THROW(scenario_matrix_path(dir / "missing.json"), LoadError);
  fs::remove_all(dir);
}

TEST(LoadValidMatrix, ListsEveryValidationError) {
  const fs::path bad = kScenarios / "matrices" / "matrix_with_x.json";
  auto errors = model::validate(load_matrix(bad));
  std::size_t error_count = 0;
  for (const auto& d : errors) error_count += d.severity == model::Severity::Error;
  ASSERT_GT(error_count, 0u);
  try {
    load_valid_matrix(bad, "simulated");
    ADD_FAILURE() << "an invalid matrix is accepted";
  } catch (const LoadError& e) {
    ASSERT_EQ(e.issues().size(), 1 + error_count);
    EXPECT_EQ(e.issues()[0].str(), bad.string() + ": the matrix has validation errors; it cannot be simulated");
    EXPECT_NE(e.issues()[1].str().find(": E-INTERSECTION-X intersection cause[1]/effect[1] ("), std::string::npos)
        << e.issues()[1].str();
  }
  EXPECT_NO_THROW(load_valid_matrix(kScenarios / "matrices" / "ch13_causes.json", "simulated"));
}

TEST(ExpectationChecker, ChecksAfterTheStepsLastCycleAndSaysWhatFailed) {
  model::Matrix m = ch13();
  auto sc = parse_scenario(
      R"({"format": "cemv-scenario/1", "steps": [{"cycles": 3, "expect": {"cause[1].active": true}},
                                                  {"expect": {"cause[1].active": false}}]})",
      m);
  auto ex = expand_scenario(sc, m);
  ExpectationChecker checker(ex);
  auto seven = [](const ExpectTarget&) -> std::optional<int> { return 7; };  // any non-zero is true
  EXPECT_TRUE(checker.after_cycle(0, seven).empty());
  EXPECT_TRUE(checker.after_cycle(1, seven).empty());
  auto third = checker.after_cycle(2, seven);
  ASSERT_EQ(third.size(), 1u);
  EXPECT_TRUE(third[0].ok);
  EXPECT_EQ(third[0].actual, 1);
  auto unknown = [](const ExpectTarget&) -> std::optional<int> { return std::nullopt; };
  auto fourth = checker.after_cycle(3, unknown);
  ASSERT_EQ(fourth.size(), 1u);
  EXPECT_FALSE(fourth[0].ok);
  EXPECT_EQ(fourth[0].failure_text(m.cycle_ms),
            "FAIL steps[1] (cycle 4, t = 300 ms): cause[1].active expected false, actual unknown");
  EXPECT_EQ(checker.checked(), 2u);
  EXPECT_EQ(checker.failed(), 1u);
}

}  // namespace
}  // namespace cemv::formats
