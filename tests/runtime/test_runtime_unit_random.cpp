// The runtime on many seeded random matrices (tests/support) fed with random
// inputs and operator commands: it never throws, never allocates inside
// step(), is deterministic, agrees with the scenario format on default inputs,
// every cycle satisfies invariants that follow directly from
// docs/semantics.md, and a copy taken part way goes on as the original.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/vocabulary.hpp"
#include "runtime/runtime.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv_test {
long allocation_count();
}

namespace {

using namespace cemv;

constexpr int kSeeds = 150;
constexpr int kCycles = 300;

// Index of each observable by key, to read fields of one cause or effect.
struct Fields {
  explicit Fields(const std::vector<model::Observable>& obs) {
    for (std::size_t i = 0; i < obs.size(); ++i) index[obs[i].key] = i;
  }
  int get(const std::vector<int>& snap, const std::string& key) const {
    return snap[index.at(key)];
  }
  std::map<std::string, std::size_t> index;
};

void check_invariants(const model::Matrix& m, const Fields& f, const std::vector<int>& s,
                      const std::string& where) {
  std::map<int, int> first_outs;  // group -> causes holding first out
  for (const model::Cause& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    const std::string p = "cause[" + std::to_string(c.id) + "].";
    const bool active = f.get(s, p + "active");
    // C.8: a bypassed or inhibited cause is never active.
    if (f.get(s, p + "bypassed") || f.get(s, p + "inhibited")) {
      EXPECT_FALSE(active) << where << p;
    }
    // C.8: a soft bypass is a bypass.
    if (f.get(s, p + "soft_bypassed")) {
      EXPECT_TRUE(f.get(s, p + "bypassed")) << where << p;
    }
    // C.4: all tags soft-bypassed never requests a trip.
    if (f.get(s, p + "voting") == static_cast<int>(model::Voting::Bypass)) {
      EXPECT_FALSE(f.get(s, p + "trip_requested")) << where << p;
      EXPECT_TRUE(f.get(s, p + "degraded")) << where << p;
    }
    // C.9: tripped tags are voting tags.
    EXPECT_LE(f.get(s, p + "tripped_tags"), static_cast<int>(c.tags.size())) << where << p;
    // C.6: without a time function, active needs the request or the ack latch.
    if (c.time.mode == model::TimeMode::None && active) {
      EXPECT_TRUE(f.get(s, p + "trip_requested") || f.get(s, p + "ack_required")) << where << p;
    }
    // C.7: only manual-ack causes can require an acknowledgement.
    if (c.auto_ack) {
      EXPECT_FALSE(f.get(s, p + "ack_required")) << where << p;
    }
    // C.9: hysteresis and delta only for analog causes.
    if (c.input == model::InputKind::Discrete) {
      EXPECT_FALSE(f.get(s, p + "hysteresis_active")) << where << p;
      EXPECT_FALSE(f.get(s, p + "delta_alarm")) << where << p;
    }
    if (c.first_out_group == 0) {
      EXPECT_FALSE(f.get(s, p + "first_out")) << where << p;
    }
    if (f.get(s, p + "first_out")) ++first_outs[c.first_out_group];
  }
  // C.11: at most one first out per group.
  for (auto [group, n] : first_outs) EXPECT_LE(n, 1) << where << " group " << group;

  for (const model::Effect& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    const std::string p = "effect[" + std::to_string(e.id) + "].";
    const bool active = f.get(s, p + "active");
    // E.6: a bypassed effect is never active; the output delay runs only while active.
    if (f.get(s, p + "bypassed")) {
      EXPECT_FALSE(active) << where << p;
    }
    if (f.get(s, p + "output_delay_running")) {
      EXPECT_TRUE(active) << where << p;
    }
    if (e.output_delay_ms == 0) {
      EXPECT_FALSE(f.get(s, p + "output_delay_running")) << where << p;
    }
    // E.3: overrides only where configured.
    if (!e.override_time) {
      EXPECT_FALSE(f.get(s, p + "override_active")) << where << p;
    }
    if (f.get(s, p + "override_prealarm")) {
      EXPECT_TRUE(f.get(s, p + "override_active")) << where << p;
    }
    // E.11: OK to reset only when latched.
    if (f.get(s, p + "ok_to_reset")) {
      EXPECT_TRUE(f.get(s, p + "latched")) << where << p;
    }
    if (!e.process_data) {
      EXPECT_FALSE(f.get(s, p + "masked")) << where << p;
      EXPECT_FALSE(f.get(s, p + "pass_through_active")) << where << p;
    }
  }
}

TEST(RandomMatrices, InvariantsDeterminismNoAllocation) {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const model::Matrix m = testsupport::random_matrix(seed);
    const auto frames = testsupport::random_inputs(m, seed, kCycles);
    runtime::Runtime a(m);
    runtime::Runtime b(m);

    const auto obs = model::observables(m);
    const Fields fields(obs);
    std::vector<int> sa, sb;
    sa.reserve(obs.size());
    sb.reserve(obs.size());
    long allocations = 0;
    for (int k = 0; k < kCycles; ++k) {
      const long before = cemv_test::allocation_count();
      a.step(frames[k]);
      allocations += cemv_test::allocation_count() - before;
      b.step(frames[k]);
      a.snapshot(sa);
      b.snapshot(sb);
      ASSERT_EQ(sa, sb) << "cycle " << k + 1;
      check_invariants(m, fields, sa, "cycle " + std::to_string(k + 1) + " ");
      if (::testing::Test::HasFailure()) return;
    }
    EXPECT_EQ(allocations, 0);
  }
}

// A copy of a runtime (runtime::Runtime's copy constructor, what seeded
// simulation continues a prefix from) steps exactly as the original from the
// cycle it was taken, timers, latches, soft bypasses and simulation included,
// and stepping the copy leaves the original as it was.
TEST(RandomMatrices, ACopyGoesOnAsTheOriginal) {
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const model::Matrix m = testsupport::random_matrix(seed);
    const auto frames = testsupport::random_inputs(m, seed, kCycles);
    runtime::Runtime a(m);
    std::vector<int> sa, sb, sc;
    for (int k = 0; k < kCycles / 2; ++k) a.step(frames[k]);
    runtime::Runtime b = a;
    runtime::Runtime c(m);
    c = a;
    // The copy runs ahead on other inputs first: the original must not see it.
    runtime::Runtime scratch = a;
    for (int k = 0; k < 20; ++k) scratch.step(frames[k]);
    for (int k = kCycles / 2; k < kCycles; ++k) {
      a.step(frames[k]);
      b.step(frames[k]);
      c.step(frames[k]);
      a.snapshot(sa);
      b.snapshot(sb);
      c.snapshot(sc);
      ASSERT_EQ(sa, sb) << "cycle " << k + 1;
      ASSERT_EQ(sa, sc) << "cycle " << k + 1;
    }
    EXPECT_EQ(a.cycles_run(), b.cycles_run());
  }
}

}  // namespace
