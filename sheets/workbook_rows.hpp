// The row-import rule of 6.6.3, internal to formats/: a table's elements are
// the rows (or, in the intersections overview, the columns) whose number cell
// holds a number, read from the first one down to the first empty number
// cell; what follows an empty number cell is not imported, and at most 128
// elements are (3.4). Both are warnings naming the cells left out: the manual
// drops them silently, cemv says so.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "formats/diagnostics.hpp"
#include "sheets/workbook_sheet.hpp"

namespace cemv::formats::workbook {

// Where an issue of a workbook is: FILE:SHEET:ROW:COLUMN with the cell's A1
// address (and the column's header, when it has one) in front of the message,
// e.g. `m.ods:Causes configuration:5:24: error: X5 (Time (ms)): 'abc' is not a
// whole number`.
LoadIssue place(const std::string& file, const Sheet& sheet, std::size_t row, std::size_t column,
                const std::string& header, std::string what);

struct NumberedLine {
  std::size_t line = 0;   // the row (or column) in the sheet
  int number = 0;         // the cause or effect number in its cell
};

// Reads the numbers along one line of a sheet: down column `fixed` from row
// `first` (rows = true), or along row `fixed` from column `first`. Numbers must
// be whole numbers 1-128 (errors otherwise). Returns the lines in sheet order,
// at most `limit` (128, 6.6.3; later ones are a warning).
// `kind` names the elements in messages ("cause").
std::vector<NumberedLine> numbered_lines(const Sheet& sheet, bool rows, std::size_t fixed, std::size_t first,
                                         const std::string& kind, const std::string& header, const std::string& file,
                                         std::vector<LoadIssue>& errors, std::vector<LoadIssue>& warnings,
                                         std::size_t limit = 128);

// A whole number in [min, max] from a cell text; nullopt-like false when not.
bool whole_number(const std::string& text, long long min, long long max, long long& out);

}  // namespace cemv::formats::workbook
