// Scenarios `cemv-scenario/1` (docs/scenario.md, issue 3 section 4): a sequence
// of steps (input values, operator commands, a number of scan cycles, expected
// status) checked against one matrix. Parsing resolves every name against the
// matrix, so a typo in a tag, a command or an expectation key is a LoadError
// naming the bad item, never a silently passing test.
//
// The expansion (expand_scenario) turns a scenario into the plain per-cycle
// CycleInput sequence plus the checks to make after given cycles; the runtime's
// `cemv simulate`, the encoder's differential test and the test generator all
// replay scenarios through it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/io.hpp"
#include "model/matrix.hpp"

namespace cemv::model {

inline constexpr const char* kScenarioFormat = "cemv-scenario/1";

// Guard against scenarios that would expand to an unreasonable trace.
inline constexpr std::uint64_t kMaxScenarioCycles = 1'000'000;
// ... and against an expansion too large for memory: cycles x input tags.
inline constexpr std::uint64_t kMaxScenarioTagValues = 32'000'000;

// One input assignment: the tag (index into InputTable), and what is set. A
// plain value sets the value and good quality; {"value","quality"} may set
// either or both (an omitted part keeps its previous state).
struct InputSetting {
  std::size_t tag = 0;
  std::optional<float> value;
  std::optional<bool> bad_quality;
};

// What an expectation looks at.
struct ExpectTarget {
  enum class Kind { OutputTag, Status } kind = Kind::Status;
  // Status: the observable (same key/kind/id/field/tag as model::observables());
  // OutputTag: the output tag's effect and position as an observable too
  // (field "tag"), plus the name as written in the matrix.
  Observable observable;
  std::string output_tag;
};

struct Expectation {
  std::string key;          // as written in the scenario
  std::string where;        // JSON path, e.g. "steps[2].expect.cause[1].active"
  ExpectTarget target;
  FieldType type = FieldType::Bool;
  int expected = 0;         // Bool 0/1, Int as is, Voting as the Voting enumerator
};
// "true", "3", "1oo2": how an expected or actual value of this type is written.
std::string expectation_value_text(FieldType type, int value);

struct ScenarioStep {
  std::string description;
  std::vector<InputSetting> inputs;
  std::vector<Command> commands;
  std::uint64_t cycles = 1;
  std::vector<Expectation> expect;
};

struct Scenario {
  std::string description;
  std::vector<InputSetting> initial;
  std::vector<ScenarioStep> steps;
};

// Parses and resolves a scenario against `m`. Throws LoadError (every problem
// found, each with its JSON path) on syntax errors, unknown keys, unknown tags,
// commands, causes, effects or expectation keys, wrong types and ms that are
// not a multiple of cycle_ms.
Scenario parse_scenario(std::string_view json_text, const Matrix& m,
                        const std::string& source_name = "");
Scenario load_scenario(const std::filesystem::path& file, const Matrix& m);

// The value of one input tag before any scenario sets it (issue 3 section 4):
// cause inputs at their non-tripped value (discrete DTT TRUE, ETT FALSE; analog
// high limit - hysteresis - 1.0, low limit + hysteresis + 1.0, computed in double
// and rounded once to float), every other Boolean tag FALSE, good quality. A tag
// read by several causes takes the value of the first cause (by id) that reads it.
TagValue default_tag_value(const Matrix& m, const InputTag& tag);
// Every input at its default, no commands; indexed by InputTable(m).
CycleInput default_cycle_input(const Matrix& m);

// A scenario unrolled into scan cycles.
struct ExpandedScenario {
  struct Check {
    std::size_t step = 0;      // 0-based step index
    std::size_t cycle = 0;     // 0-based index into `cycles`: check after this cycle
    const std::vector<Expectation>* expect = nullptr;  // points into the Scenario
  };
  std::vector<CycleInput> cycles;
  std::vector<std::size_t> step_of_cycle;  // 0-based step index of each cycle
  std::vector<Check> checks;               // one per step, in cycle order
};
// Inputs persist from cycle to cycle until a step changes them; a step's
// commands are issued in its first cycle only. `sc` must outlive the result.
ExpandedScenario expand_scenario(const Scenario& sc, const Matrix& m);

}  // namespace cemv::model
