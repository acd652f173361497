// The words of cemv diff's outputs, shared by the printers (print.cpp) and
// the SARIF log (sarif.cpp): internal to diff/.
#pragma once

#include <string>

#include "checker/equivalence.hpp"
#include "diff/print.hpp"

namespace cemv::diff {

std::string value_text(model::FieldType t, int v);
// "behaviour changed", "unchanged, behaviour equivalent", "added", ...
std::string behaviour_words(const EffectBehaviour& e);
std::string effect_label(const EffectBehaviour& e);  // "effect[2] NAME"
// "critical     changed cause[3] NAME", with a move's numbers.
std::string change_line(const ElementChange& c);
// "time.ms: 2000 -> 3000", "[non-critical]" when it is.
std::string field_line(const FieldChange& f);
// "effect[1].active in cycle 3: OLD 1, NEW 0"
std::string distinction_text(const checker::Distinction& d);
// The scenario file written for a group's distinguishing run ("" if none).
std::string scenario_of(const DiffReport& r, const std::string& group);

}  // namespace cemv::diff
