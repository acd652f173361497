// The cones of a product's outputs and their groups (plc_check/cones.hpp):
// outputs whose cones share no state variable are proved apart, a chain of
// shared variables puts outputs in one group, and the inputs a variable
// depends on decide which pairs and guards get a candidate.
#include <gtest/gtest.h>

#include <algorithm>

#include "checker/limits.hpp"
#include "encoder/transition_system.hpp"
#include "plc_check/cones.hpp"
#include "plc_check/sampling.hpp"

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

// Each layer as its top, then its variables.
std::vector<Sets> layers(const TransitionSystem& ts, const std::vector<z3::expr>& outputs) {
  std::vector<Sets> out;
  for (const auto& l : cemv::plc_check::layers_of(ts, cones_of(ts, outputs), Supports(ts))) out.push_back({l.top, l.vars});
  return out;
}

// A layer's top is the variables of one cone that read exactly the same
// inputs: c (i1, reading a) and a (i1) are one, b (i2) and k (no input) one
// each. Its variables are those and what they read, and k, which reads no
// input and may guard any relation. Fewest inputs first, then smallest.
TEST(PlcCones, LayersComeByTheirInputs) {
  System s;
  const std::size_t a = 0, b = 1, c = 2, k = 3;
  EXPECT_EQ(layers(s.ts, {s.c, s.b, s.k}), (std::vector<Sets>{{{k}, {k}}, {{b}, {b, k}}, {{a, c}, {a, c, k}}}));
  // A cone over c and b together: the pair's layers alone, no layer of both
  // (no variable reads both i1 and i2).
  EXPECT_EQ(layers(s.ts, {s.c && s.b}), (std::vector<Sets>{{{b}, {b}}, {{a, c}, {a, c}}}));
}

// d' = d or (a and b) reads i1 and i2: its layer holds the two causes'
// variables and comes after their layers.
TEST(PlcCones, AnEffectsLayerComesAfterItsCauses) {
  z3::context ctx;
  TransitionSystem ts{ctx};
  const z3::expr i1 = ts.make_inputvar("i1", ctx.bool_sort());
  const z3::expr i2 = ts.make_inputvar("i2", ctx.bool_sort());
  const z3::expr a = ts.make_statevar("a", ctx.bool_sort());
  const z3::expr b = ts.make_statevar("b", ctx.bool_sort());
  const z3::expr d = ts.make_statevar("d", ctx.bool_sort());
  for (const auto& v : {a, b, d}) ts.set_init(v, ctx.bool_val(false));
  ts.assign_next(a, a || i1);
  ts.assign_next(b, i2);
  ts.assign_next(d, d || (a && b));
  ts.check_complete();
  EXPECT_EQ(layers(ts, {d}), (std::vector<Sets>{{{0}, {0}}, {{1}, {1}}, {{2}, {0, 1, 2}}}));
}

// z' = (a or i2) and not (a or i2): constant FALSE, as the matrix encodes an
// effect's output delay of 0 ms (E.7), and o' = ite(z, i2, a) reads i2 only
// through it. y' = y or i2 stays FALSE in the samples below without being
// constant.
struct WithConstant {
  z3::context ctx;
  TransitionSystem ts{ctx};
  z3::expr i1 = ts.make_inputvar("i1", ctx.bool_sort());
  z3::expr i2 = ts.make_inputvar("i2", ctx.bool_sort());
  z3::expr a = ts.make_statevar("a", ctx.bool_sort());
  z3::expr z = ts.make_statevar("z", ctx.bool_sort());
  z3::expr o = ts.make_statevar("o", ctx.bool_sort());
  z3::expr y = ts.make_statevar("y", ctx.bool_sort());
  WithConstant() {
    for (const auto& v : {a, z, o, y}) ts.set_init(v, ctx.bool_val(false));
    ts.assign_next(a, a || i1);
    ts.assign_next(z, (a || i2) && !(a || i2));
    ts.assign_next(o, z3::ite(z, i2, a));
    ts.assign_next(y, y || i2);
    ts.check_complete();
  }
};

TEST(PlcCones, ConstantStatesAreNoDependency) {
  WithConstant s;
  const cemv::checker::SafetyProblem p{&s.ts, s.ctx.bool_val(true), s.ctx.bool_val(true)};
  const std::size_t a = 0, z = 1, o = 2;
  EXPECT_FALSE(Supports(s.ts).related(a, o, true));  // o reads i2 through z
  cemv::plc_check::Samples samples;
  using V = cemv::encoder::Evaluator::Value;
  samples.states = {{V{0, 0}, V{0, 0}, V{0, 0}, V{0, 0}}, {V{1, 0}, V{0, 0}, V{1, 0}, V{0, 0}}};
  cemv::checker::Limits limits;
  cemv::checker::WorkMeter meter(s.ctx, limits);
  // z is constant; y is FALSE in every sample but not constant.
  const auto constants = cemv::plc_check::constant_states(p, samples, limits, meter);
  EXPECT_EQ(constants, (std::vector<std::size_t>{z}));
  EXPECT_TRUE(Supports(s.ts, constants).related(a, o, true));
}

// A 2oo3 low limit of three analog inputs (ordered integers) at 1,000,000,
// beside a fourth input compared with 60 small numerals: the seeded runs
// draw each input near its own limit, so that the trip falls after it rose
// (an off-delay runs); drawn among every numeral, two of the three inputs
// are above the limit together about once in 10,000 scans.
TEST(PlcCones, SeededRunsDrawInputsNearTheirOwnLimits) {
  z3::context ctx;
  TransitionSystem ts{ctx};
  std::vector<z3::expr> x;
  for (const char* n : {"x1", "x2", "x3"}) x.push_back(ts.make_inputvar(n, ctx.int_sort()));
  const z3::expr w = ts.make_inputvar("w", ctx.int_sort());
  const z3::expr prev = ts.make_statevar("trip_prev", ctx.bool_sort());
  const z3::expr fell = ts.make_statevar("fell", ctx.bool_sort());
  const z3::expr level = ts.make_statevar("level", ctx.int_sort());
  auto one = [&](const z3::expr& v) { return z3::ite(v <= 1000000, ctx.int_val(1), ctx.int_val(0)); };
  const z3::expr trip = one(x[0]) + one(x[1]) + one(x[2]) >= 2;
  z3::expr lvl = ctx.int_val(0);
  for (int c = 0; c < 60; ++c) lvl = z3::ite(w >= c, ctx.int_val(c), lvl);
  ts.set_init(prev, ctx.bool_val(false));
  ts.set_init(fell, ctx.bool_val(false));
  ts.set_init(level, ctx.int_val(0));
  ts.assign_next(prev, trip);
  ts.assign_next(fell, fell || (prev && !trip));
  ts.assign_next(level, lvl);
  ts.check_complete();
  const cemv::checker::SafetyProblem p{&ts, ctx.bool_val(true), ctx.bool_val(true)};
  const auto samples = cemv::plc_check::sample(p);
  ASSERT_FALSE(samples.states.empty());
  EXPECT_TRUE(std::any_of(samples.states.begin(), samples.states.end(), [](const auto& st) { return st[1].i == 1; }))
      << "no sampled run lets the 2oo3 trip fall";
}

}  // namespace

namespace {

// A counter the inputs hold for stretches: many distinct states of the
// product, few of each cone's variables.
struct Counting {
  z3::context ctx;
  TransitionSystem ts{ctx};
  z3::expr i1 = ts.make_inputvar("i1", ctx.bool_sort());
  z3::expr i2 = ts.make_inputvar("i2", ctx.bool_sort());
  z3::expr a = ts.make_statevar("a", ctx.bool_sort());
  z3::expr n = ts.make_statevar("n", ctx.int_sort());
  z3::expr b = ts.make_statevar("b", ctx.bool_sort());
  Counting() {
    ts.set_init(a, ctx.bool_val(false));
    ts.set_init(n, ctx.int_val(0));
    ts.set_init(b, ctx.bool_val(false));
    ts.assign_next(a, i1);
    ts.assign_next(n, z3::ite(i1, z3::ite(n < 50, n + 1, n), ctx.int_val(0)));
    ts.assign_next(b, z3::ite(i2, !b, b));
    ts.check_complete();
  }
};

}  // namespace

// Sampled by cones: each cone's states are the distinct projections of the
// product's distinct states, in the order first reached, weighted by how many
// of the product's states each stands for; at most max_states are kept.
TEST(PlcCones, SampledConesAreTheProjectionsOfTheProductsStates) {
  Counting s;
  const cemv::checker::SafetyProblem p{&s.ts, s.ctx.bool_val(true), s.ctx.bool_val(true)};
  const auto whole = cemv::plc_check::sample(p);
  cemv::plc_check::SamplingOptions o;
  o.cones = {{0, 1}, {2}};
  const auto by_cones = cemv::plc_check::sample(p, o);
  ASSERT_FALSE(whole.states.empty());
  EXPECT_TRUE(by_cones.states.empty());
  ASSERT_EQ(by_cones.cones.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    std::vector<std::vector<std::int64_t>> expected;
    std::vector<std::size_t> weights;
    for (const auto& st : whole.states) {
      std::vector<std::int64_t> proj;
      for (std::size_t v : o.cones[c]) proj.push_back(st[v].i);
      const auto it = std::find(expected.begin(), expected.end(), proj);
      if (it == expected.end()) {
        expected.push_back(proj);
        weights.push_back(1);
      } else {
        ++weights[static_cast<std::size_t>(it - expected.begin())];
      }
    }
    std::vector<std::vector<std::int64_t>> got;
    for (const auto& st : by_cones.cones[c].states) {
      got.emplace_back();
      for (const auto& v : st) got.back().push_back(v.i);
    }
    EXPECT_EQ(got, expected) << "cone " << c;
    EXPECT_EQ(by_cones.cones[c].weights, weights) << "cone " << c;
  }
  EXPECT_LT(by_cones.cones[1].states.size(), whole.states.size());
  o.max_states = 5;
  const auto bounded = cemv::plc_check::sample(p, o);
  EXPECT_EQ(bounded.cones[0].states.size(), 5u);
  EXPECT_EQ(bounded.cones[1].states.size(), by_cones.cones[1].states.size());  // 2 distinct: under the bound
  EXPECT_EQ(bounded.cones[1].weights, by_cones.cones[1].weights);
  // A full cone's kept states still count every state of the product they
  // stand for, also in the scans where none of the cone's variables changed.
  for (std::size_t k = 0; k < 5; ++k) EXPECT_EQ(bounded.cones[0].weights[k], by_cones.cones[0].weights[k]) << k;
  EXPECT_EQ(bounded.unchanged, whole.unchanged);
}
