// The structural comparison of two versions of a matrix (docs/change-acceptance.md,
// manual 11.2 and 6.2.3): causes and effects matched by name and by id, a
// renumbering recognised as a move (6.3.2, 6.4.2 warn that inserting a row
// shifts every number after it), and every field that changed, each
// classified critical (safety logic: what the runtime reads) or non-critical
// (texts and display: names, descriptions, notes, SIL, SIF assignment and
// names, units).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::diff {

struct FieldChange {
  std::string field;      // JSON path inside the element: "time.ms", "tags[2].ett"
  std::string old_value;  // canonical JSON text, "" when absent
  std::string new_value;
  bool critical = true;
};

enum class ChangeKind { Added, Removed, Changed, Moved, Unchanged };
const char* to_string(ChangeKind);

struct ElementChange {
  enum class Element { Matrix, Cause, Effect, Intersection } element = Element::Cause;
  ChangeKind kind = ChangeKind::Changed;
  int old_id = 0;         // cause or effect id (Intersection: the cause), 0 = none
  int new_id = 0;
  int old_effect = 0;     // Intersection: the effect ids
  int new_effect = 0;
  std::string name;       // the element's name (NEW's when it has one)
  std::vector<FieldChange> fields;  // Changed / Moved: what differs besides the number
  bool critical() const;
  std::string label() const;  // "cause[3] LT100_HH", "intersection cause[3]/effect[1]"
};

struct StructuralDiff {
  // id maps of the matching: OLD id -> NEW id (matched elements only).
  std::map<int, int> cause_map, effect_map;
  std::vector<ElementChange> changes;  // matrix, causes by old id, effects, intersections
  bool any_critical() const;
  bool empty() const { return changes.empty(); }
};

StructuralDiff compare_structure(const model::Matrix& old_m, const model::Matrix& new_m);

// NEW renumbered into OLD's numbering along the matching (matched elements
// take their OLD id, added ones the smallest free ids), internal references
// and intersections rewritten to match: the same configuration as NEW, keyed
// like OLD, so that observables and operator commands of the two versions
// pair up (docs/change-acceptance.md, "Moves"). `new_to_old` receives the
// id maps NEW -> relabelled.
struct Relabelling {
  model::Matrix matrix;
  std::map<int, int> cause_ids, effect_ids;  // NEW id -> relabelled id
};
Relabelling relabel(const model::Matrix& new_m, const StructuralDiff& d, const model::Matrix& old_m);

}  // namespace cemv::diff
