// Traps of the property language that parse but rarely mean what the author
// meant, found when a file is read (docs/properties.md, "Traps"): an
// assumption that excludes `override_effect` but not `stop_override` (one
// button, docs/semantics.md E.3 and O.3), or either command on an effect
// whose override only its reset tag toggles (O.3 refuses the commands there).
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// The warnings of `file` as `FILE:LINE:COL: warning: ...` lines, one per
// place (an assumption shared by many properties is reported once), and each
// affected property's notes get the warning's text too.
std::vector<std::string> find_traps(PropertyFile& file, const model::Matrix& m);

}  // namespace cemv::properties
