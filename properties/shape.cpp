#include "properties/shape.hpp"

#include <algorithm>
#include <limits>

namespace cemv::properties {

const Expr* antecedent_of(const Property& p) {
  switch (p.kind) {
    case PropertyKind::Response: return &p.trigger;
    case PropertyKind::Reachable: return &p.body;
    case PropertyKind::Invariant:
      return p.body.kind == Expr::Kind::Implies && !p.body.args.empty() ? &p.body.args[0] : nullptr;
    case PropertyKind::Never:
      return p.body.kind == Expr::Kind::And && p.body.args.size() >= 2 ? &p.body.args[0] : nullptr;
  }
  return nullptr;
}

long long earliest_cycle(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Held: return e.cycles + (e.args.empty() ? 0 : earliest_cycle(e.args[0]));
    case Expr::Kind::Prev: return 1 + (e.args.empty() ? 0 : earliest_cycle(e.args[0]));
    case Expr::Kind::Rose: return e.args.empty() ? 0 : earliest_cycle(e.args[0]);
    case Expr::Kind::And: {
      long long most = 0;
      for (const auto& a : e.args) most = std::max(most, earliest_cycle(a));
      return most;
    }
    case Expr::Kind::Or: {
      if (e.args.empty()) return 0;
      long long least = std::numeric_limits<long long>::max();
      for (const auto& a : e.args) least = std::min(least, earliest_cycle(a));
      return least;
    }
    default: return 0;
  }
}

namespace {

bool counts(const Expr& e) {
  if ((e.kind == Expr::Kind::Held || e.kind == Expr::Kind::Within) && e.cycles > 1) return true;
  if (e.kind == Expr::Kind::Since) return true;
  for (const auto& a : e.args)
    if (counts(a)) return true;
  return false;
}

}  // namespace

bool counts_cycles(const Property& p) {
  if (p.kind == PropertyKind::Response && p.within_cycles > 1) return true;
  if (counts(p.body) || counts(p.trigger) || counts(p.response)) return true;
  for (const auto& a : p.assumptions)
    if (counts(a.expr)) return true;
  return false;
}

}  // namespace cemv::properties
