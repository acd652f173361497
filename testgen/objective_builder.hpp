// Internal to testgen/: the helpers the objective catalogue is written with.
// An objective is written as a `reachable` expression of the property
// language (docs/properties.md), so the checker's monitor, the concrete
// evaluator and the cone-of-influence slicing all apply to it unchanged.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen::detail {

class ObjectiveBuilder {
 public:
  ObjectiveBuilder(const model::Matrix& m, std::vector<Objective>& out) : m_(m), out_(out) {}

  const model::Matrix& matrix() const { return m_; }

  void add(const std::string& id, const std::string& kind, const std::string& text, model::Node element,
           int sif, const std::string& expr, int horizon, std::vector<std::string> observe, bool simulates = false) {
    Objective o;
    o.id = id;
    o.kind = kind;
    o.text = text;
    o.element = element;
    o.sif = sif;
    // Property names are identifiers joined by dots, and `cause`, `effect`
    // are keywords: the id with its dots as underscores, after "obj_".
    std::string name = "obj_" + id;
    for (auto& ch : name)
      if (ch == '.') ch = '_';
    // Tests act like a field engineer: no simulation of tags (a simulated
    // value would reach almost any objective without exercising the logic,
    // docs/semantics.md O.8), except where forcing an output is the point.
    o.property = "property " + name + " {\n" +
                 (simulates ? std::string() : "  assume not issued(simulate_tag)\n  assume not issued(stop_simulation)\n") +
                 "  reachable " + expr + "\n}\n";
    o.simulates = simulates;
    o.horizon = horizon;
    o.observe = std::move(observe);
    out_.push_back(std::move(o));
  }

  // Durations of docs/semantics.md T.2: whole cycles, rounded up.
  int cycles(std::uint64_t ms) const {
    return static_cast<int>((ms + m_.cycle_ms - 1) / m_.cycle_ms);
  }

 private:
  const model::Matrix& m_;
  std::vector<Objective>& out_;
};

inline std::string ck(const model::Cause& c, const std::string& field) {
  return "cause[" + std::to_string(c.id) + "]." + field;
}
inline std::string ek(const model::Effect& e, const std::string& field) {
  return "effect[" + std::to_string(e.id) + "]." + field;
}
inline std::string label(const model::Cause& c) { return "cause " + std::to_string(c.id) + " " + c.name; }
inline std::string label(const model::Effect& e) { return "effect " + std::to_string(e.id) + " " + e.name; }
// A tag in expression position: a string is always a tag name (internal
// references included).
inline std::string tag_atom(const std::string& name) { return "\"" + name + "\""; }
inline std::string num(float v) {
  std::string s = model::float_text(v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}
inline int first_sif(const std::vector<int>& sif) { return sif.empty() ? 0 : sif.front(); }
inline std::string join(const std::vector<std::string>& parts, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s += (i ? sep : "") + parts[i];
  return s;
}

void cause_objectives(ObjectiveBuilder& b, const model::Cause& c);
void effect_objectives(ObjectiveBuilder& b, const model::Effect& e);
void intersection_objectives(ObjectiveBuilder& b, const model::Effect& e);
void matrix_objectives(ObjectiveBuilder& b);

}  // namespace cemv::testgen::detail
