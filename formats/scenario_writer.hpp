// The one writer of `cemv-scenario/1` (docs/scenario.md), beside its reader
// (formats/scenario.hpp). A run is given as its cycle inputs and the steps it
// is cut into; the writer states what each step changes (inputs against the
// step before, its commands), how long it lasts, and what is expected after
// it. Checker counterexamples, generated tests, field tests and the
// distinguishing runs of `cemv mutate` and `cemv diff` are all written here.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

// One expected value: `key` as written (an observable key, or an output
// tag's name), its type, the value (Bool 0/1, Int, Voting enumerator).
struct ExpectedValue {
  std::string key;
  model::FieldType type = model::FieldType::Bool;
  int value = 0;
};

struct WrittenStep {
  std::size_t cycles = 1;                            // scan cycles, from the end of the step before
  std::optional<std::string> description;
  std::optional<std::vector<ExpectedValue>> expect;  // checked after the step's last cycle
};

enum class Durations { Cycles, Milliseconds };  // a step's length as `cycles` or `ms`

struct ScenarioRun {
  std::string matrix;                      // the `matrix` key ("" = none)
  std::optional<std::string> description;
  std::vector<model::CycleInput> cycles;   // indexed by model::InputTable(m)
  std::vector<WrittenStep> steps;          // their cycles add up to cycles.size()
  Durations durations = Durations::Cycles;
  bool first_step_states_every_input = false;  // else only the inputs that differ from start-up
  // Inputs (model::InputTable indices) the first step states even where
  // they keep their start-up value: for a run meant for another matrix too,
  // whose defaults differ there.
  std::vector<std::size_t> first_step_also_states;
};

// A run checked once, after its last cycle (a counterexample, a witness, a
// distinguishing run): a step where inputs change or commands are issued,
// lengths in cycles, `expect` on the last step.
ScenarioRun checked_at_end(std::vector<model::CycleInput> cycles, std::string description,
                           std::vector<ExpectedValue> expect);

// The text; std::logic_error when the steps do not cover the cycles, or a
// step would not repeat its cycles (commands or changed inputs after its
// first cycle), so that the file always replays the run it was given.
std::string scenario_text(const model::Matrix& m, const ScenarioRun& run);

// The lengths of the steps a run is cut into when a step starts at the first
// cycle, after each checkpoint (0-based cycles), at a cycle with commands and
// at one whose inputs differ from the cycle before. Any other cycle holds the
// step before, so a hold of hours is one step.
std::vector<std::size_t> step_lengths(const std::vector<model::CycleInput>& cycles,
                                      const std::vector<std::size_t>& checkpoints);

// One command as the format writes it, on one line:
// {"op":"soft_bypass_tag","cause":1,"tag":2,"on":true}.
std::string command_text(const model::Matrix& m, const model::Command& c);

}  // namespace cemv::formats
