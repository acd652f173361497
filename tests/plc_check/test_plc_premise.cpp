// A Houdini query's premise without the clauses its equalities repeat
// (plc_check/premise.hpp): what is left out follows from what is kept, and
// nothing is left out through an equality the premise does not hold.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "plc_check/premise.hpp"

namespace {

using cemv::plc_check::FactShape;
using cemv::plc_check::shape_of;
using cemv::plc_check::without_repeats;
using Positions = std::vector<std::size_t>;

struct Premise {
  z3::context ctx;
  std::vector<z3::expr> facts;
  std::vector<FactShape> shapes;
  z3::expr var(const std::string& name) { return ctx.bool_const(name.c_str()); }
  void add(const z3::expr& f) {
    facts.push_back(f);
    shapes.push_back(shape_of(f));
  }
  Positions every() const {
    Positions all;
    for (std::size_t i = 0; i < facts.size(); ++i) all.push_back(i);
    return all;
  }
};

TEST(PlcPremise, AClauseRepeatedThroughAnEqualityIsLeftOut) {
  Premise p;
  const z3::expr a = p.var("a"), a2 = p.var("a2"), b = p.var("b"), b2 = p.var("b2");
  p.add(a == a2);
  p.add(b == !b2);
  p.add(a || b);
  p.add(a2 || !b2);                  // the same clause: a2 is a, not b2 is b
  p.add(z3::implies(b2, a));         // the same clause again, as an implication
  p.add(a || !b);                    // another clause
  EXPECT_EQ(without_repeats(p.shapes, p.every()), (Positions{0, 1, 2, 5}));
}

TEST(PlcPremise, AChainOfEqualitiesJoinsItsEnds) {
  Premise p;
  const z3::expr a = p.var("a"), b = p.var("b"), c = p.var("c"), d = p.var("d");
  p.add(c || d);
  p.add(a == b);
  p.add(b == c);
  p.add(a || d);
  EXPECT_EQ(without_repeats(p.shapes, p.every()), (Positions{0, 1, 2}));
}

TEST(PlcPremise, AnEqualityOutsideThePremiseJoinsNothing) {
  Premise p;
  const z3::expr a = p.var("a"), a2 = p.var("a2"), b = p.var("b");
  p.add(a == a2);
  p.add(a || b);
  p.add(a2 || b);
  EXPECT_EQ(without_repeats(p.shapes, {1, 2}), (Positions{1, 2}));
  EXPECT_EQ(without_repeats(p.shapes, {0, 1, 2}), (Positions{0, 1}));
}

TEST(PlcPremise, OtherFactsAreKeptAsTheyAre) {
  Premise p;
  const z3::expr a = p.var("a"), b = p.var("b");
  const z3::expr x = p.ctx.int_const("x");
  p.add(a == b);
  p.add(z3::implies(a, x == 0));
  p.add(z3::implies(b, x == 0));  // not a clause of literals: kept
  p.add(x >= 0);
  EXPECT_EQ(p.shapes[1].kind, FactShape::Kind::Other);
  EXPECT_EQ(without_repeats(p.shapes, p.every()), (Positions{0, 1, 2, 3}));
}

// Seeded random premises over eight flags: the facts kept imply each fact
// left out (the premise is the same formula), and some are left out.
TEST(PlcPremise, WhatIsKeptImpliesWhatIsLeftOut) {
  std::mt19937 rng(7);
  std::size_t left_out = 0;
  for (int round = 0; round < 50; ++round) {
    Premise p;
    std::vector<z3::expr> flags;
    for (int i = 0; i < 8; ++i) flags.push_back(p.var("f" + std::to_string(i)));
    auto literal = [&] {
      const z3::expr v = flags[rng() % flags.size()];
      return rng() % 2 ? v : !v;
    };
    for (int i = 0; i < 30; ++i) {
      switch (rng() % 4) {
        case 0: p.add(literal() == literal()); break;
        case 1: p.add(z3::implies(literal(), literal())); break;
        default: p.add(literal() || literal() || (rng() % 2 ? literal() : literal())); break;
      }
    }
    const Positions kept = without_repeats(p.shapes, p.every());
    z3::solver s(p.ctx);
    for (std::size_t i : kept) s.add(p.facts[i]);
    for (std::size_t i = 0; i < p.facts.size(); ++i) {
      if (std::find(kept.begin(), kept.end(), i) != kept.end()) continue;
      ++left_out;
      s.push();
      s.add(!p.facts[i]);
      EXPECT_EQ(s.check(), z3::unsat) << "round " << round << ": " << p.facts[i];
      s.pop();
    }
  }
  EXPECT_GT(left_out, 50u);
}

}  // namespace
