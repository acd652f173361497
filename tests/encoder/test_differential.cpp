// The differential test (docs/encoding.md): the runtime and the encoder must
// agree on every observable in every cycle.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "tests/encoder/diff_support.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

namespace fs = std::filesystem;
using namespace cemv;

namespace {

constexpr int kShards = 6;
constexpr int kMatricesPerShard = 50;  // 6 x 50 = 300 matrices
constexpr int kCycles = 300;

class RandomShard : public ::testing::TestWithParam<int> {};

TEST_P(RandomShard, RuntimeAndEncoderAgreeEveryCycle) {
  int shard = GetParam();
  for (int i = 0; i < kMatricesPerShard; ++i) {
    std::uint64_t seed = 1000u + static_cast<std::uint64_t>(shard * kMatricesPerShard + i);
    model::Matrix m = testsupport::random_matrix(seed);
    auto inputs = testsupport::random_inputs(m, seed, kCycles);
    auto d = encoder_test::compare(m, inputs);
    ASSERT_FALSE(d.has_value()) << encoder_test::report(seed, m, inputs, *d);
  }
}
INSTANTIATE_TEST_SUITE_P(Shards, RandomShard, ::testing::Range(0, kShards));

// Larger matrices (up to 30 causes, 12 effects): more references, cycles,
// first-out groups and XooN assignments per matrix.
class LargeShard : public ::testing::TestWithParam<int> {};

TEST_P(LargeShard, RuntimeAndEncoderAgreeEveryCycle) {
  testsupport::MatrixOptions opt;
  opt.min_causes = 10;
  opt.max_causes = 30;
  opt.min_effects = 4;
  opt.max_effects = 12;
  for (int i = 0; i < 15; ++i) {
    std::uint64_t seed = 500000u + static_cast<std::uint64_t>(GetParam() * 15 + i);
    model::Matrix m = testsupport::random_matrix(seed, opt);
    auto inputs = testsupport::random_inputs(m, seed, kCycles);
    auto d = encoder_test::compare(m, inputs);
    ASSERT_FALSE(d.has_value()) << encoder_test::report(seed, m, inputs, *d);
  }
}
INSTANTIATE_TEST_SUITE_P(Shards, LargeShard, ::testing::Range(0, 2));

// Tags whose simulation is not allowed (O.8): both refuse simulate_tag on
// them, whatever the value, and agree on everything else.
TEST(SimulationRestricted, RuntimeAndEncoderAgreeEveryCycle) {
  testsupport::MatrixOptions opt;
  opt.p_simulation_forbidden = 0.4;
  int restricted = 0;
  for (int i = 0; i < 40; ++i) {
    std::uint64_t seed = 700000u + static_cast<std::uint64_t>(i);
    model::Matrix m = testsupport::random_matrix(seed, opt);
    for (const auto& c : m.causes)
      for (const auto& t : c.tags) restricted += !t.simulation_allowed;
    auto inputs = testsupport::random_inputs(m, seed, kCycles);
    auto d = encoder_test::compare(m, inputs);
    ASSERT_FALSE(d.has_value()) << encoder_test::report(seed, m, inputs, *d);
  }
  EXPECT_GT(restricted, 10);  // the option was exercised
}

// Regression (found by the differential test, seed 1169, while the runtime was
// in progress): a group deactivation ends a running override in the cycle
// where req_R falls. E.5 clears the R latch because the override was running
// at the end of the previous cycle (E.3 `was_running`), so the effect goes
// inactive without a reset.
TEST(Regression, GroupDeactivationEndingOverrideWhileRequestFallsClearsRLatch) {
  model::Matrix m;
  m.name = "REG";
  m.cycle_ms = 100;
  m.group_deactivation = model::GroupDeactivation{"EN_GDM", "SET_GDM"};
  model::Cause c;
  c.id = 1;
  c.name = "C1";
  c.tags.push_back({"IN1", false, true});
  m.causes.push_back(c);
  model::Effect e;
  e.id = 1;
  e.name = "E1";
  e.tags.push_back({"OUT1", false});
  e.reset_tag = "RST";
  e.override_time = model::Override{10, 0};
  m.effects.push_back(e);
  m.intersections.push_back({1, 1, model::IntersectionType::R, std::nullopt, ""});
  model::InputTable t(m);
  auto frame = [&](float in1, float rst, float en, float set) {
    model::CycleInput f;
    f.tags.resize(t.size());
    f.tags[*t.find("IN1")].value = in1;
    f.tags[*t.find("RST")].value = rst;
    f.tags[*t.find("EN_GDM")].value = en;
    f.tags[*t.find("SET_GDM")].value = set;
    return f;
  };
  std::vector<model::CycleInput> in = {frame(1, 0, 0, 0), frame(0, 0, 0, 0), frame(0, 1, 0, 0),
                                       frame(0, 0, 0, 0), frame(1, 0, 1, 1), frame(1, 0, 1, 1)};
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  std::vector<int> active, latched, override_active;
  for (const auto& f : in) {
    ev.step(f);
    active.push_back(ev.value("effect[1].active"));
    latched.push_back(ev.value("effect[1].latched"));
    override_active.push_back(ev.value("effect[1].override_active"));
  }
  EXPECT_EQ(active, (std::vector<int>{0, 1, 0, 0, 0, 0}));
  EXPECT_EQ(override_active, (std::vector<int>{0, 0, 1, 1, 0, 0}));
  EXPECT_EQ(latched, (std::vector<int>{0, 1, 1, 1, 0, 0}));
  auto d = encoder_test::compare(m, in);
  EXPECT_FALSE(d.has_value()) << encoder_test::report(0, m, in, *d);
}

std::vector<fs::path> example_matrices() {
  std::vector<fs::path> out;
  fs::path root = fs::path(CEMV_SOURCE_DIR) / "examples";
  if (fs::exists(root))
    for (const auto& d : fs::directory_iterator(root))
      if (fs::exists(d.path() / "matrix.json")) out.push_back(d.path() / "matrix.json");
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Examples, RandomInputsAgree) {
  auto files = example_matrices();
  ASSERT_FALSE(files.empty());
  for (const auto& f : files) {
    model::Matrix m = formats::load_matrix(f);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      auto inputs = testsupport::random_inputs(m, seed, kCycles);
      auto d = encoder_test::compare(m, inputs);
      ASSERT_FALSE(d.has_value()) << f << "\n" << encoder_test::report(seed, m, inputs, *d);
    }
  }
}

// Every scenario of the project: next to each example (scenario-*.json) and
// under tests/scenarios (rejects/ included). Each names its matrix with its
// "matrix" key (docs/scenario.md), so no test keeps a mapping of its own.
std::vector<fs::path> every_scenario() {
  std::vector<fs::path> out;
  for (const auto& f : example_matrices())
    for (const auto& s : fs::directory_iterator(f.parent_path()))
      if (s.path().filename().string().starts_with("scenario") && s.path().extension() == ".json")
        out.push_back(s.path());
  const fs::path root = fs::path(CEMV_SOURCE_DIR) / "tests" / "scenarios";
  for (const fs::path& dir : {root, root / "rejects"})
    for (const auto& s : fs::directory_iterator(dir))
      if (s.path().extension() == ".json") out.push_back(s.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The scenario files that must not load, each with a part of the reason
// (tests/scenarios/scenarios.cmake checks the whole message of each).
const std::map<std::string, std::string> kRejectionCases = {
    {"rejects/ms_not_multiple.json", "250 is not a multiple of cycle_ms"},
    {"rejects/syntax_error.json", "JSON syntax error"},
    {"rejects/trivial.json", "the matrix has validation errors"},
    {"rejects/typo_tag.json", "unknown tag 'INHI13'"},
    {"rejects/unknown_command.json", "unknown command 'reset_cause'"},
    {"rejects/unknown_expect_cause.json", "no cause named 'ON_DELAI'"},
    {"rejects/unknown_expect_field.json", "unknown cause field 'actived'"},
    {"rejects/unknown_expect_key.json", "unknown expectation key 'O99'"},
    {"rejects/unknown_step_key.json", "expekt: unknown key"},
};
// Scenarios that load but expect something wrong on purpose: the encoder must
// fail exactly the expectations the runtime fails (scenario_failing_expectation_exit_1).
const std::map<std::string, std::vector<std::string>> kFailingCases = {
    {"rejects/failing_expectation.json",
     {"FAIL steps[1] (cycle 21, t = 2000 ms): cause[1].active expected true, actual false"}},
};

// The name a scenario has in the two lists above.
std::string case_name(const fs::path& scenario) {
  return scenario.parent_path().filename() == "rejects" ? "rejects/" + scenario.filename().string()
                                                        : scenario.filename().string();
}

std::string issues_text(const formats::LoadError& e) {
  std::string text;
  for (const auto& i : e.issues()) text += i.str() + "\n";
  return text;
}

// Every scenario reaches the encoder (docs/encoding.md): the encoder meets each
// expectation, and agrees with the runtime on every cycle. A file that does not
// load fails the test unless it is a listed rejection case.
TEST(Scenarios, EncoderMeetsExpectationsAndAgrees) {
  const auto scenarios = every_scenario();
  ASSERT_FALSE(scenarios.empty());
  std::set<std::string> rejected;
  std::size_t checked = 0, encoded = 0;
  for (const auto& sf : scenarios) {
    const std::string name = case_name(sf);
    model::Matrix m;
    formats::Scenario sc;
    try {
      auto mf = formats::scenario_matrix_path(sf);
      ASSERT_TRUE(mf.has_value()) << sf << " names no matrix (its \"matrix\" key)";
      m = formats::load_valid_matrix(*mf, "encoded");
      sc = formats::load_scenario(sf, m);
    } catch (const formats::LoadError& e) {
      auto listed = kRejectionCases.find(name);
      if (listed == kRejectionCases.end()) {
        ADD_FAILURE() << sf << " does not load and is not a rejection case:\n" << issues_text(e);
      } else {
        EXPECT_NE(issues_text(e).find(listed->second), std::string::npos)
            << sf << " is rejected for another reason than \"" << listed->second << "\":\n" << issues_text(e);
        rejected.insert(name);
      }
      continue;
    }
    EXPECT_EQ(kRejectionCases.count(name), 0u) << sf << " is a rejection case but loads";
    auto ex = formats::expand_scenario(sc, m);
    z3::context ctx;
    auto enc = encoder::encode(ctx, m);
    encoder::Evaluator ev(*enc);
    formats::ExpectationChecker checker(ex);
    auto value = [&](const formats::ExpectTarget& t) -> std::optional<int> { return ev.value(t.observable.key); };
    std::vector<std::string> failures;
    for (std::size_t k = 0; k < ex.cycles.size(); ++k) {
      model::CycleInput in = ex.cycles[k];
      in.commands = enc->canonical_commands(in.commands);
      ev.step(in);
      for (const auto& o : checker.after_cycle(k, value))
        if (!o.ok) failures.push_back(o.failure_text(m.cycle_ms));
    }
    auto failing = kFailingCases.find(name);
    EXPECT_EQ(failures, failing == kFailingCases.end() ? std::vector<std::string>{} : failing->second)
        << sf << " (" << name << ")";
    checked += checker.checked();
    ++encoded;
    auto d = encoder_test::compare(m, ex.cycles);
    EXPECT_FALSE(d.has_value()) << sf << "\n" << encoder_test::report(0, m, ex.cycles, *d);
  }
  for (const auto& [name, reason] : kRejectionCases)
    EXPECT_EQ(rejected.count(name), 1u) << name << " was expected to be rejected (" << reason << ")";
  EXPECT_EQ(encoded + rejected.size(), scenarios.size());
  EXPECT_GT(checked, 0u);
}

}  // namespace
