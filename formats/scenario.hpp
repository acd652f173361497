// Scenarios `cemv-scenario/1` (docs/scenario.md): a sequence
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
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/diagnostics.hpp"
#include "model/vocabulary.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

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
  model::Observable observable;
  std::string output_tag;
};

struct Expectation {
  std::string key;          // as written in the scenario
  std::string where;        // JSON path, e.g. "steps[2].expect.cause[1].active"
  ExpectTarget target;
  model::FieldType type = model::FieldType::Bool;
  int expected = 0;         // Bool 0/1, Int as is, Voting as the Voting enumerator
};
// "true", "3", "1oo2": how an expected or actual value of this type is written.
std::string expectation_value_text(model::FieldType type, int value);

struct ScenarioStep {
  std::string description;
  std::vector<InputSetting> inputs;
  std::vector<model::Command> commands;
  std::uint64_t cycles = 1;
  std::vector<Expectation> expect;
};

struct Scenario {
  std::string matrix;  // the `matrix` key as written (a path relative to the file); may be empty
  std::string description;
  std::vector<InputSetting> initial;
  std::vector<ScenarioStep> steps;
};

// Parses and resolves a scenario against `m`. Throws LoadError (every problem
// found, each with its JSON path) on syntax errors, unknown keys, unknown tags,
// commands, causes, effects or expectation keys, wrong types and ms that are
// not a multiple of cycle_ms.
Scenario parse_scenario(std::string_view json_text, const model::Matrix& m,
                        const std::string& source_name = "");
Scenario load_scenario(const std::filesystem::path& file, const model::Matrix& m);

// The matrix file a scenario names with its `matrix` key, resolved against the
// folder of the scenario file; nullopt when the scenario has no such key.
// Reads only the top level: everything else needs the matrix to be resolved.
// Throws LoadError when the file is unreadable or not JSON, or the key is not
// a non-empty string.
std::optional<std::filesystem::path> scenario_matrix_path(const std::filesystem::path& scenario_file);
// The same from the text of a scenario (the `matrix` key as written, not
// resolved), for a scenario read from standard input.
std::optional<std::string> scenario_matrix_key(std::string_view json_text, const std::string& source_name);

// A path written inside an input file (the `matrix` key) is untrusted: a
// pull request's scenario may name any file. It is resolved against the
// folder of the file that holds it (`base`) and must lead to a file inside
// `root` (the working folder), symbolic links followed; an absolute path, or
// one that leaves `root`, is refused with a LoadError placed at `key_name`
// in `source_text` (exit 2), unless `trust` (cemv simulate --trust-paths).
std::filesystem::path resolve_inner_path(const std::string& path, const std::filesystem::path& base,
                                         const std::filesystem::path& root, bool trust,
                                         std::string_view source_text, const std::string& source_name,
                                         const std::string& key_name);

// A scenario unrolled into scan cycles.
struct ExpandedScenario {
  struct Check {
    std::size_t step = 0;      // 0-based step index
    std::size_t cycle = 0;     // 0-based index into `cycles`: check after this cycle
    const std::vector<Expectation>* expect = nullptr;  // points into the Scenario
  };
  std::vector<model::CycleInput> cycles;
  std::vector<std::size_t> step_of_cycle;  // 0-based step index of each cycle
  std::vector<Check> checks;               // one per step, in cycle order
};
// Inputs persist from cycle to cycle until a step changes them; a step's
// commands are issued in its first cycle only. `sc` must outlive the result.
ExpandedScenario expand_scenario(const Scenario& sc, const model::Matrix& m);

// One expectation checked after its cycle.
struct ExpectationOutcome {
  std::size_t step = 0;    // 0-based step index
  std::size_t cycle = 0;   // 0-based cycle index
  const Expectation* expectation = nullptr;
  std::optional<int> actual;  // nullopt: the implementation has no value ("unknown")
  bool ok = false;
  // "FAIL steps[1] (cycle 21, t = 2000 ms): cause[1].active expected true, actual false"
  std::string failure_text(std::uint32_t cycle_ms) const;
};

// The one expectation-checking loop of every replay (the runtime's `cemv
// simulate`, the encoder's scenario test): after each cycle, the expectations
// due then are compared with the implementation's values. Bool values compare
// as 0/1, whatever non-zero value the implementation gives.
class ExpectationChecker {
 public:
  // The value an implementation gives an expectation's target after the
  // current cycle; nullopt when it has none.
  using Actual = std::function<std::optional<int>(const ExpectTarget&)>;
  explicit ExpectationChecker(const ExpandedScenario& ex) : ex_(ex) {}
  // Checks the expectations due after 0-based cycle `cycle` (cycles in order).
  std::vector<ExpectationOutcome> after_cycle(std::size_t cycle, const Actual& actual);
  std::size_t checked() const { return checked_; }
  std::size_t failed() const { return failed_; }

 private:
  const ExpandedScenario& ex_;
  std::size_t next_check_ = 0;
  std::size_t checked_ = 0;
  std::size_t failed_ = 0;
};

}  // namespace cemv::formats
