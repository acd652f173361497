#include "checker/witness_pool.hpp"

#include <algorithm>

#include "runtime/runtime.hpp"

namespace cemv::checker {

namespace {
// Enough for the traces of a large standard set to be tried quickly: each
// question evaluates the property on every kept trace.
constexpr std::size_t kCapacity = 256;
}  // namespace

void WitnessPool::add(properties::Trace trace) {
  if (trace.empty()) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (traces_.size() < kCapacity) traces_.push_back(std::make_shared<const properties::Trace>(std::move(trace)));
}

bool WitnessPool::witnesses(const model::Matrix& m, const properties::Property& p,
                            const std::vector<properties::Assumption>& file_assumptions,
                            bool need_antecedent) const {
  std::vector<std::shared_ptr<const properties::Trace>> traces;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    traces = traces_;
  }
  const properties::Evaluator evaluator(m);
  for (const auto& t : traces) {
    properties::Evaluation ev = evaluator.evaluate(p, file_assumptions, *t);
    if (ev.judged >= 1 && (!need_antecedent || ev.antecedent_met)) return true;
  }
  return false;
}

bool WitnessPool::search(const model::Matrix& m, const properties::Property& p,
                         const std::vector<properties::Assumption>& file_assumptions, bool need_antecedent,
                         const RunSpace& space, int runs) {
  if (space.tags.empty() && space.commands.empty()) return false;
  // Long enough for the cone's delays (the holds drawn are the matrix's own
  // durations), short enough that a question no run answers costs little:
  // hours of soft bypass are left to the engines.
  constexpr std::size_t kSegments = 16;
  constexpr std::size_t kMaxCycles = kMaxRunCycles;
  RandomRuns gen(space, 0x77a1e55ULL);
  const properties::Evaluator evaluator(m);
  const model::CycleInput start = model::default_cycle_input(m);
  std::vector<int> observed;
  for (int r = 0; r < runs; ++r) {
    const std::vector<model::CycleInput> cycles = expand(m, gen.next(kSegments, kMaxCycles), start);
    runtime::Runtime rt(m);
    properties::Trace trace;
    trace.reserve(cycles.size());
    for (const auto& in : cycles) {
      rt.step(in);
      rt.snapshot(observed);
      trace.push_back({in, observed});
    }
    const properties::Evaluation ev = evaluator.evaluate(p, file_assumptions, trace);
    if (ev.judged >= 1 && (!need_antecedent || ev.antecedent_met)) {
      add(std::move(trace));
      return true;
    }
  }
  return false;
}

}  // namespace cemv::checker
