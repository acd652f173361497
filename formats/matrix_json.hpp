// Reading and writing `cemv-matrix/1` (docs/format.md), the canonical form and
// the matrix signature.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

// Parses and checks the structure of a matrix: syntax, types, unknown keys,
// ranges, limits of 3.4, tag-name syntax of 6.1.4. Cross-element plausibility
// (11.5: duplicate ids or names, dangling references, ...) is validate()'s job,
// not the loader's; elements come back sorted by id (stable).
model::Matrix parse_matrix(std::string_view json_text, const std::string& source_name = "");
model::Matrix load_matrix(const std::filesystem::path& file);

// load_matrix, then validate (11.5): a matrix with validation errors cannot be
// simulated or encoded, so it is refused with a LoadError (exit 2) whose
// issues say so (`FILE: the matrix has validation errors; it cannot be USE`)
// and then list every error (`FILE: RULE ELEMENT (SECTION): MESSAGE`).
// Warnings do not refuse a matrix.
// Each refusal line is placed at its element in the file (element_position).
model::Matrix load_valid_matrix(const std::filesystem::path& file, const std::string& use);
// The same for a text already read (standard input: source_name "<stdin>").
model::Matrix parse_valid_matrix(std::string_view json_text, const std::string& source_name,
                                 const std::string& use);

// Where the element a validation finding names (model::Diagnostic::element:
// "matrix", "cause[3] NAME", "effect[2]", "intersection cause[1]/effect[2]")
// starts in the matrix text: the object of the first element with that id, or
// the top-level object for "matrix"; nullopt when there is no such element.
std::optional<std::size_t> element_offset(const JsonPositions& positions, std::string_view element);

// The canonical form: every field written (defaults included), keys sorted,
// elements ordered by id, floats in their shortest round-trip single-precision
// form, two-space indentation, trailing newline.
std::string to_canonical_json(const model::Matrix& m);
void save_matrix(const model::Matrix& m, const std::filesystem::path& file);

// SHA-256 of the canonical form, lowercase hex. Ties every report to one exact
// matrix version.
std::string signature(const model::Matrix& m);

// SHA-256 of any bytes (a source sheet, a parameters or property file), lowercase hex.
std::string sha256_hex(std::string_view bytes);

}  // namespace cemv::formats
