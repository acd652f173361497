// Internal to the concrete evaluator (evaluator.cpp, evaluator_stream.cpp):
// what its two ways of running share, the atoms and the antecedent, never
// an operator's meaning over time.
#pragma once

#include "model/vocabulary.hpp"
#include "properties/ast.hpp"

namespace cemv::properties::detail {

inline bool matches(const CommandPattern& p, const model::Command& c) {
  if (c.op != p.op) return false;
  if (p.cause && c.cause != *p.cause) return false;
  if (p.effect && c.effect != *p.effect) return false;
  if (p.tag && c.tag != *p.tag) return false;
  if (p.group && c.group != *p.group) return false;
  if (p.on && c.on != *p.on) return false;
  if (p.tag_name && model::tag_key(c.tag_name) != model::tag_key(*p.tag_name)) return false;
  return true;
}

template <class T>
bool compare(CompareOp op, T a, T b) {
  switch (op) {
    case CompareOp::Eq: return a == b;
    case CompareOp::Ne: return a != b;
    case CompareOp::Lt: return a < b;
    case CompareOp::Le: return a <= b;
    case CompareOp::Gt: return a > b;
    case CompareOp::Ge: return a >= b;
  }
  return false;
}

// The antecedent that vacuity is judged on (docs/properties.md, "Vacuity").
inline const Expr* antecedent(const Property& p) {
  if (p.kind == PropertyKind::Response) return &p.trigger;
  if (p.kind == PropertyKind::Invariant && p.body.kind == Expr::Kind::Implies) return &p.body.args[0];
  if (p.kind == PropertyKind::Never && p.body.kind == Expr::Kind::And && !p.body.args.empty()) return &p.body.args[0];
  return nullptr;
}

}  // namespace cemv::properties::detail
