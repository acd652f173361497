// The layout description of a C&E sheet, `cemv-sheet-layout/1` (docs/csv.md
// "The layout description"): what the grid importer cannot know for sure from
// a vendor's sheet. Which sheet of a workbook holds the matrix, which axis the
// causes are on, which columns (rows) hold the attributes of the elements
// (id, description, tag, setpoint, unit, voting, SIL, action), what each mark
// means, the footnotes' texts, which side of a setpoint trips, and how deleted
// rows are shown. Every part may be left out and is then found from the sheet;
// the import returns the layout it used, complete, so that it can be saved and
// given again for the next revision of the same sheet.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::formats {

inline constexpr const char* kSheetLayoutFormat = "cemv-sheet-layout/1";

// Which axis of a grid holds the causes (docs/csv.md "Orientation"). Auto
// decides from the evidence of the sheet, and refuses when it is missing or
// disagrees.
enum class CsvOrientation { Auto, CausesAsRows, EffectsAsRows };

// What a label column holds for the row elements, or a header row for the
// column elements. Causes take Id to TripSide and Note; effects Id,
// Description, Tag, Sil, Action and Note.
enum class SheetAttribute { Id, Description, Tag, Setpoint, Unit, Voting, Sil, TripSide, Action, Note };

// Where one attribute is: a 1-based column of the sheet (A = 1) for the
// elements on the rows, a 1-based row for the elements on the columns.
struct AttributePlace {
  SheetAttribute attribute = SheetAttribute::Id;
  int position = 0;
};

// What a mark in a grid cell means: an intersection type (6.5.2) with an
// optional footnote (`S*`: S, footnote `*`), or no intersection (`NP`).
struct MarkMeaning {
  std::optional<model::IntersectionType> type;  // nullopt: no intersection
  std::string footnote;                         // `*`, `(1)`; empty: none
};

// How the sheet shows a deleted row (or column): struck through (workbooks
// only: a CSV has no formatting), or a word in one of its label cells.
struct DeletedRule {
  bool strikethrough = true;
  std::vector<std::string> words{"DELETED"};  // whole words, any letter case
};

struct SheetLayout {
  std::string sheet;  // workbooks: the name of the matrix sheet; empty = the one sheet with a grid
  CsvOrientation orientation = CsvOrientation::Auto;
  // The places of the attributes; empty = found from the headers of the sheet.
  // Given, they need the orientation, and the elements start right after the
  // last place (the first data column after the last cause column, ...).
  std::vector<AttributePlace> causes;
  std::vector<AttributePlace> effects;
  std::map<std::string, MarkMeaning> marks;       // beyond N, S, V, R, X, * and their footnote forms
  std::map<std::string, std::string> footnotes;   // `*` or `(1)` -> text
  std::string remarks_sheet;                      // workbooks: a sheet of `KEY | text` footnote rows
  std::map<std::string, model::LimitType> trip_sides;  // cause sheet id -> the side its setpoint trips on
  DeletedRule deleted;
};

// Reads a layout description (guarded JSON, every problem placed at
// FILE:LINE:COL with its JSON path). Throws LoadError.
SheetLayout parse_sheet_layout(std::string_view json_text, const std::string& source_name);

// The layout as JSON, keys in a fixed order: indented for a file, or on one
// line for the import summary. Deterministic.
std::string sheet_layout_json(const SheetLayout& layout, bool one_line = false);

// The names used in the layout and in messages.
const char* to_string(SheetAttribute attribute);
const char* to_string(CsvOrientation orientation);  // "auto", "causes-as-rows", "effects-as-rows"
// A column as spreadsheets name it (1 -> "A", 28 -> "AB").
std::string column_letters(int column);

}  // namespace cemv::formats
