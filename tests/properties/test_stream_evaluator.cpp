// The concrete evaluator's two ways of running (properties/evaluator.hpp):
// StreamEvaluator, stepped cycle by cycle, must give what Evaluator::evaluate
// gives on the trace stepped so far (holds, first violation or witness, the
// trigger, the judged prefix, the assumptions, the antecedent), at every cut
// of the trace, and a copy taken part way must go on as the original does.
// On the examples' requirements and standard sets, and on random properties
// using every operator and kind on random matrices.
#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "property_generator.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

void expect_same(const Evaluation& column, const Evaluation& stream, const std::string& what) {
  EXPECT_EQ(column.holds, stream.holds) << what;
  EXPECT_EQ(column.cycle, stream.cycle) << what;
  EXPECT_EQ(column.trigger_cycle, stream.trigger_cycle) << what;
  EXPECT_EQ(column.judged, stream.judged) << what;
  EXPECT_EQ(column.assumptions_held, stream.assumptions_held) << what;
  EXPECT_EQ(column.antecedent_met, stream.antecedent_met) << what;
}

// Compares at a few cuts of the trace; returns how many properties found a
// violation or witness on the whole trace.
int compare(const model::Matrix& m, const PropertyFile& f, const Trace& t, const std::string& what) {
  Evaluator column(m);
  int decided = 0;
  const std::vector<std::size_t> cuts{0, 1, 2, 7, 40, t.size() / 2, t.size()};
  for (const auto& p : f.properties) {
    StreamEvaluator stream(m, p, f.assumptions);
    std::optional<StreamEvaluator> copy;
    std::size_t stepped = 0;
    for (std::size_t cut : cuts) {
      Trace prefix(t.begin(), t.begin() + static_cast<long>(cut));
      for (; stepped < cut; ++stepped) {
        stream.step(t[stepped].input, t[stepped].observables);
        if (copy) copy->step(t[stepped].input, t[stepped].observables);
      }
      const Evaluation expected = column.evaluate(p, f.assumptions, prefix);
      expect_same(expected, stream.result(), what + ": " + p.name + " after " + std::to_string(cut) + " cycles");
      if (copy) expect_same(expected, copy->result(), what + ": " + p.name + " (copy)");
      // final(): nothing later changes the verdict.
      if (stream.final()) {
        const Evaluation whole = column.evaluate(p, f.assumptions, t);
        EXPECT_EQ(whole.holds, expected.holds) << what << ": " << p.name << " final after " << cut;
        EXPECT_EQ(whole.cycle, expected.cycle) << what << ": " << p.name << " final after " << cut;
      }
      if (cut == 7) copy = stream;
    }
    decided += stream.result().cycle.has_value();
  }
  return decided;
}

TEST(StreamEvaluator, ExamplesRequirementsAndStandardSets) {
  for (const char* name : {"tank-overfill", "pipeline-hipps", "burner-management", "compressor"}) {
    const std::string dir = std::string(CEMV_SOURCE_DIR) + "/examples/" + name;
    const model::Matrix m = formats::load_matrix(dir + "/matrix.json");
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const Trace t = testing::run_inputs(m, testsupport::random_inputs(m, seed, 600));
      compare(m, load_properties(dir + "/requirements.props", m), t, std::string(name) + " requirements");
      compare(m, standard_properties(m), t, std::string(name) + " standard");
    }
  }
}

TEST(StreamEvaluator, RandomPropertiesOnRandomMatrices) {
  int decided = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const model::Matrix m = testsupport::random_matrix(seed);
    const std::string text = PropertyGenerator(m, seed * 101).file(25);
    const PropertyFile f = parse_properties(text, m, "random.props");
    decided += compare(m, f, testing::run_inputs(m, testsupport::random_inputs(m, seed, 300)),
                       "seed " + std::to_string(seed));
    total += static_cast<int>(f.properties.size());
    if (HasFailure()) {
      ADD_FAILURE() << text;
      break;
    }
  }
  // Both outcomes must occur often, or agreeing says little.
  EXPECT_GT(decided, total / 5);
  EXPECT_LT(decided, total * 4 / 5);
}

}  // namespace
}  // namespace cemv::properties
