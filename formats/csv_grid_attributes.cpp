// What each label column and header row of a C&E grid holds (docs/csv.md
// "Attributes"): given by the layout, or read from its header (the common
// spellings of id, description, tag, setpoint, unit, voting, SIL, trip side,
// action, remarks) and its values (csv_grid_headers.cpp). An attribute column
// is never read as an element.
#include <algorithm>
#include <map>
#include <optional>

#include "formats/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

namespace {

std::vector<std::string> lower_words(const std::string& text) {
  std::vector<std::string> out;
  std::string w;
  for (char c : text) {
    const bool digit = c >= '0' && c <= '9', letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (digit || letter) w += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    else if (!w.empty()) out.push_back(std::move(w)), w.clear();
  }
  if (!w.empty()) out.push_back(std::move(w));
  return out;
}

ElementKind kind_word(const std::string& w) {
  static const std::map<std::string, ElementKind> words{
      {"cause", ElementKind::Cause},       {"causes", ElementKind::Cause},      {"initiator", ElementKind::Cause},
      {"initiators", ElementKind::Cause},  {"input", ElementKind::Cause},       {"inputs", ElementKind::Cause},
      {"detection", ElementKind::Cause},   {"effect", ElementKind::Effect},     {"effects", ElementKind::Effect},
      {"output", ElementKind::Effect},     {"outputs", ElementKind::Effect},    {"final", ElementKind::Effect},
      {"element", ElementKind::Effect},    {"elements", ElementKind::Effect},   {"actuation", ElementKind::Effect},
      {"actuator", ElementKind::Effect},   {"of", ElementKind::Unknown}};
  auto it = words.find(w);
  return it == words.end() ? ElementKind::Unknown : it->second;
}

bool is_kind_word(const std::string& w) { return w == "of" || kind_word(w) != ElementKind::Unknown; }

// The spellings of each attribute (docs/csv.md "Attributes"), as lower-case
// words joined by blanks, kind words (cause, effect, output, ...) removed.
const std::map<std::string, SheetAttribute>& spellings() {
  static const std::map<std::string, SheetAttribute> table = [] {
    std::map<std::string, SheetAttribute> t;
    auto add = [&](SheetAttribute a, std::initializer_list<const char*> names) {
      for (const char* n : names) t[n] = a;
    };
    add(SheetAttribute::Id, {"id", "no", "nr", "num", "number", "item", "item no", "item nr", "item number", "ref",
                             "ref no", "reference", "line no", "pos", "position", "sr no", "s no", "serial no"});
    add(SheetAttribute::Description, {"description", "desc", "descr", "service", "service description",
                                      "narrative"});
    add(SheetAttribute::Tag, {"instrument", "instrument no", "instrument number", "loop", "loop no",
                              "equipment no"});
    add(SheetAttribute::Setpoint, {"setpoint", "set point", "set pt", "sp", "trip setpoint", "trip set point",
                                   "trip point", "trip value", "trip setting", "trip level", "trip limit",
                                   "limit", "setting", "alarm setpoint", "alarm setting", "alarm limit"});
    add(SheetAttribute::Unit, {"unit", "units", "eu", "eng unit", "eng units", "engineering unit",
                               "engineering units", "uom", "unit of measure"});
    add(SheetAttribute::Voting, {"voting", "vote", "votes", "voting logic", "logic", "architecture", "moon",
                                 "xooy", "redundancy", "voting arrangement"});
    add(SheetAttribute::Sil, {"sil", "sil level", "sil rating", "sil class", "required sil", "sil req",
                              "sil requirement", "safety integrity level"});
    add(SheetAttribute::TripSide, {"trip direction", "trip side", "direction", "limit type", "high low", "h l",
                                   "hi lo", "trip type", "alarm type"});
    add(SheetAttribute::Action, {"action", "actions", "final action", "operation", "command", "safe state"});
    add(SheetAttribute::Note, {"remark", "remarks", "note", "notes", "comment", "comments"});
    return t;
  }();
  return table;
}

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

std::optional<HeaderMeaning> attribute_of_header(const std::string& text) {
  const std::string_view t = trim(text);
  if (t == "#") return HeaderMeaning{SheetAttribute::Id, ElementKind::Unknown};
  HeaderMeaning m;
  std::string phrase;
  bool tag = false;
  for (const auto& w : lower_words(std::string(t))) {
    if (is_kind_word(w)) {
      const ElementKind k = kind_word(w);
      if (k != ElementKind::Unknown) m.kind = m.kind == ElementKind::Unknown || m.kind == k ? k : ElementKind::Unknown;
      continue;
    }
    tag = tag || w == "tag" || w == "tags";
    join_to(phrase, " ", w);
  }
  if (phrase.empty()) return std::nullopt;
  if (tag) {
    m.attribute = SheetAttribute::Tag;
    return m;
  }
  const auto it = spellings().find(phrase);
  if (it == spellings().end()) return std::nullopt;
  m.attribute = it->second;
  return m;
}

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
