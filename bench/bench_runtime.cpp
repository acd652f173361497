// Target (bench/README.md): one scan cycle (Runtime::step) of the generated
// 128 x 128 x 1024 matrix that uses every option: target under 20 us per
// cycle, and no heap allocation inside step (counted by replacing the global
// operator new of this binary).
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "runtime/runtime.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

// ---- Allocation counter -------------------------------------------------------
// Every allocation of this process goes through these; the benchmark reads the
// counter around the timed loop, which runs nothing but step().

namespace {
std::atomic<long long> g_allocations{0};

void* counted_alloc(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}

void* counted_aligned_alloc(std::size_t n, std::align_val_t al) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  std::size_t a = static_cast<std::size_t>(al);
  std::size_t size = (n + a - 1) / a * a;
  if (void* p = std::aligned_alloc(a, size ? size : a)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return counted_alloc(n); }
void* operator new[](std::size_t n) { return counted_alloc(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try { return counted_alloc(n); } catch (...) { return nullptr; }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try { return counted_alloc(n); } catch (...) { return nullptr; }
}
void* operator new(std::size_t n, std::align_val_t al) { return counted_aligned_alloc(n, al); }
void* operator new[](std::size_t n, std::align_val_t al) { return counted_aligned_alloc(n, al); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace {

using namespace cemv;

constexpr int kFrames = 1000;

void BM_RuntimeStepBigMatrix(benchmark::State& state) {
  const model::Matrix m = testsupport::big_matrix(1);
  const auto frames = testsupport::random_inputs(m, 1, kFrames);
  long long at_start = g_allocations.load();
  runtime::Runtime rt(m);
  // Proves the counter sees the runtime's allocations (construction allocates).
  state.counters["allocs_construct"] = static_cast<double>(g_allocations.load() - at_start);
  std::size_t k = 0;
  long long before = g_allocations.load();
  for (auto _ : state) {
    rt.step(frames[k]);
    k = k + 1 == frames.size() ? 0 : k + 1;
  }
  long long allocations = g_allocations.load() - before;
  state.counters["allocs_per_step"] =
      benchmark::Counter(static_cast<double>(allocations), benchmark::Counter::kAvgIterations);
  state.counters["allocs_total"] = static_cast<double>(allocations);
  state.counters["input_tags"] = static_cast<double>(rt.inputs().size());
  state.SetLabel("target < 20 us/cycle, 0 allocations");
}
BENCHMARK(BM_RuntimeStepBigMatrix)->Unit(benchmark::kMicrosecond);

// The same with a quiet plant (default inputs, no commands): the floor.
void BM_RuntimeStepBigMatrixQuiet(benchmark::State& state) {
  const model::Matrix m = testsupport::big_matrix(1);
  runtime::Runtime rt(m);
  const model::CycleInput in = rt.default_input();
  long long before = g_allocations.load();
  for (auto _ : state) rt.step(in);
  long long allocations = g_allocations.load() - before;
  state.counters["allocs_per_step"] =
      benchmark::Counter(static_cast<double>(allocations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_RuntimeStepBigMatrixQuiet)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
