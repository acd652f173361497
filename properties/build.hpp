// A small builder of the resolved AST (properties/ast.hpp) for properties that
// cemv generates itself: the standard set today. A generated property is made
// as a tree against one matrix and printed only for people
// (properties/print.hpp), never written as text and parsed back.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"
#include "properties/names.hpp"

namespace cemv::properties::build {

// The status fields generated properties read (model::cause_fields and
// effect_fields name them; docs/properties.md).
enum class CauseField { Active, TripRequested, Voting };
enum class EffectField { Active, Bypassed, OverrideActive, OutputDelayRunning, Latched };
const char* to_string(CauseField f);
const char* to_string(EffectField f);

class Builder {
 public:
  explicit Builder(const model::Matrix& m) : names_(m) {}

  // Atoms resolved against the matrix; std::logic_error for an element, field
  // or tag the matrix does not have (a generator's mistake, not the user's).
  Expr cause(int id, CauseField f) const;
  Expr effect(int id, EffectField f) const;
  Expr bad(const std::string& tag) const;  // the input tag's bad quality
  // issued(simulate_tag, tag = TAG)
  Expr simulate_issued(const std::string& tag) const;

  static Expr prev(Expr a) { return Expr::unary(Expr::Kind::Prev, std::move(a)); }
  static Expr held(Expr a, int cycles) { return Expr::unary(Expr::Kind::Held, std::move(a), cycles); }
  static Expr negate(Expr a) { return Expr::unary(Expr::Kind::Not, std::move(a)); }
  static Expr all(std::vector<Expr> args) { return Expr::nary(Expr::Kind::And, std::move(args)); }
  static Expr implies(Expr a, Expr b) { return Expr::binary(Expr::Kind::Implies, std::move(a), std::move(b)); }
  // count(args) >= at_least
  static Expr at_least(std::vector<Expr> args, int at_least);
  static Expr voting_is_not(Expr voting, model::Voting v);

  // A property of the set: `always body`, `reachable body`, with assumptions.
  static Property invariant(std::string name, std::string description, Expr body, std::vector<Expr> assumptions = {});
  static Property reachable(std::string name, std::string description, Expr body);

  const model::InputTable& inputs() const { return names_.inputs(); }

 private:
  MatrixNames names_;
};

// A property as a block of the property language, for people (a report, a
// file written for reading): `property NAME "DESCRIPTION" { assume ... STATEMENT }`.
std::string block_text(const Property& p, const model::InputTable& inputs);

}  // namespace cemv::properties::build
