// The random-run falsifier of an equivalence question (checker/equivalence.hpp):
// seeded random runs of both reference runtimes side by side, on one plant
// (every tag both read takes one value) and the same operator: a mutant
// that differs mostly does so on a run of a few segments, found long before
// a solver has unrolled the analog arithmetic or a long timer
// (checker/random_runs.hpp). The inputs vary over both cones, held for the
// durations of both matrices. The runs are searched on the slices the
// product encodes (the cones of the group's roots, run by the runtime: a
// 128 x 128 matrix costs the cycles of its cone only), and what is found
// is replayed on both whole matrices. What the runs cannot separate goes to
// the provers. The runs are not a proof of "shortest": the decider runs BMC
// a few cycles deep before them (checker/equivalence.cpp).
#pragma once

#include <optional>

#include "checker/equivalence_product.hpp"

namespace cemv::checker {

class RandomFalsifier {
 public:
  explicit RandomFalsifier(const EquivalenceQuestion& q) : q_(q) {}
  // The 0-based cycle of a difference the runs found, replayed on both whole
  // matrices (`out` filled: verdict, method "simulation", distinction);
  // nullopt when they found none within a third of the group's time.
  std::optional<int> find(GroupEquivalence& out) const;

 private:
  const EquivalenceQuestion& q_;
};

}  // namespace cemv::checker
