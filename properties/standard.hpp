// The standard property set of a matrix (`cemv check --standard`): what every
// matrix should satisfy, derived from the matrix alone so that a CI gate needs
// no hand-written file (docs/properties.md, "Standard properties").
#pragma once

#include <string>

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// The standard properties, built as trees (properties/build.hpp) in a fixed
// order (intersections by cause then effect, then per effect, then per
// cause); source locations are 0 (generated). Names are stable:
//   std.intersection.cI.eJ  std.output_delay.eJ  std.reachable.eJ
//   std.resettable.eJ       std.failsafe.cI
// The matrix must have passed validation without errors.
PropertyFile standard_properties(const model::Matrix& m);

// The same printed in the property language, one block per property, for
// people (and for a file to start one's own requirements from).
std::string standard_properties_text(const model::Matrix& m);

}  // namespace cemv::properties
