// The runs that trip an effect's causes together (plc_check/sampling.hpp,
// SamplingOptions::trips): a state that independent draws do not reach (every
// input of a vote held at once, then a reset's rising edge while it is held),
// and the trips `at_rest` states for the tank example's effects.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "encoder/transition_system.hpp"
#include "formats/matrix_json.hpp"
#include "plc_check/sampling.hpp"
#include "plc_check/shared_proof.hpp"

namespace {

using cemv::checker::Value;
using cemv::encoder::TransitionSystem;
using cemv::plc_check::SamplingOptions;

// A 16oo16 vote: `n` counts the scans all sixteen inputs are held (up to 5);
// `o` latches a rising edge of `r` once the vote has held three scans, with
// `r` one of the voters (its edge needs it at rest first).
struct Vote {
  z3::context ctx;
  TransitionSystem ts{ctx};
  std::vector<z3::expr> in;
  z3::expr r = ts.make_inputvar("r", ctx.bool_sort());
  z3::expr n = ts.make_statevar("n", ctx.int_sort());
  z3::expr rp = ts.make_statevar("rp", ctx.bool_sort());
  z3::expr o = ts.make_statevar("o", ctx.bool_sort());
  Vote() {
    z3::expr all = ctx.bool_val(true);
    for (int i = 0; i < 16; ++i) {
      in.push_back(ts.make_inputvar(("i" + std::to_string(i)).c_str(), ctx.bool_sort()));
      all = all && in.back();
    }
    ts.set_init(n, ctx.int_val(0));
    ts.set_init(rp, ctx.bool_val(false));
    ts.set_init(o, ctx.bool_val(false));
    ts.assign_next(n, z3::ite(all, z3::ite(n < 5, n + 1, n), ctx.int_val(0)));
    ts.assign_next(rp, r);
    ts.assign_next(o, o || (n >= 3 && r && !rp));
    ts.check_complete();
  }
};

bool reached(const cemv::plc_check::Samples& s, std::size_t var, std::int64_t value) {
  return std::any_of(s.states.begin(), s.states.end(), [&](const auto& st) { return st[var].i == value; });
}

TEST(PlcSampling, ATripHoldsEveryVoterAndPulsesTheResetFromRest) {
  Vote v;
  const cemv::checker::SafetyProblem p{&v.ts, v.ctx.bool_val(true), v.ctx.bool_val(true)};
  SamplingOptions o;
  o.runs = 4;
  const auto drawn = cemv::plc_check::sample(p, o);
  ASSERT_FALSE(drawn.states.empty());
  EXPECT_FALSE(reached(drawn, 0, 5)) << "sixteen independent draws held for five scans";
  SamplingOptions::Trip trip;
  for (int i = 0; i < 16; ++i) trip.inputs["i" + std::to_string(i)] = Value{.i = 1};
  trip.inputs["r"] = Value{.i = 1};
  trip.hold = 6;
  trip.pulses = {{{"r", Value{.i = 1}}}};
  o.trips = {trip};
  const auto tripped = cemv::plc_check::sample(p, o);
  EXPECT_TRUE(reached(tripped, 0, 5)) << "the vote never held in the trip's run";
  EXPECT_TRUE(reached(tripped, 2, 1)) << "no rising edge of the reset while the vote held";
  // The random runs are the same with or without the trips: they come first.
  auto ints = [](const auto& st) {
    std::vector<std::int64_t> out;
    for (const auto& x : st) out.push_back(x.i);
    return out;
  };
  ASSERT_GE(tripped.states.size(), drawn.states.size());
  for (std::size_t i = 0; i < drawn.states.size(); ++i)
    EXPECT_EQ(ints(tripped.states[i]), ints(drawn.states[i])) << "state " << i;
}

// The tank example: each effect's causes at their tripping values, held
// through the longest delay, and its reset: the tag where it has one, the
// operator's override and reset commands where it has none.
TEST(PlcSampling, TripsTripEachEffectsCausesAndPulseItsReset) {
  const auto m = cemv::formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/matrix.json", "test");
  const SamplingOptions o = cemv::plc_check::at_rest(m);
  ASSERT_EQ(o.trips.size(), 3u);
  const auto& close = o.trips[0];  // XV_101: causes 1-3, latched, reset by HS_101_RST
  for (const char* t : {"input.LT_100A", "input.LT_100B", "input.LT_100C"}) {
    ASSERT_EQ(close.inputs.count(t), 1u) << t;
    EXPECT_TRUE(close.inputs.at(t).is_float);
    EXPECT_EQ(close.inputs.at(t).f, 93.0f) << t << ": limit 90, hysteresis 2, one past";
  }
  EXPECT_EQ(close.inputs.count("input.LSHH_100"), 1u);
  EXPECT_EQ(close.inputs.count("input.HS_100_ESD"), 1u);
  EXPECT_EQ(close.inputs.count("input.LT_102"), 0u) << "cause 4 has no intersection with effect 1";
  EXPECT_EQ(close.hold, 22) << "the 2 s on-delay's 20 scans of 100 ms, and two";
  ASSERT_EQ(close.pulses.size(), 1u);
  EXPECT_EQ(close.pulses[0].count("input.HS_101_RST"), 1u);
  const auto& pump = o.trips[1];  // P_101_RUN: no reset tag
  ASSERT_EQ(pump.pulses.size(), 2u);
  EXPECT_EQ(pump.pulses[0].count("cmd.override_effect[2]"), 1u);
  EXPECT_EQ(pump.pulses[1].count("cmd.reset_effect[2]"), 1u);
  const auto& low = o.trips[2];  // P_102_RUN: cause 4, low limit 10, hysteresis 3, 5 s
  ASSERT_EQ(low.inputs.count("input.LT_102"), 1u);
  EXPECT_EQ(low.inputs.at("input.LT_102").f, 6.0f);
  EXPECT_EQ(low.hold, 52);
}

// Without a reset tag an effect is reset and overridden by the operator's
// commands, which count only while secure write is enabled (M.3): the
// pulses set its enable tag with the command.
TEST(PlcSampling, CommandPulsesEnableSecureWrite) {
  auto m = cemv::formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/matrix.json", "test");
  const auto plain = cemv::plc_check::at_rest(m).trips[1].pulses;  // P_101_RUN: no reset tag
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain[0].size(), 1u) << "no secure write: the command alone";
  m.secure_write = cemv::model::SecureWrite{"EN_SWC"};
  const auto pulses = cemv::plc_check::at_rest(m).trips[1].pulses;
  ASSERT_EQ(pulses.size(), 2u);
  for (const auto& p : pulses) {
    ASSERT_EQ(p.count("input.EN_SWC"), 1u);
    EXPECT_EQ(p.at("input.EN_SWC").i, 1);
    EXPECT_EQ(p.size(), 2u);
  }
  EXPECT_EQ(pulses[0].count("cmd.override_effect[2]"), 1u);
  EXPECT_EQ(pulses[1].count("cmd.reset_effect[2]"), 1u);
}

// An effect reset by another effect's output tag (`Effect[x][y]`, E.1) sees
// a rising edge only when that tag follows its effect: with pass-through,
// while the process value is TRUE (E.8, E.9). The trip's run holds it so.
TEST(PlcSampling, AResetByAPassThroughTagHoldsItsProcessValueHealthy) {
  auto m = cemv::formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/matrix.json", "test");
  ASSERT_EQ(m.effects.size(), 3u);
  EXPECT_EQ(cemv::plc_check::at_rest(m).trips[2].inputs.count("input.XV_101_BPCS"), 0u);
  m.effects[2].reset_tag = "Effect[1][1]";  // XV_101, pass-through of XV_101_BPCS
  const SamplingOptions o = cemv::plc_check::at_rest(m);
  const auto& low = o.trips[2];
  ASSERT_EQ(low.inputs.count("input.XV_101_BPCS"), 1u);
  EXPECT_EQ(low.inputs.at("input.XV_101_BPCS").i, 1);
  EXPECT_EQ(low.inputs.at("input.LT_102").f, 6.0f) << "the trip's own inputs as before";
  m.effects[0].process_data.reset();
  EXPECT_EQ(cemv::plc_check::at_rest(m).trips[2].inputs.count("input.XV_101_BPCS"), 0u) << "no process value";
}

}  // namespace
