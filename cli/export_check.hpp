// Export never writes what import refuses (docs/csv.md "Invalid matrices"):
// a matrix with validation errors is exported only when the sheet reads back
// to it (the record layout and the workbooks with the same signature, the
// grid with the same intersections); otherwise the export is refused with the
// validation errors, each at its element in the matrix file (exit 2).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "model/matrix.hpp"

namespace cemv::cli {

// `reimport` reads the exported bytes back and returns why they do not give
// the matrix back (nullopt when they do). Called only for an invalid matrix.
// `matrix_text` is the matrix file as read, named `matrix_name` in messages.
void refuse_unreadable_export(const std::string& matrix_text, const std::string& matrix_name, const model::Matrix& m,
                              const std::string& what, const std::function<std::optional<std::string>()>& reimport);

}  // namespace cemv::cli
