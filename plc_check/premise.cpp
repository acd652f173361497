// A premise without the clauses its equalities repeat (premise.hpp).
#include "plc_check/premise.hpp"

#include <algorithm>
#include <cstdint>
#include <set>
#include <unordered_map>

namespace cemv::plc_check {

namespace {

using Literal = FactShape::Literal;

// `e` as a literal: a Boolean constant under any number of negations.
bool literal_of(z3::expr e, Literal& out) {
  bool negated = false;
  while (e.is_app() && e.decl().decl_kind() == Z3_OP_NOT) {
    negated = !negated;
    e = e.arg(0);
  }
  if (!e.is_bool() || !e.is_const()) return false;
  out = {e.id(), negated};
  return true;
}

// The classes of literals the equalities make, each named by one variable.
class Classes {
 public:
  Literal find(Literal l) {
    while (true) {
      const auto it = parent_.find(l.var);
      if (it == parent_.end()) return l;
      l = {it->second.var, l.negated != it->second.negated};
    }
  }
  // a = b: a's class joins b's.
  void join(Literal a, Literal b) {
    a = find(a);
    b = find(b);
    if (a.var != b.var) parent_[a.var] = {b.var, a.negated != b.negated};
  }

 private:
  std::unordered_map<unsigned, Literal> parent_;  // var -> (parent's var, negated relative to it)
};

}  // namespace

FactShape shape_of(const z3::expr& fact) {
  FactShape s;
  if (!fact.is_app()) return s;
  const Z3_decl_kind k = fact.decl().decl_kind();
  std::vector<Literal> lits(fact.num_args());
  for (unsigned i = 0; i < fact.num_args(); ++i)
    if (!literal_of(fact.arg(i), lits[i])) return s;
  if (k == Z3_OP_OR) {
    s.kind = FactShape::Kind::Clause;
  } else if (k == Z3_OP_IMPLIES && lits.size() == 2) {
    lits[0].negated = !lits[0].negated;
    s.kind = FactShape::Kind::Clause;
  } else if (k == Z3_OP_EQ && lits.size() == 2) {
    s.kind = FactShape::Kind::Equality;
  } else {
    return s;
  }
  s.literals = std::move(lits);
  return s;
}

std::vector<std::size_t> without_repeats(const std::vector<FactShape>& shapes, const std::vector<std::size_t>& premise) {
  Classes classes;
  for (std::size_t i : premise)
    if (shapes[i].kind == FactShape::Kind::Equality) classes.join(shapes[i].literals[0], shapes[i].literals[1]);
  std::set<std::vector<std::uint64_t>> seen;
  std::vector<std::size_t> out;
  std::vector<std::uint64_t> key;
  for (std::size_t i : premise) {
    if (shapes[i].kind == FactShape::Kind::Clause) {
      key.clear();
      for (const Literal& l : shapes[i].literals) {
        const Literal r = classes.find(l);
        key.push_back(2 * std::uint64_t{r.var} + (r.negated ? 1 : 0));
      }
      std::sort(key.begin(), key.end());
      if (!seen.insert(key).second) continue;
    }
    out.push_back(i);
  }
  return out;
}

}  // namespace cemv::plc_check
