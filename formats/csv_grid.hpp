// The grid layout of real C&E spreadsheets (docs/csv.md "The grid layout"),
// shared by the files that read and write it; not part of the public interface
// of cemv_formats (that is formats/csv.hpp).
//
// Reading a grid takes three steps, each in its own file:
//  - csv_grid_shape.cpp: the sheet (padding and legend rows set apart), where
//    its header rows and label columns end, and whether the description row
//    lines up with the id row;
//  - csv_grid_orientation.cpp: which axis holds the causes, from evidence;
//  - csv_grid.cpp: the elements, with csv_grid_numbers.cpp for their numbers
//    and names and csv_grid_cells.cpp for the intersections.
#pragma once

#include <algorithm>
#include <cstddef>
#include <map>
#include <utility>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/csv.hpp"
#include "formats/csv_text.hpp"

namespace cemv::formats::grid {

// A grid cell's mark: a type letter (6.5.2), then footnote references `(n)`,
// blanks allowed around them ("R(1)", "N (1)(2)"). nullopt for anything else.
struct Mark {
  char letter;
  std::vector<std::string> footnotes;  // the numbers, as written
};
std::optional<Mark> parse_mark(std::string_view text);

// The number an id ends in (`TMA-D-40` -> 40), if any (at most 6 digits).
std::optional<int> trailing_number(std::string_view id);

// A field as the grid reads it: trimmed, control characters as blanks; "" past
// the end of the record.
std::string cell_text(const CsvRecord& row, std::size_t index);

// A cell that only names an axis, such as "Causes/Detection", "Effects" or
// "Final elements": words for causes or effects and nothing else.
bool corner_label_like(const std::string& text);

// The records of a grid file, with what surrounds the grid set apart.
struct Sheet {
  std::vector<CsvRecord> rows;    // leading empty columns removed from each
  std::vector<CsvRecord> legend;  // rows whose first cell is `(n)`
  std::size_t empty_rows_skipped = 0;     // above the grid
  std::size_t empty_columns_skipped = 0;  // left of the grid
  // The file column of a field index of `rows` (1-based).
  int column_of(std::size_t index) const {
    return static_cast<int>(index + 1 + empty_columns_skipped);
  }
};

// Splits the text (separator given, or detected from the first lines) and sets
// apart the padding and the legend rows. Throws LoadError.
Sheet read_sheet(std::string_view text, char separator, const std::string& source);

// Where the parts of the grid are, as indexes into Sheet::rows and field
// indexes. The header rows are the rows above first_data_row, the label columns
// the columns left of first_data_column; together they form the corner block,
// whose cells are never intersections.
struct Shape {
  std::size_t first_data_row = 0;
  std::size_t first_data_column = 0;
  std::size_t column_end = 0;  // one past the last column with an id or a description
  std::size_t description_row = 0;  // the first header row with text over the data columns
  std::size_t id_row = 0;           // the last one
  std::vector<std::size_t> extra_rows;  // header rows with text between or around them
  std::optional<std::size_t> description_column;  // the first label column with text in data rows
  std::optional<std::size_t> id_column;           // the last one
  std::vector<std::size_t> extra_columns;
};

// Finds the shape; refuses (LoadError naming the line) a sheet that is not a
// grid, and a description row that does not line up with its id row.
Shape find_shape(const Sheet& sheet, const std::string& source);

// The label of a header row or label column (its text in the corner block), e.g.
// "Tag"; empty when there is none.
std::string row_label(const Sheet& sheet, const Shape& shape, std::size_t row);
std::string column_label(const Sheet& sheet, const Shape& shape, std::size_t column);

// Which axis holds the causes, and the evidence in words ("from the corner
// labels ('Effects/Actuation' in line 1, column 2; ...)").
struct OrientationDecision {
  CsvOrientation orientation = CsvOrientation::CausesAsRows;
  std::string evidence;
  std::optional<LoadIssue> disagreement;  // evidence against an --orientation given
};

// Auto: decided from the corner labels and the id patterns; refused (LoadError
// naming the id row's line) when they are missing or disagree. Otherwise the
// requested orientation, with any evidence against it as a disagreement.
OrientationDecision decide_orientation(const Sheet& sheet, const Shape& shape,
                                       CsvOrientation requested, const std::string& source);

// One cause or effect as the sheet has it, then as numbered and named.
struct SheetElement {
  std::string sheet_id;       // as written, trimmed
  std::string text;           // description, trimmed
  int line = 0;
  int column = 0;             // of the id cell
  int id = 0;
  std::string name;
  std::string tag;
  std::string note;
  std::string unnamed;        // the name when the id is empty: CAUSE_LINE_<n>, EFFECT_COL_<c>
  std::string tag_from_sheet; // from a tag row or column
};


// The warnings of a grid import, handed out in file order (line, column).
class GridWarnings {
 public:
  explicit GridWarnings(std::string source) : source_(std::move(source)) {}
  // At "line L, column C" (the line alone when column is 0).
  void at(int line, int column, std::string what) {
    issues_.push_back({{line, column}, LoadIssue{csv_text::where_of(source_, line, column), std::move(what)}});
  }
  // At "line L, columns 3-12, 14".
  void at_columns(int line, const std::vector<int>& columns, std::string what) {
    issues_.push_back({{line, 0},
                       LoadIssue{csv_text::where_of(source_, line) + ", columns " + csv_text::number_ranges(columns),
                                 std::move(what)}});
  }
  void add(int line, LoadIssue issue) { issues_.push_back({{line, 0}, std::move(issue)}); }
  std::vector<LoadIssue> in_file_order() {
    std::stable_sort(issues_.begin(), issues_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<LoadIssue> out;
    for (auto& [order, issue] : issues_) out.push_back(std::move(issue));
    return out;
  }

 private:
  std::string source_;
  std::vector<std::pair<std::pair<int, int>, LoadIssue>> issues_;
};

// Numbers and names the elements of one kind (`cause`, prefix `C`, at most
// `limit`, 3.4): the number the sheet id ends in when every id has one, else
// the position; names and tags are the sanitized ids, made unique with _2, _3.
// A repeated id keeps both elements (the later one gets the next free number).
// Defects (duplicates, ids out of order) are reported through warn.
void number_elements(std::vector<SheetElement>& elements, const char* kind, const char* prefix,
                     int limit, GridWarnings& warnings);

// The elements of both axes, and which of them are the causes.
struct GridAxes {
  const std::vector<SheetElement>& rows;      // one per data row
  const std::vector<std::size_t>& sheet_rows;  // the Sheet::rows index of each
  const std::vector<SheetElement>& columns;    // one per data column
  bool causes_are_rows;
};

// One intersection per marked cell, its footnotes explained by the legend
// (`(1)` -> text) as its note. Stray values, lower-case marks, short rows,
// unexplained footnotes and a mix of empty and blank cells are warnings.
std::vector<model::Intersection> read_intersections(const Sheet& sheet, const Shape& shape,
                                                    const GridAxes& axes,
                                                    const std::map<std::string, std::string>& legend,
                                                    GridWarnings& warnings);

// Reads a grid: the three steps above. Throws LoadError.
CsvImportResult import_grid(std::string_view text, const std::string& source,
                            const CsvImportOptions& options);

}  // namespace cemv::formats::grid
