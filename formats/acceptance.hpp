// The field acceptance record (docs/acceptance.md): the filled field
// checklist a team hands back (cemv-field-checklist/1, the CSV that
// `cemv testgen` writes into DIR/field/, with Result, Initials and Date per
// step), and the acceptance status `cemv record` derives from it
// (cemv-acceptance/1: per test and step the result, who and when; per cause,
// effect and intersection accepted, deviation or not-tested). Both read and
// written here only.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace cemv::formats {

inline constexpr const char* kFieldChecklistFormat = "cemv-field-checklist/1";
inline constexpr const char* kAcceptanceFormat = "cemv-acceptance/1";

// ---- the filled checklist ---------------------------------------------------

struct FilledRow {
  int line = 0;          // 1-based line of the row in its file
  std::string test;      // "F001"
  int step = 0;          // 1-based
  std::string action;    // as printed, to check the row is the step it names
  std::string result;    // "" = not performed, "OK", or the deviation as written
  std::string initials;
  std::string date;      // YYYY-MM-DD
};

struct FilledChecklist {
  std::string file;
  std::string matrix;
  std::string signature;
  int signature_line = 0;
  double resolution = 0.1;
  std::vector<FilledRow> rows;
};

// Throws LoadError (FILE:LINE: error: ...) for a file that is not a field
// checklist, a row without test or step, a result without initials or date,
// a date that is not YYYY-MM-DD.
FilledChecklist read_filled_checklist(std::string_view text, const std::string& file);

// ---- the acceptance status ------------------------------------------------

enum class StepStatus { Ok, Deviation, Open };
enum class AcceptanceStatus { Accepted, Deviation, NotTested };
const char* to_string(StepStatus);
const char* to_string(AcceptanceStatus);

struct StepResult {
  std::string result, initials, date;
  std::string file;
  int line = 0;
};

struct StepAcceptance {
  std::string test;
  int step = 0;
  std::string phase;
  StepStatus status = StepStatus::Open;
  std::vector<StepResult> records;       // every checklist that gave a result, in reading order
  std::vector<std::string> objectives;   // witnessed by the step
};

enum class ElementKind { Cause, Effect, Intersection };
const char* to_string(ElementKind);

struct ElementAcceptance {
  ElementKind kind = ElementKind::Cause;
  int cause = 0, effect = 0;   // the ids (an intersection has both)
  std::string name;            // cause or effect name; "" for an intersection
  AcceptanceStatus status = AcceptanceStatus::NotTested;
  int steps_ok = 0, steps_deviation = 0, steps_open = 0;
  std::vector<std::string> deviations;  // "F001 step 3: XV_221B did not close (JS, 2026-03-02)"
  std::string carried_over;             // the earlier record it comes from ("" = this one)
  std::string key() const;              // "cause[1]", "effect[2]", "intersection cause[1]/effect[2]"
};

struct Acceptance {
  std::string matrix;
  std::string signature;
  std::string tool;
  std::vector<std::string> checklists;   // the filled files, as given
  std::vector<StepAcceptance> steps;     // field suite order
  std::vector<ElementAcceptance> elements;  // causes, effects, intersections, by id
};

std::string acceptance_json(const Acceptance& a);
// Throws LoadError with the JSON path of what is wrong.
Acceptance read_acceptance(std::string_view text, const std::string& file);

}  // namespace cemv::formats
