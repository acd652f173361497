#include "checker/witness_pool.hpp"

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

}  // namespace cemv::checker
