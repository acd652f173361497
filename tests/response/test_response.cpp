// `cemv response` on small matrices whose answer the semantics fixes
// (docs/semantics.md T.2, C.6, E.7, E.8, I.4): every figure is the one the
// runtime takes, and every T-1 counterexample replays on the runtime with the
// effect not yet active (docs/response-time.md).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "checker/engines/portfolio.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "checker/replay.hpp"
#include "model/vocabulary.hpp"
#include "response/paths.hpp"
#include "formats/matrix_json.hpp"
#include "properties/build.hpp"
#include "properties/evaluator.hpp"
#include "properties/parser.hpp"
#include "properties/print.hpp"
#include "response/analysis.hpp"
#include "response/demand.hpp"
#include "response/property.hpp"
#include "response/report.hpp"
#include "tests/support/random_matrix.hpp"
#include "tests/support/same_tree.hpp"

namespace {

using namespace cemv;
using response::Figure;
using response::Verdict;

// A matrix with one SIF group: `causes` and `effects` are JSON array bodies.
model::Matrix matrix(const std::string& causes, const std::string& effects, const std::string& intersections,
                     const std::string& extra = "") {
  std::string text = R"({"format": "cemv-matrix/1", "name": "T", "cycle_ms": 100,
    "sif_groups": {"1": {"name": "S", "process_safety_time_ms": 5000}},)" +
                     extra + R"("causes": [)" + causes + R"(], "effects": [)" + effects +
                     R"(], "intersections": [)" + intersections + "]}";
  return formats::parse_matrix(text, "test.json");
}

std::string cause(int id, const std::string& tag, const std::string& more = "") {
  return R"({"id": )" + std::to_string(id) + R"(, "name": "C)" + std::to_string(id) + R"(", "sif": [1], "tags": [{"name": ")" +
         tag + R"("}])" + (more.empty() ? "" : ", " + more) + "}";
}
std::string effect(int id, const std::string& tag, const std::string& more = "") {
  return R"({"id": )" + std::to_string(id) + R"(, "name": "E)" + std::to_string(id) + R"(", "sif": [1], "tags": [{"name": ")" +
         tag + R"("}])" + (more.empty() ? "" : ", " + more) + "}";
}
std::string link(int c, int e, const std::string& type = "N") {
  return R"({"cause": )" + std::to_string(c) + R"(, "effect": )" + std::to_string(e) + R"(, "type": ")" + type + R"("})";
}

std::filesystem::path scratch_root() {
  return std::filesystem::temp_directory_path() / ("cemv-response-test-" + std::to_string(::getpid()));
}

std::filesystem::path scratch(const std::string& name) {
  auto dir = scratch_root() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The scratch directories go when every test passed; a failure keeps them,
// with the scenarios and logs it names.
class RemoveScratchWhenPassed : public ::testing::Environment {
 public:
  void TearDown() override {
    if (::testing::UnitTest::GetInstance()->Passed()) {
      std::error_code ignored;
      std::filesystem::remove_all(scratch_root(), ignored);
    }
  }
};
[[maybe_unused]] ::testing::Environment* const remove_scratch =
    ::testing::AddGlobalTestEnvironment(new RemoveScratchWhenPassed);

response::ResponseResult analyse(const model::Matrix& m, const std::filesystem::path& out, bool conservative = false) {
  response::ResponseOptions o;
  o.out_dir = out.string();
  o.conservative = conservative;
  return response::analyse(m, o);
}

const response::PathResult& only_path(const response::ResponseResult& r, int effect_id) {
  for (const auto& p : r.paths)
    if (p.path.effect == effect_id) return p;
  throw std::runtime_error("no path to effect " + std::to_string(effect_id));
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The position of an observable in a runtime trace's rows (model::observables).
std::size_t observable_index(const model::Matrix& m, const std::string& key) {
  const auto all = model::observables(m);
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].key == key) return i;
  throw std::runtime_error("no observable " + key);
}

// The scenario replays on the runtime: `cemv simulate` checks its
// expectations (the property's signals after the last cycle) and exits 0.
void expect_replays(const model::Matrix& m, const std::filesystem::path& dir, const std::string& scenario) {
  ASSERT_FALSE(scenario.empty());
  const auto matrix_file = dir / "matrix.json";
  formats::save_matrix(m, matrix_file);
  std::string cmd = std::string(CEMV_BINARY) + " simulate " + matrix_file.string() + " " + (dir / scenario).string() +
                    " > " + (dir / "simulate.log").string() + " 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << read(dir / "simulate.log");
}

// The last cycle of the T-1 scenario expects the effect's output at its
// normal (not tripped) value: a DTT tag still 1.
void expect_not_yet_active(const std::filesystem::path& dir, const std::string& scenario, int effect) {
  std::string text = read(dir / scenario);
  std::string key = "\"effect[" + std::to_string(effect) + "].tag[1]\": true";
  EXPECT_NE(text.find(key), std::string::npos) << text;
}

// The path's figure is exactly `cycles`, and its T - 1 counterexample
// replays on the runtime with `effect` not yet active.
void expect_exact(const model::Matrix& m, const std::filesystem::path& dir, const response::PathResult& p,
                  long long cycles, int effect) {
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, cycles);
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, effect);
}

// The T - 1 counterexample is the demand itself (docs/response-time.md,
// "Method"): one quiet cycle, then only the trigger's tag changed and held
// for T cycles, at whose end the outputs have not yet responded.
void expect_demand_run(const std::filesystem::path& dir, const std::string& scenario, const std::string& tag,
                       int held) {
  const auto j = nlohmann::json::parse(read(dir / scenario));
  const auto& steps = j.at("steps");
  ASSERT_EQ(steps.size(), 2u) << j.dump(1);
  EXPECT_EQ(steps[0].at("cycles"), 1);
  EXPECT_EQ(steps[1].at("cycles"), held);
  ASSERT_EQ(steps[1].at("inputs").size(), 1u) << j.dump(1);
  EXPECT_TRUE(steps[1].at("inputs").contains(tag)) << j.dump(1);
}

TEST(Response, DirectPathWithoutDelayIsTwoCycles) {
  auto m = matrix(cause(1, "S1"), effect(1, "Y1"), link(1, 1), R"("watchdog_ms": 250,)");
  auto dir = scratch("direct");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  EXPECT_EQ(p.logic.kind, Figure::Kind::Exact);
  EXPECT_EQ(p.logic.cycles, 0);
  EXPECT_EQ(*p.total_ms, 200);
  EXPECT_EQ(*p.margin_ms, 4800);
  EXPECT_EQ(p.verdict, Verdict::Ok);
  EXPECT_TRUE(p.logic.counterexample.empty());  // nothing below 0 to falsify
  auto c = analyse(m, dir, true);
  EXPECT_EQ(*only_path(c, 1).total_ms, 500);  // twice watchdog_ms
}

TEST(Response, OnDelayOfTwoSecondsTakesTwentyCycles) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 2000}, "sensor_ms": 300)"),
                  effect(1, "Y1", R"("actuator_ms": 1500)"), link(1, 1));
  auto dir = scratch("on_delay");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 20);  // T.2: started in cycle s, expires in s + 20
  EXPECT_EQ(*p.logic_ms, 2000);
  EXPECT_EQ(*p.total_ms, 300 + 2000 + 200 + 1500);
  EXPECT_EQ(p.verdict, Verdict::Ok);
  EXPECT_EQ(p.logic.counterexample, "response.c1.e1.scenario.json");
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, 1);
  expect_demand_run(dir, p.logic.counterexample, "S1", 20);
}

TEST(Response, OutputDelayAddsItsCycles) {
  auto m = matrix(cause(1, "S1"), effect(1, "Y1", R"("output_delay_ms": 500)"), link(1, 1));
  auto dir = scratch("output_delay");
  const auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 5, 1));
  // After an on-delay: the two delays add up (10 + 20 cycles).
  auto both = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 1000})"),
                     effect(1, "Y1", R"("output_delay_ms": 2000)"), link(1, 1));
  auto dir2 = scratch("on_and_output_delay");
  const auto r2 = analyse(both, dir2);
  const auto& q = only_path(r2, 1);
  ASSERT_EQ(q.logic.kind, Figure::Kind::Exact) << q.logic.reason;
  EXPECT_EQ(q.logic.cycles, 30);
  expect_replays(both, dir2, q.logic.counterexample);
  expect_not_yet_active(dir2, q.logic.counterexample, 1);
}

// I.4: a reference to an element evaluated earlier in the scan reads its
// current value (no cycle); one that closes a cycle reads the previous
// cycle's value and adds that cycle.
TEST(Response, ChainThroughAReferenceAddsItsCycleOnlyWhenItReadsThePreviousValue) {
  // Forward chain: cause 1 -> effect 1 -> cause 2 (reads Effect[1], ETT) -> effect 2.
  auto forward = matrix(cause(1, "S1") + "," + R"({"id": 2, "name": "C2", "sif": [1], "tags": [{"name": "Effect[1]", "ett": true}]})",
                        effect(1, "Y1") + "," + effect(2, "Y2"), link(1, 1) + "," + link(2, 2));
  auto dir = scratch("chain");
  auto r = analyse(forward, dir);
  const auto& p = only_path(r, 2);
  ASSERT_EQ(p.path.causes, std::vector<int>{1});
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 0);
  // A closing reference: cause 1 (or: S1, Effect[2]) -> effect 1; cause 2
  // (Effect[1]) -> effect 2. Effect 2 feeds cause 1 and effect 1 feeds cause
  // 2: a cycle, whose smallest node, cause 1, goes first and reads effect 2's
  // previous value. The path S3 (cause 3) -> effect 2 -> cause 1 -> effect 1
  // crosses that reference and takes one cycle.
  auto closing = matrix(R"({"id": 1, "name": "C1", "sif": [1], "function": "or", "tags": [{"name": "S1"}, {"name": "Effect[2]", "ett": true}]},)"
                        R"({"id": 2, "name": "C2", "sif": [1], "tags": [{"name": "Effect[1]", "ett": true}]},)"
                        R"({"id": 3, "name": "C3", "sif": [1], "tags": [{"name": "S3"}]})",
                        effect(1, "Y1") + "," + effect(2, "Y2"), link(1, 1) + "," + link(2, 2) + "," + link(3, 2));
  auto dir3 = scratch("chain3");
  auto r3 = analyse(closing, dir3);
  bool found = false;
  for (const auto& q : r3.paths)
    if (q.path.effect == 1 && q.path.causes == std::vector<int>{3}) {
      found = true;
      ASSERT_EQ(q.logic.kind, Figure::Kind::Exact) << q.logic.reason;
      EXPECT_EQ(q.logic.cycles, 1);
      expect_replays(closing, dir3, q.logic.counterexample);
    }
  EXPECT_TRUE(found);
}

// A relay continues a route only when the upstream element being active
// trips it (docs/response-time.md, "Paths"). `Effect[1]` reads 1 when effect 1
// is active: a de-energize-to-trip tag trips on 0, so effect 1 responding to
// S1 *releases* cause 2 (a permissive), and S1 -> effect 2 is no route.
// `Effect[1][1]` reads effect 1's output tag, at its safe value 0 (DTT) when
// effect 1 responds: a DTT reference trips on exactly that.
TEST(Response, ReferenceThatTheDemandReleasesIsNoRoute) {
  auto keys = [](const model::Matrix& m) {
    std::set<std::string> out;
    for (const auto& p : response::response_paths(m, {})) out.insert(p.key());
    return out;
  };
  auto relay = [](const std::string& tag, bool ett) {
    return R"({"id": 2, "name": "C2", "sif": [1], "tags": [{"name": ")" + tag + R"(", "ett": )" +
           (ett ? "true" : "false") + "}]}";
  };
  auto with_relay = [&](const std::string& tag, bool ett) {
    return matrix(cause(1, "S1") + "," + relay(tag, ett), effect(1, "Y1") + "," + effect(2, "Y2"),
                  link(1, 1) + "," + link(2, 2));
  };
  EXPECT_EQ(keys(with_relay("Effect[1]", true)), (std::set<std::string>{"c1.e1", "c1.e2"}));
  EXPECT_EQ(keys(with_relay("Effect[1]", false)), (std::set<std::string>{"c1.e1"}));
  EXPECT_EQ(keys(with_relay("Effect[1][1]", false)), (std::set<std::string>{"c1.e1", "c1.e2"}));
  EXPECT_EQ(keys(with_relay("Effect[1][1]", true)), (std::set<std::string>{"c1.e1"}));
  // The runtime agrees: with S1 tripped and held, cause 2 reading Effect[1]
  // DTT goes inactive once effect 1 responds, and effect 2 never does.
  const auto m = with_relay("Effect[1]", false);
  auto dir = scratch("released");
  response::Path p;
  p.causes = {1};
  p.effect = 2;
  p.elements = {{model::Node::Kind::Cause, 1}, {model::Node::Kind::Effect, 2}};
  const auto trace = checker::run_on_runtime(m, response::demand_run(m, p, response::Mode::Normal, 20));
  const std::size_t c2 = observable_index(m, "cause[2].active"), e2 = observable_index(m, "effect[2].active");
  EXPECT_EQ(trace.observables.front()[c2], 1);  // the plant quiet: effect 1 inactive, the permissive trips
  EXPECT_EQ(trace.observables.back()[c2], 0);
  EXPECT_EQ(trace.observables.back()[e2], 0);
}

// While the effect is inactive, a pass-through shows the BPCS value P: as P
// on a DTT tag and NOT P on an ETT one (E.9), so P = 1 keeps every tag away
// from its safe value, whatever its ett. The demand run's quiet plant sets
// that, and its run is the T - 1 counterexample for an effect whose first
// tag is ETT too (it used to set P = 0 there: every tag safe at rest).
TEST(Response, PassThroughIsQuietAwayFromTheSafeValuesOfEveryTag) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 2000})"),
                  R"({"id": 1, "name": "E1", "sif": [1], "tags": [{"name": "Y1", "ett": true}, {"name": "Y2"}],
                      "process_data": {"tag": "BPCS1", "pass_through": true}})",
                  link(1, 1));
  auto dir = scratch("pass_through_ett");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 20);
  expect_replays(m, dir, p.logic.counterexample);
  expect_demand_run(dir, p.logic.counterexample, "S1", 20);
  const auto j = nlohmann::json::parse(read(dir / p.logic.counterexample));
  EXPECT_EQ(j.at("steps")[0].at("inputs").at("BPCS1"), true) << j.dump(1);
}

// An effect latched at start-up answers the plain demand at once: cause 2
// reads Cause[1] de-energize-to-trip (a permissive, tripped while cause 1
// is quiet), pulses for 500 ms at start-up and sets effect 1's S latch.
// Nothing holds cause 2 off (no bypass or inhibit tag). The T - 1 run is
// the demand after the plant settled and effect 1 was reset
// (response::demand_run_after_reset): the reset_effect command, then S1.
TEST(Response, EffectLatchedAtStartUpIsResetBeforeTheDemand) {
  auto m = matrix(cause(1, "S1") + "," +
                      R"({"id": 2, "name": "C2", "sif": [1], "tags": [{"name": "Cause[1]", "ett": false}],
                          "time": {"mode": "timed", "ms": 500}})",
                  effect(1, "Y1", R"("output_delay_ms": 500)"), link(1, 1) + "," + link(2, 1, "S"));
  auto dir = scratch("latched_at_start");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.path.causes, std::vector<int>{1});
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 5, 1));
  // That run, not an engine's trace: the plant settles for 6 cycles (the
  // 500 ms pulse and output delay, and one more), then the reset.
  const auto j = nlohmann::json::parse(read(dir / p.logic.counterexample));
  ASSERT_EQ(j.at("steps").size(), 3u) << j.dump(1);
  EXPECT_EQ(j.at("steps")[0].at("cycles"), 6) << j.dump(1);
  EXPECT_EQ(j.at("steps")[1].at("commands")[0].at("op"), "reset_effect") << j.dump(1);
  // The plain demand shows nothing: effect 1 is latched when S1 trips.
  const auto plain = checker::run_on_runtime(m, response::demand_run(m, p.path, response::Mode::Normal, 4));
  EXPECT_EQ(plain.observables[1][observable_index(m, "effect[1].active")], 1);
}

// A start-up pulse that comes back: cause 2 reads `Effect[3]`
// de-energize-to-trip, so it trips while effect 3 is not active; its 1 s
// pulse activates effect 3 and latches effect 1 (S), and when the pulse ends
// effect 3 falls and cause 2 pulses again. The settled demand trips cause 4,
// which holds effect 3 active, so that cause 2 pulses once; then effect 1 is
// reset (the reset counts only with secure write enabled, M.3) and the
// demand on cause 1 shows its 0.5 s on-delay.
TEST(Response, StartUpPulseThatComesBackIsReleasedBeforeTheDemand) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 500})") + "," +
                      cause(2, "Effect[3]", R"("time": {"mode": "timed", "ms": 1000})") + "," + cause(4, "S4"),
                  effect(1, "Y1") + "," + effect(3, "Y3"),
                  link(1, 1) + "," + link(2, 1, "S") + "," + link(2, 3) + "," + link(4, 3),
                  R"("secure_write": {"enable_tag": "EN"},)");
  auto dir = scratch("start_up_pulse");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.path.causes, std::vector<int>{1});
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 5, 1));
  // The settled run, not an engine's trace: cause 4 tripped from the first
  // cycle, the reset with secure write enabled.
  const auto j = nlohmann::json::parse(read(dir / p.logic.counterexample));
  const auto& steps = j.at("steps");
  ASSERT_GE(steps.size(), 3u) << j.dump(1);
  EXPECT_EQ(steps[0].at("inputs").at("S4"), false) << j.dump(1);
  EXPECT_EQ(steps[1].at("commands")[0].at("op"), "reset_effect") << j.dump(1);
  EXPECT_EQ(steps[1].at("inputs").at("EN"), true) << j.dump(1);
  // Without cause 4, the pulse comes back after the reset.
  const auto reset = response::demand_run_after_reset(m, p.path, response::Mode::Normal, 4);
  ASSERT_TRUE(reset);
  const auto again = checker::run_on_runtime(m, *reset);
  EXPECT_EQ(again.observables.back()[observable_index(m, "effect[1].active")], 1);
}

// Cause 1 is an `or` of S1 and `Effect[2]`, de-energize-to-trip: it trips at
// rest while effect 2 is not active, so a demand after a quiet cycle is no
// fresh demand. A demand at start-up is: its 0.5 s on-delay and effect 1's
// 0.3 s output delay.
TEST(Response, DemandAtStartUpIsFreshWhereTheCauseTripsAtRest) {
  auto m = matrix(R"({"id": 1, "name": "C1", "sif": [1], "function": "or", "tags": [{"name": "S1"}, {"name": "Effect[2]"}],
                      "time": {"mode": "on_delay", "ms": 500}})" "," + cause(3, "S3"),
                  effect(1, "Y1", R"("output_delay_ms": 300)") + "," + effect(2, "Y2"),
                  link(1, 1, "S") + "," + link(3, 2));
  auto dir = scratch("start_up_demand");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 8, 1));
  const auto j = nlohmann::json::parse(read(dir / p.logic.counterexample));
  EXPECT_EQ(j.at("steps")[0].at("inputs").at("S1"), false) << j.dump(1);  // tripped from the first cycle
  const auto plain = checker::run_on_runtime(m, response::demand_run(m, p.path, response::Mode::Normal, 7));
  EXPECT_EQ(plain.observables[0][observable_index(m, "cause[1].trip_requested")], 1);  // tripped at rest
  // The demand at start-up violates "within 7 cycles" by itself, where the
  // plain demand judges nothing (its trigger never rises freshly).
  const auto file = response::response_property(m, p.path, response::Mode::Normal, 7, "start");
  auto judge = [&](const checker::ConcreteTrace& run) {
    properties::Trace trace;
    for (std::size_t i = 0; i < run.inputs.size(); ++i) trace.push_back({run.inputs[i], run.observables[i]});
    return properties::Evaluator(m).evaluate(file, trace).at(0);
  };
  const auto at_start_up =
      judge(checker::run_on_runtime(m, response::demand_run_at_start_up(m, p.path, response::Mode::Normal, 7)));
  EXPECT_FALSE(at_start_up.holds);
  EXPECT_EQ(at_start_up.cycle, std::optional<std::size_t>(7));
  EXPECT_TRUE(judge(plain).holds);
}

TEST(Response, TwoOutOfThreeWithOneBadInputReportsItsDegradedFigure) {
  // Discrete switches (de-energize-to-trip): 2oo3 with "degrade" becomes 1oo2
  // when one of them goes bad (C.4).
  auto m = matrix(R"({"id": 1, "name": "C1", "sif": [1], "function": "2oo3", "bad_quality": "degrade",
                      "time": {"mode": "on_delay", "ms": 1000},
                      "tags": [{"name": "LS_A"}, {"name": "LS_B"}, {"name": "LS_C"}]})",
                  effect(1, "Y1"), link(1, 1));
  auto dir = scratch("degraded");
  const auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 10);
  ASSERT_TRUE(p.degraded);
  ASSERT_EQ(p.degraded->kind, Figure::Kind::Exact) << p.degraded->reason;
  EXPECT_EQ(p.degraded->cycles, 10);
  EXPECT_EQ(*p.degraded_total_ms, 1200);
  expect_replays(m, dir, p.degraded->counterexample);
}

// Without the degraded figure (cemv defeats needs only T): the same normal
// figure, and no degraded one is computed or reported.
TEST(Response, NormalFigureAloneIsTheSameWithoutTheDegradedOne) {
  auto m = matrix(R"({"id": 1, "name": "C1", "sif": [1], "function": "2oo3", "bad_quality": "degrade",
                      "time": {"mode": "on_delay", "ms": 1000},
                      "tags": [{"name": "LS_A"}, {"name": "LS_B"}, {"name": "LS_C"}]})",
                  effect(1, "Y1"), link(1, 1));
  const auto both = analyse(m, scratch("with_degraded"));
  response::ResponseOptions o;
  o.degraded = false;
  const auto normal = response::analyse(m, o);
  const auto& a = only_path(both, 1);
  const auto& b = only_path(normal, 1);
  ASSERT_TRUE(a.degraded);
  EXPECT_FALSE(b.degraded);
  EXPECT_FALSE(b.degraded_total_ms);
  ASSERT_EQ(b.logic.kind, Figure::Kind::Exact) << b.logic.reason;
  EXPECT_EQ(b.logic.cycles, a.logic.cycles);
  EXPECT_EQ(b.total_ms, a.total_ms);
  EXPECT_EQ(b.verdict, a.verdict);
}

// A bad input in `ignore` mode votes with the value it delivers (C.3): an
// `and` of two switches whose bad input delivers its healthy value never
// trips. The degraded figure is `unbounded`, shown by the demand run itself
// (the bad input at its healthy value, the other tripped), held to the cap.
TEST(Response, IgnoredBadInputOfAnAndHoldsTheDegradedResponseOff) {
  auto m = matrix(R"({"id": 1, "name": "C1", "sif": [1], "function": "and", "bad_quality": "ignore",
                      "tags": [{"name": "PS_A"}, {"name": "PS_B"}]})",
                  effect(1, "Y1"), link(1, 1));
  auto dir = scratch("ignored_bad_input");
  const auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 0);
  ASSERT_TRUE(p.degraded);
  ASSERT_EQ(p.degraded->kind, Figure::Kind::Unbounded) << p.degraded->reason;
  expect_replays(m, dir, p.degraded->counterexample);
  const auto j = nlohmann::json::parse(read(dir / p.degraded->counterexample));
  ASSERT_EQ(j.at("steps").size(), 2u) << j.dump(1);
  const auto& demand = j.at("steps")[1].at("inputs");
  EXPECT_EQ(demand.at("PS_A").at("quality"), "bad") << j.dump(1);
  EXPECT_EQ(demand.at("PS_A").at("value"), true) << j.dump(1);  // healthy: DTT reads 1
  EXPECT_EQ(demand.at("PS_B"), false) << j.dump(1);
}

TEST(Response, OffDelayAndTimedCausesRespondAtOnce) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "off_delay", "ms": 3000})") + "," +
                      cause(2, "S2", R"("time": {"mode": "timed", "ms": 5000})"),
                  effect(1, "Y1") + "," + effect(2, "Y2", R"("output_delay_ms": 200)"), link(1, 1) + "," + link(2, 2));
  auto r = analyse(m, scratch("timers"));
  const auto& off = only_path(r, 1);
  ASSERT_EQ(off.logic.kind, Figure::Kind::Exact) << off.logic.reason;
  EXPECT_EQ(off.logic.cycles, 0);  // the off-delay delays only the end of a trip
  const auto& timed = only_path(r, 2);
  ASSERT_EQ(timed.logic.kind, Figure::Kind::Exact) << timed.logic.reason;
  EXPECT_EQ(timed.logic.cycles, 2);  // the pulse starts with the demand; the output delay follows
}

// A mask switched by an operator is maintenance and assumed off; a mask the
// logic drives (here: cause 2's activity) holds the outputs off for ever.
TEST(Response, MaskedPathIsUnbounded) {
  auto m = matrix(cause(1, "S1") + "," + cause(2, "S2"),
                  effect(1, "Y1", R"("process_data": {"tag": "BPCS_1", "mask_tag": "Cause[2]"})") + "," +
                      effect(2, "Y2", R"("process_data": {"tag": "BPCS_2", "mask_tag": "MASK_2"})"),
                  link(1, 1) + "," + link(1, 2));
  auto dir = scratch("masked");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  EXPECT_EQ(p.logic.kind, Figure::Kind::Unbounded);
  EXPECT_EQ(p.verdict, Verdict::Unbounded);
  EXPECT_EQ(response::exit_code(r), 1);
  expect_replays(m, dir, p.logic.counterexample);
  const auto& switched = only_path(r, 2);
  ASSERT_EQ(switched.logic.kind, Figure::Kind::Exact) << switched.logic.reason;
  EXPECT_EQ(switched.logic.cycles, 0);
}

TEST(Response, OverTheProcessSafetyTimeFails) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 5000})"), effect(1, "Y1"), link(1, 1));
  auto dir = scratch("over");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  EXPECT_EQ(*p.total_ms, 5200);
  EXPECT_EQ(*p.margin_ms, -200);
  EXPECT_EQ(p.verdict, Verdict::Over);
  EXPECT_EQ(response::exit_code(r), 1);
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, 1);
  std::string json = response::response_report(r, "m.json", response::Format::Json, "");
  EXPECT_NE(json.find("\"schema\": \"cemv-response/1\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"verdict\": \"over\""), std::string::npos) << json;
}

// 6.5.2: an XooN assignment is one path, triggered by X of its N causes.
TEST(Response, XooNAssignmentIsOnePathTriggeredByXCauses) {
  auto m = matrix(cause(1, "S1") + "," + cause(2, "S2") + "," + cause(3, "S3"), effect(1, "Y1"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2},
                     {"cause": 3, "effect": 1, "type": "N", "xoon": 2})");
  auto r = analyse(m, scratch("xoon"));
  ASSERT_EQ(r.paths.size(), 1u);
  const auto& p = r.paths.front();
  EXPECT_EQ(p.path.causes, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(p.path.needed, 2);
  EXPECT_EQ(p.path.key(), "c1_2_3.e1");  // a name the property language reads
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 0);
}

// The demand of an XooN path is a fixed set of X causes, each held since its
// rise (docs/response-time.md, "XooN paths"). Three 1 s on-delays, 2oo3: pairs
// that take turns every 4 cycles keep two conditions true in every cycle, yet
// no cause's timer ever expires. That is no demand, so the figure is the
// on-delay, not `unbounded`.
TEST(Response, XooNCausesTakingTurnsAreNoDemand) {
  const std::string delay = R"("time": {"mode": "on_delay", "ms": 1000})";
  auto m = matrix(cause(1, "S1", delay) + "," + cause(2, "S2", delay) + "," + cause(3, "S3", delay), effect(1, "Y1"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2},
                     {"cause": 3, "effect": 1, "type": "N", "xoon": 2})");
  auto dir = scratch("xoon_turns");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 10, 1));
  // The pairs {1,2}, {1,3}, {2,3} in turn, 4 cycles each (switches are DTT:
  // 0 is tripped): two conditions in every cycle, the effect never active,
  // and the bound of 10 cycles not violated.
  const model::InputTable table(m);
  model::CycleInput quiet = model::default_cycle_input(m);
  for (const char* tag : {"S1", "S2", "S3"}) quiet.tags[*table.find(tag)].value = 1.0f;
  std::vector<model::CycleInput> turns{quiet};
  const std::vector<std::pair<const char*, const char*>> pairs{{"S1", "S2"}, {"S1", "S3"}, {"S2", "S3"}};
  for (int round = 0; round < 4; ++round)
    for (const auto& [a, b] : pairs) {
      model::CycleInput c = quiet;
      c.tags[*table.find(a)].value = 0.0f;
      c.tags[*table.find(b)].value = 0.0f;
      turns.insert(turns.end(), 4, c);
    }
  const auto run = checker::run_on_runtime(m, turns);
  for (const auto& o : run.observables) ASSERT_EQ(o[observable_index(m, "effect[1].active")], 0);
  const auto file = response::response_property(m, p.path, response::Mode::Normal, 10, "turns");
  properties::Trace trace;
  for (std::size_t i = 0; i < run.inputs.size(); ++i) trace.push_back({run.inputs[i], run.observables[i]});
  const auto e = properties::Evaluator(m).evaluate(file, trace).at(0);
  EXPECT_TRUE(e.assumptions_held);
  EXPECT_TRUE(e.holds);
  EXPECT_FALSE(e.antecedent_met);  // no set of two held for 10 cycles
}

// Members of an XooN set may rise at different times. A timed (pulse) cause
// that rises first has ended its pulse when the last member rises, and the
// XooN never sees two active causes: `unbounded`, although both tripping in
// one cycle responds at once.
TEST(Response, XooNWhosePulseEndsBeforeTheSetCompletesIsUnbounded) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "timed", "ms": 500})") + "," + cause(2, "S2"), effect(1, "Y1"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2})");
  auto dir = scratch("xoon_pulse");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Unbounded) << p.logic.reason;
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, 1);
  const auto together = checker::run_on_runtime(m, response::demand_run(m, p.path, response::Mode::Normal, 0));
  EXPECT_EQ(together.observables.back()[observable_index(m, "effect[1].active")], 1);
}

// The demand set with the pulses first: the 0.2 s pulse of cause 2 ends
// before the 1 s on-delay of cause 1 fires, while the slowest set (causes 1
// and 3) responds after 1 s. The unbounded counterexample is that run: one
// quiet cycle, then causes 1 and 2 tripped and held.
TEST(Response, XooNDemandWithItsPulseFirstShowsItUnbounded) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 1000})") + "," +
                      cause(2, "S2", R"("time": {"mode": "timed", "ms": 200})") + "," +
                      cause(3, "S3", R"("time": {"mode": "on_delay", "ms": 500})"),
                  effect(1, "Y1"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2},
                     {"cause": 3, "effect": 1, "type": "N", "xoon": 2})");
  auto dir = scratch("xoon_pulse_first");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Unbounded) << p.logic.reason;
  expect_replays(m, dir, p.logic.counterexample);
  const auto j = nlohmann::json::parse(read(dir / p.logic.counterexample));
  ASSERT_EQ(j.at("steps").size(), 2u) << j.dump(1);
  const auto& demand = j.at("steps")[1].at("inputs");
  EXPECT_EQ(demand.size(), 2u) << j.dump(1);
  EXPECT_EQ(demand.at("S1"), false) << j.dump(1);
  EXPECT_EQ(demand.at("S2"), false) << j.dump(1);
}

// An XooN bound is proved from its member lemmas (docs/response-time.md,
// "Compositional proof"): each cause is active once its on-delay has run
// while its condition holds, and the induction then only spans the effect's
// output delay. The slowest set, causes 1 (1 s) and 2 (0.5 s), responds
// after 1 s and the 0.3 s output delay.
TEST(Response, XooNBoundIsProvedFromItsMemberLemmas) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 1000})") + "," +
                      cause(2, "S2", R"("time": {"mode": "on_delay", "ms": 500})") + "," + cause(3, "S3"),
                  effect(1, "Y1", R"("output_delay_ms": 300)"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2},
                     {"cause": 3, "effect": 1, "type": "N", "xoon": 2})");
  auto dir = scratch("xoon_lemmas");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 13);
  EXPECT_NE(p.logic.method.find("from member lemmas"), std::string::npos) << p.logic.method;
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, 1);
  // One lemma per cause that is not timed, each its own property.
  const auto lemmas = response::member_lemmas(m, p.path, response::Mode::Normal, 13, "l");
  ASSERT_TRUE(lemmas);
  EXPECT_EQ(lemmas->names, (std::vector<std::string>{"l.c1", "l.c2", "l.c3"}));
  EXPECT_EQ(lemmas->delays, (std::vector<long long>{10, 5, 0}));
  const std::string term = properties::to_text(lemmas->terms[0], model::InputTable(m));
  EXPECT_NE(term.find("not held(cause[1].active, 3 cycles)"), std::string::npos) << term;
  EXPECT_EQ(lemmas->file.properties.size(), 3u);
}

// Cause 1 activates effect 2 once its 0.5 s on-delay has run, and effect 2
// bypasses cause 2, the other member of the 2oo2. No demand lasts beyond
// that cycle (a bypassed cause of the path is no demand), and until then the
// XooN never sees both: the path never responds to a demand that can be
// held, `unbounded` with the reason. An override of effect 2 (1 s at most)
// would lift the bypass for that long; it is an operation on the path, and
// the figure does not count it.
TEST(Response, DemandThatTheLogicEndsIsUnbounded) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 500})") + "," +
                      cause(2, "S2", R"("bypass_tag": "Effect[2]")"),
                  effect(1, "Y1") + "," + effect(2, "Y2", R"("override": {"max_s": 1, "prealarm_s": 0})"),
                  R"({"cause": 1, "effect": 1, "type": "N", "xoon": 2}, {"cause": 2, "effect": 1, "type": "N", "xoon": 2},
                     {"cause": 1, "effect": 2, "type": "V"})");
  auto dir = scratch("demand_ended");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Unbounded) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 4);
  EXPECT_NE(p.logic.reason.find("cannot last longer than 5 cycles"), std::string::npos) << p.logic.reason;
  EXPECT_EQ(p.verdict, Verdict::Unbounded);
  expect_replays(m, dir, p.logic.counterexample);
  expect_not_yet_active(dir, p.logic.counterexample, 1);
  const std::string text =
      properties::build::file_text(response::response_property(m, p.path, response::Mode::Normal, 5, "t"),
                                   model::InputTable(m));
  EXPECT_NE(text.find("assume not effect[2].override_active"), std::string::npos) << text;
}

// A cause bypassed through a de-energize-to-trip output of another effect
// (`Effect[2][1]` reads 1 while effect 2 is not active) is held off from
// start-up. The demand runs trip cause 3, which activates effect 2 at once,
// in every cycle (docs/response-time.md, "Method"), so that the demand run is
// the T - 1 counterexample.
TEST(Response, BypassThroughAnEffectOutputIsReleasedInTheDemandRun) {
  auto m = matrix(cause(1, "S1", R"("bypass_tag": "Effect[2][1]", "time": {"mode": "on_delay", "ms": 500})") + "," +
                      cause(3, "S3"),
                  effect(1, "Y1") + "," + effect(2, "Y2"), link(1, 1) + "," + link(3, 2));
  auto dir = scratch("bypass_released");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 5);
  EXPECT_EQ(p.logic.method.find("directed run"), std::string::npos);  // the bound is proved by an engine
  expect_replays(m, dir, p.logic.counterexample);
  expect_demand_run(dir, p.logic.counterexample, "S1", 5);
  const auto first = nlohmann::json::parse(read(dir / p.logic.counterexample)).at("steps")[0].at("inputs");
  EXPECT_EQ(first.at("S3"), false) << first.dump();
  // Without cause 3 tripped, cause 1 is bypassed in the first cycle.
  const auto plain = checker::run_on_runtime(m, {model::default_cycle_input(m)});
  EXPECT_EQ(plain.observables[0][observable_index(m, "cause[1].bypassed")], 1);
}

// Cause 1 is bypassed while effect 2 is active, and a permissive (cause 3
// reads `Cause[4]`, de-energize-to-trip) keeps effect 2 active at rest. The
// demand with the path alone holds cause 3 off by its bypass tag, and is the
// T - 1 counterexample.
TEST(Response, DemandAloneHoldsOffWhatBypassesThePath) {
  auto m = matrix(cause(1, "S1", R"("bypass_tag": "Effect[2]", "time": {"mode": "on_delay", "ms": 500})") + "," +
                      cause(3, "Cause[4]", R"("bypass_tag": "BY3")") + "," + cause(4, "S4"),
                  effect(1, "Y1") + "," + effect(2, "Y2"), link(1, 1) + "," + link(3, 2));
  auto dir = scratch("held_off_holder");
  auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_EQ(p.logic.kind, Figure::Kind::Exact) << p.logic.reason;
  EXPECT_EQ(p.logic.cycles, 5);
  expect_replays(m, dir, p.logic.counterexample);
  expect_demand_run(dir, p.logic.counterexample, "S1", 5);
  const auto first = nlohmann::json::parse(read(dir / p.logic.counterexample)).at("steps")[0].at("inputs");
  EXPECT_EQ(first.at("BY3"), true) << first.dump();
}

// Tag T is read by cause 3, which activates effect 2 and so inhibits cause 1
// of the path when T is 0, and by cause 4 of the path's effect, energize-to-
// trip, which wants T at 0 but also needs U. The quiet plant sets T to 1:
// the causes that would hold a path cause off are quiet last, and the demand
// run is the T - 1 counterexample.
TEST(Response, QuietPlantKeepsWhatWouldHoldThePathOffQuiet) {
  auto m = matrix(cause(1, "S1", R"("inhibit_tag": "Effect[2]", "time": {"mode": "on_delay", "ms": 500})") + "," +
                      cause(3, "T") + "," +
                      R"({"id": 4, "name": "C4", "sif": [1], "function": "and",
                          "tags": [{"name": "T", "ett": true}, {"name": "U", "ett": true}]})",
                  effect(1, "Y1") + "," + effect(2, "Y2"), link(1, 1) + "," + link(3, 2) + "," + link(4, 1));
  auto dir = scratch("quiet_holders");
  auto r = analyse(m, dir);
  const response::PathResult* p = nullptr;
  for (const auto& x : r.paths)
    if (x.path.effect == 1 && x.path.causes == std::vector<int>{1}) p = &x;
  ASSERT_TRUE(p);
  ASSERT_EQ(p->logic.kind, Figure::Kind::Exact) << p->logic.reason;
  EXPECT_EQ(p->logic.cycles, 5);
  expect_replays(m, dir, p->logic.counterexample);
  expect_demand_run(dir, p->logic.counterexample, "S1", 5);
  // T at 1 from the first cycle on: its scenario default, or set there.
  const auto first = nlohmann::json::parse(read(dir / p->logic.counterexample)).at("steps")[0];
  EXPECT_EQ(first.value("inputs", nlohmann::json::object()).value("T", true), true) << first.dump();
}

// Long delays are not unrolled (docs/response-time.md, "Method"): a 30 min
// on-delay at 100 ms is exactly 18,000 cycles, proved, and the run one cycle
// short (17,999 cycles of a held demand) replays on the runtime.
TEST(Response, ThirtyMinuteOnDelayIsExactWithoutUnrolling) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 1800000})"), effect(1, "Y1"), link(1, 1));
  auto dir = scratch("long");
  const auto r = analyse(m, dir);
  const auto& p = only_path(r, 1);
  ASSERT_NO_FATAL_FAILURE(expect_exact(m, dir, p, 18000, 1));
}

// The proof of a bound does not unroll it: one induction step of the
// invariant engine, with the monitor-bound candidates of its miner
// (docs/response-time.md, "Method"), proves an on-delay of 10 cycles then an
// output delay of 20 at T = 30, and cannot prove T = 29.
TEST(Response, InvariantEngineProvesTheBoundInOneStep) {
  auto m = matrix(cause(1, "S1", R"("time": {"mode": "on_delay", "ms": 1000})"),
                  effect(1, "Y1", R"("output_delay_ms": 2000)"), link(1, 1));
  const auto path = response::response_paths(m, {}).at(0);
  for (long long t : {30LL, 29LL}) {
    auto file = response::response_property(m, path, response::Mode::Normal, t, "probe");
    z3::context ctx;
    auto problem = checker::reduce(checker::property_problem(m, file, file.properties.at(0))(ctx));
    auto r = checker::make_prover(checker::Method::InvariantsInduction)
                 ->prove(problem.problem, checker::Limits{}.with_work(60 * checker::kMega));
    if (t == 30) {
      EXPECT_EQ(r.verdict, checker::Verdict::Proved) << r.reason_text();
      EXPECT_LE(r.k, 1);
    } else {
      EXPECT_NE(r.verdict, checker::Verdict::Proved);
    }
  }
}

// A wide cone (big_matrix's effect 8, reached from cause 19 through internal
// references: 471 state variables, 122 after the reductions) is not asked in
// order of invariants+induction, whose relational miner would spend the whole
// limit at k = 0 there, but of PDR, which proves the bound at once
// (checker::CheckOptions::engines_when_wide); its T - 1 is the demand run.
// big_matrix's cause 124 -> effect 23 is a direct path in a cone of 318
// state variables (after the exact reductions), most of them other causes of
// effect 23 and the effects their references read. No engine proves T = 13
// there within a minute; on the path's own elements, the rest free
// (checker/localize.hpp), PDR does in a second, and the proof re-checks on
// the whole cone. T - 1 is the demand with effect 23's other causes held
// off by their bypass and inhibit tags: several of them are tripped at rest.
TEST(Response, WideConeIsProvedOnItsLocalization) {
  const model::Matrix m = testsupport::big_matrix(1);
  response::Path path;
  for (const auto& p : response::response_paths(m, {}))
    if (p.effect == 23 && p.causes == std::vector<int>{124}) path = p;
  ASSERT_EQ(path.effect, 23);
  auto dir = scratch("wide_cone");
  response::SearchOptions so;
  so.out_dir = dir.string();
  const Figure f = response::least_response(m, path, response::Mode::Normal, so);
  ASSERT_EQ(f.kind, Figure::Kind::Exact) << f.reason;
  EXPECT_EQ(f.cycles, 13);
  EXPECT_EQ(f.method, "pdr, localized");
  expect_replays(m, dir, f.counterexample);
  // The scenario is that demand: one quiet cycle (others held off), then the
  // trigger held, and no engine's trace.
  const auto j = nlohmann::json::parse(read(dir / f.counterexample));
  EXPECT_EQ(j.at("steps").size(), 2u) << j.dump(1);
  const auto plain = response::demand_run(m, path, response::Mode::Normal, 12);
  const auto alone = response::demand_run_alone(m, path, response::Mode::Normal, 12);
  ASSERT_TRUE(alone.has_value());
  std::size_t held_off = 0;
  for (std::size_t i = 0; i < plain.front().tags.size(); ++i)
    held_off += plain.front().tags[i].value != alone->front().tags[i].value;
  EXPECT_GT(held_off, 0u);
}

// The command line's progress line is fed by the analysis: the number of
// paths once, then each path's start and end, each path once (a path in two
// groups is decided once), two jobs at a time.
TEST(Response, ProgressSeesEveryPathOnce) {
  auto m = formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
  response::ResponseOptions o;
  o.jobs = 2;
  std::size_t planned = 0;
  std::vector<std::string> started, done;
  o.on_plan = [&](std::size_t n) { planned = n; };
  o.on_start = [&](const std::string& key) { started.push_back(key); };
  o.on_done = [&](const std::string& key) { done.push_back(key); };
  const auto r = response::analyse(m, o);
  std::set<std::string> keys;
  for (const auto& p : r.paths) keys.insert(p.path.key());
  EXPECT_EQ(planned, keys.size());
  EXPECT_EQ(std::set<std::string>(started.begin(), started.end()), keys);
  EXPECT_EQ(std::set<std::string>(done.begin(), done.end()), keys);
  EXPECT_EQ(started.size(), keys.size());
  EXPECT_EQ(done.size(), keys.size());
}

}  // namespace

namespace {
// Random matrices with SIF groups (tests/support/random_matrix.hpp): every
// path decided or `unknown` with a reason, nothing refuted by cemv's own
// checks (an InternalError would throw), every counterexample replayed.
// CEMV_RESPONSE_SEEDS=N tries N seeds (200: 381 paths, 39 of them XooN, in
// 81 s).
TEST(Response, RandomMatricesAreDecidedAndTheirCounterexamplesReplay) {
  const int seeds = std::getenv("CEMV_RESPONSE_SEEDS") ? std::atoi(std::getenv("CEMV_RESPONSE_SEEDS")) : 12;
  int paths = 0, xoon = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const model::Matrix m = testsupport::random_matrix(static_cast<std::uint64_t>(seed));
    if (m.sif_groups.empty()) continue;
    auto dir = scratch("random_" + std::to_string(seed));
    response::ResponseOptions o;
    o.out_dir = dir.string();
    o.jobs = 2;
    const auto r = response::analyse(m, o);
    for (const auto& p : r.paths) {
      ++paths;
      xoon += p.path.causes.size() > 1;
      if (p.logic.kind == Figure::Kind::Unknown) {
        EXPECT_FALSE(p.logic.reason.empty()) << "seed " << seed << " " << p.path.key();
        continue;
      }
      if (!p.logic.counterexample.empty()) expect_replays(m, dir, p.logic.counterexample);
    }
  }
  // The sample is not empty, and it has XooN paths (member lemmas).
  EXPECT_GT(paths, 10);
  EXPECT_GT(xoon, 0);
}
}  // namespace

// The bounds, member lemmas and trip requirements are built as trees; their
// text for people reads back as the same trees, on random matrices with every
// option and on the examples.
TEST(ResponseProperty, PrintsAsItsTree) {
  std::vector<model::Matrix> ms;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) ms.push_back(testsupport::random_matrix(seed));
  for (const char* n : {"burner-management", "compressor", "pipeline-hipps", "tank-overfill"})
    ms.push_back(formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + n + "/matrix.json", "t"));
  int paths = 0;
  for (const auto& m : ms) {
    const model::InputTable inputs(m);
    auto roundtrip = [&](const properties::PropertyFile& f) {
      const auto back = properties::parse_properties(properties::build::file_text(f, inputs), m, f.file_name);
      EXPECT_EQ(testsupport::tree_difference(back, f), "") << properties::build::file_text(f, inputs);
    };
    for (const auto& p : response::response_paths(m, {})) {
      ++paths;
      for (auto mode : {response::Mode::Normal, response::Mode::Degraded}) {
        if (mode == response::Mode::Degraded && p.voted.empty()) continue;
        roundtrip(response::response_property(m, p, mode, 9, "bound"));
        if (auto lemmas = response::member_lemmas(m, p, mode, 9, "bound.members")) {
          roundtrip(lemmas->file);
          roundtrip(response::response_property(m, p, mode, 9, "bound", lemmas->terms));
        }
      }
      roundtrip(response::requirement_property(m, p, 9, "requirement", {}));
    }
  }
  EXPECT_GT(paths, 40);
}

namespace {
// ResponseOptions::known (cemv defeats --response): the figures a caller
// gives are taken as given, with no probe, and the others are decided as
// without them; given the figures of an earlier run, every path's figures
// and verdict are that run's.
TEST(Response, KnownFiguresAreTakenAsGiven) {
  auto m = formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
  response::ResponseOptions o;
  o.degraded = false;
  const auto first = response::analyse(m, o);
  ASSERT_GT(first.paths.size(), 1u);
  response::ResponseOptions again = o;
  for (const auto& p : first.paths) again.known[p.path.key()] = p.logic;
  const auto second = response::analyse(m, again);
  ASSERT_EQ(second.paths.size(), first.paths.size());
  for (std::size_t i = 0; i < first.paths.size(); ++i) {
    EXPECT_EQ(second.paths[i].logic.kind, first.paths[i].logic.kind) << first.paths[i].path.key();
    EXPECT_EQ(second.paths[i].logic.cycles, first.paths[i].logic.cycles) << first.paths[i].path.key();
    EXPECT_EQ(second.paths[i].verdict, first.paths[i].verdict) << first.paths[i].path.key();
  }
  // One path given a figure no probe would find: it is reported as given,
  // and the path beside it is decided as before.
  response::ResponseOptions one = o;
  Figure given;
  given.kind = Figure::Kind::Exact;
  given.cycles = 12345;
  one.known[first.paths[0].path.key()] = given;
  const auto third = response::analyse(m, one);
  EXPECT_EQ(third.paths[0].logic.cycles, 12345);
  EXPECT_EQ(third.paths[0].logic.probes, 0);
  EXPECT_EQ(third.paths[1].logic.cycles, first.paths[1].logic.cycles);
  EXPECT_GT(third.paths[1].logic.probes, 0);
}
}  // namespace
