// The mutation report on a matrix with an internal reference and a comment
// cause (docs/mutation.md, docs/testgen.md "reference" objectives): an N cell
// added where the effect already follows the cause through `Effect[1][1]` is
// detected by the suite (the `reference` objective forces the output), and
// the comment cause made `normal` is equivalent on the common observables,
// its only difference its interface.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "mutate/mutants.hpp"
#include "mutate/mutation_report.hpp"
#include "testgen/testgen.hpp"

namespace {

using namespace cemv;

const char* kMatrix = R"({
  "format": "cemv-matrix/1", "name": "REFS", "cycle_ms": 100,
  "causes": [
    {"id": 1, "name": "HS_1", "function": "normal", "tags": [{"name": "HS_1", "ett": true}]},
    {"id": 2, "name": "XV1_OFF", "function": "normal", "bad_quality": "ignore",
     "tags": [{"name": "Effect[1][1]", "ett": false, "soft_bypass_allowed": false}], "soft_bypass": {"allowed": false}},
    {"id": 3, "name": "LSL_3", "function": "comment", "tags": [{"name": "LSL_3"}]}
  ],
  "effects": [
    {"id": 1, "name": "XV_1", "tags": [{"name": "XV_1", "ett": false}]},
    {"id": 2, "name": "XV_2", "tags": [{"name": "XV_2", "ett": false}]}
  ],
  "intersections": [
    {"cause": 1, "effect": 1, "type": "N"},
    {"cause": 2, "effect": 2, "type": "N"},
    {"cause": 3, "effect": 1, "type": "*"}
  ]
})";

TEST(MutationReport, ReferenceObjectiveAndInterfaceOnlyMutants) {
  const model::Matrix m = formats::parse_valid_matrix(kMatrix, "refs.json", "tested");
  const testgen::TestSuite suite = testgen::generate_tests(m);
  const auto apart = std::find_if(suite.objectives.begin(), suite.objectives.end(),
                                  [](const auto& r) { return r.objective.id == "reference.c1.e2.apart"; });
  ASSERT_NE(apart, suite.objectives.end());
  EXPECT_TRUE(apart->objective.simulates);
  ASSERT_EQ(apart->status, testgen::ObjectiveStatus::Covered) << apart->reason;
  // Its test forces the output that cause 2 reads.
  EXPECT_NE(suite.tests[apart->test].scenario_json.find("simulate_tag"), std::string::npos);
  // No other objective's witness may force a tag.
  for (const auto& r : suite.objectives) {
    if (!r.objective.simulates) {
      EXPECT_EQ(r.objective.property.assumptions.size(), 2u) << r.objective.id;  // no simulate_tag, no stop_simulation
    }
  }

  mutate::MutationOptions mo;
  const mutate::MutationReport report = mutate::mutation_report(m, suite, mo);
  auto find = [&](const std::string& id) {
    const auto it = std::find_if(report.mutants.begin(), report.mutants.end(), [&](const auto& o) { return o.id == id; });
    EXPECT_NE(it, report.mutants.end()) << id;
    return it;
  };
  const auto added = find("intersection-added.N.c1e2");
  ASSERT_NE(added, report.mutants.end());
  EXPECT_EQ(added->status, mutate::MutantStatus::Detected);
  const auto normal = find("cause-function.normal.c3");
  ASSERT_NE(normal, report.mutants.end());
  EXPECT_EQ(normal->status, mutate::MutantStatus::Equivalent) << normal->equivalence.reason;
  EXPECT_EQ(normal->equivalence.basis, checker::EquivalenceBasis::InterfaceOnly);
  EXPECT_EQ(normal->equivalence.method, "interface-only");
  EXPECT_NE(normal->equivalence.reason.find("cause[3].active"), std::string::npos);
  EXPECT_GE(report.interface_only, 1u);
  EXPECT_EQ(report.survived, 0u);
}

// `cemv mutate --suite --jobs N`: the report does not depend on N.
TEST(MutationReport, TheReportDoesNotDependOnJobs) {
  const model::Matrix m = formats::parse_valid_matrix(kMatrix, "refs.json", "tested");
  const testgen::TestSuite suite = testgen::generate_tests(m);
  mutate::MutationOptions one, three;
  three.jobs = 3;
  const mutate::MutationReport a = mutate::mutation_report(m, suite, one);
  EXPECT_GT(a.detected, 0u);
  EXPECT_EQ(mutate::report_json(a), mutate::report_json(mutate::mutation_report(m, suite, three)));
}

// A mutant's verdict replay stops each test at its first failure: the same
// tests fail as when every test runs to its end.
TEST(MutationReport, VerdictReplayFailsTheTestsAFullReplayFails) {
  const model::Matrix m = formats::parse_valid_matrix(kMatrix, "refs.json", "tested");
  const testgen::TestSuite suite = testgen::generate_tests(m);
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& t : suite.tests) texts.emplace_back(t.file_name, t.scenario_json);
  std::size_t failures = 0;
  for (const auto& mu : mutate::mutants(m).mutants) {
    const testgen::ReplayResult full = testgen::replay_texts(mu.matrix, texts);
    const testgen::ReplayResult verdicts = testgen::replay_verdicts(mu.matrix, texts);
    ASSERT_EQ(full.tests.size(), verdicts.tests.size());
    for (std::size_t i = 0; i < full.tests.size(); ++i) {
      EXPECT_EQ(full.tests[i].passed, verdicts.tests[i].passed) << mu.id << " " << full.tests[i].name;
      EXPECT_LE(verdicts.tests[i].cycles, full.tests[i].cycles) << mu.id;
      if (full.tests[i].passed) {
        EXPECT_EQ(full.tests[i].cycles, verdicts.tests[i].cycles) << mu.id;
        EXPECT_EQ(full.tests[i].expectations, verdicts.tests[i].expectations) << mu.id;
      } else {
        ++failures;
      }
    }
  }
  EXPECT_GT(failures, 3u);
}

}  // namespace
