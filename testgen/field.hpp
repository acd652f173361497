// The field suite (docs/testgen.md, "Field suite"): one loop per test, a
// cause (or an XooN group) and what it drives, in the steps a technician with
// a calibrator, a stopwatch and the Safety Matrix Viewer performs on the
// plant: initial conditions, the trip at a value a calibrator sets, holds in
// seconds, observations of what can be seen (outputs in plant words, Viewer
// indications of manual 10.6), acknowledge, reset, restore. Every test is run
// on the reference runtime while it is built (its observations are what the
// runtime shows) and written as a cemv-scenario/1 file that replays green.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "formats/acceptance.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen {

using formats::kFieldChecklistFormat;

struct FieldOptions {
  double resolution = 0.1;  // of the calibrator / the tag's unit: values are printed and set to it
  std::string matrix_ref;   // the scenarios' `matrix` key
  // --total-timeout: polled before each loop test is built and before each
  // test's objectives are placed; what is left is listed, not guessed.
  const checker::CancelToken* cancel = nullptr;
};

struct FieldTestStep {
  int number = 0;                      // 1-based within the test
  std::string phase;                   // "Initial conditions", "Test", "Restore"
  std::vector<std::string> actions;    // "Set FT_210 to 19.9 % (trip: limit 25 %, low)"
  std::uint64_t hold_ms = 0;           // "Hold for at least 2.5 s"
  std::vector<std::string> expected;   // "XV_221A closed (de-energized) within 1 s"
  std::vector<std::string> objectives; // the objective ids this step witnesses first (the appendix)
  std::vector<std::string> again;      // witnessed again here, first by an earlier step
  std::size_t first_cycle = 0, last_cycle = 0;  // 0-based, in the test's run
};

struct FieldTest {
  std::string id;          // "F001"
  std::string file_name;   // "F001-cause-1-bsl201-flame-fail.scenario.json"
  int sif = 0;
  std::string title;       // "Cause 1 BSL201_FLAME_FAIL: Main flame failure ..."
  std::vector<int> causes; // tripped, in order
  std::vector<int> effects;  // driven by them (processed intersections)
  std::vector<FieldTestStep> steps;
  std::uint64_t field_s = 0;   // estimate of the time on the plant
  std::uint64_t cycles = 0;    // the replayed run
  std::vector<model::CycleInput> inputs;
  std::string scenario_json;
};

// How an objective of the catalogue (derive_objectives) stands in the field
// suite: witnessed by a step, or automated-only with the reason.
struct FieldObjective {
  Objective objective;
  int test = -1;   // index into FieldSuite::tests; -1 = automated-only
  int step = 0;    // 1-based step of that test
  std::string reason;  // automated-only: why
};

// The mutation figures of the field suite beside the automated suite's
// (`cemv testgen --mutation-report`, docs/mutation.md): what field testing
// alone leaves open.
struct FieldMutation {
  std::size_t mutants = 0, equivalent = 0;
  std::size_t field = 0;        // detected by the field suite
  std::size_t automated = 0;    // detected by the automated suite
  std::vector<std::string> automated_only;  // "id: description", detected by the automated suite only
  std::vector<std::string> neither;         // non-equivalent, detected by neither (or undecided)
};

struct FieldSuite {
  std::string matrix_name;
  std::string signature;
  double resolution = 0.1;
  std::vector<FieldTest> tests;            // by SIF group, then cause
  std::vector<FieldObjective> objectives;  // catalogue order
  std::vector<std::string> untested;       // causes no loop test trips, with the reason
  std::uint64_t field_s = 0;
  std::optional<FieldMutation> mutation;   // with --mutation-report
  // The cancel token ended the suite: the loops not built are in `untested`,
  // the objectives not placed say so; every test written still replays green.
  bool interrupted = false;
  std::size_t witnessed() const;
};

// Throws checker::InternalError when a test does not replay green.
FieldSuite generate_field_suite(const model::Matrix& m, const FieldOptions& options = {});

// A value as the calibrator sets it, at `resolution`: "19.9", "2.85".
std::string field_value_text(double v, double resolution);

// The checklist (MD, one printable HTML page, CSV with Result, Initials and
// Date per step and the matrix signature).
std::string field_checklist_markdown(const model::Matrix& m, const FieldSuite& s, const std::string& date,
                                     const std::string& tool);
std::string field_checklist_html(const model::Matrix& m, const FieldSuite& s, const std::string& date,
                                 const std::string& tool);
std::string field_checklist_csv(const model::Matrix& m, const FieldSuite& s, const std::string& date,
                                const std::string& tool);

}  // namespace cemv::testgen

namespace cemv::testgen {

// The acceptance status from filled field checklists (docs/acceptance.md):
// each row matched to its step of `s` (the field suite of `m` at the
// checklists' resolution), each step's objectives mapped to their elements.
// Throws formats::LoadError (FILE:LINE) for a checklist whose signature is
// not the matrix's, a row naming a step the suite does not have, or a row
// whose action is not the step's (a checklist of another cemv version).
formats::Acceptance record_acceptance(const model::Matrix& m, const FieldSuite& s,
                                      const std::vector<formats::FilledChecklist>& filled, const std::string& tool);

}  // namespace cemv::testgen
