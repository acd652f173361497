// The differential check shared by the ctest shards and the --long runner:
// one matrix, one input sequence, the runtime and the encoder side by side.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::encoder_test {

struct Disagreement {
  std::size_t cycle = 0;     // 0-based
  std::string key;
  int runtime = 0;
  int encoder = 0;
};

// Runs both on `inputs` (commands put in the encoder's canonical order, the
// same list for both); the first differing observable, if any.
std::optional<Disagreement> compare(const model::Matrix& m,
                                    const std::vector<model::CycleInput>& inputs);

// A readable report: seed, first difference, the matrix (canonical JSON) and
// the inputs up to the differing cycle, after shrinking the matrix (dropping
// causes, effects, intersections) and the cycles while the disagreement stays.
std::string report(std::uint64_t seed, const model::Matrix& m,
                   const std::vector<model::CycleInput>& inputs, const Disagreement& d);

}  // namespace cemv::encoder_test
