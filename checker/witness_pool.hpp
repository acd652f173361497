// Runtime traces that one check run has already produced (counterexamples,
// witnesses), kept to answer the vacuity questions of the properties decided
// after them: a trace of the reference runtime in which the concrete
// evaluator finds a property's assumptions holding and its antecedent met
// shows that the property is not vacuous, with no solver involved.
//
// The standard property set asks the same question many times over (every
// intersection of a cause needs that cause active, which may take an
// on-delay's worth of cycles to reach); the first witness serves the rest.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"
#include "properties/evaluator.hpp"

namespace cemv::checker {

class WitnessPool {
 public:
  // Thread-safe. Traces beyond the pool's capacity are not kept.
  void add(properties::Trace trace);
  // Whether some kept trace judges `p` on at least one cycle (its assumptions
  // hold in the first) and, when `need_antecedent`, meets its antecedent.
  bool witnesses(const model::Matrix& m, const properties::Property& p,
                 const std::vector<properties::Assumption>& file_assumptions, bool need_antecedent) const;

 private:
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const properties::Trace>> traces_;
};

}  // namespace cemv::checker
