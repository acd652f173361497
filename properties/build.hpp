// A small builder of the resolved AST (properties/ast.hpp) for properties that
// cemv generates itself: the standard set, the coverage objectives of
// testgen/, the bounds of response/. A generated property is made
// as a tree against one matrix and printed only for people
// (properties/print.hpp), never written as text and parsed back.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"
#include "properties/names.hpp"

namespace cemv::properties::build {

// The status fields generated properties read (model::cause_fields and
// effect_fields name them; docs/properties.md).
enum class CauseField {
  Active, TripRequested, TrippedTags, Voting, Degraded, Bypassed, SoftBypassed, Inhibited, AckRequired, FirstOut,
  HysteresisActive, DeltaAlarm, Prewarning, TimerRunning, BypassTimeout, BypassPrealarm
};
enum class EffectField {
  Active, Latched, OkToReset, OverrideActive, OverrideFailedTimeout, OverrideFailedCause, OverridePrealarm, Bypassed,
  SoftBypassed, Masked, PassThroughActive, OutputDelayRunning
};
const char* to_string(CauseField f);
const char* to_string(EffectField f);

class Builder {
 public:
  explicit Builder(const model::Matrix& m) : names_(m) {}

  // Atoms resolved against the matrix; std::logic_error for an element, field
  // or tag the matrix does not have (a generator's mistake, not the user's).
  Expr cause(int id, CauseField f) const;
  Expr effect(int id, EffectField f) const;
  Expr effect_tag(int id, int k) const;    // effect[id].tag[k], k 1-based
  // A tag by name as an expression reads it: an input tag's value (Boolean
  // or analog), an output tag's or an internal reference's observable.
  Expr tag(const std::string& name) const;
  Expr bad(const std::string& tag) const;  // the input tag's bad quality
  Expr good(const std::string& tag) const { return negate(bad(tag)); }
  // issued(simulate_tag, tag = TAG)
  Expr simulate_issued(const std::string& tag) const;
  // issued(OP), issued(OP, cause = C), issued(OP, effect = E), ... (0: any).
  static Expr issued(model::CommandOp op, int cause = 0, int effect = 0, std::optional<bool> on = {});

  static Expr prev(Expr a) { return Expr::unary(Expr::Kind::Prev, std::move(a)); }
  static Expr held(Expr a, int cycles) { return Expr::unary(Expr::Kind::Held, std::move(a), cycles); }
  static Expr rose(Expr a) { return Expr::unary(Expr::Kind::Rose, std::move(a)); }
  static Expr fell(Expr a) { return Expr::unary(Expr::Kind::Fell, std::move(a)); }
  static Expr within(Expr a, int cycles) { return Expr::unary(Expr::Kind::Within, std::move(a), cycles); }
  static Expr since(Expr a, Expr b) { return Expr::binary(Expr::Kind::Since, std::move(a), std::move(b)); }
  static Expr negate(Expr a) { return Expr::unary(Expr::Kind::Not, std::move(a)); }
  static Expr all(std::vector<Expr> args) { return Expr::nary(Expr::Kind::And, std::move(args)); }
  static Expr any(std::vector<Expr> args) { return Expr::nary(Expr::Kind::Or, std::move(args)); }
  static Expr implies(Expr a, Expr b) { return Expr::binary(Expr::Kind::Implies, std::move(a), std::move(b)); }
  static Expr iff(Expr a, Expr b) { return Expr::binary(Expr::Kind::Iff, std::move(a), std::move(b)); }
  static Expr count(std::vector<Expr> args) { return Expr::nary(Expr::Kind::Count, std::move(args)); }
  // Comparisons as the language types them: an analog value with a float
  // constant, an integer with an integer, a voting with a voting; a Boolean
  // signal `== true` is `iff true` (properties/expressions.cpp).
  static Expr compare(CompareOp op, Expr a, Expr b) { return Expr::compare(op, std::move(a), std::move(b)); }
  static Expr equals(Expr a, std::int64_t v) { return compare(CompareOp::Eq, std::move(a), Expr::integer(v)); }
  static Expr equals(Expr a, float v) { return compare(CompareOp::Eq, std::move(a), Expr::real(v)); }
  static Expr equals(Expr a, model::Voting v) { return compare(CompareOp::Eq, std::move(a), Expr::voting(v)); }
  static Expr equals(Expr a, bool v) { return iff(std::move(a), Expr::boolean(v)); }
  // count(args) >= at_least
  static Expr at_least(std::vector<Expr> args, int at_least);
  static Expr voting_is_not(Expr voting, model::Voting v);

  // A property of the set: `always body`, `reachable body`, with assumptions.
  static Property invariant(std::string name, std::string description, Expr body, std::vector<Expr> assumptions = {});
  static Property reachable(std::string name, std::string description, Expr body,
                            std::vector<Expr> assumptions = {});
  static Property never(std::string name, std::string description, Expr body, std::vector<Expr> assumptions = {});
  // `whenever trigger then response within N cycles`.
  static Property response(std::string name, std::string description, Expr trigger, Expr response, int cycles,
                           std::vector<Expr> assumptions = {});
  static Assumption assumption(Expr a) { return Assumption{"", std::move(a), {}}; }

  const model::InputTable& inputs() const { return names_.inputs(); }

 private:
  MatrixNames names_;
};

// A property as a block of the property language, for people (a report, a
// file written for reading): `property NAME "DESCRIPTION" { assume ... STATEMENT }`.
std::string block_text(const Property& p, const model::InputTable& inputs);
// A file of generated properties for people: its assumptions, then each block.
std::string file_text(const PropertyFile& f, const model::InputTable& inputs);

}  // namespace cemv::properties::build
