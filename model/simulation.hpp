#pragma once
// Whether the operator may simulate a tag (O.8): every element that names it
// permits it (comment elements name nothing).

#include <string>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model {

inline bool simulation_permitted(const Matrix& m, const std::string& tag) {
  for (const auto& c : m.causes)
    for (const auto& t : c.tags)
      if (c.function != CauseFunction::Comment && tag_key(t.name) == tag_key(tag) && !t.simulation_allowed)
        return false;
  for (const auto& e : m.effects)
    for (const auto& t : e.tags)
      if (e.function != EffectFunction::Comment && tag_key(t.name) == tag_key(tag) && !t.simulation_allowed)
        return false;
  return true;
}

}  // namespace cemv::model
