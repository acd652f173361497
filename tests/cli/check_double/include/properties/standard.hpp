// TEST DOUBLE of properties/standard.hpp (see ../../README.md).
#pragma once

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

PropertyFile standard_properties(const model::Matrix& m);

}  // namespace cemv::properties
