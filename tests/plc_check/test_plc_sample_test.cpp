// A mined candidate evaluated on sampled states (plc_check/sample_test.hpp)
// agrees with Z3's own evaluation on seeded random states, and a candidate
// it cannot evaluate is left to Houdini (no test).
#include <gtest/gtest.h>

#include <random>
#include <unordered_map>
#include <vector>

#include "plc_check/sample_test.hpp"

namespace {

using cemv::encoder::Evaluator;
using cemv::plc_check::SampleTest;

struct Vars {
  z3::context ctx;
  z3::expr a = ctx.bool_const("a"), b = ctx.bool_const("b"), c = ctx.bool_const("c");
  z3::expr x = ctx.int_const("x"), y = ctx.int_const("y");
  // Columns in a state: y, a, x, c, b (not the order of their names).
  std::unordered_map<unsigned, std::size_t> column{{y.id(), 0}, {a.id(), 1}, {x.id(), 2}, {c.id(), 3}, {b.id(), 4}};

  // `e` with the state's values put in, simplified by Z3.
  bool z3_holds(const z3::expr& e, const std::vector<Evaluator::Value>& s) {
    z3::expr_vector from(ctx), to(ctx);
    for (const z3::expr& v : {a, b, c})
      from.push_back(v), to.push_back(ctx.bool_val(s[column.at(v.id())].i != 0));
    for (const z3::expr& v : {x, y})
      from.push_back(v), to.push_back(ctx.int_val(s[column.at(v.id())].i));
    z3::expr copy = e;
    return copy.substitute(from, to).simplify().is_true();
  }
};

TEST(PlcSampleTest, AgreesWithZ3OnSeededStates) {
  Vars v;
  const std::vector<z3::expr> candidates{
      !v.a || v.b,                                    // a mined clause
      z3::implies(v.c, v.x == 2 * v.y - 1),           // a guarded linear relation
      v.x <= v.y + 1,                                 // a difference bound
      v.x - v.y >= -2,                                //
      z3::mk_or(z3::expr_vector(v.ctx)) || !v.a,      // an empty disjunction
      v.a == !v.b,                                    // flags equal or opposite
      z3::ite(v.a, v.x, v.y) > 2 || (v.b && v.c),     // strict and non-strict at the boundary
      !(v.x < 0) && (-v.y) != v.x,                    //
      v.x >= 2 || v.y < v.x,                          //
      (v.a ^ v.c) || v.x * 5 == 10,                   //
  };
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> flag(0, 1), num(-4, 6);
  for (const z3::expr& c : candidates) {
    const auto test = SampleTest::compile(c, v.column);
    ASSERT_TRUE(test.has_value()) << c;
    int held = 0, broke = 0;
    for (int k = 0; k < 400; ++k) {
      std::vector<Evaluator::Value> s(5);
      s[0].i = num(rng);
      s[2].i = num(rng);
      for (std::size_t f : {1u, 3u, 4u}) s[f].i = flag(rng);
      const bool expected = v.z3_holds(c, s);
      ASSERT_EQ(test->holds(s), expected) << c << " in state " << k;
      (expected ? held : broke) += 1;
    }
    // Each candidate both holds and breaks in some state: the boundaries are reached.
    EXPECT_GT(held, 0) << c;
    EXPECT_GT(broke, 0) << c;
  }
}

TEST(PlcSampleTest, BreaksAClauseOnlyWhereBothLiteralsAreFalse) {
  Vars v;
  const auto test = SampleTest::compile(!v.a || v.b, v.column);
  ASSERT_TRUE(test.has_value());
  std::vector<Evaluator::Value> s(5);
  s[1].i = 1;  // a
  s[4].i = 0;  // b
  EXPECT_FALSE(test->holds(s));
  s[4].i = 1;
  EXPECT_TRUE(test->holds(s));
  s[1].i = 0;
  s[4].i = 0;
  EXPECT_TRUE(test->holds(s));
}

TEST(PlcSampleTest, LeavesToHoudiniWhatItCannotEvaluate) {
  Vars v;
  const z3::expr outside = v.ctx.int_const("z");  // no column
  EXPECT_FALSE(SampleTest::compile(v.x <= outside, v.column).has_value());
  EXPECT_FALSE(SampleTest::compile(v.x * v.y >= 0, v.column).has_value());  // a product of variables
  EXPECT_FALSE(SampleTest::compile(v.x / 2 >= 0, v.column).has_value());    // division
  EXPECT_FALSE(SampleTest::compile(v.ctx.real_const("r") >= 0, v.column).has_value());
  const z3::expr big = v.ctx.int_val("100000000000000000000000");
  EXPECT_FALSE(SampleTest::compile(v.x <= big, v.column).has_value());  // not a 64-bit numeral
}

}  // namespace
