// The two implementations of the property language against each other: the
// concrete evaluator (properties/evaluator.*) on the reference runtime's trace,
// and the symbolic monitor (properties/monitor.*) compiled into the full
// encoding and run by the encoder's Evaluator on the same inputs. They share
// no code; here they must report the same first violation (or witness) and the
// same judged prefix, cycle for cycle, for the examples' requirements, the
// standard sets, and random properties using every operator on random
// matrices. Commands are given in the encoding's canonical form (the same
// convention as the encoder's differential test), so commands the encoding
// has no input for do not occur (docs/properties.md, the symbolic monitor).
#include <gtest/gtest.h>

#include <optional>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"
#include "property_generator.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

struct Symbolic {
  std::optional<std::size_t> cycle;
  std::size_t judged = 0;
};

// The monitor's verdict on the inputs: the judged prefix ends at the first
// cycle whose assumption is false; the first cycle with `good` false inside it
// is the violation (Reachable: the witness).
Symbolic run_monitor(const model::Matrix& m, const Property& p, const std::vector<Assumption>& file,
                     const std::vector<model::CycleInput>& frames) {
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  Monitor mon = compile_monitor(*enc, p, file);
  enc->ts.name_term("diff.good", mon.good);
  enc->ts.name_term("diff.assumption", mon.assumption);
  encoder::Evaluator ev(*enc);
  Symbolic s;
  s.judged = frames.size();
  for (std::size_t k = 0; k < frames.size(); ++k) {
    ev.step(frames[k]);
    if (!ev.value("diff.assumption")) {
      s.judged = k;
      break;
    }
    if (!s.cycle && !ev.value("diff.good")) s.cycle = k;
  }
  return s;
}

// Random inputs with each cycle's commands as the full encoding processes them.
std::vector<model::CycleInput> frames_for(const model::Matrix& m, std::uint64_t seed, int cycles) {
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  auto frames = testsupport::random_inputs(m, seed, cycles);
  for (auto& f : frames) f.commands = enc->canonical_commands(f.commands);
  return frames;
}

int compare(const model::Matrix& m, const PropertyFile& f, const std::vector<model::CycleInput>& frames,
            const std::string& what) {
  Trace t = testing::run_inputs(m, frames);
  Evaluator concrete(m);
  int decided = 0;
  for (const auto& p : f.properties) {
    Evaluation c = concrete.evaluate(p, f.assumptions, t);
    Symbolic s = run_monitor(m, p, f.assumptions, frames);
    EXPECT_EQ(c.judged, s.judged) << what << ": " << p.name;
    EXPECT_EQ(c.cycle, s.cycle) << what << ": " << p.name;
    decided += c.cycle.has_value();
  }
  return decided;
}

TEST(TwoImplementations, ExamplesRequirementsAndStandardSets) {
  for (const char* name : {"tank-overfill", "pipeline-hipps", "burner-management", "compressor"}) {
    std::string dir = std::string(CEMV_SOURCE_DIR) + "/examples/" + name;
    model::Matrix m = formats::load_matrix(dir + "/matrix.json");
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      auto frames = frames_for(m, seed, 600);
      compare(m, load_properties(dir + "/requirements.props", m), frames, std::string(name) + " requirements");
      compare(m, standard_properties(m), frames, std::string(name) + " standard");
    }
  }
}

TEST(TwoImplementations, RandomPropertiesOnRandomMatrices) {
  int decided = 0, total = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    model::Matrix m = testsupport::random_matrix(seed);
    std::string text = PropertyGenerator(m, seed * 101).file(25);
    PropertyFile f = parse_properties(text, m, "random.props");
    decided += compare(m, f, frames_for(m, seed, 300), "seed " + std::to_string(seed));
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
