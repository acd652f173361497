// The one writer of cemv-scenario/1 (formats/scenario_writer.hpp) against its
// reader: seeded random runs of random matrices with every option, cut into
// steps at random checkpoints, read back as the same cycles and expectations.
#include <cstring>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "formats/scenario.hpp"
#include "formats/scenario_writer.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv {
namespace {

// The commands the reader can resolve: random runs also issue commands with
// unknown targets, which the runtime refuses and a file cannot name.
void keep_nameable(const model::Matrix& m, std::vector<model::CycleInput>& cycles) {
  using Op = model::CommandOp;
  const model::InputTable table(m);
  auto cause = [&](int id) {
    const model::Cause* c = m.find_cause(id);
    return c && c->function != model::CauseFunction::Comment;
  };
  auto effect = [&](int id) {
    const model::Effect* e = m.find_effect(id);
    return e && e->function != model::EffectFunction::Comment;
  };
  auto nameable = [&](const model::Command& x) {
    switch (x.op) {
      case Op::AckCause:
      case Op::SoftBypassCause: return cause(x.cause);
      case Op::SoftBypassTag:
        return cause(x.cause) && x.tag >= 1 && x.tag <= static_cast<int>(m.find_cause(x.cause)->tags.size());
      case Op::ResetEffect:
      case Op::OverrideEffect:
      case Op::StopOverride:
      case Op::SoftBypassEffect: return effect(x.effect);
      case Op::SimulateTag: return table.find(x.tag_name).has_value();
      case Op::StopSimulation: return x.tag_name.empty() || table.find(x.tag_name).has_value();
      case Op::ClearFirstOut: return x.group >= 1 && x.group <= model::kMaxFirstOutGroup;
      case Op::ClearAlarms: return x.cause != 0 ? cause(x.cause) : effect(x.effect);
    }
    return false;
  };
  for (auto& c : cycles) std::erase_if(c.commands, [&](const model::Command& x) { return !nameable(x); });
}

bool same_command(const model::Command& a, const model::Command& b) {
  return a.op == b.op && a.cause == b.cause && a.effect == b.effect && a.tag == b.tag && a.group == b.group &&
         a.on == b.on && a.tag_name == b.tag_name && std::memcmp(&a.value, &b.value, sizeof(float)) == 0;
}

TEST(ScenarioWriter, RandomRunsReadBackAsWritten) {
  int runs = 0, failures = 0;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    const model::Matrix m = testsupport::random_matrix(seed);
    auto cycles = testsupport::random_inputs(m, seed * 7, 120);
    keep_nameable(m, cycles);
    const auto all = model::observables(m);
    std::mt19937_64 rng(seed);
    std::vector<std::size_t> checkpoints;
    for (std::size_t k = 0; k < cycles.size(); ++k)
      if (rng() % 9 == 0) checkpoints.push_back(k);
    formats::ScenarioRun run;
    run.description = "seed " + std::to_string(seed);
    run.cycles = cycles;
    run.durations = seed % 2 ? formats::Durations::Cycles : formats::Durations::Milliseconds;
    run.first_step_states_every_input = seed % 3 == 0;
    std::size_t k = 0;
    std::vector<std::vector<formats::ExpectedValue>> expected;
    for (std::size_t n : formats::step_lengths(cycles, checkpoints)) {
      formats::WrittenStep s;
      s.cycles = n;
      if (rng() % 2) s.description = "step at " + std::to_string(k);
      std::vector<formats::ExpectedValue> e;
      for (int i = 0; i < 3; ++i) {
        const auto& o = all[rng() % all.size()];
        const int v = o.type == model::FieldType::Bool ? int(rng() % 2)
                      : o.type == model::FieldType::Int ? int(rng() % 4)
                                                          : int(rng() % 7);
        e.push_back({o.key, o.type, v});
      }
      if (rng() % 2) s.expect = e;
      expected.push_back(s.expect.value_or(std::vector<formats::ExpectedValue>{}));
      run.steps.push_back(s);
      k += n;
    }
    const std::string text = formats::scenario_text(m, run);
    formats::Scenario sc;
    try {
      sc = formats::parse_scenario(text, m, "written");
    } catch (const formats::LoadError& e) {
      ADD_FAILURE() << seed << ": " << e.what() << "\n" << text.substr(0, 2000);
      continue;
    }
    ++runs;
    const auto ex = formats::expand_scenario(sc, m);
    ASSERT_EQ(ex.cycles.size(), cycles.size()) << seed;
    for (std::size_t c = 0; c < cycles.size(); ++c) {
      for (std::size_t i = 0; i < cycles[c].tags.size(); ++i) {
        const auto &a = cycles[c].tags[i], &b = ex.cycles[c].tags[i];
        const bool same = a.bad_quality == b.bad_quality && std::memcmp(&a.value, &b.value, sizeof(float)) == 0;
        failures += !same;
        EXPECT_TRUE(same) << seed << " cycle " << c << " tag " << i;
      }
      ASSERT_EQ(cycles[c].commands.size(), ex.cycles[c].commands.size()) << seed << " cycle " << c;
      for (std::size_t j = 0; j < cycles[c].commands.size(); ++j)
        EXPECT_TRUE(same_command(cycles[c].commands[j], ex.cycles[c].commands[j])) << seed << " cycle " << c;
    }
    ASSERT_EQ(sc.steps.size(), run.steps.size()) << seed;
    for (std::size_t s = 0; s < sc.steps.size(); ++s) {
      EXPECT_EQ(sc.steps[s].description, run.steps[s].description.value_or("")) << seed;
      // A key written twice in one step is one expectation, the last value.
      std::map<std::string, int> want;
      for (const auto& x : expected[s]) want[x.key] = x.value;
      std::map<std::string, int> got;
      for (const auto& x : sc.steps[s].expect) got[x.key] = x.expected;
      EXPECT_EQ(got, want) << seed << " step " << s;
    }
    if (failures > 20) break;
  }
  EXPECT_EQ(runs, 30);
}

// A run whose steps would not repeat it is refused, never written wrong.
TEST(ScenarioWriter, StepsThatDoNotRepeatTheRunAreRefused) {
  const model::Matrix m = testsupport::random_matrix(3);
  auto cycles = testsupport::random_inputs(m, 5, 40);
  formats::ScenarioRun run;
  run.cycles = cycles;
  run.steps.push_back({cycles.size() - 1, std::nullopt, std::nullopt});
  EXPECT_THROW(formats::scenario_text(m, run), std::logic_error);  // one cycle left over
  run.steps = {{cycles.size(), std::nullopt, std::nullopt}};
  EXPECT_THROW(formats::scenario_text(m, run), std::logic_error);  // inputs change inside the one step
}

}  // namespace
}  // namespace cemv
