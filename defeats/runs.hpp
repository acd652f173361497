// Directed runs for a defeat question (docs/defeats.md, "Method"): cemv
// response's demand runs with the actions of the set taken from the start, so
// that the checker shows most defeats by one run of the runtime (replayed on
// the property's encoding) before any engine is asked.
#pragma once

#include <vector>

#include "defeats/actions.hpp"
#include "response/paths.hpp"
#include "model/vocabulary.hpp"

namespace cemv::defeats {

using Run = std::vector<model::CycleInput>;

// Each of `demand_runs` with the actions of `set` (indices into `actions`):
// soft bypasses commanded in the first cycle; bypass, inhibit and mask tags
// TRUE throughout; an input simulated at its quiet value from the first
// cycle; an output simulated at its unsafe value; an input in bad quality
// delivering its quiet value from the cycle the demand begins. An override
// needs a running request first and is left to the engines.
// Where the set touches tags of a voted trigger cause (a tag soft bypass, a
// simulation, a bad quality), a second run takes those tags as the ones
// beyond the limit, and as many of the rest as the demand had: a defeat of
// a 2oo3 needs the tags taken out to be the ones that see the demand.
std::vector<Run> defeat_runs(const model::Matrix& m, const response::Path& p, const std::vector<Action>& actions,
                             const std::vector<int>& set, const std::vector<Run>& demand_runs);

}  // namespace cemv::defeats
