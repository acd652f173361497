// The grid layout of real C&E spreadsheets (docs/csv.md "The grid layout"),
// shared by the files that read and write it; not part of the public interface
// of cemv_sheets (that is sheets/csv.hpp).
//
// Reading a grid takes these steps, each in its own file:
//  - csv_grid_sheet.cpp: the sheet, its records with the padding and legend
//    rows set apart;
//  - csv_grid_shape.cpp: where its header rows and label columns end, and
//    whether the description row lines up with the id row;
//  - csv_grid_attributes.cpp: what each label column and header row holds
//    (id, description, tag, setpoint, ...), from the layout or the headers
//    (their words in csv_grid_header_words.cpp), with csv_grid_headers.cpp
//    reading them from their values (a stacked effect header: description,
//    action, tag, SIL in any order);
//  - csv_grid_orientation.cpp: which axis holds the causes, from evidence;
//  - csv_grid_elements.cpp: the elements of each axis, voting groups and
//    deleted rows, with csv_grid_values.cpp for the values of their
//    attributes and csv_grid_numbers.cpp for their numbers and names;
//  - csv_grid_cells.cpp: the intersections;
//  - csv_grid.cpp: the matrix, the summary and the layout used.
#pragma once

#include <algorithm>
#include <cstddef>
#include <map>
#include <set>
#include <utility>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sheets/csv.hpp"
#include "formats/csv_text.hpp"

namespace cemv::formats::grid {

// A grid cell's mark: a type letter (6.5.2), then footnote references `(n)`
// or a star `*` (`**`, `***`), blanks allowed around them ("R(1)", "N (1)(2)",
// "S*"). nullopt for anything else.
struct Mark {
  char letter;
  std::vector<std::string> footnotes;  // as keys: "(1)", "*"
};
std::optional<Mark> parse_mark(std::string_view text);

// What a header says it holds: an attribute and, when it names one, the kind
// of element ("Cause description", "Output tag"). nullopt for anything else,
// corner labels ("Causes/Detection") included.
enum class ElementKind { Unknown, Cause, Effect };
struct HeaderMeaning {
  SheetAttribute attribute;
  ElementKind kind = ElementKind::Unknown;
};
std::optional<HeaderMeaning> attribute_of_header(const std::string& text);

// A merged range of a workbook's sheet, in file lines and columns (1-based,
// inclusive).
struct Range {
  int first_line = 0, first_column = 0, last_line = 0, last_column = 0;
};

// What a workbook says of its cells besides their texts (a CSV says nothing):
// struck-through cells and merged ranges (those whose first cell holds text),
// at file lines and columns, and the footnotes of its remarks sheet.
struct SheetExtras {
  std::set<std::pair<int, int>> struck;         // the whole text
  std::set<std::pair<int, int>> partly_struck;  // a part of it
  std::map<std::pair<int, int>, Range> merges;  // by first cell
  std::map<std::string, std::string> remarks;   // footnote key -> text
  std::string remarks_place;                    // "sheet 'Remarks'", for messages
};

// The number an id ends in (`TMA-D-40` -> 40), if any (at most 6 digits).
std::optional<int> trailing_number(std::string_view id);

// A field as the grid reads it: trimmed, control characters as blanks; "" past
// the end of the record.
std::string cell_text(const CsvRecord& row, std::size_t index);

// A record with nothing but blanks in its fields.
bool blank_record(const CsvRecord& r);

// A cell that only names an axis, such as "Causes/Detection", "Effects" or
// "Final elements": words for causes or effects and nothing else.
bool corner_label_like(const std::string& text);

// The records of a grid file, with what surrounds the grid set apart.
struct Sheet {
  std::vector<CsvRecord> rows;    // leading empty columns removed from each
  std::vector<CsvRecord> legend;  // rows whose first cell is `(n)` or `*`
  std::size_t empty_rows_skipped = 0;     // above the grid
  std::size_t empty_columns_skipped = 0;  // left of the grid
  SheetExtras extras;                     // a workbook's formats
  // The file column of a field index of `rows` (1-based).
  int column_of(std::size_t index) const {
    return static_cast<int>(index + 1 + empty_columns_skipped);
  }
  // The index of `rows` at a file line, or nullopt (padding, legend).
  std::optional<std::size_t> row_at(int line) const;
};

// Splits the text (separator given, or detected from the first lines) and sets
// apart the padding and the legend rows. Throws LoadError.
Sheet read_sheet(std::string_view text, char separator, const std::string& source);

// One attribute of the elements of an axis: a label column (the attributes of
// the elements on the rows) or a header row (of those on the columns).
struct Slot {
  SheetAttribute attribute = SheetAttribute::Note;
  std::size_t index = 0;   // field index (a label column) or Sheet::rows index (a header row)
  std::string label;       // its header, e.g. "Set point"; empty when it has none
  bool by_header = false;  // recognised from its header (or given by the layout), not by position
  std::string evidence;    // why, for the summary: "its label and tag-shaped values 'XV-301', ..."
};

// What the values of a header row (label column) are (csv_grid_headers.cpp):
// output tags (letters, a separator, digits: `XV-301`), SIL levels (`SIL 2`),
// action verbs (`CLOSE`, `DE-ENERGISE`), numbers 0-4 only, numbers or ids,
// or free text.
enum class HeaderContent { Tags, Sil, Actions, SmallNumbers, Ids, Text };
bool tag_shaped(std::string_view text);
bool action_word(std::string_view text);  // the verbs of docs/csv.md "Stacked effect header"

// A header row (label column) without a place given by the layout.
struct HeaderCandidate {
  std::size_t index = 0;             // as Slot::index
  std::string label;                 // row_label / column_header
  std::vector<std::string> values;   // its cells over the data columns (in the data rows)
  std::string name;                  // "header row 4", "label column 3"
  std::string place;                 // LoadIssue::where of its first value
};
// The slots of one axis, each from its label and its values: a label that
// agrees is evidence, one against the values is refused; tag, SIL and action
// rows by their values; the id row by a label, numbers or ids, else the tags;
// free text the description (then notes). Two rows that could each be the tag
// (SIL, id) row, or a stacked header without tags or ids, are refused naming
// the candidates (LoadError). header_rows: the candidates are header rows.
std::vector<Slot> classify_headers(const std::vector<HeaderCandidate>& candidates, bool header_rows);

// Where the parts of the grid are, as indexes into Sheet::rows and field
// indexes. The header rows are the rows above first_data_row, the label columns
// the columns left of first_data_column; together they form the corner block,
// whose cells are never intersections.
struct Shape {
  std::size_t first_data_row = 0;
  std::size_t first_data_column = 0;
  std::size_t column_end = 0;  // one past the last column with an id or a description
  std::vector<std::size_t> header_rows;    // with text over the data columns, in order
  std::vector<std::size_t> label_columns;  // with text in the data rows, in order
  std::vector<Slot> row_slots;     // the label columns: attributes of the elements on the rows
  std::vector<Slot> column_slots;  // the header rows: attributes of the elements on the columns
  bool given = false;              // the places come from the layout
  // From the slots: the id row and column, the description row (the id row when none).
  std::size_t description_row = 0;
  std::size_t id_row = 0;
  std::optional<std::size_t> id_column;
  const Slot* row_slot(SheetAttribute a) const;
  const Slot* column_slot(SheetAttribute a) const;
};

// Whether the sheet has the shape of a grid (header rows of ids above rows of
// marks), without reading it: how a workbook's matrix sheet is found.
bool has_grid_shape(const Sheet& sheet);

// Finds the shape (the places the layout gives, if any, else from the sheet)
// and what each label column and header row holds; refuses (LoadError naming
// the line) a sheet that is not a grid, and a description row that does not
// line up with its id row.
Shape find_shape(const Sheet& sheet, const std::string& source, const SheetLayout& layout);

// The attributes of the label columns and header rows (csv_grid_attributes.cpp):
// the layout's places, else each read from its header and its values
// (classify_headers). Refuses (LoadError) a layout place outside the corner
// block, and what classify_headers refuses.
void assign_slots(const Sheet& sheet, Shape& shape, const SheetLayout& layout, const std::string& source);

// The header of a label column: its cell in the last row of the corner block
// that heads two or more label columns (vendor sheets: Item | Description |
// Tag | ...); empty when none.
std::string column_header(const Sheet& sheet, const Shape& shape, std::size_t column);
// The label of a header row: its one text left of the data columns (a row
// with several is the row of column headers, and has none); empty when none.
std::string row_label(const Sheet& sheet, const Shape& shape, std::size_t row);

// Which axis holds the causes, and the evidence in words ("from the corner
// labels ('Effects/Actuation' in line 1, column 2; ...)").
struct OrientationDecision {
  CsvOrientation orientation = CsvOrientation::CausesAsRows;
  std::string evidence;
  std::optional<LoadIssue> disagreement;  // evidence against an --orientation given
};

// Auto: decided from the corner labels and the id patterns; refused (LoadError
// naming the id row's line) when they are missing or disagree. Otherwise the
// requested orientation, with any evidence against it as a disagreement;
// corner labels or attribute headers that all say the other are a refusal,
// but for corner labels when `over_labels` (a layout's orientation: it says
// what the sheet cannot, and wins over its labels with a warning).
// `given_by` names where a requested orientation comes from in messages
// ("--orientation", "the layout's orientation").
OrientationDecision decide_orientation(const Sheet& sheet, const Shape& shape,
                                       CsvOrientation requested, const std::string& source,
                                       const std::string& given_by = "--orientation", bool over_labels = false);

// One cause or effect as the sheet has it, then as numbered and named.
struct SheetElement {
  std::string sheet_id;       // as written, trimmed
  std::string text;           // description, trimmed
  int line = 0;
  int column = 0;             // of the id cell
  int id = 0;
  std::string name;
  std::vector<std::string> tags;  // from tag cells; named after the element when none
  std::string note;
  std::string unnamed;        // the name when the id is empty: CAUSE_LINE_<n>, EFFECT_COL_<c>
  int sil = 0;
  std::optional<model::CauseFunction> function;  // from the voting
  std::optional<model::AnalogParams> analog;      // from setpoint, unit and trip side
  int first_line = 0, last_line = 0;  // the rows (columns) it spans: a voting group has several
};


// The warnings (or the errors) of a grid import, handed out in file order
// (line, column).
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
  bool empty() const { return issues_.empty(); }
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
// What cannot be read right: every one is reported, then the import is refused.
using GridErrors = GridWarnings;

// Numbers and names the elements of one kind (`cause`, prefix `C`, at most
// `limit`, 3.4): the number the sheet id ends in when every id has one, else
// the position; names and tags are the sanitized ids, made unique with _2, _3.
// A repeated id keeps both elements (the later one gets the next free number).
// Defects (duplicates, ids out of order) are reported through warn.
void number_elements(std::vector<SheetElement>& elements, const char* kind, const char* prefix,
                     int limit, GridWarnings& warnings);

// The elements of one axis as csv_grid_elements.cpp reads them: which element
// each data row (or column) belongs to, and what the summary says of them.
inline constexpr int kDeletedLine = -1;
struct AxisElements {
  std::vector<SheetElement> elements;
  std::map<std::size_t, int> element_of;  // Sheet::rows index (field index) -> element, or kDeletedLine
  std::vector<std::string> deleted;       // "row 15 ('4', 'Feed pump ...', struck through)"
  std::vector<std::string> groups;        // "rows 10-12 (2oo3)"
  int analog = 0;                         // setpoints read as analog limits
};

// The things an axis is read with: its kind, the layout (trip sides, deleted
// rule), where to report.
struct AxisContext {
  ElementKind kind;
  const SheetLayout& layout;
  const std::string& source;
  GridWarnings& warnings;
  GridErrors& errors;
  // The trip sides the plant parameters give (`causes.ID.analog.limit_type`,
  // by sheet id or cause name): one more source that must agree.
  const std::map<std::string, model::LimitType>& parameter_trip_sides;
};
// The elements on the rows (every row below the header with text) and on the
// columns (every column up to column_end): their attributes, voting groups
// (rows merged, or without id and description under a voting), deleted rows.
AxisElements read_row_elements(const Sheet& sheet, const Shape& shape, AxisContext context);
AxisElements read_column_elements(const Sheet& sheet, const Shape& shape, AxisContext context);

// The marks a grid may hold: N, S, V, R, X and * with footnotes (`R(1)`,
// `S*`), lower case with a warning, and those the layout gives a meaning.
class MarkTable {
 public:
  explicit MarkTable(const std::map<std::string, MarkMeaning>& layout_marks) : layout_(layout_marks) {}
  struct Reading {
    bool known = false;                            // false: a mark nobody gave a meaning
    std::optional<model::IntersectionType> type;   // nullopt: no intersection (NP)
    std::vector<std::string> footnotes;
    bool lower_case = false;
  };
  Reading read(const std::string& text) const;
  bool is_mark(const std::string& text) const { return read(text).known; }

 private:
  const std::map<std::string, MarkMeaning>& layout_;
};

// The elements of both axes, which of them are the causes, and which element
// each data row and column belongs to.
struct GridAxes {
  const AxisElements& rows;
  const AxisElements& columns;
  bool causes_are_rows;
};

// One intersection per marked cell, its footnotes explained by the legend
// (`(1)` -> text) as its note; a voting group's rows give one intersection.
// Lower-case marks, short rows, unexplained footnotes, text right of the grid
// and a mix of empty and blank cells are warnings; a mark without a meaning, a
// group's rows marked differently and a struck-through mark of an element
// that is not deleted are errors.
std::vector<model::Intersection> read_intersections(const Sheet& sheet, const Shape& shape,
                                                    const GridAxes& axes, const MarkTable& marks,
                                                    const std::map<std::string, std::string>& legend,
                                                    GridWarnings& warnings, GridErrors& errors);

// Reads a grid: the steps above. `extras` are a workbook's formats and
// remarks (none for a CSV). Throws LoadError.
CsvImportResult import_grid(std::string_view text, const std::string& source,
                            const CsvImportOptions& options, const SheetExtras& extras = {});

}  // namespace cemv::formats::grid
