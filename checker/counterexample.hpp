// A counterexample or witness as the people who read it need it: the cycle
// inputs the runtime replays, written as a `cemv-scenario/1` file whose
// constant stretches are folded into `cycles` and whose last step expects the
// values of the property's signals at the violation (so `cemv simulate` on the
// file passes exactly when the runtime reproduces the run).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::checker {

struct ScenarioExpectation {
  std::string key;    // an observable key, e.g. "effect[1].active"
  model::FieldType type = model::FieldType::Bool;
  int value = 0;
};

// `inputs`: one CycleInput per cycle, indexed by model::InputTable(m). Each
// cycle's commands are written in the order given, which is the order the
// runtime ran them (cycle_inputs gives model::CommandOrder's), so that
// `cemv simulate` on the file repeats the run.
// `expect`: checked after the last cycle.
std::string scenario_json(const model::Matrix& m, const std::vector<model::CycleInput>& inputs,
                          const std::string& description,
                          const std::vector<ScenarioExpectation>& expect);

// One command as the scenario format writes it, on one line:
// {"op":"soft_bypass_tag","cause":1,"tag":2,"on":true}.
std::string command_text(const model::Matrix& m, const model::Command& c);

// Writes `text` to a temporary file beside `path` and renames it into place,
// so an interrupted run leaves the old file or none, never half of one.
// Throws std::runtime_error naming the file when a write fails.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

}  // namespace cemv::checker
