// The differential test (issue 4 section 2): the runtime and the encoder must
// agree on every observable in every cycle.
#include <gtest/gtest.h>

#include <filesystem>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "model/format.hpp"
#include "model/scenario.hpp"
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
    model::Matrix m = model::load_matrix(f);
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
    model::Matrix m = model::load_matrix(mf);
    model::Scenario sc;
    try {
      sc = model::load_scenario(sf, m);
    } catch (const model::LoadError&) {
      continue;  // negative scenario files (rejected input) are the runtime's tests
    }
    auto ex = model::expand_scenario(sc, m);
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
