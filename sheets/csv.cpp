// Spreadsheet import (6.6), docs/csv.md: which layout a CSV file has, and
// --strict over the grid's warnings.
#include "sheets/csv.hpp"

#include "sheets/csv_grid.hpp"

namespace cemv::formats {

namespace {

// --strict (for CI): every warning of the import is an error.
LoadError strict_refusal(const std::vector<LoadIssue>& warnings) {
  std::vector<LoadIssue> errors = warnings;
  errors.push_back({"", std::to_string(warnings.size()) +
                            (warnings.size() == 1 ? " import warning is" : " import warnings are") +
                            " an error under --strict"});
  return LoadError(errors);
}

}  // namespace

CsvImportResult import_csv(std::string_view text, const std::string& source_name,
                           const CsvImportOptions& options) {
  CsvLayoutKind layout = options.layout;
  if (layout == CsvLayoutKind::Auto) {
    // The record layout starts with a record type or its header in column 1
    // (`#property,` as export writes it); a grid starts with a label or nothing.
    layout = starts_as_csv_records(text) ? CsvLayoutKind::Records : CsvLayoutKind::Grid;
  }
  if (layout == CsvLayoutKind::Records) {
    if (options.sheet_layout)
      throw LoadError({{source_name, "a layout description (cemv-sheet-layout/1) is for a C&E grid; the file is "
                                     "the record layout cemv-csv/1, which says where everything is"}});
    CsvImportResult result;
    result.layout = CsvLayoutKind::Records;
    result.matrix = import_csv_records(text, source_name);
    return result;
  }
  CsvImportResult result = grid::import_grid(text, source_name, options);
  if (options.strict && !result.warnings.empty()) throw strict_refusal(result.warnings);
  return result;
}

}  // namespace cemv::formats
