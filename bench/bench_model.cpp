// Target (bench/README.md): load (parse the canonical text) and validate the
// generated 128 x 128 x 1024 matrix in under 50 ms.
#include <benchmark/benchmark.h>

#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

const std::string& big_text() {
  static const std::string text = formats::to_canonical_json(testsupport::big_matrix(1));
  return text;
}

void BM_LoadAndValidateBigMatrix(benchmark::State& state) {
  const std::string& text = big_text();
  for (auto _ : state) {
    model::Matrix m = formats::parse_matrix(text, "big.json");
    auto diagnostics = model::validate(m);
    benchmark::DoNotOptimize(diagnostics.data());
  }
  state.SetLabel("target < 50 ms; " + std::to_string(text.size() / 1024) + " KiB canonical JSON");
}
BENCHMARK(BM_LoadAndValidateBigMatrix)->Unit(benchmark::kMillisecond);

// The two halves on their own, to see where the time goes.
void BM_ParseBigMatrix(benchmark::State& state) {
  const std::string& text = big_text();
  for (auto _ : state) {
    model::Matrix m = formats::parse_matrix(text, "big.json");
    benchmark::DoNotOptimize(m.causes.data());
  }
}
BENCHMARK(BM_ParseBigMatrix)->Unit(benchmark::kMillisecond);

void BM_ValidateBigMatrix(benchmark::State& state) {
  model::Matrix m = formats::parse_matrix(big_text(), "big.json");
  for (auto _ : state) {
    auto diagnostics = model::validate(m);
    benchmark::DoNotOptimize(diagnostics.data());
  }
}
BENCHMARK(BM_ValidateBigMatrix)->Unit(benchmark::kMillisecond);

void BM_CanonicalJsonBigMatrix(benchmark::State& state) {
  model::Matrix m = testsupport::big_matrix(1);
  for (auto _ : state) {
    std::string text = formats::to_canonical_json(m);
    benchmark::DoNotOptimize(text.data());
  }
}
BENCHMARK(BM_CanonicalJsonBigMatrix)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
