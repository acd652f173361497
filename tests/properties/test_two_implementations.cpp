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

// Random properties over a matrix's signals, every operator and kind.
class PropertyGenerator {
 public:
  PropertyGenerator(const model::Matrix& m, std::uint64_t seed) : m_(m), rng_(seed), inputs_(m) {
    for (const auto& o : model::observables(m))
      if (o.type == model::FieldType::Bool) bools_.push_back(o.key);
      else if (o.field == "tripped_tags") ints_.push_back(o.key);
      else votings_.push_back(o.key);
    for (const auto& c : m.causes)
      if (c.analog && c.function != model::CauseFunction::Comment)
        for (const auto& t : c.tags)
          if (inputs_.find(t.name)) analogs_.push_back({t.name, c.analog->limit});
    for (const auto& t : inputs_.tags())
      if (t.kind == model::TagKind::Bool) bool_tags_.push_back(t.name);
  }

  std::string file(int properties) {
    std::string out;
    if (rng_.chance(0.3)) out += "assume " + expr(1) + "\n";
    for (int i = 0; i < properties; ++i) {
      out += "property p" + std::to_string(i) + " {\n";
      if (rng_.chance(0.3)) out += "  assume " + expr(1) + "\n";
      switch (rng_.uniform(0, 3)) {
        case 0: out += "  always " + expr(3); break;
        case 1: out += "  never " + expr(3); break;
        case 2: out += "  reachable " + expr(3); break;
        default:
          out += "  whenever " + expr(2) + " then " + expr(2) + " within " + std::to_string(rng_.uniform(0, 6)) +
                 " cycles";
      }
      out += "\n}\n";
    }
    return out;
  }

 private:
  std::string quote(const std::string& tag) { return "\"" + tag + "\""; }

  std::string atom() {
    for (;;) {
      switch (rng_.uniform(0, 9)) {
        case 0: case 1: case 2:
          if (!bools_.empty()) return rng_.pick(bools_);
          break;
        case 3:
          if (!bool_tags_.empty()) return quote(rng_.pick(bool_tags_));
          break;
        case 4:
          if (!inputs_.tags().empty()) return "bad(" + quote(inputs_.tags()[rng_.uniform(0, int(inputs_.size()) - 1)].name) + ")";
          break;
        case 5:
          if (!analogs_.empty()) {
            auto [tag, limit] = rng_.pick(analogs_);
            static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
            return quote(tag) + " " + ops[rng_.uniform(0, 5)] + " " + model::float_text(limit + rng_.uniform(-2, 2));
          }
          break;
        case 6:
          if (!ints_.empty()) return rng_.pick(ints_) + " >= " + std::to_string(rng_.uniform(0, 2));
          break;
        case 7:
          if (!votings_.empty()) return rng_.pick(votings_) + (rng_.chance(0.5) ? " == 1oo2" : " != 2oo3");
          break;
        case 8: {
          static const char* ops[] = {"ack_cause", "reset_effect", "override_effect", "soft_bypass_cause",
                                      "soft_bypass_tag", "soft_bypass_effect", "simulate_tag", "clear_alarms"};
          return std::string("issued(") + ops[rng_.uniform(0, 7)] + ")";
        }
        default: return rng_.chance(0.5) ? "true" : "false";
      }
    }
  }

  std::string expr(int depth) {
    if (depth == 0 || rng_.chance(0.25)) return atom();
    std::string a = expr(depth - 1);
    switch (rng_.uniform(0, 12)) {
      case 0: return "not (" + a + ")";
      case 1: return "(" + a + ") and (" + expr(depth - 1) + ")";
      case 2: return "(" + a + ") or (" + expr(depth - 1) + ")";
      case 3: return "(" + a + ") implies (" + expr(depth - 1) + ")";
      case 4: return "(" + a + ") iff (" + expr(depth - 1) + ")";
      case 5: return "prev(" + a + ")";
      case 6: return "rose(" + a + ")";
      case 7: return "fell(" + a + ")";
      case 8: return "held(" + a + ", " + std::to_string(rng_.uniform(0, 5)) + " cycles)";
      case 9: return "within(" + a + ", " + std::to_string(rng_.uniform(0, 5)) + " cycles)";
      case 10: return "since(" + a + ", " + expr(depth - 1) + ")";
      case 11:
        return "count(" + a + ", " + expr(depth - 1) + ", " + expr(depth - 1) + ") >= " +
               std::to_string(rng_.uniform(0, 3));
      default: return "prev(prev(" + a + "))";
    }
  }

  const model::Matrix& m_;
  testsupport::Rng rng_;
  model::InputTable inputs_;
  std::vector<std::string> bools_, ints_, votings_, bool_tags_;
  std::vector<std::pair<std::string, float>> analogs_;
};

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
