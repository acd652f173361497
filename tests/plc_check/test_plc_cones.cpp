// The cones of a product's outputs and their groups (plc_check/cones.hpp):
// outputs whose cones share no state variable are proved apart, a chain of
// shared variables puts outputs in one group, and the inputs a variable
// depends on decide which pairs and guards get a candidate.
#include <gtest/gtest.h>

#include "encoder/transition_system.hpp"
#include "plc_check/cones.hpp"

namespace {

using cemv::encoder::TransitionSystem;
using cemv::plc_check::cones_of;
using cemv::plc_check::overlapping;
using cemv::plc_check::Supports;
using Sets = std::vector<std::vector<std::size_t>>;

// a' = a or i1, c' = a (a's follower), b' = b xor i2, k' = FALSE (a first-scan flag).
struct System {
  z3::context ctx;
  TransitionSystem ts{ctx};
  z3::expr i1 = ts.make_inputvar("i1", ctx.bool_sort());
  z3::expr i2 = ts.make_inputvar("i2", ctx.bool_sort());
  z3::expr a = ts.make_statevar("a", ctx.bool_sort());
  z3::expr b = ts.make_statevar("b", ctx.bool_sort());
  z3::expr c = ts.make_statevar("c", ctx.bool_sort());
  z3::expr k = ts.make_statevar("k", ctx.bool_sort());
  System() {
    for (const auto& v : {a, b, c}) ts.set_init(v, ctx.bool_val(false));
    ts.set_init(k, ctx.bool_val(true));
    ts.assign_next(a, a || i1);
    ts.assign_next(b, b != i2);
    ts.assign_next(c, a);
    ts.assign_next(k, ctx.bool_val(false));
    ts.check_complete();
  }
};

TEST(PlcCones, DisjointConesGetSeparateGroups) {
  System s;
  // Outputs reading c, b, and a: c's cone holds a, b's holds b alone.
  const Sets cones = cones_of(s.ts, {s.c, s.b, !s.a});
  EXPECT_EQ(cones, (Sets{{0, 2}, {1}, {0}}));  // statevars: a, b, c, k
  EXPECT_EQ(overlapping(cones), (Sets{{0, 2}, {1}}));
  // Two outputs over b and c together are one group with both cones.
  EXPECT_EQ(overlapping(cones_of(s.ts, {s.b && s.c, s.b})), (Sets{{0, 1}}));
}

TEST(PlcCones, AChainOfSharedVariablesIsOneGroup) {
  EXPECT_EQ(overlapping(Sets{{0, 1}, {2}, {1, 3}, {3, 4}, {5}, {}}), (Sets{{0, 2, 3}, {1}, {4}, {5}}));
  EXPECT_EQ(overlapping(Sets{}), Sets{});
  // The group of a later cone that links two earlier ones starts at the first.
  EXPECT_EQ(overlapping(Sets{{0}, {1}, {0, 1}}), (Sets{{0, 1, 2}}));
}

TEST(PlcCones, SupportsRelateVariablesOfTheSameInputs) {
  System s;
  const Supports sup(s.ts);
  const std::size_t a = 0, b = 1, c = 2, k = 3;
  EXPECT_TRUE(sup.related(a, c, true));   // both read i1
  EXPECT_FALSE(sup.related(a, b));        // i1 against i2
  EXPECT_TRUE(sup.related(k, b));         // no input is included in every support
  EXPECT_FALSE(sup.related(k, b, true));
  EXPECT_TRUE(sup.may_guard(k, a, c));    // reads no input
  EXPECT_TRUE(sup.may_guard(a, c, SIZE_MAX));
  EXPECT_FALSE(sup.may_guard(b, a, c));   // reads i2, which neither does
  EXPECT_FALSE(sup.may_guard(b, a, b));   // i2 alone, not the pair's i1 and i2
  EXPECT_TRUE(sup.may_guard(c, a, a));    // exactly the pair's i1
}

}  // namespace
