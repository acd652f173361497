// Internal to testgen/: the witness of an objective found by seeded random
// runs on the reference runtime (checker/random_runs.hpp), for objectives
// whose witness BMC does not reach within its budget: a 100-cycle output
// delay behind a 2oo3 analog cause, a 5 s pulse that must end before a latch
// shows. Only the inputs of the objective's cone vary, held for the matrix's
// own durations; the concrete evaluator judges every run cycle by cycle
// (properties::StreamEvaluator, from the state the prefix leaves), and the first run
// that witnesses the objective is made short (checker::minimise_run). The
// caller then lets BMC find the last cycles from a state shortly before the
// witness, and replays the result on the runtime like every other test.
#pragma once

#include <cstdint>
#include <vector>

#include "testgen/search.hpp"

namespace cemv::testgen::detail {

// At most `runs` runs of `segments` segments after `prefix`; Found with the
// cycles after the prefix (ending at the witness), or Undecided. The seed
// fixes the runs, so the answer does not depend on time or load.
SearchResult explore(const model::Matrix& m, const Goal& g, const std::vector<model::CycleInput>& prefix,
                     std::uint64_t seed, int runs = 300, std::size_t segments = 10);

}  // namespace cemv::testgen::detail
