// The test generator on the examples: objectives are well-formed properties
// with unique ids; a generated suite covers its objectives and replays green;
// replay reports failures on a matrix the suite was not made for.
#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "checker/replay.hpp"
#include "formats/matrix_json.hpp"
#include "properties/build.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "testgen/explore.hpp"
#include "testgen/scenario_writer.hpp"
#include "testgen/sweep.hpp"
#include "testgen/checklist.hpp"
#include "testgen/testgen.hpp"
#include "tests/support/random_matrix.hpp"
#include "tests/support/same_tree.hpp"

namespace {

using namespace cemv;

const char* kExamples[] = {"burner-management", "compressor", "pipeline-hipps", "tank-overfill"};

model::Matrix example(const std::string& name) {
  return formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json", "tested");
}

TEST(Objectives, EveryExampleParsesWithUniqueIds) {
  for (const char* name : kExamples) {
    model::Matrix m = example(name);
    auto objs = testgen::derive_objectives(m);
    ASSERT_GT(objs.size(), 50u) << name;
    std::set<std::string> ids;
    for (const auto& o : objs) EXPECT_TRUE(ids.insert(o.id).second) << name << ": " << o.id;
    // Printed for people, each objective reads back as the tree it is.
    auto file = properties::parse_properties(testgen::objectives_file_text(m, objs), m, "objectives");
    ASSERT_EQ(file.properties.size(), objs.size()) << name;
    for (std::size_t i = 0; i < objs.size(); ++i)
      EXPECT_EQ(testsupport::tree_difference(file.properties[i], objs[i].property), "") << name << " " << objs[i].id;
  }
}

// Generated matrices with every option (internal references among the tags
// of a cause included, which have no quality of their own) give objectives
// whose text for people reads back as the same trees: the catalogue of the
// 128 x 128 benchmark matrix too.
TEST(Objectives, RandomMatricesPrintAsTheirTrees) {
  auto check = [](const model::Matrix& m, const std::string& what) {
    const auto objs = testgen::derive_objectives(m);
    const auto file = properties::parse_properties(testgen::objectives_file_text(m, objs), m, "objectives");
    ASSERT_EQ(file.properties.size(), objs.size()) << what;
    for (std::size_t i = 0; i < objs.size(); ++i)
      ASSERT_EQ(testsupport::tree_difference(file.properties[i], objs[i].property), "") << what << " " << objs[i].id;
  };
  for (std::uint64_t seed = 1; seed <= 12; ++seed) check(testsupport::random_matrix(seed), std::to_string(seed));
  check(testsupport::big_matrix(1), "big_matrix");
}

// An objective as text for people.
std::string text_of(const model::Matrix& m, const testgen::Objective& o) {
  return properties::build::block_text(o.property, model::InputTable(m));
}

// intersection.cI.none leaves out the effects that what the cause reads
// also drives: compressor cause 5 reads Effect[1] (active only with effect 1),
// cause 8 reads Cause[1] and Cause[3] (which trip every other effect), so
// neither objective can hold with those effects inactive.
TEST(Objectives, NoneLeavesOutEffectsTheReferencesDrive) {
  std::map<std::string, std::string> none;
  const model::Matrix m = example("compressor");
  for (const auto& o : testgen::derive_objectives(m))
    if (o.id.size() > 5 && o.id.substr(o.id.size() - 5) == ".none") none[o.id] = text_of(m, o);
  ASSERT_TRUE(none.count("intersection.c5.none"));
  EXPECT_EQ(none["intersection.c5.none"].find("effect[1]"), std::string::npos);
  EXPECT_NE(none["intersection.c5.none"].find("not effect[5].active"), std::string::npos);
  EXPECT_FALSE(none.count("intersection.c8.none"));
  // Cause 2 reads only its own transmitter: every effect it cannot reach.
  ASSERT_TRUE(none.count("intersection.c2.none"));
  EXPECT_NE(none["intersection.c2.none"].find("not effect[5].active"), std::string::npos);
}

// Effects reached only through internal references get a `reference`
// objective that may force outputs; every other objective excludes forcing.
TEST(Objectives, ReferenceObjectivesForEffectsReachedThroughReferences) {
  std::map<std::string, testgen::Objective> ref;
  const model::Matrix m = example("compressor");
  for (const auto& o : testgen::derive_objectives(m)) {
    if (o.kind == "reference") ref[o.id] = o;
    else EXPECT_NE(text_of(m, o).find("assume not issued(simulate_tag)"), std::string::npos) << o.id;
  }
  for (const char* id : {"reference.c1.e2.apart", "reference.c3.e2.apart", "reference.c8.e2.apart",
                         "reference.c6.e3.apart", "reference.c6.e4.apart", "reference.c5.e2.apart"}) {
    ASSERT_TRUE(ref.count(id)) << id;
    EXPECT_TRUE(ref[id].simulates);
    EXPECT_TRUE(ref[id].property.assumptions.empty()) << id;
  }
  // Linked pairs and effects the cause cannot reach have none.
  EXPECT_FALSE(ref.count("reference.c1.e1.apart"));
  EXPECT_FALSE(ref.count("reference.c2.e5.apart"));
  for (const char* name : {"burner-management", "pipeline-hipps", "tank-overfill"})
    for (const auto& o : testgen::derive_objectives(example(name))) EXPECT_NE(o.kind, "reference") << name;
}

// burner-management: an S cell of cause 1 on effect 1, whose override a
// reset-tag edge toggles. The edge must be the runtime's (T.4): in the first
// cycle there is none, so a run that starts with the reset tag TRUE and
// cause 1 tripping toggles nothing and witnesses nothing; the same tag
// raised a cycle later does.
TEST(Objectives, NotOverriddenNeedsAnEdgeTheRuntimeSees) {
  const model::Matrix m = example("burner-management");
  testgen::Objective o;
  for (const auto& x : testgen::derive_objectives(m))
    if (x.id == "intersection.c1.e1.not_overridden") o = x;
  ASSERT_EQ(o.id, "intersection.c1.e1.not_overridden");
  const model::InputTable table(m);
  model::CycleInput tripped = model::default_cycle_input(m);
  auto set = [&](model::CycleInput& in, const char* tag, float v, bool bad) {
    in.tags[*table.find(tag)] = {v, bad};
  };
  set(tripped, "BSL_201B", 1.0f, true);  // bad quality counts as tripped: cause 1 trips (2oo3 with C)
  set(tripped, "BSL_201C", 0.0f, false);
  model::CycleInput reset = tripped;
  set(reset, "HS_221_RST", 1.0f, false);
  auto witness = [&](const std::vector<model::CycleInput>& inputs) {
    const auto run = checker::run_on_runtime(m, inputs);
    properties::Trace trace;
    for (std::size_t k = 0; k < run.inputs.size(); ++k) trace.push_back({run.inputs[k], run.observables[k]});
    const auto e = properties::Evaluator(m).evaluate(o.property, {}, trace);
    return e.holds ? e.cycle : std::nullopt;
  };
  EXPECT_EQ(witness({reset, reset}), std::nullopt);  // held TRUE from start-up: no edge
  EXPECT_EQ(witness({tripped, reset}), std::optional<std::size_t>(1));
}

// pipeline-hipps: causes 2, 3, 4 trip effects 1 and 2 as a 2oo3 XooN
// assignment. Each cause must count in a witness of its own: a run that
// trips causes 3 and 4 shows `xoon.e1.at` but not that cause 2's cell is
// there; the run that trips causes 2 and 3 does, and on the matrix without
// cause 2's cell the effect stays inactive in that run.
TEST(Objectives, EveryCauseOfAnXooNAssignmentCounts) {
  const model::Matrix m = example("pipeline-hipps");
  std::map<std::string, testgen::Objective> xoon;
  for (const auto& o : testgen::derive_objectives(m))
    if (o.kind == "xoon") xoon[o.id] = o;
  for (const char* id : {"xoon.e1.at", "xoon.e1.c2.counts", "xoon.e1.c3.counts", "xoon.e1.c4.counts",
                         "xoon.e2.c2.counts", "xoon.e2.c3.counts", "xoon.e2.c4.counts"})
    ASSERT_TRUE(xoon.count(id)) << id;
  const model::InputTable table(m);
  auto tripped = [&](std::initializer_list<const char*> tags) {
    model::CycleInput in = model::default_cycle_input(m);
    for (const char* t : tags) in.tags[*table.find(t)] = {0.0f, false};  // the switches are DTT
    return in;
  };
  auto witnessed = [&](const model::Matrix& mx, const testgen::Objective& o, const model::CycleInput& in) {
    const auto run = checker::run_on_runtime(mx, {in, in});
    properties::Trace trace;
    for (std::size_t k = 0; k < run.inputs.size(); ++k) trace.push_back({run.inputs[k], run.observables[k]});
    return properties::Evaluator(mx).evaluate(o.property, {}, trace).holds;
  };
  const auto c3c4 = tripped({"PSHH_302B", "PSHH_302C"}), c2c3 = tripped({"PSHH_302A", "PSHH_302B"});
  EXPECT_TRUE(witnessed(m, xoon["xoon.e1.at"], c3c4));
  EXPECT_FALSE(witnessed(m, xoon["xoon.e1.c2.counts"], c3c4));
  EXPECT_TRUE(witnessed(m, xoon["xoon.e1.c2.counts"], c2c3));
  model::Matrix removed = m;
  std::erase_if(removed.intersections, [](const model::Intersection& x) { return x.cause == 2 && x.effect == 1; });
  EXPECT_FALSE(witnessed(removed, xoon["xoon.e1.c2.counts"], c2c3));
}

TEST(Objectives, CatalogueNamesTheIssueKinds) {
  model::Matrix m = example("tank-overfill");
  std::set<std::string> kinds;
  for (const auto& o : testgen::derive_objectives(m)) kinds.insert(o.kind);
  for (const char* k : {"voting-row", "mcdc", "limit", "hysteresis", "timer", "bypass", "first-out", "intersection",
                        "reset", "pass-through", "output", "bad-quality"})
    EXPECT_TRUE(kinds.count(k)) << k;
}

// One SIF group of the tank example end to end: every objective covered,
// the files replay green, coverage and checklist carry the signature.
TEST(Generate, TankLowLevelGroupCoveredAndGreen) {
  model::Matrix m = example("tank-overfill");
  testgen::TestgenOptions o;
  o.sif = 2;
  testgen::TestSuite s = testgen::generate_tests(m, o);
  ASSERT_FALSE(s.objectives.empty());
  EXPECT_EQ(s.covered, s.objectives.size());
  ASSERT_FALSE(s.tests.empty());
  for (const auto& t : s.tests) {
    EXPECT_EQ(t.sif, 2);
    EXPECT_FALSE(t.field_steps.empty());
  }
  auto r = testgen::replay_suite(m, s);
  EXPECT_TRUE(r.all_passed());
  EXPECT_NE(testgen::coverage_json(s, "cemv test").find(formats::signature(m)), std::string::npos);
  auto h = testgen::checklist_header(m, s, "cemv test");
  for (const auto& text : {testgen::checklist_markdown(m, s, h), testgen::checklist_html(m, s, h),
                           testgen::checklist_csv(m, s, h)})
    EXPECT_NE(text.find(formats::signature(m)), std::string::npos);
  // Every covered objective names a test that exists.
  for (const auto& res : s.objectives) {
    ASSERT_GE(res.test, 0);
    ASSERT_LT(res.test, static_cast<int>(s.tests.size()));
  }
  // The timed soft bypass of cause 4 (3600 s, prealarm 3000 s): its four
  // checkpoints follow each other in one test, since a test is bounded by
  // its steps and an hour's hold is one step ("Wait 50 min").
  std::set<int> bypass_tests;
  for (const auto& res : s.objectives)
    if (res.objective.id.rfind("cause.4.bypass.", 0) == 0 && res.objective.id.find("prealarm") != std::string::npos)
      bypass_tests.insert(res.test);
  for (const auto& res : s.objectives)
    if (res.objective.id.rfind("cause.4.bypass.timeout", 0) == 0) bypass_tests.insert(res.test);
  EXPECT_EQ(bypass_tests.size(), 1u);
  for (const auto& t : s.tests) EXPECT_LE(t.steps, o.max_test_steps + 20) << t.id;
  // A matrix with the low-level cause's limit moved: the suite catches it.
  model::Matrix mutant = m;
  for (auto& c : mutant.causes)
    if (c.id == 4) c.analog->limit += 1.0f;
  EXPECT_FALSE(testgen::replay_suite(mutant, s).all_passed());
}

// Seeded random runs on the runtime find what BMC's budget does not reach
// on a loaded machine: one cycle before a 100-cycle output delay expires,
// behind a 2oo3 analog cause with an on-delay (pipeline-hipps effect 3), and
// an S latch that holds after a 5 s pulse ends (cause 6). The runtime and the
// concrete evaluator confirm the witness in the run's last cycle.
TEST(Explore, FindsLongDelayWitnesses) {
  for (const auto& [name, id] : {std::pair{"pipeline-hipps", "effect.3.delay.before"},
                                 std::pair{"pipeline-hipps", "intersection.c6.e1.latched"}}) {
    model::Matrix m = example(name);
    std::vector<testgen::Objective> objs;
    for (auto& o : testgen::derive_objectives(m))
      if (o.id == id) objs.push_back(o);
    ASSERT_EQ(objs.size(), 1u) << id;
    const auto file = testgen::objectives_file(objs);
    const auto& p = file.properties[0];
    testgen::detail::Goal g{&file, &p, properties::property_roots(p, file.assumptions, m), objs[0].horizon};
    // From start-up, and after a prefix (the runtime and the evaluator
    // continued from their copies after it): the witness is the run's last
    // cycle on the whole trace, as the evaluator over whole traces judges it.
    for (std::size_t prefix_cycles : {std::size_t{0}, std::size_t{37}}) {
      const std::vector<model::CycleInput> prefix(prefix_cycles, model::default_cycle_input(m));
      const auto r = testgen::detail::explore(m, g, prefix, 42);
      ASSERT_EQ(r.kind, testgen::detail::SearchResult::Kind::Found) << id << ": " << r.reason;
      std::vector<model::CycleInput> all = prefix;
      all.insert(all.end(), r.cycles.begin(), r.cycles.end());
      const auto t = checker::run_on_runtime(m, all);
      properties::Trace trace;
      for (std::size_t k = 0; k < t.inputs.size(); ++k) trace.push_back({t.inputs[k], t.observables[k]});
      const auto e = properties::Evaluator(m).evaluate(p, file.assumptions, trace);
      ASSERT_TRUE(e.holds && e.cycle) << id;
      EXPECT_EQ(*e.cycle + 1, all.size()) << id << " after " << prefix_cycles;
    }
  }
}

// One incremental BMC for a group's objectives (testgen/sweep.hpp): from
// start-up, the shortest run reaching any of the short objectives of
// tank-overfill's SIF group 2 (cause 4 and its effect) reaches several at once, each confirmed by the runtime and the
// concrete evaluator in the run's last cycle; continued from that run's end,
// the next question reaches objectives the first did not, and the same
// question gives the same run.
TEST(Sweep, OneWitnessCoversSeveralObjectives) {
  const model::Matrix m = example("tank-overfill");
  std::vector<testgen::Objective> objs;
  for (auto& o : testgen::derive_objectives(m))
    if (o.sif == 2 && !o.simulates && o.horizon < 8) objs.push_back(o);
  ASSERT_GE(objs.size(), 3u);
  const auto file = testgen::objectives_file(objs);
  testgen::detail::SweepQuestion q;
  q.file = &file;
  q.max_depth = 16;
  q.budget = 20 * checker::kMega;
  for (const auto& p : file.properties) {
    q.targets.push_back(&p);
    for (const auto& n : properties::property_roots(p, file.assumptions, m)) q.roots.push_back(n);
  }
  std::sort(q.roots.begin(), q.roots.end());
  q.roots.erase(std::unique(q.roots.begin(), q.roots.end()), q.roots.end());
  const testgen::TestgenOptions options;
  auto witnessed = [&](const std::vector<model::CycleInput>& run, std::size_t i) {
    const auto t = checker::run_on_runtime(m, run);
    properties::Trace trace;
    for (std::size_t k = 0; k < t.inputs.size(); ++k) trace.push_back({t.inputs[k], t.observables[k]});
    const auto e = properties::Evaluator(m).evaluate(file.properties[i], file.assumptions, trace);
    return e.holds && e.cycle && *e.cycle + 1 == run.size();
  };
  const auto first = testgen::detail::sweep(m, options, q);
  ASSERT_FALSE(first.cycles.empty()) << first.reason;
  EXPECT_GE(first.reached.size(), 2u);
  for (std::size_t i : first.reached) EXPECT_TRUE(witnessed(first.cycles, i)) << objs[i].id;
  const auto again = testgen::detail::sweep(m, options, q);
  EXPECT_EQ(again.reached, first.reached);
  EXPECT_EQ(again.cycles.size(), first.cycles.size());
  // Continued: the objectives the first run reached are no longer asked.
  testgen::detail::SweepQuestion next = q;
  next.prefix = &first.cycles;
  next.targets.clear();
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < file.properties.size(); ++i)
    if (std::find(first.reached.begin(), first.reached.end(), i) == first.reached.end()) {
      next.targets.push_back(&file.properties[i]);
      index.push_back(i);
    }
  const auto second = testgen::detail::sweep(m, options, next);
  ASSERT_FALSE(second.cycles.empty()) << second.reason;
  std::vector<model::CycleInput> run = first.cycles;
  run.insert(run.end(), second.cycles.begin(), second.cycles.end());
  for (std::size_t j : second.reached) EXPECT_TRUE(witnessed(run, index[j])) << objs[index[j]].id;
}

// The held sweep (testgen/sweep.hpp, SweepQuestion::held): tank-overfill's
// objectives behind cause 1's 2 s on-delay and soft-bypass timers (SIF group
// 1, horizon of 8 cycles or more), asked together on macro steps of held
// inputs from start-up: one run, longer than the cycle sweep's 16 cycles and
// within the question's bound, reaches at least one of them, and every one
// it claims is confirmed by the runtime and the concrete evaluator in the
// run's last cycle; the same question gives the same run.
TEST(Sweep, HeldStepsReachTimerObjectives) {
  const model::Matrix m = example("tank-overfill");
  std::vector<testgen::Objective> objs;
  for (auto& o : testgen::derive_objectives(m))
    if (o.sif == 1 && !o.simulates && o.horizon >= 8) objs.push_back(o);
  ASSERT_GE(objs.size(), 3u);
  const auto file = testgen::objectives_file(objs);
  testgen::detail::SweepQuestion q;
  q.file = &file;
  q.held = true;
  q.max_depth = 8;
  q.budget = 20 * checker::kMega;
  int horizon = 0;
  for (std::size_t i = 0; i < objs.size(); ++i) {
    const auto& p = file.properties[i];
    q.targets.push_back(&p);
    horizon = std::max(horizon, objs[i].horizon);
    for (const auto& n : properties::property_roots(p, file.assumptions, m)) q.roots.push_back(n);
  }
  q.max_cycles = 2 * horizon + 40;
  std::sort(q.roots.begin(), q.roots.end());
  q.roots.erase(std::unique(q.roots.begin(), q.roots.end()), q.roots.end());
  const testgen::TestgenOptions options;
  const auto first = testgen::detail::sweep(m, options, q);
  ASSERT_FALSE(first.cycles.empty()) << first.reason;
  EXPECT_GT(first.cycles.size(), 16u);
  EXPECT_LE(static_cast<std::int64_t>(first.cycles.size()), q.max_cycles);
  const auto t = checker::run_on_runtime(m, first.cycles);
  properties::Trace trace;
  for (std::size_t k = 0; k < t.inputs.size(); ++k) trace.push_back({t.inputs[k], t.observables[k]});
  for (std::size_t i : first.reached) {
    const auto e = properties::Evaluator(m).evaluate(file.properties[i], file.assumptions, trace);
    EXPECT_TRUE(e.holds && e.cycle && *e.cycle + 1 == first.cycles.size()) << objs[i].id;
  }
  const auto again = testgen::detail::sweep(m, options, q);
  EXPECT_EQ(again.reached, first.reached);
  EXPECT_EQ(again.cycles.size(), first.cycles.size());
}

// A step holds its inputs for as many cycles as nothing changes: 10,000
// cycles with one input change, one command and a checkpoint are 4 steps
// (the cycle after a checkpoint starts a step), and the scenario file stays
// small whatever the hold.
TEST(Generate, LongHoldsAreOneStep) {
  const model::Matrix m = example("tank-overfill");
  std::vector<model::CycleInput> inputs(10000, model::default_cycle_input(m));
  for (std::size_t k = 5000; k < inputs.size(); ++k) inputs[k].tags[0].value = 95.0f;
  model::Command reset;
  reset.op = model::CommandOp::ResetEffect;
  reset.effect = m.effects.front().id;
  inputs[7000].commands.push_back(reset);
  const std::vector<std::size_t> checkpoints{5999, 9999};
  EXPECT_EQ(testgen::detail::count_steps(inputs, checkpoints), 3u + 1u);
  EXPECT_EQ(testgen::detail::count_steps(inputs, {}), 3u);
  const auto run = checker::run_on_runtime(m, inputs);
  // The snapshots at the checkpoints are the runtime's after those cycles.
  const auto snapshots = testgen::detail::snapshots_at(m, inputs, checkpoints);
  ASSERT_EQ(snapshots.size(), 2u);
  EXPECT_EQ(snapshots.at(5999), run.observables[5999]);
  EXPECT_EQ(snapshots.at(9999), run.observables[9999]);
  std::vector<testgen::detail::Checkpoint> cps{{5999, {"a"}, {}}, {9999, {"b"}, {}}};
  std::size_t steps = 0;
  std::vector<testgen::FieldStep> field;
  const std::string text = testgen::detail::test_scenario_json(m, "", "hold", inputs, snapshots, cps, steps, field);
  EXPECT_EQ(steps, 4u);
  EXPECT_EQ(field.size(), 4u);
  EXPECT_LT(text.size(), 20000u);
}

TEST(Replay, ReportsLoadErrorsAsFailedTests) {
  model::Matrix m = example("tank-overfill");
  auto r = testgen::replay_texts(m, {{"bad", R"({"format":"cemv-scenario/1","steps":[{"inputs":{"NO_SUCH_TAG":true}}]})"}});
  ASSERT_EQ(r.tests.size(), 1u);
  EXPECT_FALSE(r.tests[0].passed);
  EXPECT_NE(r.tests[0].load_error.find("NO_SUCH_TAG"), std::string::npos);
}

}  // namespace
