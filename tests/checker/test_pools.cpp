// What the checker keeps between problems: Z3 contexts (checker/context_pool)
// and the runtime traces of a check run (checker/witness_pool).
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <filesystem>
#include <stdexcept>
#include <thread>

#include "checker/context_pool.hpp"
#include "checker/engines/solving.hpp"
#include "checker/witness_pool.hpp"
#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"
#include "properties/parser.hpp"
#include "runtime/runtime.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

// Every problem gets a context of its own: nothing of an earlier problem,
// however it ended, is in it.
TEST(ContextPool, EveryBorrowerGetsAFreshContext) {
  {
    PooledContext a;
    z3::expr x = (*a).int_const("x");
    z3::solver s(*a);
    s.add(x > 1);
    EXPECT_EQ(s.check(), z3::sat);
    Limits over;
    over.deadline = Clock::now();
    Watchdog watchdog(*a, over);  // fires at once: the deadline has passed
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  PooledContext b;
  z3::solver s(*b);
  EXPECT_EQ(s.assertions().size(), 0u);
  EXPECT_EQ(s.check(), z3::sat);  // not left cancelled by the interrupt above
}

long minor_page_faults() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_minflt;
}

// A fresh context allocates and fills about 17 MB (two tables of Z3 4.8.12):
// on fresh pages from the kernel that is some 4,200 page faults a context,
// most of the CPU of the commands that ask many small questions
// (docs/checker.md, "Z3 notes"). The pages of the last context are reused:
// ten contexts in a row fault far fewer pages than one context's tables.
TEST(ContextPool, AFreshContextReusesTheLastOnesPages) {
  { PooledContext warm; }
  const long before = minor_page_faults();
  for (int i = 0; i < 10; ++i) {
    PooledContext c;
    z3::solver s(*c);
    s.add((*c).int_const("x") > i);
    EXPECT_EQ(s.check(), z3::sat);
  }
  const long faults = minor_page_faults() - before;
  EXPECT_LT(faults, 2000) << "ten contexts faulted " << faults << " pages";
}

// The tank example: cause 3 is the emergency stop pushbutton HS-100, a
// discrete de-energize-to-trip tag: FALSE trips it.
struct Tank {
  model::Matrix m = formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
  properties::Trace run(const std::vector<model::CycleInput>& inputs) const {
    runtime::Runtime rt(m);
    properties::Trace t;
    for (const auto& in : inputs) {
      rt.step(in);
      std::vector<int> observables;
      rt.snapshot(observables);
      t.push_back({in, observables});
    }
    return t;
  }
};

TEST(WitnessPool, AnswersWithATraceThatMeetsTheAntecedent) {
  Tank tank;
  auto f = properties::parse_properties(
      "property p \"\" { always cause[3].active implies effect[1].active }\n"
      "property q \"\" { assume not cause[3].active\n always cause[3].active implies effect[1].active }\n",
      tank.m, "<test>");
  WitnessPool pool;
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[0], f.assumptions, true));
  // At rest: the assumptions hold, the antecedent is not met.
  std::vector<model::CycleInput> rest(3, model::default_cycle_input(tank.m));
  pool.add(tank.run(rest));
  EXPECT_TRUE(pool.witnesses(tank.m, f.properties[0], f.assumptions, false));
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[0], f.assumptions, true));
  // The pushbutton pressed: cause 3 trips.
  std::vector<model::CycleInput> pressed = rest;
  const auto button = model::InputTable(tank.m).find("HS_100_ESD");
  ASSERT_TRUE(button);
  for (int k = 0; k < 3; ++k) {
    model::CycleInput in = model::default_cycle_input(tank.m);
    in.tags[*button].value = 0.0f;
    pressed.push_back(in);
  }
  pool.add(tank.run(pressed));
  EXPECT_TRUE(pool.witnesses(tank.m, f.properties[0], f.assumptions, true));
  // Its assumption excludes exactly the cycles that meet the antecedent.
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[1], f.assumptions, true));
  EXPECT_TRUE(pool.witnesses(tank.m, f.properties[1], f.assumptions, false));
}

// Cause 1 of the tank is a 2oo3 of analog transmitters with a 2 s on-delay
// (20 cycles): the seeded random runs of its cone reach it held for 5 cycles
// on the runtime, keep that run, and the pool answers from it afterwards. An
// antecedent that no run can meet leaves the pool as it was.
TEST(WitnessPool, RandomRunsFindAnAntecedentBehindAVotedDelay) {
  Tank tank;
  auto f = properties::parse_properties(
      "property p \"\" { always held(cause[1].active, 5 cycles) implies effect[1].active }\n"
      "property q \"\" { always cause[1].active and not cause[1].active implies effect[1].active }\n",
      tank.m, "<test>");
  const RunSpace space = run_space(tank.m, nullptr, {"LT_100A", "LT_100B", "LT_100C"}, {});
  WitnessPool pool;
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[0], f.assumptions, true));
  EXPECT_FALSE(pool.search(tank.m, f.properties[1], f.assumptions, true, space, 8));
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[0], f.assumptions, false));  // nothing was kept
  ASSERT_TRUE(pool.search(tank.m, f.properties[0], f.assumptions, true, space, 8));
  EXPECT_TRUE(pool.witnesses(tank.m, f.properties[0], f.assumptions, true));
  EXPECT_FALSE(pool.witnesses(tank.m, f.properties[1], f.assumptions, true));
}

}  // namespace
