// Directed runs for a defeat question (docs/defeats.md, "Method"): cemv
// response's demand runs with the actions of the set taken from the start, so
// that the checker shows most defeats by one run of the runtime (replayed on
// the property's encoding) before any engine is asked.
#pragma once

#include <vector>

#include "defeats/actions.hpp"
#include "model/vocabulary.hpp"

namespace cemv::defeats {

using Run = std::vector<model::CycleInput>;

// Each of `demand_runs` with the actions of `set` (indices into `actions`):
// soft bypasses commanded in the first cycle; bypass, inhibit and mask tags
// TRUE throughout; an input simulated at its quiet value from the first
// cycle; an output simulated at its unsafe value; an input in bad quality
// delivering its quiet value from the cycle the demand begins. An override
// needs a running request first and is left to the engines.
std::vector<Run> defeat_runs(const model::Matrix& m, const std::vector<Action>& actions, const std::vector<int>& set,
                             const std::vector<Run>& demand_runs);

}  // namespace cemv::defeats
