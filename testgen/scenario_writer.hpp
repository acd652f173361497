// Internal to testgen/: a test as a cemv-scenario/1 file (docs/scenario.md),
// written by the format's one writer (formats/scenario_writer.hpp). Unlike a
// checker counterexample (one expectation block at the end), a test checks at
// every checkpoint: each cycle where it witnesses an objective ends a step
// whose `expect` lists what an engineer can observe there (output tags, cause
// and effect active, trip requests, latches, alarms) and the signals of the
// objectives witnessed. Durations are written in ms.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen::detail {

struct Checkpoint {
  std::size_t cycle = 0;                 // 0-based
  std::vector<std::string> descriptions; // the objectives witnessed here
  std::vector<std::string> observe;      // their keys, shown first
};

// The observable keys a checkpoint expects, in a fixed order, besides the
// objectives' own: what can be seen in the field.
std::vector<model::Observable> field_observables(const model::Matrix& m);

// The number of steps test_scenario_json writes for these inputs and
// checkpoint cycles (0-based): what bounds the length of a test. A step
// starts at the first cycle, after a checkpoint, at a cycle with operator
// commands, or where the inputs change (formats::step_lengths), so a hold of
// hours is one step ("Wait 8 h"), however many cycles it spans.
std::size_t count_steps(const std::vector<model::CycleInput>& inputs, const std::vector<std::size_t>& checkpoints);

// The runtime's snapshots (model::observables order) after the given cycles
// of a run: what a test's checkpoints expect, without the run's trace.
std::map<std::size_t, std::vector<int>> snapshots_at(const model::Matrix& m, const std::vector<model::CycleInput>& inputs,
                                                     const std::vector<std::size_t>& cycles);

// `snapshots`: snapshots_at the checkpoints' cycles. Returns the file text
// and the number of steps.
std::string test_scenario_json(const model::Matrix& m, const std::string& matrix_ref, const std::string& description,
                               const std::vector<model::CycleInput>& inputs,
                               const std::map<std::size_t, std::vector<int>>& snapshots,
                               const std::vector<Checkpoint>& checkpoints, std::size_t& steps,
                               std::vector<FieldStep>& field);

}  // namespace cemv::testgen::detail
