// The record layout `cemv-csv/1` (6.6, bulk data engineering; docs/csv.md):
// one RFC 4180 file, one record per row, the first column naming the record
// type (property, sif_group, cause, cause_tag, effect, effect_tag,
// intersection), each type with its own header row. It holds every field of
// cemv-matrix/1, so export then import is lossless. The grid layout of real
// C&E spreadsheets, and import_csv that reads either, are in sheets/csv.hpp.
#pragma once

#include <string>
#include <string_view>

#include "formats/csv_rfc4180.hpp"
#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

inline constexpr const char* kCsvLayout = "cemv-csv/1";

// The whole matrix as a `cemv-csv/1` file (CRLF line ends, deterministic).
std::string export_csv(const model::Matrix& m);

// Whether the text starts as the record layout does: a record type or its
// header in column 1 (`#property,` as export writes it), after a UTF-8 BOM.
bool starts_as_csv_records(std::string_view text);

// Reads a `cemv-csv/1` file (strict RFC 4180), checked by parse_matrix; every
// problem at its line and column. Throws LoadError.
model::Matrix import_csv_records(std::string_view text, const std::string& source_name);

}  // namespace cemv::formats
