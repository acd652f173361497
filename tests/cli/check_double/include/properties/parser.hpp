// TEST DOUBLE of properties/parser.hpp (see ../../README.md).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

PropertyFile parse_properties(std::string_view text, const model::Matrix& m, const std::string& file_name);
void check_distinct_names(const std::vector<PropertyFile>& files);

}  // namespace cemv::properties
