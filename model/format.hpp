// Reading and writing `cemv-matrix/1` (docs/format.md), the canonical form and
// the matrix signature.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::model {

// One problem with an input file: where (a JSON path such as
// `causes[3].tags[1].name`, or `line 4, column 7` for syntax and CSV) and what.
struct LoadIssue {
  std::string where;
  std::string what;
  std::string str() const { return where.empty() ? what : where + ": " + what; }
};

// Thrown when a file cannot be read or is not a well-formed matrix; carries every
// problem found, in file order. The CLI prints them and exits 2.
class LoadError : public std::runtime_error {
 public:
  explicit LoadError(std::vector<LoadIssue> issues);
  const std::vector<LoadIssue>& issues() const { return issues_; }

 private:
  std::vector<LoadIssue> issues_;
};

// Largest file the loaders accept, and deepest JSON nesting: guards against
// hostile inputs (a matrix of the 3.4 limits is well under 1 MiB).
inline constexpr std::size_t kMaxFileBytes = 16u << 20;
inline constexpr int kMaxJsonDepth = 64;

// Parses and checks the structure of a matrix: syntax, types, unknown keys,
// ranges, limits of 3.4, tag-name syntax of 6.1.4. Cross-element plausibility
// (11.5: duplicate ids or names, dangling references, ...) is validate()'s job,
// not the loader's; elements come back sorted by id (stable).
Matrix parse_matrix(std::string_view json_text, const std::string& source_name = "");
Matrix load_matrix(const std::filesystem::path& file);

// The canonical form: every field written (defaults included), keys sorted,
// elements ordered by id, floats in their shortest round-trip single-precision
// form, two-space indentation, trailing newline.
std::string to_canonical_json(const Matrix& m);
void save_matrix(const Matrix& m, const std::filesystem::path& file);

// SHA-256 of the canonical form, lowercase hex. Ties every report to one exact
// matrix version.
std::string signature(const Matrix& m);

// Reads a whole file with the size guard; throws LoadError.
std::string read_text_file(const std::filesystem::path& file);

// Why a name is not a valid tag name by the syntax rules of 6.1.4 (e.g.
// "'#TIC__543' repeats '_'"), or nullopt when it is valid. Internal references
// (Cause[x], Effect[x], Effect[x][y], 6.1.3) are valid tag names.
std::optional<std::string> tag_name_problem(std::string_view name);

// Same for cause and effect names: 1-32 letters, digits and '_' (6.3.4, 6.4.4).
std::optional<std::string> element_name_problem(std::string_view name);

// Shortest decimal text that reads back as the same float (e.g. 0.1f -> "0.1").
std::string float_text(float v);

}  // namespace cemv::model
