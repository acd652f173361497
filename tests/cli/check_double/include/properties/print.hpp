// TEST DOUBLE of properties/print.hpp (see ../../README.md): the double's
// properties have no expressions, so their text is their kind, name and
// description (what the result cache keys on).
#pragma once

#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

std::string to_text(const Expr& e, const model::InputTable& inputs);
std::string statement_text(const Property& p, const model::InputTable& inputs);

}  // namespace cemv::properties
