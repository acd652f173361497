// The requirement files next to the examples (examples/*/requirements.props):
// - they parse against their matrix and every property carries `# expect:`;
// - no property expected `proved` is violated, and every property expected
//   `reachable` is witnessed, on the runtime traces of the example's scenarios
//   and of seeded random inputs (with and without maintenance commands);
// - every property expected `falsified` is violated on a short hand-made trace
//   (the seeded defects their READMEs explain).
// The checker proves what these traces can only fail to refute.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "tests/support/random_inputs.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

const char* const kExamples[] = {"tank-overfill", "pipeline-hipps", "burner-management", "compressor"};

std::string dir(const std::string& example) { return std::string(CEMV_SOURCE_DIR) + "/examples/" + example; }

struct Example {
  model::Matrix m;
  PropertyFile f;
};

Example load(const std::string& name) {
  Example e;
  e.m = formats::load_matrix(dir(name) + "/matrix.json");
  e.f = load_properties(dir(name) + "/requirements.props", e.m);
  return e;
}

const Property& property(const PropertyFile& f, const std::string& name) {
  for (const auto& p : f.properties)
    if (p.name == name) return p;
  throw std::runtime_error("no property " + name);
}

// Random inputs, optionally without the commands an assumption may exclude.
std::vector<model::CycleInput> random_frames(const model::Matrix& m, std::uint64_t seed, int cycles, int variant) {
  auto frames = testsupport::random_inputs(m, seed, cycles);
  for (auto& f : frames) {
    std::erase_if(f.commands, [&](const model::Command& c) {
      if (variant == 0) return false;
      if (variant == 1) return c.op == model::CommandOp::SimulateTag || c.op == model::CommandOp::SoftBypassTag;
      return true;  // variant 2: no commands at all
    });
  }
  return frames;
}

TEST(Requirements, EveryExampleHasAParsedFileWithExpectedVerdicts) {
  std::map<std::string, int> requirement_numbers;
  for (const char* name : kExamples) {
    Example e = load(name);
    ASSERT_FALSE(e.f.properties.empty()) << name;
    int falsified = 0;
    for (const auto& p : e.f.properties) {
      EXPECT_TRUE(is_verdict(p.expect)) << name << ": " << p.name << " has no '# expect:' comment";
      EXPECT_FALSE(p.description.empty()) << name << ": " << p.name;
      falsified += p.expect == "falsified";
      if (p.name.rfind("req", 0) == 0) ++requirement_numbers[p.name.substr(0, p.name.find('.'))];
    }
    EXPECT_GE(falsified, 1) << name << " needs a seeded-defect requirement";
  }
  // The eight requirements of the property language's brief, each written somewhere.
  for (int r = 1; r <= 8; ++r) EXPECT_GT(requirement_numbers["req" + std::to_string(r)], 0) << "requirement " << r;
}

TEST(Requirements, RuntimeTracesAgreeWithTheExpectedVerdicts) {
  for (const char* name : kExamples) {
    Example e = load(name);
    Evaluator ev(e.m);
    std::vector<std::pair<std::string, Trace>> traces;
    for (const auto& entry : std::filesystem::directory_iterator(dir(name)))
      if (entry.path().filename().string().rfind("scenario-", 0) == 0)
        traces.emplace_back(entry.path().filename().string(), testing::run_scenario(e.m, entry.path()));
    for (std::uint64_t seed = 1; seed <= 6; ++seed)
      for (int variant = 0; variant < 3; ++variant)
        traces.emplace_back("random seed " + std::to_string(seed) + " variant " + std::to_string(variant),
                            testing::run_inputs(e.m, random_frames(e.m, seed * 31 + variant, 3000, variant)));
    std::set<std::string> witnessed, antecedent_met;
    for (const auto& [what, t] : traces) {
      for (const auto& r : ev.evaluate(e.f, t)) {
        const Property& p = property(e.f, r.name);
        if (p.expect == "proved") {
          EXPECT_TRUE(r.holds) << name << " " << what << ": " << r.name << " violated in cycle " << *r.cycle;
        }
        if (p.expect == "unreachable") {
          EXPECT_FALSE(r.holds) << name << " " << what << ": " << r.name;
        }
        if (r.kind == PropertyKind::Reachable && r.holds) witnessed.insert(r.name);
        if (r.antecedent_met) antecedent_met.insert(r.name);
      }
    }
    for (const auto& p : e.f.properties) {
      if (p.expect == "reachable") {
        EXPECT_TRUE(witnessed.count(p.name)) << name << ": no trace witnesses " << p.name;
      }
      if (p.expect == "proved" && p.kind == PropertyKind::Response) {
        EXPECT_TRUE(antecedent_met.count(p.name)) << name << ": no trace triggers " << p.name << " (vacuous?)";
      }
    }
  }
}

// ---- The seeded defects, each violated on a short concrete trace ------------

struct Frames {
  explicit Frames(const model::Matrix& matrix) : m(matrix), inputs(matrix), frame(model::default_cycle_input(matrix)) {}
  const model::Matrix& m;
  model::InputTable inputs;
  model::CycleInput frame;
  std::vector<model::CycleInput> frames;
  void set(const char* tag, float v, bool bad = false) {
    auto& t = frame.tags[*inputs.find(tag)];
    t.value = v;
    t.bad_quality = bad;
  }
  void cycles(int n) { frames.insert(frames.end(), static_cast<std::size_t>(n), frame); }
};

Evaluation judge(const Example& e, const std::string& name, const Frames& run) {
  return Evaluator(e.m).evaluate(property(e.f, name), e.f.assumptions, testing::run_inputs(e.m, run.frames));
}

TEST(Requirements, TankDefectTheOnDelayIsLongerThanOneSecond) {
  Example e = load("tank-overfill");
  Frames run(e.m);
  run.set("XV_101_BPCS", 1.0f);  // the level controller holds the inlet valve open (pass-through)
  run.cycles(3);
  run.set("LT_100A", 91.0f);
  run.set("LT_100B", 92.0f);
  run.cycles(30);
  Evaluation r = judge(e, "defect.close_within_1s", run);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.trigger_cycle, 3u);
  EXPECT_EQ(r.cycle, 13u);  // 1 s after the trigger, XV-101 still open
  // The same trace satisfies requirement 1: the valve closes after 2 s.
  EXPECT_TRUE(judge(e, "req1.two_of_three_close_xv101", run).holds);
  EXPECT_TRUE(judge(e, "req1.two_of_three_close_xv101", run).antecedent_met);
}

TEST(Requirements, PipelineDefectBlowdownTakesTenAndAHalfSeconds) {
  Example e = load("pipeline-hipps");
  Frames run(e.m);
  run.cycles(2);
  run.set("PT_301A", 90.0f);
  run.set("PT_301C", 90.0f);
  run.cycles(120);
  Evaluation r = judge(e, "defect.blowdown_after_10s", run);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.cycle, 102u);  // 10 s (101 samples) of overpressure, BDV-320 still closed
}

TEST(Requirements, BurnerDefectLightOffInhibitSuppressesFlameFailure) {
  Example e = load("burner-management");
  Frames run(e.m);
  run.set("XS_200_LIGHTOFF", 1.0f);
  run.cycles(2);
  run.set("BSL_201A", 0.0f);
  run.set("BSL_201B", 0.0f);
  run.cycles(20);
  Evaluation r = judge(e, "defect.flame_failure_always_trips", run);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.trigger_cycle, 2u);
  EXPECT_EQ(r.cycle, 12u);
}

TEST(Requirements, CompressorDefectMaskKeepsTheRecycleValveClosed) {
  Example e = load("compressor");
  Frames run(e.m);
  run.set("HS_440_MASK", 1.0f);
  run.set("FY_440_BPCS", 1.0f);
  run.cycles(2);
  run.set("PT_410", 0.0f);  // lube oil pressure low-low: trips M-401 after its 1 s on-delay
  run.cycles(40);
  Evaluation r = judge(e, "defect.recycle_opens_on_trip", run);
  EXPECT_FALSE(r.holds);
  ASSERT_TRUE(r.trigger_cycle);
  EXPECT_EQ(*r.cycle, *r.trigger_cycle + 10);  // 500 ms at 50 ms cycles
}

}  // namespace
}  // namespace cemv::properties

namespace cemv::properties {
namespace {

// Requirement 3 on a trace that meets its antecedent: all three radars bad for 3 s.
TEST(Requirements, TankTotalBadQualityTripsAfterTheOnDelay) {
  Example e = load("tank-overfill");
  Frames run(e.m);
  run.cycles(2);
  for (const char* tag : {"LT_100A", "LT_100B", "LT_100C"}) run.set(tag, 50.0f, true);
  run.cycles(30);
  Evaluation r = judge(e, "req3.total_bad_quality_trips", run);
  EXPECT_TRUE(r.holds);
  EXPECT_TRUE(r.antecedent_met);
  // Without the on-delay in the requirement it would not hold: active only 2 s later.
  PropertyFile strict = parse_properties(
      "property p { always all(t in cause[1].tags: bad(t)) and not cause[1].bypassed implies effect[1].active }", e.m,
      "strict.props");
  r = Evaluator(e.m).evaluate(strict.properties[0], {}, testing::run_inputs(e.m, run.frames));
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.cycle, 2u);
}

// Requirement 4 on an override that runs into its timeout, and on one restarted
// in exactly the cycle of the timeout (the antecedent then holds and the "no new
// start" part decides). A bound one cycle shorter than 1800 s is violated, so
// the property is tight.
TEST(Requirements, PipelineOverrideEndsAfterExactly1800Seconds) {
  Example e = load("pipeline-hipps");
  Frames run(e.m);
  run.cycles(2);
  run.set("FT_311", 2000.0f);  // flow high-high: cause 7 (V on effect 4) after its 2 s on-delay
  run.cycles(28);
  run.set("HS_310_OVR", 1.0f);  // rising edge in cycle 30: the override starts
  run.cycles(1);
  run.set("HS_310_OVR", 0.0f);
  run.cycles(18005);
  Trace t = testing::run_inputs(e.m, run.frames);
  Evaluator ev(e.m);
  PropertyFile probe = parse_properties("property p { always effect[4].override_active }", e.m, "probe.props");
  std::vector<bool> active = ev.values(probe.properties[0].body, t);
  ASSERT_TRUE(active[30]);
  EXPECT_FALSE(active[29]);
  EXPECT_TRUE(active[30 + 17999]);
  EXPECT_FALSE(active[30 + 18000]);  // 18000 cycles = 1800 s
  const Property& req4 = property(e.f, "req4.override_at_most_1800s");
  EXPECT_TRUE(ev.evaluate(req4, e.f.assumptions, t).holds);

  PropertyFile shorter = parse_properties(
      "property p { never held(effect[4].override_active, 1799900 ms) and not within(rose(HS_310_OVR), 17998 cycles) }",
      e.m, "shorter.props");
  Evaluation r = ev.evaluate(shorter.properties[0], {}, t);
  EXPECT_FALSE(r.holds);
  EXPECT_EQ(r.cycle, 30u + 17999);

  // Restart in the timeout cycle: one override ends, the next begins.
  run.frames.resize(30 + 18000);
  run.set("HS_310_OVR", 1.0f);
  run.cycles(1);
  run.set("HS_310_OVR", 0.0f);
  run.cycles(10);
  t = testing::run_inputs(e.m, run.frames);
  active = ev.values(probe.properties[0].body, t);
  ASSERT_TRUE(active[30 + 18000]);
  r = ev.evaluate(req4, e.f.assumptions, t);
  EXPECT_TRUE(r.holds);
  EXPECT_TRUE(r.antecedent_met);
}

}  // namespace
}  // namespace cemv::properties
