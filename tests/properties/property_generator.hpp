// Random property files over a matrix's signals, every operator and kind:
// the two implementations of the property language (test_two_implementations.cpp)
// and the evaluator's two ways of running (test_stream_evaluator.cpp) are
// held to each other on them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv::properties {

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

}  // namespace cemv::properties
