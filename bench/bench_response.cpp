// The speed targets of `cemv response` (docs/response-time.md):
// - every path of the four examples, normal and degraded figures: < 10 s in total;
// - long delays are not unrolled: the burner's 60 s post-purge output delay
//   (600 cycles) and a 30 min on-delay at 100 ms (18,000 cycles), each beside
//   plain BMC of the same T-1 property (the ratio is the point);
// - the 128 x 128 x 1024 big_matrix: every path decided in < 120 s.
// Each benchmark runs once; wall time (the portfolio's engines run in threads).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "checker/engines/bmc.hpp"
#include "encoder/encode.hpp"
#include "formats/matrix_json.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "response/analysis.hpp"
#include "response/property.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

model::Matrix example(const std::string& name) {
  return formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / name / "matrix.json");
}

void count(benchmark::State& state, const response::ResponseResult& r) {
  int exact = 0, unbounded = 0, unknown = 0, probes = 0;
  for (const auto& p : r.paths) {
    exact += p.logic.kind == response::Figure::Kind::Exact;
    unbounded += p.logic.kind == response::Figure::Kind::Unbounded;
    unknown += p.logic.kind == response::Figure::Kind::Unknown;
    probes += p.logic.probes + (p.degraded ? p.degraded->probes : 0);
  }
  state.counters["paths"] = static_cast<double>(r.paths.size());
  state.counters["exact"] = exact;
  state.counters["unbounded"] = unbounded;
  state.counters["unknown"] = unknown;
  state.counters["probes"] = probes;
}

void BM_ExamplesAllPaths(benchmark::State& state) {
  response::ResponseOptions o;
  o.jobs = 2;
  o.timeout_s = 0;  // budgets of work only: the figures of any machine
  response::ResponseResult all;
  for (auto _ : state) {
    all.paths.clear();
    for (const char* ex : {"tank-overfill", "burner-management", "pipeline-hipps", "compressor"}) {
      auto r = response::analyse(example(ex), o);
      all.paths.insert(all.paths.end(), r.paths.begin(), r.paths.end());
    }
  }
  count(state, all);
  state.SetLabel("four examples, target < 10 s");
}
BENCHMARK(BM_ExamplesAllPaths)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// A matrix with one cause whose on-delay is `ms` at 100 ms cycles.
model::Matrix long_on_delay(std::uint32_t ms) {
  return formats::parse_matrix(R"({"format": "cemv-matrix/1", "name": "LONG", "cycle_ms": 100,
    "sif_groups": {"1": {"name": "slow", "process_safety_time_ms": 3600000}},
    "causes": [{"id": 1, "name": "C1", "sif": [1], "tags": [{"name": "S1"}],
                "time": {"mode": "on_delay", "ms": )" + std::to_string(ms) + R"(}}],
    "effects": [{"id": 1, "name": "E1", "sif": [1], "tags": [{"name": "Y1"}]}],
    "intersections": [{"cause": 1, "effect": 1, "type": "N"}]})",
                               "long.json");
}

// The path to effect `effect` from `cause`, its exact figure.
void BM_LongDelay(benchmark::State& state, model::Matrix m, int cause, int effect) {
  response::Path path;
  for (const auto& p : response::response_paths(m, {}))
    if (p.effect == effect && p.causes == std::vector<int>{cause}) path = p;
  response::Figure f;
  for (auto _ : state) f = response::least_response(m, path, response::Mode::Normal, {});
  state.counters["T"] = static_cast<double>(f.cycles);
  state.counters["probes"] = f.probes;
  state.SetLabel(std::string(f.kind == response::Figure::Kind::Exact ? "exact" : "not exact") + ", proved by " +
                 f.method);
}

// Plain BMC of the same path's property at T - 1 (a counterexample exists at
// depth T): how far it gets in 60 s.
void BM_LongDelayPlainBmc(benchmark::State& state, model::Matrix m, int cause, int effect, long long t) {
  response::Path path;
  for (const auto& p : response::response_paths(m, {}))
    if (p.effect == effect && p.causes == std::vector<int>{cause}) path = p;
  auto file = response::response_property(m, path, response::Mode::Normal, t - 1, "bmc");
  const auto& prop = file.properties.at(0);
  checker::ProverResult r;
  for (auto _ : state) {
    z3::context ctx;
    auto enc = encoder::encode(ctx, m, properties::property_roots(prop, file.assumptions, m));
    auto mon = properties::compile_monitor(*enc, prop, file.assumptions);
    checker::Limits limits;
    limits.deadline = checker::Clock::now() + std::chrono::seconds(60);
    limits.max_depth = static_cast<int>(t + 1);
    r = checker::Bmc{}.prove({&enc->ts, mon.good, mon.assumption}, limits);
  }
  state.SetLabel("plain BMC, limit 60 s: " + checker::to_string(r.verdict) + " " + r.reason_text() + ", reached depth " +
                 std::to_string(r.k) + " of " + std::to_string(t));
}

// How many paths (and estimated bounds) big_matrix has: the size of the job.
void BM_BigMatrixPaths(benchmark::State& state) {
  model::Matrix m = testsupport::big_matrix(1);
  std::vector<response::Path> paths;
  for (auto _ : state) paths = response::response_paths(m, {});
  long long voted = 0, delayed = 0;
  for (const auto& p : paths) {
    voted += !p.voted.empty();
    delayed += p.estimate > 0;
  }
  state.counters["paths"] = static_cast<double>(paths.size());
  state.counters["voted"] = static_cast<double>(voted);
  state.counters["delayed"] = static_cast<double>(delayed);
}
BENCHMARK(BM_BigMatrixPaths)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_BigMatrixAllPaths(benchmark::State& state) {
  model::Matrix m = testsupport::big_matrix(1);
  response::ResponseOptions o;
  o.jobs = 2;
  o.timeout_s = 0;  // budgets of work only: the figures of any machine
  response::ResponseResult r;
  for (auto _ : state) r = response::analyse(m, o);
  count(state, r);
  state.SetLabel("big_matrix, target: every path decided in < 120 s");
}
BENCHMARK(BM_BigMatrixAllPaths)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

// One SIF group of big_matrix (its first), one job: the CPU per path, from
// which the whole job's CPU follows (`/usr/bin/time` around the run; the
// benchmark's own CPU column counts only its main thread).
void BM_BigMatrixFirstSif(benchmark::State& state) {
  model::Matrix m = testsupport::big_matrix(1);
  response::ResponseOptions o;
  o.sifs = {m.sif_groups.begin()->first};
  o.timeout_s = 0;  // budgets of work only: the figures of any machine
  response::ResponseResult r;
  for (auto _ : state) r = response::analyse(m, o);
  count(state, r);
  state.SetLabel("big_matrix, SIF group " + std::to_string(o.sifs.front()) + " alone");
}
BENCHMARK(BM_BigMatrixFirstSif)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  // Registered here, not at static initialisation: loading a matrix needs the
  // format's tables, which other translation units construct.
  auto burner = example("burner-management");
  benchmark::RegisterBenchmark("BM_LongDelay/burner_post_purge_600", BM_LongDelay, burner, 5, 3)
      ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
  benchmark::RegisterBenchmark("BM_LongDelayPlainBmc/burner_post_purge_600", BM_LongDelayPlainBmc, burner, 5, 3, 600LL)
      ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
  auto user = long_on_delay(30 * 60 * 1000);
  benchmark::RegisterBenchmark("BM_LongDelay/on_delay_30min_18000", BM_LongDelay, user, 1, 1)
      ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
  benchmark::RegisterBenchmark("BM_LongDelayPlainBmc/on_delay_30min_18000", BM_LongDelayPlainBmc, user, 1, 1, 18000LL)
      ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
