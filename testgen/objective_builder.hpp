// Internal to testgen/: the helpers the objective catalogue is written with.
// An objective is a `reachable` property of the property language
// (docs/properties.md), built as a tree with properties/build.hpp, so the
// checker's monitor, the concrete evaluator and the cone-of-influence slicing
// all apply to it unchanged.
#pragma once

#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "properties/build.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen::detail {

using properties::Expr;
using properties::build::Builder;
using properties::build::CauseField;
using properties::build::EffectField;

// The terms of one conjunction, in order; one term is itself, several are
// one `and` (a term that is a conjunction itself stays one term).
class All {
 public:
  All() = default;
  All(std::initializer_list<Expr> terms) : terms_(terms) {}
  All& operator<<(Expr e) {
    terms_.push_back(std::move(e));
    return *this;
  }
  All& operator<<(const All& more) {
    terms_.insert(terms_.end(), more.terms_.begin(), more.terms_.end());
    return *this;
  }
  bool empty() const { return terms_.empty(); }
  Expr expr() const { return terms_.size() == 1 ? terms_.front() : Builder::all(terms_); }

 private:
  std::vector<Expr> terms_;
};

// Several alternatives: false for none, the one itself, else one `or`.
inline Expr any_of(std::vector<Expr> parts) {
  if (parts.empty()) return Expr::boolean(false);
  if (parts.size() == 1) return std::move(parts.front());
  return Builder::any(std::move(parts));
}

// `x` held for the last `n` cycles; `x` itself for n <= 0.
inline Expr held(Expr x, int n) { return n <= 0 ? x : Builder::held(std::move(x), n); }

class ObjectiveBuilder {
 public:
  ObjectiveBuilder(const model::Matrix& m, std::vector<Objective>& out) : m_(m), x_(m), out_(out) {}

  const model::Matrix& matrix() const { return m_; }

  Expr cause(const model::Cause& c, CauseField f) const { return x_.cause(c.id, f); }
  Expr effect(const model::Effect& e, EffectField f) const { return x_.effect(e.id, f); }
  Expr tag(const std::string& name) const { return x_.tag(name); }
  Expr good(const std::string& name) const { return x_.good(name); }
  Expr bad(const std::string& name) const { return x_.bad(name); }
  Expr output(const model::Effect& e, int k) const { return x_.effect_tag(e.id, k); }

  void add(const std::string& id, const std::string& kind, const std::string& text, model::Node element,
           int sif, Expr expr, int horizon, std::vector<std::string> observe, bool simulates = false) {
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
    std::vector<Expr> assumptions;
    if (!simulates) {
      assumptions.push_back(Builder::negate(Builder::issued(model::CommandOp::SimulateTag)));
      assumptions.push_back(Builder::negate(Builder::issued(model::CommandOp::StopSimulation)));
    }
    o.property = Builder::reachable(name, "", std::move(expr), std::move(assumptions));
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
  Builder x_;
  std::vector<Objective>& out_;
};

// Observable keys, for the checklist's `observe` lists.
inline std::string ck(const model::Cause& c, CauseField f) {
  return "cause[" + std::to_string(c.id) + "]." + properties::build::to_string(f);
}
inline std::string ek(const model::Effect& e, EffectField f) {
  return "effect[" + std::to_string(e.id) + "]." + properties::build::to_string(f);
}
inline std::string ek_tag(const model::Effect& e, std::size_t k) {
  return "effect[" + std::to_string(e.id) + "].tag[" + std::to_string(k) + "]";
}
inline std::string label(const model::Cause& c) { return "cause " + std::to_string(c.id) + " " + c.name; }
inline std::string label(const model::Effect& e) { return "effect " + std::to_string(e.id) + " " + e.name; }
inline std::string num(float v) {
  std::string s = model::float_text(v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}
inline int first_sif(const std::vector<int>& sif) { return sif.empty() ? 0 : sif.front(); }

void cause_objectives(ObjectiveBuilder& b, const model::Cause& c);
void effect_objectives(ObjectiveBuilder& b, const model::Effect& e);
void intersection_objectives(ObjectiveBuilder& b, const model::Effect& e);
void matrix_objectives(ObjectiveBuilder& b);

}  // namespace cemv::testgen::detail
