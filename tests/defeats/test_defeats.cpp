// `cemv defeats` on hand-made matrices whose minimal defeat sets the
// semantics fixes (docs/semantics.md C.3, C.4, O.6, E.3, I.3;
// docs/defeats.md): exactly those sets, never a set that is not minimal,
// every counterexample replayed on the runtime and judged by the concrete
// evaluator, every subset's proof a question that holds.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "checker/replay.hpp"
#include "defeats/analysis.hpp"
#include "defeats/report.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "properties/evaluator.hpp"
#include "properties/parser.hpp"
#include "response/property.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;
using Sets = std::set<std::set<std::string>>;

model::Matrix matrix(const std::string& causes, const std::string& effects, const std::string& intersections) {
  const std::string text = R"({"format": "cemv-matrix/1", "name": "D", "cycle_ms": 100,
    "sif_groups": {"1": "S"}, "causes": [)" + causes + R"(], "effects": [)" + effects +
                           R"(], "intersections": [)" + intersections + "]}";
  return formats::parse_matrix(text, "test.json");
}

// Three discrete inputs A, B, C of a 2oo3 cause 1 (SIL 2) into effect 1,
// nothing else allowed but what `more` says.
model::Matrix two_of_three(const std::string& more, bool tag_soft_bypass) {
  const std::string allowed = tag_soft_bypass ? "true" : "false";
  auto tag = [&](const char* n) {
    return std::string(R"({"name": ")") + n + R"(", "soft_bypass_allowed": )" + allowed +
           R"(, "simulation_allowed": false})";
  };
  return matrix(R"({"id": 1, "name": "C1", "sil": 2, "sif": [1], "function": "2oo3", "tags": [)" + tag("A") + ", " +
                    tag("B") + ", " + tag("C") + R"(], "soft_bypass": {"allowed": false}, )" + more + "}",
                R"({"id": 1, "name": "E1", "sil": 2, "sif": [1], "tags": [{"name": "Y", "simulation_allowed": false}]})",
                R"({"cause": 1, "effect": 1, "type": "N"})");
}

std::filesystem::path scratch(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() / ("cemv-defeats-test-" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The hand-made matrices are enumerated as the command line does (the other
// enumerations are held to the checker's through the differential test;
// MARCO also on the degraded 2oo3 below).
defeats::DefeatsResult run(const model::Matrix& m, const std::filesystem::path& out, int max_size = 2,
                           defeats::Enumeration how = defeats::DefeatsOptions{}.enumeration) {
  defeats::DefeatsOptions o;
  o.enumeration = how;
  o.max_size = max_size;
  o.out_dir = out.string();
  return defeats::analyse(m, o);
}

const defeats::PathDefeats& only_path(const defeats::DefeatsResult& r) {
  EXPECT_EQ(r.paths.size(), 1u);
  return r.paths.at(0);
}

Sets sets_of(const defeats::PathDefeats& p) {
  Sets out;
  for (const auto& s : p.sets) {
    std::set<std::string> keys;
    for (int a : s.actions) keys.insert(p.actions[a].key());
    out.insert(keys);
  }
  return out;
}

// Every reported set: its counterexample replays on the runtime and
// violates the requirement with exactly the set's actions allowed (the
// concrete evaluator judges the assumptions too: no other action occurs);
// each subset of one action fewer is covered by a question that holds and
// contains it; and no reported set contains another.
void expect_checked(const model::Matrix& m, const defeats::PathDefeats& p, const std::filesystem::path& out) {
  for (const auto& s : p.sets) {
    const defeats::Question& q = p.questions.at(s.question);
    EXPECT_EQ(q.actions, s.actions);
    ASSERT_TRUE(q.defeats());
    ASSERT_FALSE(q.scenario.empty()) << q.property;
    const formats::Scenario sc = formats::load_scenario(out / q.scenario, m);
    const formats::ExpandedScenario ex = formats::expand_scenario(sc, m);
    const checker::ConcreteTrace run = checker::run_on_runtime(m, ex.cycles);
    std::vector<std::string> excluded;
    for (std::size_t i = 0; i < p.actions.size(); ++i)
      if (!std::count(s.actions.begin(), s.actions.end(), static_cast<int>(i)))
        excluded.push_back(p.actions[i].excluded_term());
    const auto file = properties::parse_properties(
        response::requirement_property_text(m, p.path, *p.requirement, "judge", excluded), m, "judge");
    properties::Trace trace;
    for (std::size_t i = 0; i < run.inputs.size(); ++i) trace.push_back({run.inputs[i], run.observables[i]});
    const auto verdict = properties::Evaluator(m).evaluate(file, trace).at(0);
    EXPECT_FALSE(verdict.holds) << q.property << " does not violate the requirement on the runtime";
    for (const auto& [sub, proof] : s.subsets) {
      const defeats::Question& by = p.questions.at(proof);
      EXPECT_TRUE(by.holds()) << by.property;
      EXPECT_TRUE(std::includes(by.actions.begin(), by.actions.end(), sub.begin(), sub.end()));
    }
    EXPECT_EQ(s.subsets.size(), s.actions.size());
    for (const auto& t : p.sets) {
      if (&t == &s) continue;
      EXPECT_FALSE(std::includes(s.actions.begin(), s.actions.end(), t.actions.begin(), t.actions.end()))
          << "a reported set contains another";
    }
  }
}

// C.4: 2oo3 with degraded voting. One input in bad quality leaves 1oo2 of
// the others, which still trips; two leave 1oo1 of the third, which the
// demand (two inputs beyond, or bad) need not move.
TEST(Defeats, TwoOfThreeWithDegradedVotingFallsToTwoBadInputs) {
  const auto m = two_of_three(R"("bad_quality": "degrade")", false);
  for (const auto how : {defeats::Enumeration::LevelsOnEncoding, defeats::Enumeration::OneEncoding}) {
    const auto out = scratch("degraded");
    const auto r = run(m, out, 2, how);
    const auto& p = only_path(r);
    EXPECT_EQ(p.status, defeats::PathStatus::Complete) << p.reason;
    EXPECT_EQ(sets_of(p), (Sets{{"bad_quality[A]", "bad_quality[B]"},
                                {"bad_quality[A]", "bad_quality[C]"},
                                {"bad_quality[B]", "bad_quality[C]"}}));
    for (const auto& s : p.sets) EXPECT_EQ(s.set_class, defeats::SetClass::Indirect);
    EXPECT_EQ(p.distance, std::optional<int>(2));
    expect_checked(m, p, out);
  }
  // Sizes up to 1 only: none found, and the distance is "> 1".
  const auto one = run(m, scratch("degraded1"), 1);
  EXPECT_TRUE(one.paths.at(0).sets.empty());
  EXPECT_FALSE(one.paths.at(0).distance.has_value());
}

// C.3: in `trip` mode a bad input counts as tripped: no fault defeats.
TEST(Defeats, TwoOfThreeThatTripsOnBadQualityHasNoDefeat) {
  const auto m = two_of_three(R"("bad_quality": "trip")", false);
  const auto r = run(m, scratch("trip"));
  EXPECT_TRUE(only_path(r).sets.empty());
  EXPECT_EQ(only_path(r).status, defeats::PathStatus::Complete);
}

// O.6: two soft-bypassed tags leave 1oo1 of the third; with mutually
// locked maintenance the second tag's soft bypass is refused.
TEST(Defeats, MutuallyLockedMaintenanceRefusesTheSecondTagBypass) {
  const auto open = two_of_three(R"("bad_quality": "trip")", true);
  const auto out = scratch("unlocked");
  const auto r = run(open, out);
  const auto& p = only_path(r);
  EXPECT_EQ(sets_of(p), (Sets{{"soft_bypass_tag[1,1]", "soft_bypass_tag[1,2]"},
                              {"soft_bypass_tag[1,1]", "soft_bypass_tag[1,3]"},
                              {"soft_bypass_tag[1,2]", "soft_bypass_tag[1,3]"}}));
  for (const auto& s : p.sets) EXPECT_EQ(s.set_class, defeats::SetClass::Declared);
  EXPECT_FALSE(p.distance.has_value());  // no indirect set
  expect_checked(open, p, out);

  const auto locked = two_of_three(R"("bad_quality": "trip", "mutually_locked_maintenance": true)", true);
  const auto l = run(locked, scratch("locked"));
  EXPECT_TRUE(only_path(l).sets.empty());
  EXPECT_EQ(only_path(l).status, defeats::PathStatus::Complete) << only_path(l).reason;
}

// E.3, I.3: cause 1 drives effect 2 (a V cell, another safety function's
// element), which cause 3 reads through `Effect[2]` into the path's effect
// 1. An override of effect 2 suppresses the request: an indirect defeat of
// one action. Cause 1's bypass tag is the declared one.
model::Matrix through_override() {
  return matrix(
      R"({"id": 1, "name": "C1", "sil": 2, "sif": [1], "tags": [{"name": "T1", "soft_bypass_allowed": false,
          "simulation_allowed": false}], "soft_bypass": {"allowed": false}, "bypass_tag": "BYP1"},
         {"id": 3, "name": "C3", "sil": 2, "sif": [1], "tags": [{"name": "Effect[2]", "ett": true,
          "soft_bypass_allowed": false}], "soft_bypass": {"allowed": false}})",
      R"({"id": 1, "name": "E1", "sil": 2, "sif": [1], "tags": [{"name": "Y1", "simulation_allowed": false}]},
         {"id": 2, "name": "E2", "tags": [{"name": "Y2", "simulation_allowed": false}], "override": {"max_s": 600}})",
      R"({"cause": 1, "effect": 2, "type": "V"}, {"cause": 3, "effect": 1, "type": "N"})");
}

TEST(Defeats, OverrideOfAnotherEffectReadThroughAReferenceIsIndirect) {
  const auto m = through_override();
  const auto out = scratch("override");
  const auto r = run(m, out);
  const auto& p = only_path(r);
  EXPECT_EQ(p.path.key(), "c1.e1");
  EXPECT_EQ(p.status, defeats::PathStatus::Complete) << p.reason;
  EXPECT_EQ(sets_of(p), (Sets{{"cause_bypass_tag[BYP1]"}, {"override[2]"}}));
  for (const auto& s : p.sets)
    EXPECT_EQ(s.set_class, p.actions[s.actions[0]].kind == defeats::ActionKind::Override
                               ? defeats::SetClass::Indirect
                               : defeats::SetClass::Declared);
  EXPECT_EQ(p.distance, std::optional<int>(1));
  expect_checked(m, p, out);
  // The gate: a SIL 2 group whose distance is 1 fails --require-distance 2.
  EXPECT_EQ(defeats::exit_code(r, 2), 1);
  EXPECT_EQ(defeats::exit_code(r, 1), 0);
  EXPECT_EQ(defeats::exit_code(r, 0), 0);
}

// The outputs are pure functions of the result, and the run is
// reproducible: the same JSON from two runs, whatever --jobs.
TEST(Defeats, ReportIsReproducible) {
  const auto m = through_override();
  defeats::DefeatsOptions o;
  const auto a = defeats::analyse(m, o);
  o.jobs = 2;
  const auto b = defeats::analyse(m, o);
  const std::string ja = defeats::defeats_report(m, a, "m.json", defeats::Format::Json, "", 2);
  EXPECT_EQ(ja, defeats::defeats_report(m, b, "m.json", defeats::Format::Json, "", 2));
  EXPECT_NE(ja.find("\"schema\": \"cemv-defeats/1\""), std::string::npos);
  EXPECT_NE(ja.find("\"gate_failed\": true"), std::string::npos);
  const std::string text = defeats::defeats_report(m, a, "m.json", defeats::Format::Text, "", 2);
  EXPECT_NE(text.find("{override[2]}"), std::string::npos) << text;
  EXPECT_NE(text.find("gate:"), std::string::npos) << text;
}

}  // namespace

namespace {

// The differential test of the enumerations (docs/defeats.md,
// "Enumeration"): on seeded random matrices with SIF groups, the
// level-by-level enumeration on one encoding per path (the command line's)
// and the MARCO-style one find exactly the minimal sets (and the statuses,
// distances and counterexample questions) that the level-by-level
// enumeration with every set a question to the checker finds.
// Seeds are tried in order until the sample is large enough (paths decided
// both ways, with sets, among them a pair), at most CEMV_DEFEATS_SEEDS (40).
// One path of `other` against the oracle's; counts what was compared.
struct Sample {
  int compared = 0, with_sets = 0, pairs = 0;
};

void expect_same_sets(const defeats::PathDefeats& a, const defeats::PathDefeats& b, const std::string& where,
                      Sample& n) {
  ++n.compared;
  n.with_sets += !a.sets.empty();
  EXPECT_EQ(a.status, b.status) << where;
  EXPECT_EQ(sets_of(a), sets_of(b)) << where;
  EXPECT_EQ(a.distance, b.distance) << where;
  for (std::size_t s = 0; s < a.sets.size() && s < b.sets.size(); ++s) {
    n.pairs += a.sets[s].actions.size() == 2;
    EXPECT_EQ(a.sets[s].set_class, b.sets[s].set_class) << where;
    EXPECT_EQ(a.questions[a.sets[s].question].property, b.questions[b.sets[s].question].property) << where;
    EXPECT_EQ(a.questions[a.sets[s].question].method, b.questions[b.sets[s].question].method) << where;
    EXPECT_EQ(a.questions[a.sets[s].question].violation_cycle, b.questions[b.sets[s].question].violation_cycle)
        << where;
    for (const auto& [sub, proof] : b.sets[s].subsets) EXPECT_TRUE(b.questions.at(proof).holds()) << where;
  }
}

TEST(Defeats, EncodingEnumerationsFindTheSetsOfTheCheckerQuestions) {
  const int seeds = std::getenv("CEMV_DEFEATS_SEEDS") ? std::atoi(std::getenv("CEMV_DEFEATS_SEEDS")) : 40;
  Sample n;
  for (int seed = 1; seed <= seeds && !(n.compared > 10 && n.with_sets > 6 && n.pairs > 1); ++seed) {
    const model::Matrix m = testsupport::random_matrix(static_cast<std::uint64_t>(seed));
    if (m.sif_groups.empty()) continue;
    defeats::DefeatsOptions o;
    o.max_size = 2;
    o.jobs = 2;
    o.enumeration = defeats::Enumeration::LevelByLevel;
    const auto oracle = defeats::analyse(m, o);
    for (const auto how : {defeats::Enumeration::LevelsOnEncoding, defeats::Enumeration::OneEncoding}) {
      o.enumeration = how;
      const auto other = defeats::analyse(m, o);
      ASSERT_EQ(oracle.paths.size(), other.paths.size());
      for (std::size_t i = 0; i < oracle.paths.size(); ++i) {
        const auto& a = oracle.paths[i];
        const auto& b = other.paths[i];
        ASSERT_EQ(a.path.key(), b.path.key());
        if (a.status == defeats::PathStatus::Unknown || b.status == defeats::PathStatus::Unknown) continue;
        expect_same_sets(a, b,
                         "seed " + std::to_string(seed) + " path " + a.path.key() +
                             (how == defeats::Enumeration::OneEncoding ? " (MARCO)" : " (levels on one encoding)"),
                         n);
      }
    }
  }
  // The sample is not empty: paths decided both ways by each, with sets of two.
  EXPECT_GT(n.compared, 10);
  EXPECT_GT(n.with_sets, 6);
  EXPECT_GT(n.pairs, 1);
}

}  // namespace
