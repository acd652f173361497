// Syntax rules of names (6.1.4 tag names, 6.3.4 / 6.4.4 element names).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace cemv::model {

// Why a name is not a valid tag name by the syntax rules of 6.1.4 (e.g.
// "'#TIC__543' repeats '_'"), or nullopt when it is valid. Internal references
// (Cause[x], Effect[x], Effect[x][y], 6.1.3) are valid tag names.
std::optional<std::string> tag_name_problem(std::string_view name);

// Same for cause and effect names: 1-32 letters, digits and '_' (6.3.4, 6.4.4).
std::optional<std::string> element_name_problem(std::string_view name);

}  // namespace cemv::model
