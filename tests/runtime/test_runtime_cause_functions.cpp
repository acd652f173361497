// Every row of the 6.3.1 tables "Mutual dependencies of the Cause parameters":
// discrete (1-3 tags, each function type; the manual assumes DTT and we check
// ETT as its mirror, footnote "*") and analog (high and low, each function type,
// with the hysteresis sentences). Hysteresis acts at cause level (docs/semantics.md
// C.4): while the cause's logic result was TRUE in the previous cycle every tag is
// judged against the relaxed threshold and the same voting decides.
#include <gtest/gtest.h>

#include <cmath>

#include "test_sim.hpp"

namespace cemv::testing {
namespace {

struct FunctionRow {
  const char* name;
  CauseFunction function;
  int tags;
  int needed;  // tripped tags that trip the cause
};

// Printed in ctest's test list: a readable case, not the struct's raw bytes
// (which hold addresses and differ between runs).
void PrintTo(const FunctionRow& r, std::ostream* os) { *os << r.name; }

const FunctionRow kRows[] = {
    {"Standard_1tag", CauseFunction::Normal, 1, 1},  // "Input tag = FALSE"
    {"AND_2tags", CauseFunction::And, 2, 2},         // "both input tags = FALSE"
    {"OR_2tags", CauseFunction::Or, 2, 1},           // "one of the two input tags = FALSE"
    {"2oo3_3tags", CauseFunction::TwoOoThree, 3, 2}, // "at least two of three input tags = FALSE"
    {"AND_3tags", CauseFunction::And, 3, 3},         // "all three input tags = FALSE"
    {"OR_3tags", CauseFunction::Or, 3, 1},           // "one of three input tags = FALSE"
};

class DiscreteRow : public ::testing::TestWithParam<FunctionRow> {};

TEST_P(DiscreteRow, TripsExactlyWhenTheFunctionSaysSo) {
  const FunctionRow& r = GetParam();
  for (Kind kind : {Kind::DiscreteDtt, Kind::DiscreteEtt}) {
    for (int mask = 0; mask < (1 << r.tags); ++mask) {
      SCOPED_TRACE(std::string(kind_name(kind)) + " tripped-tag mask " + std::to_string(mask));
      Sim sim(make_matrix({make_cause(1, r.function, r.tags, kind)}, {make_effect(1)}, {link(1, 1)}));
      int tripped = 0;
      for (int i = 0; i < r.tags; ++i) {
        bool t = (mask >> i) & 1;
        tripped += t;
        sim.set(cat({"T1_", num(i + 1)}), t ? tripped_value(kind) : healthy_value(kind));
      }
      sim.step();
      bool expect = tripped >= r.needed;
      EXPECT_EQ(sim.b("cause[1].active"), expect);
      EXPECT_EQ(sim.b("cause[1].trip_requested"), expect);
      EXPECT_EQ(sim.get("cause[1].tripped_tags"), tripped);
      EXPECT_EQ(sim.out("Y1_1"), expect ? 0 : 1);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Table631, DiscreteRow, ::testing::ValuesIn(kRows),
                         [](const auto& info) { return std::string(info.param.name); });

// "Comment only: Never": a comment cause is not processed (3.4): it has no
// status, its tags are not inputs, and an effect it is the only cause of never
// becomes active.
TEST(Table631, CommentOnlyNeverTrips) {
  for (int n : {1, 2, 3}) {
    Cause comment = make_cause(2, CauseFunction::Comment, n, Kind::DiscreteDtt);
    Sim sim(make_matrix({make_cause(1, CauseFunction::Normal, 1, Kind::DiscreteDtt), comment},
                        {make_effect(1)}, {link(1, 1)}));
    EXPECT_FALSE(sim.runtime().inputs().find("T2_1"));
    for (const auto& o : observables(sim.matrix())) EXPECT_FALSE(o.key.starts_with("cause[2]"));
    sim.step(3);
    EXPECT_FALSE(sim.b("cause[1].active"));
  }
}

// The analog rows. For limit type high the relaxed threshold is limit - hyst =
// 85, for low limit + hyst = 15. `at_limit` trips, `between` lies between the
// limit and the relaxed threshold, `at_relaxed` is the relaxed threshold itself
// (still tripped while hysteresis applies), `beyond` is just past it.
struct AnalogPoints {
  float at_limit, between, at_relaxed, beyond;
};
AnalogPoints points(Kind k) {
  if (k == Kind::AnalogHigh) return {90.0f, 89.5f, 85.0f, 84.9f};
  return {10.0f, 10.5f, 15.0f, 15.1f};
}

class AnalogRow : public ::testing::TestWithParam<FunctionRow> {};

// "the input tag(s) have exceeded (undershot) the limit. The Cause will not
// become inactive again until ... (enough) input tags have undershot the limit
// minus hysteresis (exceeded the limit plus hysteresis)". For "AND, 2 tags, High"
// the manual says "until the two input tag have undershot"; that contradicts the
// Low row and the 3-tag AND rows ("one of"): erratum decided in docs/semantics.md C.4, the
// cause goes inactive when one of the two undershoots.
TEST_P(AnalogRow, TripsAtTheLimitAndHoldsUntilTheRelaxedThresholdIsLeft) {
  const FunctionRow& r = GetParam();
  for (Kind kind : {Kind::AnalogHigh, Kind::AnalogLow}) {
    SCOPED_TRACE(kind_name(kind));
    const AnalogPoints p = points(kind);
    Sim sim(make_matrix({make_cause(1, r.function, r.tags, kind)}, {make_effect(1)}, {link(1, 1)}));
    auto tag = [](int i) { return cat({"T1_", num(i)}); };
    // Healthy start.
    sim.step();
    EXPECT_FALSE(sim.b("cause[1].active"));
    // One tag short of the function, the others between limit and relaxed
    // threshold: no trip (hysteresis only applies after a trip).
    for (int i = 1; i <= r.tags; ++i) sim.set(tag(i), i < r.needed ? p.at_limit : p.between);
    sim.step();
    EXPECT_FALSE(sim.b("cause[1].active")) << "one tag short of the function must not trip";
    EXPECT_FALSE(sim.b("cause[1].hysteresis_active"));
    // Exactly `needed` tags at the limit itself: value >= limit (<= for low) trips.
    for (int i = 1; i <= r.tags; ++i) sim.set(tag(i), i <= r.needed ? p.at_limit : p.between);
    sim.step();
    EXPECT_TRUE(sim.b("cause[1].active")) << "tags at the limit trip the cause";
    // Every tag at the relaxed threshold: still tripped under hysteresis.
    for (int i = 1; i <= r.tags; ++i) sim.set(tag(i), p.at_relaxed);
    sim.step();
    EXPECT_TRUE(sim.b("cause[1].active")) << "the relaxed threshold itself still counts";
    // Tags leave the relaxed band one by one; the cause holds while enough remain.
    for (int left = 1; left <= r.tags; ++left) {
      sim.set(tag(left), p.beyond);
      sim.step();
      int remaining = r.tags - left;
      bool expect = remaining >= r.needed;
      EXPECT_EQ(sim.b("cause[1].active"), expect) << left << " tag(s) beyond the relaxed threshold";
      if (!expect) break;
    }
    EXPECT_FALSE(sim.b("cause[1].active"));
    // Back between limit and relaxed threshold: no hysteresis any more, no trip.
    for (int i = 1; i <= r.tags; ++i) sim.set(tag(i), p.between);
    sim.step(2);
    EXPECT_FALSE(sim.b("cause[1].active")) << "after going inactive the full limit applies again";
  }
}

INSTANTIATE_TEST_SUITE_P(Table631, AnalogRow, ::testing::ValuesIn(kRows),
                         [](const auto& info) { return std::string(info.param.name); });

// The worked example of docs/semantics.md C.4: 2oo3 high, limit 90, hysteresis 5.
TEST(Hysteresis, WorkedExample2oo3) {
  Sim sim(make_matrix({make_cause(1, CauseFunction::TwoOoThree, 3, Kind::AnalogHigh)},
                      {make_effect(1)}, {link(1, 1)}));
  auto set3 = [&](float a, float b, float c) {
    sim.set("T1_1", a);
    sim.set("T1_2", b);
    sim.set("T1_3", c);
    sim.step();
  };
  set3(84, 84, 84);
  EXPECT_FALSE(sim.b("cause[1].active"));
  set3(95, 95, 87);
  EXPECT_TRUE(sim.b("cause[1].active"));
  set3(95, 84, 87);
  EXPECT_TRUE(sim.b("cause[1].active"));
  EXPECT_TRUE(sim.b("cause[1].hysteresis_active"));
  set3(95, 84, 80);
  EXPECT_FALSE(sim.b("cause[1].active"));
}

// 6.3.1: values are REAL. The comparison is value >= limit in single precision:
// the float just below the limit does not trip.
TEST(AnalogLimit, ComparesInSinglePrecision) {
  Sim sim(make_matrix({make_cause(1, CauseFunction::Normal, 1, Kind::AnalogHigh)}, {make_effect(1)},
                      {link(1, 1)}));
  sim.set("T1_1", std::nextafter(kHighLimit, 0.0f));
  sim.step();
  EXPECT_FALSE(sim.b("cause[1].active"));
  sim.set("T1_1", kHighLimit);
  sim.step();
  EXPECT_TRUE(sim.b("cause[1].active"));
}

}  // namespace
}  // namespace cemv::testing
