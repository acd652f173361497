// The differential test (issue 4 section 2): the runtime and the encoder must
// agree on every observable in every cycle.
#include <gtest/gtest.h>

#include <filesystem>

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

// Every scenario next to an example or under tests/scenarios: the encoder meets
// each expectation, and agrees with the runtime on every cycle.
TEST(Scenarios, EncoderMeetsExpectationsAndAgrees) {
  std::vector<std::pair<fs::path, fs::path>> cases;  // matrix, scenario
  for (const auto& f : example_matrices())
    for (const auto& s : fs::directory_iterator(f.parent_path()))
      if (s.path().filename().string().starts_with("scenario") && s.path().extension() == ".json")
        cases.emplace_back(f, s.path());
  fs::path extra = fs::path(CEMV_SOURCE_DIR) / "tests" / "scenarios";
  if (fs::exists(extra))
    for (const auto& s : fs::recursive_directory_iterator(extra)) {
      if (s.path().extension() != ".json" || s.path().filename() == "matrix.json") continue;
      fs::path mx = s.path().parent_path() / "matrix.json";
      if (fs::exists(mx)) cases.emplace_back(mx, s.path());
    }
  std::sort(cases.begin(), cases.end());
  ASSERT_FALSE(cases.empty());
  int checked = 0;
  for (const auto& [mf, sf] : cases) {
    model::Matrix m = formats::load_matrix(mf);
    formats::Scenario sc;
    try {
      sc = formats::load_scenario(sf, m);
    } catch (const formats::LoadError&) {
      continue;  // negative scenario files (rejected input) are the runtime's tests
    }
    auto ex = formats::expand_scenario(sc, m);
    z3::context ctx;
    auto enc = encoder::encode(ctx, m);
    encoder::Evaluator ev(*enc);
    std::size_t next_check = 0;
    for (std::size_t k = 0; k < ex.cycles.size(); ++k) {
      model::CycleInput in = ex.cycles[k];
      in.commands = enc->canonical_commands(in.commands);
      ev.step(in);
      while (next_check < ex.checks.size() && ex.checks[next_check].cycle == k) {
        for (const auto& e : *ex.checks[next_check].expect) {
          int actual = ev.value(e.target.observable.key);
          EXPECT_EQ(actual, e.expected) << sf << " " << e.where << " (" << e.key << ") cycle " << k;
          ++checked;
        }
        ++next_check;
      }
    }
    auto d = encoder_test::compare(m, ex.cycles);
    EXPECT_FALSE(d.has_value()) << sf << "\n" << encoder_test::report(0, m, ex.cycles, *d);
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
