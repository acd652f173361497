// The bounded-response property that states "the path responds within T
// cycles", in the property language (docs/properties.md), for the checker to
// decide. docs/response-time.md explains each part.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "response/paths.hpp"

namespace cemv::response {

enum class Mode { Normal, Degraded };

// A property file with one property named `name`: whenever the trigger of `p`
// rises on a quiet cause and holds, the effect's outputs are in their active
// state within `cycles` cycles; no bypass, inhibit, override or maintenance
// operation on the path. Degraded: one input of a voted trigger cause in bad
// quality throughout, the others as the degraded voting needs them.
std::string response_property_text(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                   const std::string& name);

}  // namespace cemv::response
