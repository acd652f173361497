// Reading the inputs of a command that computes from a matrix: one function
// that loads a matrix and refuses it when it has validation errors (a checker,
// simulator or generator must never compute from an invalid matrix), and "-"
// meaning standard input for every input file argument.
#pragma once

#include <optional>
#include <string>

#include "model/matrix.hpp"

namespace cemv::cli {

// How messages name standard input.
inline constexpr const char* kStdinName = "<stdin>";

// The text of `path` ("-" = standard input). Throws formats::LoadError naming the file.
std::string read_input(const std::string& path);

// `path` as messages name it: "<stdin>" for "-".
std::string input_name(const std::string& path);

// Loads and validates a matrix. On validation errors prints them to standard
// error, saying that the matrix cannot be used to `purpose` ("checked",
// "simulated"), and returns nothing (the caller exits 2). Throws
// formats::LoadError for an unreadable or malformed file.
std::optional<model::Matrix> load_valid_matrix(const std::string& path, const std::string& purpose);

}  // namespace cemv::cli
