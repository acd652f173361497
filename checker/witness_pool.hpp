// Runtime traces that one check run has already produced (counterexamples,
// witnesses), kept to answer the vacuity questions of the properties decided
// after them: a trace of the reference runtime in which the concrete
// evaluator finds a property's assumptions holding and its antecedent met
// shows that the property is not vacuous, with no solver involved.
//
// The standard property set asks the same question many times over (every
// intersection of a cause needs that cause active, which may take an
// on-delay's worth of cycles to reach); the first witness serves the rest.
//
// When no kept trace serves, seeded random runs of the property's cone
// (checker/random_runs.hpp) are tried on the runtime before any solver: an
// antecedent that needs a voted trip held through its delays is a few
// segments of a run away, and BMC on a float cone takes seconds per cycle of
// depth to find it. The number of runs is fixed, never a time budget, so
// the same question gets the same answer on every machine.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "checker/random_runs.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"
#include "properties/evaluator.hpp"

namespace cemv::checker {

class WitnessPool {
 public:
  // The longest random run search() tries.
  static constexpr std::size_t kMaxRunCycles = 600;
  // Thread-safe. Traces beyond the pool's capacity are not kept.
  void add(properties::Trace trace);
  // Whether some kept trace judges `p` on at least one cycle (its assumptions
  // hold in the first) and, when `need_antecedent`, meets its antecedent.
  bool witnesses(const model::Matrix& m, const properties::Property& p,
                 const std::vector<properties::Assumption>& file_assumptions, bool need_antecedent) const;
  // `runs` seeded random runs over `space`, each replayed on the runtime and
  // judged as witnesses() judges; the first witness is kept. True when one is.
  bool search(const model::Matrix& m, const properties::Property& p,
              const std::vector<properties::Assumption>& file_assumptions, bool need_antecedent,
              const RunSpace& space, int runs);

 private:
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<const properties::Trace>> traces_;
};

}  // namespace cemv::checker
