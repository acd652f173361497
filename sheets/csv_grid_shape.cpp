// The shape of a C&E grid (docs/csv.md "Shape"): the padding around it, its
// header rows and label columns, and whether its description row lines up with
// its id row. Like the Safety Matrix's own import (6.6), a sheet that does not
// match is refused; nothing is guessed.
#include <algorithm>
#include <map>
#include <regex>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

bool corner_label_like(const std::string& text) {
  static const std::regex label(
      R"(^(\s|[/\\&,;:.\-x#]|and|or|of|the|list|ids?|no|numbers?|descriptions?|tags?|names?|causes?|detections?|initiators?|initiating|trips?|inputs?|effects?|actuations?|actions?|final|elements?|outputs?)+$)",
      std::regex::icase);
  static const std::regex word(
      R"((cause|detection|initiat|trip|input|effect|actuation|action|final|output))", std::regex::icase);
  return !text.empty() && std::regex_match(text, label) && std::regex_search(text, word);
}

namespace {

// The pattern of an id, its digit runs as '#' (TMA-D-40 -> TMA-D-#): only
// texts with letters and digits that are no mark.
std::optional<std::string> id_pattern(const std::string& t) {
  if (t.empty() || parse_mark(t)) return std::nullopt;
  std::string pattern;
  bool letter = false, digit = false;
  for (char ch : t) {
    if (ch >= '0' && ch <= '9') {
      if (pattern.empty() || pattern.back() != '#') pattern += '#';
      digit = true;
    } else {
      letter = letter || (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z');
      pattern += ch;
    }
  }
  if (!letter || !digit) return std::nullopt;
  return pattern;
}

// At least two cells, and more than half of the non-empty ones, are ids of one pattern.
bool ids_of_one_pattern(const std::vector<std::string>& cells) {
  std::map<std::string, int> patterns;
  int filled = 0, best = 0;
  for (const auto& t : cells) {
    if (t.empty()) continue;
    ++filled;
    if (auto p = id_pattern(t)) best = std::max(best, ++patterns[*p]);
  }
  return best >= 2 && 2 * best > filled;
}

// A row of headers: two or more attribute headers (Item, Tag No., Set point,
// ...), more than half of its texts, and no mark.
bool headers_only(const CsvRecord& row) {
  int headers = 0, texts = 0;
  for (std::size_t i = 0; i < row.fields.size(); ++i) {
    const std::string t = cell_text(row, i);
    if (t.empty()) continue;
    if (parse_mark(t)) return false;
    ++texts;
    headers += attribute_of_header(t) ? 1 : 0;
  }
  return headers >= 2 && 2 * headers > texts;
}

struct Cells {
  int marks = 0;
  int other = 0;
  int non_blank() const { return marks + other; }
};

Cells count(const std::string& t, Cells c) {
  if (t.empty()) return c;
  if (parse_mark(t)) ++c.marks;
  else ++c.other;
  return c;
}

// Row and column tests against the current boundaries (r0, c0).
class ShapeFinder {
 public:
  explicit ShapeFinder(const Sheet& sheet) : rows_(sheet.rows) {
    for (const auto& r : rows_) width_ = std::max(width_, r.fields.size());
  }

  std::size_t width() const { return width_; }

  Cells row_cells(std::size_t r, std::size_t from_column) const {
    Cells c;
    for (std::size_t i = from_column; i < rows_[r].fields.size(); ++i) c = count(cell_text(rows_[r], i), c);
    return c;
  }
  Cells column_cells(std::size_t col, std::size_t from_row, std::size_t c0) const {
    Cells c;
    for (std::size_t r = from_row; r < rows_.size(); ++r)
      if (!cached_label_row(r, c0)) c = count(cell_text(rows_[r], col), c);
    return c;
  }
  // label_row, remembered per c0: column scans ask it for every row, and a
  // hostile sheet may have thousands of rows and columns.
  bool cached_label_row(std::size_t r, std::size_t c0) const {
    if (cache_c0_ != c0) {
      label_rows_.assign(rows_.size(), -1);
      cache_c0_ = c0;
    }
    if (label_rows_[r] < 0) label_rows_[r] = label_row(r, c0) ? 1 : 0;
    return label_rows_[r] == 1;
  }
  // A row or column of the corner block that reaches into the data: axis labels
  // (left of, or above, the data) and at most one mark-like token besides,
  // such as a lone `N` in the corner; or a band: one label over the data
  // columns and nothing else there (`EFFECTS` merged over the effects).
  bool label_row(std::size_t r, std::size_t c0) const {
    int labels = 0, other = 0, band = 0, over = 0;
    for (std::size_t i = 0; i < rows_[r].fields.size(); ++i) {
      const std::string t = cell_text(rows_[r], i);
      if (i >= c0 && !t.empty()) {
        ++over;
        band += corner_label_like(t) ? 1 : 0;
      }
      if (i < c0 && corner_label_like(t)) ++labels;
      else if (!t.empty()) other += parse_mark(t) ? 1 : 2;
    }
    if (band == 1 && over == 1) return true;
    return labels > 0 && other <= 1;
  }
  bool label_column(std::size_t col, std::size_t r0) const {
    int labels = 0, other = 0, band = 0, beside = 0;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      const std::string t = cell_text(rows_[r], col);
      if (r >= r0 && !t.empty()) {
        ++beside;
        band += corner_label_like(t) ? 1 : 0;
      }
      if (r < r0 && corner_label_like(t)) ++labels;
      else if (!t.empty()) other += parse_mark(t) ? 1 : 2;
    }
    if (band == 1 && beside == 1) return true;  // `EFFECTS` merged beside the effect rows
    return labels > 0 && other <= 1;
  }

  // A row (from column c0 on) or a column (from row r0 on, label rows left
  // out) of ids sharing one pattern, such as TMA-D-<n>: a header, never data,
  // even with a lone mark among the ids (the corner `N` of the LSST table as
  // first published).
  bool id_row(std::size_t r, std::size_t c0) const {
    std::vector<std::string> cells;
    for (std::size_t i = c0; i < rows_[r].fields.size(); ++i) cells.push_back(cell_text(rows_[r], i));
    return ids_of_one_pattern(cells);
  }
  bool id_column(std::size_t col, std::size_t r0, std::size_t c0) const {
    std::vector<std::string> cells;
    for (std::size_t r = r0; r < rows_.size(); ++r)
      if (!cached_label_row(r, c0)) cells.push_back(cell_text(rows_[r], col));
    return ids_of_one_pattern(cells);
  }
  // Column col is part of the corner block: a corner label stands in it on a
  // header row that also holds descriptions or ids (LSST: 'Causes/Detection'
  // over the effect ids of the table as first published). A label on a row of
  // labels only (an `EFFECTS` band over the effect columns) says nothing of it.
  bool labelled_in_header(std::size_t col, std::size_t r0, std::size_t c0) const {
    for (std::size_t r = 0; r < r0 && r < rows_.size(); ++r)
      if (corner_label_like(cell_text(rows_[r], col)) && !label_row(r, c0)) return true;
    return false;
  }

  enum class Round { NoGrid, Moved, Settled };

  // One round: the header rows from the current label columns (the last row with
  // text over the data columns above the first row of marks is the id row), then
  // the label columns from those rows in the same way.
  Round settle(std::size_t& r0, std::size_t& c0) const {
    const std::size_t old_r0 = r0, old_c0 = c0;
    std::optional<std::size_t> marked_row;
    for (std::size_t r = 1; r < rows_.size() && !marked_row; ++r)
      if (row_cells(r, c0).marks > 0 && !label_row(r, c0) && !id_row(r, c0)) marked_row = r;
    if (!marked_row) return Round::NoGrid;
    // The rows below the label columns' headers (Item | Description | Tag No.)
    // are data, marked or not: the id row is that row or above it.
    std::size_t id_end = *marked_row;
    for (std::size_t r = 0; r < *marked_row; ++r)
      if (headers_only(rows_[r])) {
        id_end = r + 1;
        break;
      }
    std::optional<std::size_t> id_row;
    for (std::size_t r = 0; r < id_end; ++r)
      if (row_cells(r, c0).non_blank() > 0 && !label_row(r, c0)) id_row = r;
    if (!id_row) return Round::NoGrid;
    r0 = *id_row + 1;
    // Below the id row: bands, empty rows, and the headers of the label
    // columns when they have a row of their own (Item | Description | Tag No.).
    while (r0 < rows_.size() && (label_row(r0, c0) || blank_record(rows_[r0]) || headers_only(rows_[r0]))) ++r0;

    std::optional<std::size_t> marked_column;
    for (std::size_t col = 1; col < width_ && !marked_column; ++col)
      if (column_cells(col, r0, c0).marks > 0 && !label_column(col, r0) && !id_column(col, r0, c0))
        marked_column = col;
    if (!marked_column) return Round::NoGrid;
    // Left of the first marked column, a column with an id in the id row is still
    // an element (one never marked, or holding only stray values), unless it is
    // a column of the corner block: one of ids, one with a corner label in the
    // header, or one headed by an attribute (Tag, Setpoint, Voting, SIL, ...).
    c0 = *marked_column;
    while (c0 > 1) {
      const std::string id = cell_text(rows_[*id_row], c0 - 1);
      if (id.empty() || corner_label_like(id) || attribute_of_header(id)) break;
      if (id_column(c0 - 1, r0, c0) || labelled_in_header(c0 - 1, r0, c0)) break;
      --c0;
    }
    while (c0 < width_ && label_column(c0, r0)) ++c0;
    return r0 != old_r0 || c0 != old_c0 ? Round::Moved : Round::Settled;
  }

 private:
  const std::vector<CsvRecord>& rows_;
  std::size_t width_ = 0;
  mutable std::vector<signed char> label_rows_;
  mutable std::size_t cache_c0_ = static_cast<std::size_t>(-1);
};

// The description row and the id row must cover the same columns: a row one
// field short (its leading empty field lost) or one field long puts every
// description over the wrong id.
void check_alignment(const Sheet& sheet, const Shape& shape, const std::string& source) {
  if (shape.description_row == shape.id_row) return;
  const CsvRecord& d = sheet.rows[shape.description_row];
  const CsvRecord& ids = sheet.rows[shape.id_row];
  auto end_of_text = [](const CsvRecord& r) {
    std::size_t end = 0;
    for (std::size_t i = 0; i < r.fields.size(); ++i)
      if (!cell_text(r, i).empty()) end = i + 1;
    return end;
  };
  const std::size_t d_end = end_of_text(d), id_end = end_of_text(ids);
  if (d_end == id_end || d.fields.size() == ids.fields.size()) return;
  // What the first data column would read: its id under someone else's description.
  std::string example;
  const std::size_t c0 = shape.first_data_column;
  if (!cell_text(ids, c0).empty() && !cell_text(d, c0).empty())
    example = " (column " + std::to_string(sheet.column_of(c0)) + ": id " +
              model::in_quotes(cell_text(ids, c0)) + " under " + model::in_quotes(cell_text(d, c0)) + ")";
  auto fields = [&](const CsvRecord& r) {
    return std::to_string(r.fields.size() + sheet.empty_columns_skipped) + " fields";
  };
  throw LoadError({{where_of(source, d.line),
                    "the description row (line " + std::to_string(d.line) + ", " + fields(d) +
                        ", text up to column " + std::to_string(sheet.column_of(d_end - 1)) +
                        ") and the id row (line " + std::to_string(ids.line) + ", " + fields(ids) +
                        ", ids up to column " + std::to_string(sheet.column_of(id_end - 1)) +
                        ") do not cover the same columns: the descriptions would be misaligned "
                        "with their ids and cells" + example +
                        "; give both rows the same leading and trailing fields (docs/csv.md "
                        "\"Header alignment\")"}});
}

}  // namespace

namespace {

// The boundaries the layout's places fix: the first data column right of the
// last place of the elements on the rows, the first data row below the last
// place of those on the columns.
struct Fixed {
  std::optional<std::size_t> r0, c0;
};
Fixed fixed_by(const Sheet& sheet, const SheetLayout& layout, const std::string& source) {
  Fixed f;
  const bool causes_as_rows = layout.orientation != CsvOrientation::EffectsAsRows;
  const auto& columns = causes_as_rows ? layout.causes : layout.effects;
  const auto& rows = causes_as_rows ? layout.effects : layout.causes;
  int last_column = 0, last_line = 0;
  for (const auto& p : columns) last_column = std::max(last_column, p.position);
  for (const auto& p : rows) last_line = std::max(last_line, p.position);
  if (last_column > static_cast<int>(sheet.empty_columns_skipped))
    f.c0 = static_cast<std::size_t>(last_column) - sheet.empty_columns_skipped;
  if (last_line > 0) {
    const auto r = sheet.row_at(last_line);
    if (!r)
      throw LoadError({{where_of(source, last_line), "the layout places a header in row " + std::to_string(last_line) +
                                                         ", which is no row of the grid (empty, or a legend row)"}});
    f.r0 = *r + 1;
    // Below the header rows given, the row of the label columns' headers
    // (Item | Description | Tag No. | ...) when the layout gives no place of
    // theirs: headers only, never an element.
    if (columns.empty() && *f.r0 < sheet.rows.size() && headers_only(sheet.rows[*f.r0])) ++*f.r0;
  }
  return f;
}

}  // namespace

bool has_grid_shape(const Sheet& sheet) {
  if (sheet.rows.size() < 2) return false;
  ShapeFinder finder(sheet);
  std::size_t r0 = 1, c0 = finder.width() >= 3 ? 2 : 1;
  auto round = ShapeFinder::Round::Moved;
  for (int k = 0; k < 6 && round == ShapeFinder::Round::Moved; ++k) round = finder.settle(r0, c0);
  if (round == ShapeFinder::Round::NoGrid || r0 >= sheet.rows.size()) return false;
  for (std::size_t r = 0; r < r0; ++r)
    if (finder.row_cells(r, c0).non_blank() > 0 && !finder.label_row(r, c0)) return true;
  return false;
}

Shape find_shape(const Sheet& sheet, const std::string& source, const SheetLayout& layout) {
  const auto& rows = sheet.rows;
  auto refuse = [&](int line, const std::string& what) {
    throw LoadError({{where_of(source, line), "not a C&E grid: " + what + " (docs/csv.md)"}});
  };
  if (rows.size() < 2)
    refuse(rows.empty() ? 1 : rows.back().line,
           "expected header rows (descriptions, ids) above rows of marks N, S, V, R, X or *");
  ShapeFinder finder(sheet);
  const Fixed fixed = fixed_by(sheet, layout, source);
  std::size_t r0 = fixed.r0.value_or(1), c0 = fixed.c0.value_or(finder.width() >= 3 ? 2 : 1);
  auto round = ShapeFinder::Round::Moved;
  for (int k = 0; k < 6 && round == ShapeFinder::Round::Moved && !(fixed.r0 && fixed.c0); ++k) {
    round = finder.settle(r0, c0);
    if (fixed.r0) r0 = *fixed.r0;
    if (fixed.c0) c0 = *fixed.c0;
  }
  const bool found = round != ShapeFinder::Round::NoGrid;
  Shape shape;
  shape.first_data_row = r0;
  shape.first_data_column = c0;
  shape.given = !layout.causes.empty() || !layout.effects.empty();
  for (std::size_t r = 0; r < r0 && r < rows.size(); ++r)
    if (finder.row_cells(r, c0).non_blank() > 0 && !finder.label_row(r, c0)) shape.header_rows.push_back(r);
  if (!found || shape.header_rows.empty() || r0 >= rows.size())
    refuse(rows.back().line,
           !shape.header_rows.empty() ? "no rows of marks N, S, V, R, X or * below the header rows"
                                      : "no header row of ids above rows of marks N, S, V, R, X or *");
  for (std::size_t col = 0; col < c0; ++col)
    if (finder.column_cells(col, r0, c0).non_blank() > 0 && !finder.label_column(col, r0))
      shape.label_columns.push_back(col);
  assign_slots(sheet, shape, layout, source);
  std::size_t end = 0;
  for (std::size_t r : {shape.description_row, shape.id_row})
    for (std::size_t i = c0; i < rows[r].fields.size(); ++i)
      if (!cell_text(rows[r], i).empty()) end = i + 1;
  shape.column_end = end;
  check_alignment(sheet, shape, source);
  return shape;
}

std::optional<int> trailing_number(std::string_view s) {
  std::size_t i = s.size();
  while (i > 0 && s[i - 1] >= '0' && s[i - 1] <= '9') --i;
  if (i == s.size() || s.size() - i > 6) return std::nullopt;
  return std::stoi(std::string(s.substr(i)));
}

std::optional<Mark> parse_mark(std::string_view t) {
  if (t.empty() || std::string_view("NSVRXnsvrx*").find(t[0]) == std::string_view::npos)
    return std::nullopt;
  Mark mark{t[0], {}};
  std::size_t i = 1;
  auto skip_blanks = [&] {
    while (i < t.size() && (t[i] == ' ' || t[i] == '\t')) ++i;
  };
  skip_blanks();
  while (i < t.size()) {
    if (t[i] == '*' && mark.letter != '*') {  // S*, N**: a star footnote (not after the note mark itself)
      std::size_t start = i;
      while (i < t.size() && t[i] == '*') ++i;
      if (i - start > 3) return std::nullopt;
      mark.footnotes.emplace_back(t.substr(start, i - start));
      skip_blanks();
      continue;
    }
    if (t[i] != '(') return std::nullopt;
    ++i;
    skip_blanks();
    std::size_t start = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    if (i == start) return std::nullopt;
    std::string key = "(" + std::string(t.substr(start, i - start)) + ")";
    skip_blanks();
    if (i >= t.size() || t[i] != ')') return std::nullopt;
    ++i;
    skip_blanks();
    mark.footnotes.push_back(std::move(key));
  }
  return mark;
}

}  // namespace cemv::formats::grid
