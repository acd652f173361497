// The checker's speed targets (docs/performance.md):
// - every example requirement decided in under 1 s on its example;
// - requirement 4 (pipeline-hipps: an override of effect 4 never lasts longer
//   than its 1800 s, an 18,000-cycle timer) proved in under 5 s, beside plain
//   BMC to the same depth in the same run (the ratio is the point);
// - the standard property set (`cemv check --standard`) of generated matrices
//   from 8 x 8 to the 128 x 128 x 1024 big_matrix, every property decided, no
//   `unknown`, the largest in under 60 s.
// Each benchmark runs once: these are seconds-long decisions, not
// microbenchmarks. Wall time is what a user waits for (the portfolio runs
// engines in parallel threads), so the figures are real time.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>

#include "checker/check.hpp"
#include "checker/engines/bmc.hpp"
#include "formats/matrix_json.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

std::filesystem::path example(const std::string& name) {
  return std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / name;
}

checker::CheckOptions options(double timeout_s) {
  checker::CheckOptions o;
  o.property_timeout_s = timeout_s;
  o.support = false;
  return o;
}

void count_verdicts(benchmark::State& state, const checker::CheckResult& r) {
  int unknown = 0, decided = 0;
  for (const auto& p : r.properties) (p.verdict == checker::PropertyVerdict::Unknown ? unknown : decided)++;
  state.counters["properties"] = static_cast<double>(r.properties.size());
  state.counters["decided"] = decided;
  state.counters["unknown"] = unknown;
}

// One example requirement, by example and property name.
void BM_ExampleRequirement(benchmark::State& state, const std::string& ex, const std::string& property) {
  model::Matrix m = formats::load_matrix(example(ex) / "matrix.json");
  auto file = properties::load_properties(example(ex) / "requirements.props", m);
  std::erase_if(file.properties, [&](const properties::Property& p) { return p.name != property; });
  checker::CheckResult r;
  for (auto _ : state) r = checker::check_properties(m, {file}, options(60));
  count_verdicts(state, r);
  if (!r.properties.empty()) state.SetLabel(std::string(checker::to_string(r.properties[0].verdict)) + ", target < 1 s");
}

// Requirement 4 beside plain BMC of the same property to the timer's depth.
void BM_Req4PlainBmcToTimerDepth(benchmark::State& state) {
  model::Matrix m = formats::load_matrix(example("pipeline-hipps") / "matrix.json");
  auto file = properties::load_properties(example("pipeline-hipps") / "requirements.props", m);
  const properties::Property* req4 = nullptr;
  for (const auto& p : file.properties) if (p.name.rfind("req4", 0) == 0) req4 = &p;
  if (!req4) { state.SkipWithError("requirement 4 not found"); return; }
  checker::ProverResult r;
  for (auto _ : state) {
    z3::context ctx;
    auto enc = encoder::encode(ctx, m, properties::property_roots(*req4, file.assumptions, m));
    auto mon = properties::compile_monitor(*enc, *req4, file.assumptions);
    checker::Limits limits;
    limits.deadline = checker::Clock::now() + std::chrono::seconds(120);
    limits.max_depth = 18001;
    r = checker::Bmc{}.prove({&enc->ts, mon.good, mon.assumption}, limits);
  }
  state.SetLabel("plain BMC to depth 18,001 (limit 120 s): " + checker::to_string(r.verdict) + " " + r.reason_text() +
                 ", reached depth " + std::to_string(r.k));
}
BENCHMARK(BM_Req4PlainBmcToTimerDepth)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// The standard property set of a generated n x n matrix (about 40 % of the
// grid, at most 1024 intersections), and of the 128 x 128 x 1024 big_matrix.
void BM_StandardSet(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  model::Matrix m;
  if (n == 128) {
    m = testsupport::big_matrix(1);
  } else {
    testsupport::MatrixOptions o;
    o.min_causes = o.max_causes = n;
    o.min_effects = o.max_effects = n;
    o.cycle_ms = 100;
    m = testsupport::random_matrix(static_cast<std::uint64_t>(n), o);
  }
  auto standard = properties::standard_properties(m);
  checker::CheckOptions o = options(60);
  o.jobs = 2;
  o.standard = true;
  checker::CheckResult r;
  for (auto _ : state) r = checker::check_properties(m, {standard}, o);
  count_verdicts(state, r);
  state.counters["intersections"] = static_cast<double>(m.intersections.size());
  state.SetLabel(n == 128 ? "big_matrix, target: all decided in < 60 s" : "scaling");
}
BENCHMARK(BM_StandardSet)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Arg(128)
    ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// Registers one benchmark per example requirement, in file order. Called from
// main, not at static initialisation: loading a matrix needs the format's
// tables, which other translation units construct.
void register_requirements() {
  for (const char* ex : {"tank-overfill", "burner-management", "pipeline-hipps", "compressor"}) {
    model::Matrix m = formats::load_matrix(example(ex) / "matrix.json");
    auto file = properties::load_properties(example(ex) / "requirements.props", m);
    for (const auto& p : file.properties)
      benchmark::RegisterBenchmark(("BM_ExampleRequirement/" + std::string(ex) + "/" + p.name).c_str(),
                                   BM_ExampleRequirement, std::string(ex), p.name)
          ->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
  }
}

}  // namespace

int main(int argc, char** argv) {
  register_requirements();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
