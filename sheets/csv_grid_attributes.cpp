// What each label column and header row of a C&E grid holds (docs/csv.md
// "Attributes"): given by the layout, or read from its header (its words in
// csv_grid_header_words.cpp) and its values (csv_grid_headers.cpp). An
// attribute column is never read as an element.
#include <algorithm>
#include <map>
#include <optional>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

namespace {

// Candidates of one axis in order, completed by position: the last unread one
// is the id, the first the description, the others notes (a plain grid's
// rule); with no unread one, the tag (or the description) serves as the id.
std::vector<Slot> complete(std::vector<Slot> read, const std::vector<Slot>& unread) {
  auto has = [&](SheetAttribute a) {
    return std::any_of(read.begin(), read.end(), [&](const Slot& s) { return s.attribute == a; });
  };
  std::vector<Slot> rest = unread;
  if (!has(SheetAttribute::Id)) {
    std::optional<Slot> id;
    if (!rest.empty()) {
      id = rest.back();
      rest.pop_back();
    }
    for (SheetAttribute stand_in : {SheetAttribute::Tag, SheetAttribute::Description})
      for (const auto& s : read)
        if (!id && s.attribute == stand_in) id = s;
    if (id) {
      id->attribute = SheetAttribute::Id;
      read.push_back(*id);
    }
  }
  if (!has(SheetAttribute::Description) && !rest.empty()) {
    Slot d = rest.front();
    d.attribute = SheetAttribute::Description;
    read.push_back(d);
    rest.erase(rest.begin());
  }
  for (Slot s : rest) {
    s.attribute = SheetAttribute::Note;
    read.push_back(s);
  }
  std::stable_sort(read.begin(), read.end(), [](const Slot& a, const Slot& b) { return a.index < b.index; });
  return read;
}

}  // namespace

std::string column_header(const Sheet& sheet, const Shape& shape, std::size_t column) {
  for (std::size_t r = shape.first_data_row; r-- > 0;) {
    int filled = 0;
    for (std::size_t c = 0; c < shape.first_data_column; ++c) filled += cell_text(sheet.rows[r], c).empty() ? 0 : 1;
    if (filled >= 2) return cell_text(sheet.rows[r], column);
  }
  return "";
}

std::string row_label(const Sheet& sheet, const Shape& shape, std::size_t row) {
  std::string label;
  int filled = 0;
  for (std::size_t c = 0; c < shape.first_data_column; ++c)
    if (auto t = cell_text(sheet.rows[row], c); !t.empty()) label = t, ++filled;
  return filled == 1 ? label : "";
}

const Slot* Shape::row_slot(SheetAttribute a) const {
  for (const auto& s : row_slots)
    if (s.attribute == a) return &s;
  return nullptr;
}

const Slot* Shape::column_slot(SheetAttribute a) const {
  for (const auto& s : column_slots)
    if (s.attribute == a) return &s;
  return nullptr;
}

void assign_slots(const Sheet& sheet, Shape& shape, const SheetLayout& layout, const std::string& source) {
  const bool causes_as_rows = layout.orientation != CsvOrientation::EffectsAsRows;
  const auto& row_places = causes_as_rows ? layout.causes : layout.effects;
  const auto& column_places = causes_as_rows ? layout.effects : layout.causes;
  std::vector<LoadIssue> problems;
  if (!row_places.empty()) {
    for (const auto& p : row_places) {
      const long index = p.position - 1 - static_cast<long>(sheet.empty_columns_skipped);
      Slot s{p.attribute, static_cast<std::size_t>(std::max(0L, index)), "", true, "the layout's place"};
      if (index < 0)
        problems.push_back({where_of(source, sheet.rows[shape.id_row].line),
                            "the layout's " + std::string(to_string(p.attribute)) + " column " +
                                column_letters(p.position) + " is left of the grid (an empty column)"});
      s.label = column_header(sheet, shape, s.index);
      shape.row_slots.push_back(s);
    }
  } else {
    std::vector<HeaderCandidate> columns;
    for (std::size_t c : shape.label_columns) {
      HeaderCandidate h{c, column_header(sheet, shape, c), {}, "label column " + std::to_string(sheet.column_of(c)), ""};
      for (std::size_t r = shape.first_data_row; r < sheet.rows.size(); ++r) {
        if (h.place.empty() && !cell_text(sheet.rows[r], c).empty())
          h.place = where_of(source, sheet.rows[r].line, sheet.column_of(c));
        h.values.push_back(cell_text(sheet.rows[r], c));
      }
      columns.push_back(std::move(h));
    }
    shape.row_slots = classify_headers(columns, false);
  }
  if (!column_places.empty()) {
    for (const auto& p : column_places) {
      const auto index = sheet.row_at(p.position);
      if (!index || *index >= shape.first_data_row) {
        problems.push_back({where_of(source, p.position),
                            "the layout's " + std::string(to_string(p.attribute)) + " row " +
                                std::to_string(p.position) + " is not a header row of the grid"});
        continue;
      }
      shape.column_slots.push_back({p.attribute, *index, row_label(sheet, shape, *index), true, "the layout's place"});
    }
  } else {
    std::vector<HeaderCandidate> rows;
    for (std::size_t r : shape.header_rows) {
      const CsvRecord& row = sheet.rows[r];
      HeaderCandidate h{r, row_label(sheet, shape, r), {}, "header row " + std::to_string(row.line), ""};
      for (std::size_t i = shape.first_data_column; i < row.fields.size(); ++i) {
        if (h.place.empty() && !cell_text(row, i).empty()) h.place = where_of(source, row.line, sheet.column_of(i));
        h.values.push_back(cell_text(row, i));
      }
      rows.push_back(std::move(h));
    }
    shape.column_slots = classify_headers(rows, true);
  }
  if (!problems.empty()) throw LoadError(problems);
  // Places given without an id: the tag (or the description) is the id, as
  // when they are found.
  if (!row_places.empty()) shape.row_slots = complete(shape.row_slots, {});
  if (!column_places.empty()) shape.column_slots = complete(shape.column_slots, {});
  if (const Slot* id = shape.column_slot(SheetAttribute::Id)) shape.id_row = id->index;
  else if (!shape.column_slots.empty()) shape.id_row = shape.column_slots.back().index;
  const Slot* d = shape.column_slot(SheetAttribute::Description);
  shape.description_row = d ? d->index : shape.id_row;
  const Slot* id_column = shape.row_slot(SheetAttribute::Id);
  shape.id_column = id_column ? std::optional<std::size_t>(id_column->index) : std::nullopt;
}

}  // namespace cemv::formats::grid
