// Target (bench/README.md): building the transition system of the generated
// 128 x 128 x 1024 matrix that uses every option (target under 2 s), and the
// cone-of-influence slice for one effect (target under 50 ms).
//
// Each iteration encodes into a fresh Z3 context (Z3 hash-conses terms, so
// re-encoding into a used context would be unrealistically cheap); creating and
// destroying the context is not timed.
#include <benchmark/benchmark.h>

#include <memory>

#include "encoder/encode.hpp"
#include "model/graph.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

const model::Matrix& big() {
  static const model::Matrix m = testsupport::big_matrix(1);
  return m;
}

void run(benchmark::State& state, const std::vector<model::Node>& roots) {
  std::size_t states = 0, nodes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto ctx = std::make_unique<z3::context>();
    state.ResumeTiming();
    auto enc = encoder::encode(*ctx, big(), roots);
    state.PauseTiming();
    states = enc->ts.statevars().size();
    nodes = enc->nodes.size();
    enc.reset();
    ctx.reset();
    state.ResumeTiming();
  }
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["state_vars"] = static_cast<double>(states);
}

void BM_EncodeBigMatrixFull(benchmark::State& state) {
  run(state, {});
  state.SetLabel("target < 2 s");
}
BENCHMARK(BM_EncodeBigMatrixFull)->Unit(benchmark::kMillisecond)->Iterations(3);

// The effect with the largest cone of influence: the worst single-effect slice.
model::Node widest_effect() {
  model::DependencyGraph g(big());
  model::Node best{model::Node::Kind::Effect, 0};
  std::size_t most = 0;
  for (const auto& e : big().effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    model::Node n{model::Node::Kind::Effect, e.id};
    std::size_t size = g.feeders_of(n).size();
    if (size > most) {
      most = size;
      best = n;
    }
  }
  return best;
}

void BM_EncodeBigMatrixOneEffectSlice(benchmark::State& state) {
  static const model::Node root = widest_effect();
  run(state, {root});
  state.SetLabel("target < 50 ms; effect[" + std::to_string(root.id) + "], the widest cone");
}
BENCHMARK(BM_EncodeBigMatrixOneEffectSlice)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
