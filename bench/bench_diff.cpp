// Target (bench/README.md): the change comparison of two generated
// 128 x 128 x 1024 matrices (testsupport::big_matrix) that differ in one
// intersection finishes in under 10 s: the structural comparison, then the
// semantic comparison of every effect (the effects whose cone is unchanged are
// decided by the identical-cone argument; only the changed cones go to the
// product of the two transition systems).
//
// Two changes of one intersection of the effect with the widest cone of
// influence (the worst case for the product): the intersection removed, and
// its type changed. Both NEW matrices are checked valid before timing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include "diff/semantic.hpp"
#include "diff/structural.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"
#include "model/validate.hpp"
#include "tests/support/random_matrix.hpp"

namespace {

using namespace cemv;

const model::Matrix& big() {
  static const model::Matrix m = testsupport::big_matrix(1);
  return m;
}

bool valid(const model::Matrix& m) {
  for (const auto& d : model::validate(m))
    if (d.severity == model::Severity::Error) return false;
  return true;
}

// Effects ordered by the size of their cone, widest first.
std::vector<int> effects_by_cone() {
  model::DependencyGraph g(big());
  std::vector<std::pair<std::size_t, int>> v;
  for (const auto& e : big().effects)
    if (e.function != model::EffectFunction::Comment)
      v.push_back({g.feeders_of(model::Node{model::Node::Kind::Effect, e.id}).size(), e.id});
  std::sort(v.begin(), v.end(), [](auto a, auto b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  std::vector<int> out;
  for (auto& [size, id] : v) out.push_back(id);
  return out;
}

struct Pair {
  model::Matrix changed;
  std::string what;
};

// The first valid single-intersection edit of the widest-cone effect possible.
Pair one_intersection_changed(bool remove) {
  for (int effect : effects_by_cone())
    for (std::size_t i = 0; i < big().intersections.size(); ++i) {
      const auto& x = big().intersections[i];
      if (x.effect != effect || x.xoon) continue;
      model::Matrix m = big();
      std::string what;
      if (remove) {
        m.intersections.erase(m.intersections.begin() + static_cast<long>(i));
        what = "intersection cause[" + std::to_string(x.cause) + "]/effect[" + std::to_string(effect) + "] removed";
      } else {
        using T = model::IntersectionType;
        m.intersections[i].type = x.type == T::N ? T::S : T::N;
        what = "intersection cause[" + std::to_string(x.cause) + "]/effect[" + std::to_string(effect) + "] " +
               model::to_string(x.type) + " -> " + model::to_string(m.intersections[i].type);
      }
      if (valid(m)) return {std::move(m), what};
    }
  throw std::runtime_error("no valid single-intersection edit");
}

void run(benchmark::State& state, const Pair& p) {
  std::size_t changed = 0, equivalent = 0, unknown = 0, product = 0;
  for (auto _ : state) {
    diff::StructuralDiff s = diff::compare_structure(big(), p.changed);
    diff::SemanticDiff d = diff::compare_behaviour(big(), p.changed, s);
    changed = equivalent = unknown = product = 0;
    for (const auto& e : d.effects) {
      changed += e.result.verdict == checker::EquivalenceVerdict::Differs;
      equivalent += e.result.verdict == checker::EquivalenceVerdict::Equivalent;
      unknown += e.result.verdict == checker::EquivalenceVerdict::Unknown;
      product += e.result.basis != checker::EquivalenceBasis::IdenticalCone;
    }
  }
  state.counters["effects_changed"] = static_cast<double>(changed);
  state.counters["equivalent"] = static_cast<double>(equivalent);
  state.counters["undecided"] = static_cast<double>(unknown);
  state.counters["on_product"] = static_cast<double>(product);
  state.SetLabel("target < 10 s; " + p.what);
}

void BM_DiffBigMatrixIntersectionRemoved(benchmark::State& state) {
  static const Pair p = one_intersection_changed(true);
  run(state, p);
}
BENCHMARK(BM_DiffBigMatrixIntersectionRemoved)->Unit(benchmark::kSecond)->Iterations(1);

void BM_DiffBigMatrixIntersectionTypeChanged(benchmark::State& state) {
  static const Pair p = one_intersection_changed(false);
  run(state, p);
}
BENCHMARK(BM_DiffBigMatrixIntersectionTypeChanged)->Unit(benchmark::kSecond)->Iterations(1);

// The structural comparison alone.
void BM_DiffBigMatrixStructureOnly(benchmark::State& state) {
  static const Pair p = one_intersection_changed(true);
  for (auto _ : state) benchmark::DoNotOptimize(diff::compare_structure(big(), p.changed));
}
BENCHMARK(BM_DiffBigMatrixStructureOnly)->Unit(benchmark::kMillisecond);

}  // namespace

// With CEMV_DIFF_PAIR_DIR set, the pairs are written there first (old.json,
// removed.json, type-changed.json), so that one comparison can be rerun and
// profiled as `cemv diff old.json removed.json`.
int main(int argc, char** argv) {
  if (const char* dir = std::getenv("CEMV_DIFF_PAIR_DIR")) {
    auto write = [&](const char* name, const model::Matrix& m) {
      std::ofstream(std::string(dir) + "/" + name) << formats::to_canonical_json(m) << "\n";
    };
    write("old.json", big());
    write("removed.json", one_intersection_changed(true).changed);
    write("type-changed.json", one_intersection_changed(false).changed);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
