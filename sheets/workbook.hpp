// Workbooks (6.6, docs/workbook.md): the Safety Matrix's six tables (matrix
// properties, alarm profiles, causes configuration, intersections overview,
// effects configuration, legend) as an OpenDocument (`*.ods`) or Office Open
// XML (`*.xlsx`) spreadsheet, read and written losslessly; and a workbook
// holding a C&E grid on one of its sheets (the LSST table saved from a
// spreadsheet program, a contractor's SIS matrix among a cover, a history and
// remarks), read as import-csv reads the grid, with what the workbook adds:
// merged voting groups, struck-through deleted rows, a remarks sheet.
//
// Everything comes from outside: a workbook is read under the limits of
// docs/workbook.md "Limits" (file, inflated entries, cells, rows, text), every
// problem is a LoadError placed at FILE:SHEET:ROW:COLUMN.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/diagnostics.hpp"
#include "sheets/sheet_layout.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

enum class WorkbookFormat { Ods, Xlsx };

// From the file name's extension (.ods / .xlsx, any letter case); nullopt otherwise.
std::optional<WorkbookFormat> workbook_format_of(std::string_view file_name);

struct WorkbookImportResult {
  model::Matrix matrix;             // passed the JSON loader's checks (not validate's)
  std::vector<LoadIssue> warnings;  // in sheet order: rows not imported (6.6.3), ignored tag options, ...
  std::string summary;              // how the workbook was read
  // A C&E grid: the layout it was read with, complete (docs/csv.md "The
  // layout description"); none for the six tables.
  std::optional<SheetLayout> layout_used;
  bool grid = false;                // a C&E grid (which states only ids, descriptions and cells), not the six tables
};

// What the caller says of a workbook that holds a C&E grid (docs/workbook.md
// "Vendor C&E workbooks"): its sheet and its layout. Neither applies to the
// six tables.
struct WorkbookImportOptions {
  std::string sheet;                       // a name (any letter case) or a number 1-64; empty = the one with a grid
  std::optional<SheetLayout> sheet_layout; // its `sheet`, if any, is the sheet too
  CsvOrientation orientation = CsvOrientation::Auto;  // as CsvImportOptions (the layout's must agree)
  std::map<std::string, model::LimitType> parameter_trip_sides;  // as CsvImportOptions
};

// Reads a workbook from its bytes (no file system access). The format is told
// by the content (ODS: `mimetype`/`content.xml`, XLSX: the package parts), not
// the name; `file_name` names the input in messages and, for a grid, gives
// the matrix its name as for a CSV grid. Throws LoadError.
WorkbookImportResult import_workbook(std::string_view bytes, const std::string& file_name,
                                     const WorkbookImportOptions& options = {});

// import_workbook's matrix alone: the entry point of the fuzz target.
model::Matrix parse_workbook(std::string_view bytes, std::string_view file_name);

// The six tables of the matrix as a workbook file's bytes, deterministic (the
// same matrix gives the same bytes). Importing them gives back the same
// canonical JSON and signature.
std::string export_workbook(const model::Matrix& m, WorkbookFormat format);

}  // namespace cemv::formats
