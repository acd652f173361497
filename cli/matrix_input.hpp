// "-" as standard input for the input files of a command: reading them, and
// loading a matrix from them through formats::load_valid_matrix's rule (a
// matrix with validation errors is refused, listing them, exit 2). Every
// command that computes from a matrix (graph, export-smt,
// simulate, check) loads it through load_valid_matrix; report and validate,
// which show the errors, and fmt, signature and export-csv, which convert it,
// read it with load_matrix_input.
#pragma once

#include <string>

#include "model/matrix.hpp"

namespace cemv::cli {

// How messages name standard input.
inline constexpr const char* kStdinName = "<stdin>";

// The text of `path` ("-" = standard input). Throws formats::LoadError naming the file.
std::string read_input(const std::string& path);

// `path` as messages name it: "<stdin>" for "-".
std::string input_name(const std::string& path);

// formats::load_matrix, also for "-": throws formats::LoadError naming the file.
model::Matrix load_matrix_input(const std::string& path);

// formats::load_valid_matrix, also for "-": throws formats::LoadError for an
// unreadable or malformed file and for a matrix with validation errors, which
// cannot be `use`d ("checked", "simulated").
model::Matrix load_valid_matrix(const std::string& path, const std::string& use);

}  // namespace cemv::cli
