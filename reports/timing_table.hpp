// The timing table of `cemv simulate` (docs/scenario.md): for every input tag
// and every observable, its value at the first cycle and at each change.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "model/vocabulary.hpp"

namespace cemv::reports {

class TimingTable {
 public:
  // One row per input tag (InputTable order), then per observable.
  TimingTable(const model::InputTable& inputs, const std::vector<model::Observable>& observables);

  // The values of cycle `cycle_no` (1-based): the cycle's inputs and the
  // snapshot of every observable (model::observables order).
  void record(std::uint64_t cycle_no, const model::CycleInput& in, const std::vector<int>& snapshot);

  // Only the signals that change are listed, names padded to one column.
  void print(std::ostream& out, std::uint32_t cycle_ms) const;

 private:
  struct Timeline {
    std::string name;
    std::vector<std::pair<std::uint64_t, std::string>> points;
    void record(std::uint64_t cycle, std::string v);
  };
  const model::InputTable& inputs_;
  const std::vector<model::Observable>& observables_;
  std::vector<Timeline> lines_;
};

}  // namespace cemv::reports
