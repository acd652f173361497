// Spreadsheet import (6.6, bulk data engineering) and the grid export, docs/csv.md.
//
// Two layouts:
//  - the record layout `cemv-csv/1`: one RFC 4180 file, one record per row, the
//    first column naming the record type (property, sif_group, cause, cause_tag,
//    effect, effect_tag, intersection), each type with its own header row. It holds
//    every field of cemv-matrix/1, so export then import is lossless.
//  - the grid layout of real C&E spreadsheets (e.g. the LSST TMA interlock table):
//    a row of effect descriptions, a row of effect ids, then per cause its
//    description, its id and one cell per effect (N/S/V/R/X/* with optional
//    footnotes like `R(1)`). Imported as it is: defects become warnings with line
//    and column, and no safety parameter the grid does not state is invented.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

// The record layout's export and reading, which import_csv calls for it.
#include "formats/csv.hpp"
#include "formats/diagnostics.hpp"
#include "sheets/sheet_layout.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

// ---- The grid export ------------------------------------------------------------

// The matrix as a C&E grid (docs/csv.md "Grid export"): descriptions and sheet
// ids in the two header rows, one N/S/V/R/X/* cell per intersection, notes as
// footnotes with legend rows. Auto means causes as rows. Importing it gives back
// the same intersections; every other field stays out of a grid.
std::string export_csv_grid(const model::Matrix& m,
                            CsvOrientation orientation = CsvOrientation::CausesAsRows);

// ---- Import -------------------------------------------------------------------

enum class CsvLayoutKind { Auto, Records, Grid };

struct CsvImportOptions {
  CsvLayoutKind layout = CsvLayoutKind::Auto;
  char separator = 0;  // grid layout only; 0 = detect from the header rows
  // Grid layout only: the matrix name (6.1.2: at most 16 characters); empty =
  // the sanitized file stem.
  std::string matrix_name;
  CsvOrientation orientation = CsvOrientation::Auto;  // grid layout only
  bool strict = false;  // every warning is an error (LoadError), for CI
  // Grid layout only: what the sheet holds where (cemv-sheet-layout/1); its
  // orientation, when not auto, is the one read (an orientation above too
  // must be the same). Whatever it leaves out is found from the sheet.
  std::optional<SheetLayout> sheet_layout;
  // Grid layout only: the trip sides of the plant parameters (--params,
  // params_trip_sides), by cause sheet id or name.
  std::map<std::string, model::LimitType> parameter_trip_sides;
};

struct CsvImportResult {
  model::Matrix matrix;                    // already checked by parse_matrix
  std::vector<LoadIssue> warnings;  // in file order
  CsvLayoutKind layout = CsvLayoutKind::Records;
  // Grid layout: how the sheet was read, for the engineer to check at a glance
  // ("read 36 causes (rows 3-38, ids in column 2), ...; orientation ...").
  std::string summary;
  CsvOrientation orientation = CsvOrientation::CausesAsRows;  // grid layout only
  // Grid layout: the layout the sheet was read with, complete (the given one
  // with what was found from the sheet), to be saved and given again.
  SheetLayout layout_used;
};

// Reads either layout (Auto: the record layout when the first cell is one of its
// record types or headers, e.g. `#property`, else the grid). `source_name` names the input in messages, and
// for the grid gives the matrix its name and title (its file stem). Throws
// LoadError (line/column) when the text cannot be read as a matrix.
CsvImportResult import_csv(std::string_view text, const std::string& source_name,
                           const CsvImportOptions& options = {});

// The grid's identifier rule: letters, digits and `_` only, no leading, trailing
// or repeated `_` (6.1.4 chart-name rules, which also satisfy the element-name
// rule), at most max_length characters. `TMA-D-1` -> `TMA_D_1`. Empty when
// nothing is left.
std::string sanitize_identifier(std::string_view text, std::size_t max_length);

}  // namespace cemv::formats
