// The correspondence templates (plc_check/correspondence.hpp): beside the
// checker's clauses over pairs of Booleans, an equality of a program flag and
// a matrix flag under a guard is a candidate where the two move together
// under the guard in the samples, not where both are constant there (an
// override's flags of the causes active at its start are all FALSE until it
// starts: every pair would be "equal" under every other flag; the clauses
// state the constants). Without those clauses it is a candidate in both.
#include <gtest/gtest.h>

#include <algorithm>

#include "encoder/transition_system.hpp"
#include "plc_check/correspondence.hpp"
#include "plc_check/sampling.hpp"

namespace {

using cemv::encoder::TransitionSystem;

// g and h, matrix flags that guard; plc.p the program's flag, q the matrix's.
struct System {
  z3::context ctx;
  TransitionSystem ts{ctx};
  z3::expr i = ts.make_inputvar("i", ctx.bool_sort());
  z3::expr g = ts.make_statevar("g", ctx.bool_sort());
  z3::expr h = ts.make_statevar("h", ctx.bool_sort());
  z3::expr p = ts.make_statevar("plc.p", ctx.bool_sort());
  z3::expr q = ts.make_statevar("q", ctx.bool_sort());
  System() {
    for (const auto& v : {g, h, p, q}) {
      ts.set_init(v, ctx.bool_val(false));
      ts.assign_next(v, i);
    }
    ts.check_complete();
  }
};

// Samples of (g, h, plc.p, q), as rows.
cemv::plc_check::Samples samples_of(const std::vector<std::vector<int>>& rows) {
  cemv::plc_check::Samples s;
  for (const auto& r : rows) {
    s.states.emplace_back();
    for (int x : r) {
      cemv::encoder::Evaluator::Value v;
      v.i = x;
      s.states.back().push_back(v);
    }
  }
  return s;
}

bool has(const std::vector<z3::expr>& cs, const z3::expr& e) {
  return std::any_of(cs.begin(), cs.end(), [&](const z3::expr& c) { return z3::eq(c, e); });
}

TEST(PlcTemplates, AGuardedEqualityNeedsTheFlagsToMoveUnderTheGuard) {
  System s;
  const cemv::checker::SafetyProblem prob{&s.ts, s.ctx.bool_val(true), s.ctx.bool_val(true)};
  // plc.p and q differ in the last sample, so they are not equal everywhere.
  // Under not h (rows 1, 3, 4) they move together: 0, 1, 0. Under not g
  // (rows 1 and 2) both are FALSE: two constants, not a correspondence.
  const auto samples = samples_of({{0, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 1, 1}, {1, 0, 0, 0}, {1, 1, 1, 0}});
  const auto cs = cemv::plc_check::correspondence_candidates(prob, samples, {0, 1, 2, 3}, nullptr, true);
  EXPECT_FALSE(has(cs, s.p == s.q));
  EXPECT_TRUE(has(cs, z3::implies(!s.h, s.p == s.q)));
  EXPECT_FALSE(has(cs, z3::implies(!s.g, s.p == s.q)));
  // Without the checker's clauses, nothing else states the two constants.
  const auto alone = cemv::plc_check::correspondence_candidates(prob, samples, {0, 1, 2, 3}, nullptr, false);
  EXPECT_TRUE(has(alone, z3::implies(!s.h, s.p == s.q)));
  EXPECT_TRUE(has(alone, z3::implies(!s.g, s.p == s.q)));
}

TEST(PlcTemplates, FlagsThatMoveUnderTheGuardKeepTheirGuardedEquality) {
  System s;
  const cemv::checker::SafetyProblem prob{&s.ts, s.ctx.bool_val(true), s.ctx.bool_val(true)};
  // The same, with plc.p and q both TRUE in a third sample under not g.
  const auto samples =
      samples_of({{0, 0, 0, 0}, {0, 1, 0, 0}, {1, 0, 1, 1}, {1, 0, 0, 0}, {1, 1, 1, 0}, {0, 1, 1, 1}});
  const auto cs = cemv::plc_check::correspondence_candidates(prob, samples, {0, 1, 2, 3}, nullptr, true);
  EXPECT_FALSE(has(cs, s.p == s.q));
  EXPECT_TRUE(has(cs, z3::implies(!s.g, s.p == s.q)));
}

}  // namespace
