// The speed targets of `cemv defeats` (docs/defeats.md, docs/performance.md):
// - every path of the four examples, minimal sets up to K = 2: < 30 s in total;
// - the 128 x 128 x 1024 big_matrix's SIF group 1, K = 1: < 120 s.
// The command line's defaults (DefeatsOptions as cmd_defeats.cpp sets them:
// --jobs 1, no --timeout) but K and the group. Each benchmark runs once; wall
// time ("Time") and the process's CPU time ("CPU"). The figures include the
// response analysis that gives each path its requirement T.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "defeats/analysis.hpp"
#include "formats/matrix_json.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

void count(benchmark::State& state, const std::vector<defeats::DefeatsResult>& results) {
  double paths = 0, sets = 0, questions = 0, incomplete = 0;
  for (const auto& r : results)
    for (const auto& p : r.paths) {
      ++paths;
      sets += static_cast<double>(p.sets.size());
      questions += static_cast<double>(p.questions.size());
      incomplete += p.status != defeats::PathStatus::Complete;
    }
  state.counters["paths"] = paths;
  state.counters["sets"] = sets;
  state.counters["questions"] = questions;
  state.counters["incomplete"] = incomplete;
}

void BM_DefeatsExamplesK2(benchmark::State& state) {
  defeats::DefeatsOptions o;
  o.max_size = 2;
  std::vector<defeats::DefeatsResult> all;
  for (auto _ : state) {
    all.clear();
    for (const char* ex : {"tank-overfill", "burner-management", "pipeline-hipps", "compressor"})
      all.push_back(defeats::analyse(
          formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / ex / "matrix.json"), o));
  }
  count(state, all);
  state.SetLabel("four examples, K = 2, target < 30 s");
}
BENCHMARK(BM_DefeatsExamplesK2)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime()->MeasureProcessCPUTime();

void BM_DefeatsBigMatrixK1(benchmark::State& state) {
  const model::Matrix m = testsupport::big_matrix(1);
  defeats::DefeatsOptions o;
  o.sifs = {1};
  o.max_size = 1;
  std::vector<defeats::DefeatsResult> all;
  for (auto _ : state) {
    all.clear();
    all.push_back(defeats::analyse(m, o));
  }
  count(state, all);
  state.SetLabel("big_matrix SIF group 1, K = 1, target < 120 s");
}
BENCHMARK(BM_DefeatsBigMatrixK1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime()->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
