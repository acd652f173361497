// Counterexamples with round analog values (checker/round_values.hpp): a
// run found on the reduced problem comes back with the floats next to the
// limits (90.0000076); round_values keeps the violation with round numbers.
#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>

#include "checker/check/recheck.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "checker/round_values.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

namespace {

using namespace cemv;
using namespace cemv::checker;
using check::replay_counterexample;

bool round_number(float v) { return v == static_cast<float>(std::round(v * 1000.0) / 1000.0); }

struct Tank {
  model::Matrix matrix = formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) /
                                              "examples/tank-overfill/matrix.json");
  properties::PropertyFile file = properties::parse_properties(R"(
property never_closes {
  assume not issued(simulate_tag)
  assume not issued(soft_bypass_tag)
  assume not issued(soft_bypass_cause)
  never effect[1].active
}
)", matrix, "test.props");
};

// The shortest run to the trip of effect 1, found on the reduced problem.
Trace lifted_run(const OwnedProblem& original) {
  const OwnedProblem reduced = reduce(original);
  const ProverResult r = Bmc().prove(reduced.problem, Limits{}.with_work(50 * kMega).with_depth(30));
  EXPECT_EQ(r.verdict, Verdict::Falsified);
  return lift_trace(original.problem, r.cex);
}

// Every analog value moved to the next float above it: what a run from the
// reduced problem looks like at its least readable.
void next_floats_up(Trace& run) {
  for (auto& cycle : run.cycles)
    for (auto& v : cycle.inputs)
      if (v.is_float) v.f = std::nextafter(v.f, std::numeric_limits<float>::max());
}

TEST(RoundValues, AnalogInputsOfARunFromTheReducedProblemBecomeRoundNumbers) {
  Tank t;
  z3::context ctx;
  const OwnedProblem original = property_problem(t.matrix, t.file, t.file.properties[0])(ctx);
  Trace run = lifted_run(original);
  ASSERT_GT(run.length(), 0u);
  next_floats_up(run);
  replay_counterexample(original.problem, run);  // still a run to the trip
  int ugly = 0;
  for (const auto& cycle : run.cycles)
    for (const auto& v : cycle.inputs) ugly += v.is_float && !round_number(v.f);
  ASSERT_GT(ugly, 0);

  const Trace rounded = round_values(original.problem, run);
  ASSERT_EQ(rounded.length(), run.length());
  ASSERT_EQ(rounded.input_names, run.input_names);
  EXPECT_NO_THROW(replay_counterexample(original.problem, rounded));
  for (std::size_t k = 0; k < rounded.length(); ++k)
    for (std::size_t i = 0; i < rounded.input_names.size(); ++i) {
      const Value& v = rounded.cycles[k].inputs[i];
      if (v.is_float) EXPECT_TRUE(round_number(v.f)) << rounded.input_names[i] << " in cycle " << k << ": " << v.f;
      else EXPECT_EQ(v, run.cycles[k].inputs[i]) << "only analog values change";
    }
}

// A trace that is no counterexample of the problem (here: it goes on a
// cycle past the violation) is given back as it is.
TEST(RoundValues, ATraceThatDoesNotViolateIsLeftAlone) {
  Tank t;
  z3::context ctx;
  const OwnedProblem original = property_problem(t.matrix, t.file, t.file.properties[0])(ctx);
  Trace run = lifted_run(original);
  ASSERT_GT(run.length(), 0u);
  run.cycles.push_back(run.cycles.back());
  next_floats_up(run);
  const Trace same = round_values(original.problem, run);
  for (std::size_t k = 0; k < run.length(); ++k) EXPECT_EQ(same.cycles[k].inputs, run.cycles[k].inputs);
}

}  // namespace
