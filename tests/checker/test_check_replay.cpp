// The checker never reports a counterexample that the reference runtime does
// not reproduce. A wrong rule planted in the encoding (the transition system
// the engines search) yields a trace that the runtime, judged by the concrete
// evaluator, does not violate: check_properties must stop with InternalError
// (exit 4 at the command line), showing where the two sides differ.
#include <filesystem>
#include <optional>

#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "checker/replay.hpp"
#include "encoder/encode.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "properties/parser.hpp"

namespace {

using namespace cemv;

model::Matrix tank() {
  return formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
}

// With the hard bypass key off and no soft bypass, cause 1 is never bypassed.
constexpr const char* kNeverBypassed = R"(
property cause1.not_bypassed "cause 1 is not bypassed while its key is off" {
  assume not HS_100_BYP
  assume not issued(soft_bypass_cause)
  never cause[1].bypassed
}
)";

checker::CheckOptions quick() {
  checker::CheckOptions o;
  o.property_timeout_s = 60;
  o.support = false;
  return o;
}

TEST(CheckReplay, HonestEncodingProvesTheProperty) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kNeverBypassed, m, "never_bypassed.props");
  auto r = checker::check_properties(m, {file}, quick());
  ASSERT_EQ(r.properties.size(), 1u);
  EXPECT_EQ(r.properties[0].verdict, checker::PropertyVerdict::Proved) << r.properties[0].reason;
}

TEST(CheckReplay, PlantedWrongRuleIsCaughtByTheRuntimeReplay) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kNeverBypassed, m, "never_bypassed.props");
  checker::CheckOptions o = quick();
  // The planted rule: cause 1 reads as bypassed in every cycle.
  o.modify_encoding = [](encoder::Encoding& enc) {
    enc.ts.name_term("cause[1].bypassed", enc.ts.ctx().bool_val(true));
  };
  try {
    checker::check_properties(m, {file}, o);
    FAIL() << "a counterexample the runtime does not reproduce was reported";
  } catch (const checker::InternalError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("does not reproduce"), std::string::npos) << what;
    EXPECT_NE(what.find("cause[1].bypassed"), std::string::npos) << what;
  }
}

// Directed runs (CheckOptions::directed_runs): a candidate counterexample
// from the caller, found on the runtime, must also violate the property on
// the encoding before it is reported.
constexpr const char* kCause2NeverActive = R"(
property cause2.never_active "cause 2 never trips" {
  never cause[2].active
}
)";

// The plant at rest, then LSHH_100 tripped for `tripped` cycles.
std::vector<model::CycleInput> high_level_switch_run(const model::Matrix& m, int tripped) {
  const model::CycleInput rest = model::default_cycle_input(m);
  model::CycleInput trip = rest;
  trip.tags[*model::InputTable(m).find("LSHH_100")].value = m.find_cause(2)->tags[0].ett ? 1.0f : 0.0f;
  std::vector<model::CycleInput> run{rest};
  run.resize(1 + static_cast<std::size_t>(tripped), trip);
  return run;
}

TEST(CheckReplay, DirectedRunThatViolatesIsTheCounterexample) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kCause2NeverActive, m, "cause2.props");
  checker::CheckOptions o = quick();
  o.directed_runs = {std::vector<model::CycleInput>(3, model::default_cycle_input(m)),
                     high_level_switch_run(m, 3)};
  auto r = checker::check_properties(m, {file}, o);
  const auto& p = r.properties.at(0);
  ASSERT_EQ(p.verdict, checker::PropertyVerdict::Falsified) << p.reason;
  EXPECT_EQ(p.method, "directed run");
  // Cause 2 trips in the cycle its switch does: the run is cut there.
  EXPECT_EQ(p.violation_cycle, 1);
  ASSERT_TRUE(p.trace.has_value());
  EXPECT_EQ(p.trace->inputs.size(), 2u);
}

TEST(CheckReplay, DirectedRunsThatDoNotViolateLeaveTheEngines) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kCause2NeverActive, m, "cause2.props");
  checker::CheckOptions o = quick();
  o.directed_runs = {std::vector<model::CycleInput>(3, model::default_cycle_input(m))};
  auto r = checker::check_properties(m, {file}, o);
  const auto& p = r.properties.at(0);
  ASSERT_EQ(p.verdict, checker::PropertyVerdict::Falsified) << p.reason;
  EXPECT_EQ(p.method, "bmc");
}

TEST(CheckReplay, DirectedRunTheEncodingDoesNotReproduceIsAnInternalError) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kCause2NeverActive, m, "cause2.props");
  checker::CheckOptions o = quick();
  o.directed_runs = {high_level_switch_run(m, 3)};
  // The planted rule: cause 2 never reads as active in the encoding.
  o.modify_encoding = [](encoder::Encoding& enc) {
    enc.ts.name_term("cause[2].active", enc.ts.ctx().bool_val(false));
  };
  try {
    checker::check_properties(m, {file}, o);
    FAIL() << "a directed run the encoding does not reproduce was reported";
  } catch (const checker::InternalError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("directed run, the encoding does not"), std::string::npos) << what;
  }
}

// encoded_trace is the inverse of cycle_inputs on what the encoding reads:
// values (Bool and Float32) and qualities of the encoded tags; a cycle with a
// command is refused.
TEST(CheckReplay, EncodedTraceIsTheInverseOfCycleInputs) {
  model::Matrix m = tank();
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  std::vector<model::CycleInput> run(3, model::default_cycle_input(m));
  const model::InputTable table(m);
  run[1].tags[*table.find("LT_100A")].value = 91.5f;
  run[1].tags[*table.find("LT_100B")].bad_quality = true;
  run[2].tags[*table.find("LSHH_100")].value = 1.0f - run[0].tags[*table.find("LSHH_100")].value;
  std::optional<checker::Trace> t = checker::encoded_trace(run, *enc, enc->ts);
  ASSERT_TRUE(t.has_value());
  ASSERT_EQ(t->length(), 3u);
  const auto back = checker::cycle_inputs(*t, *enc, m);
  for (std::size_t k = 0; k < run.size(); ++k)
    for (std::size_t i = 0; i < run[k].tags.size(); ++i) {
      if (!enc->tag_value[i]) continue;
      EXPECT_EQ(back[k].tags[i].value, run[k].tags[i].value) << "cycle " << k << " tag " << i;
      EXPECT_EQ(back[k].tags[i].bad_quality, run[k].tags[i].bad_quality) << "cycle " << k << " tag " << i;
    }
  // Commands map to the encoding's command inputs and back.
  // (The last of the encoding's commands: a reset, override or soft bypass.)
  ASSERT_FALSE(enc->commands.empty());
  std::optional<model::Command> command = enc->commands.back().command();
  run[1].commands.push_back(*command);
  t = checker::encoded_trace(run, *enc, enc->ts);
  ASSERT_TRUE(t.has_value());
  const auto with_command = checker::cycle_inputs(*t, *enc, m);
  ASSERT_EQ(with_command[1].commands.size(), 1u);
  EXPECT_EQ(with_command[1].commands[0].op, command->op);
  EXPECT_EQ(with_command[1].commands[0].cause, command->cause);
  EXPECT_EQ(with_command[1].commands[0].effect, command->effect);
  EXPECT_TRUE(with_command[0].commands.empty());
  // A command the encoding has no input for (no cause 999) cannot be mapped.
  model::Command ack;
  ack.op = model::CommandOp::AckCause;
  ack.cause = 999;
  run[2].commands.push_back(ack);
  EXPECT_FALSE(checker::encoded_trace(run, *enc, enc->ts).has_value());
  // Unless the caller asks for such commands to be left out, and counted.
  std::size_t dropped = 0;
  t = checker::encoded_trace(run, *enc, enc->ts, &dropped);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(dropped, 1u);
  EXPECT_EQ(checker::cycle_inputs(*t, *enc, m)[2].commands.size(), 0u);
  EXPECT_EQ(checker::cycle_inputs(*t, *enc, m)[1].commands.size(), 1u);
}

}  // namespace
