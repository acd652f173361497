// The test generator's speed targets (docs/testgen.md, "Speed"):
// - every objective of the generated 128 x 128 x 1024 big_matrix (every
//   option of cemv-matrix/1) decided in under 120 s with --jobs 2;
// - the tests and steps reported against the objectives (counters);
// - the replay of the whole suite on the runtime in under 1 s.
// Each benchmark runs once (seconds-long work); wall time is the figure.
#include <benchmark/benchmark.h>

#include "testgen/testgen.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

testgen::TestSuite& suite() {
  static testgen::TestSuite s = [] {
    testgen::TestgenOptions o;
    o.jobs = 2;
    o.objective_work = 5 * checker::kMega;
    o.proof_work = 2 * checker::kMega;
    return testgen::generate_tests(testsupport::big_matrix(1), o);
  }();
  return s;
}

void BM_TestgenBigMatrix(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(suite());
  const auto& s = suite();
  state.counters["objectives"] = static_cast<double>(s.objectives.size());
  state.counters["covered"] = static_cast<double>(s.covered);
  state.counters["infeasible"] = static_cast<double>(s.infeasible);
  state.counters["undecided"] = static_cast<double>(s.undecided);
  state.counters["tests"] = static_cast<double>(s.tests.size());
  state.counters["steps"] = static_cast<double>(s.total_steps);
  state.counters["cycles"] = static_cast<double>(s.total_cycles);
}
BENCHMARK(BM_TestgenBigMatrix)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_ReplayBigMatrixSuite(benchmark::State& state) {
  const model::Matrix m = testsupport::big_matrix(1);
  const auto& s = suite();
  for (auto _ : state) {
    auto r = testgen::replay_suite(m, s);
    if (!r.all_passed()) state.SkipWithError("the suite does not replay green");
  }
}
BENCHMARK(BM_ReplayBigMatrixSuite)->Iterations(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
