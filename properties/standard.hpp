// The standard property set of a matrix (`cemv check --standard`): what every
// matrix should satisfy, derived from the matrix alone so that a CI gate needs
// no hand-written file (docs/properties.md, "Standard properties").
#pragma once

#include <string>

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// The standard properties in the property language, one block per property,
// in a fixed order (intersections by cause then effect, then per effect, then
// per cause). Names are stable:
//   std.intersection.cI.eJ  std.output_delay.eJ  std.reachable.eJ
//   std.resettable.eJ       std.failsafe.cI
// The matrix must have passed validation without errors.
std::string standard_properties_text(const model::Matrix& m);

// The same, parsed and resolved; source locations are 0 (generated).
PropertyFile standard_properties(const model::Matrix& m);

}  // namespace cemv::properties
