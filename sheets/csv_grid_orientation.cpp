// Which axis of a C&E grid holds the causes (docs/csv.md "Orientation"). Real
// C&E workbooks use both orientations; the grid is read only when the evidence
// says which one it is, and the summary names that evidence. Missing or
// conflicting evidence is a refusal that asks for --orientation: the Safety
// Matrix's import (6.6) never guesses either.
#include <algorithm>
#include <map>
#include <regex>
#include <set>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

namespace {

enum class Kind { None, Causes, Effects };

constexpr const char* kCausesAsRows = "causes-as-rows";
constexpr const char* kEffectsAsRows = "effects-as-rows";

const char* name_of(CsvOrientation o) {
  return o == CsvOrientation::EffectsAsRows ? kEffectsAsRows : kCausesAsRows;
}

// The axis a corner label names: cause words (cause, detection, initiator,
// trip, input) or effect words (effect, actuation, action, final element,
// output); a cell with both ("Cause / Effect") names neither.
Kind label_kind(const std::string& text) {
  static const std::regex cause(R"(cause|detection|initiat|trip|input)", std::regex::icase);
  static const std::regex effect(R"(effect|actuation|action|final|output)", std::regex::icase);
  const bool c = std::regex_search(text, cause), e = std::regex_search(text, effect);
  return c == e ? Kind::None : c ? Kind::Causes : Kind::Effects;
}

// The letter groups of an id (`TMA-D-40` -> TMA, D) that name its kind: a
// letter for the axis (C, D detection, I initiator; A actuation, E effect, F
// final element) or an instrument of ISA 5.1 (sensors and switches for causes,
// valves for effects).
Kind id_kind(const std::string& id) {
  static const std::set<std::string> cause = {
      "C", "D", "I", "CA", "DET", "INIT", "PT", "LT", "TT", "FT", "AT", "PDT", "PS", "LS", "TS",
      "FS", "PSH", "PSHH", "PSL", "PSLL", "LSH", "LSHH", "LSL", "LSLL", "TSH", "TSHH", "TSL",
      "TSLL", "FSH", "FSHH", "FSL", "FSLL", "PB", "HS", "ZS", "ZSO", "ZSC", "GD"};
  static const std::set<std::string> effect = {"A", "E", "F", "FE", "ACT", "XV", "SDV", "ESDV",
                                               "BDV", "XY", "SOV", "MOV"};
  bool c = false, e = false;
  std::string token;
  auto flush = [&] {
    c = c || cause.count(token);
    e = e || effect.count(token);
    token.clear();
  };
  for (char ch : id) {
    if ((ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z')) token += static_cast<char>(ch & ~0x20);
    else flush();
  }
  flush();
  return c == e ? Kind::None : c ? Kind::Causes : Kind::Effects;
}

// "TMA-D-<n>": the id with its digit groups replaced by <n>.
std::string pattern_of(const std::string& id) {
  static const std::regex digits(R"(\d+)");
  return std::regex_replace(id, digits, "<n>");
}

struct Evidence {
  std::set<CsvOrientation> says;
  std::vector<std::string> items;
};

// A label left of the column headers names the columns; one above the row
// headers names the rows: the label belongs to the axis whose headers it is
// nearer to (LSST: 'Effects/Actuation' in the id column of the description row,
// 'Causes/Detection' in the description column of the id row).
Evidence corner_labels(const Sheet& sheet, const Shape& shape) {
  Evidence ev;
  auto item = [&](const std::string& t, std::size_t r, std::size_t col, bool causes_are_rows) {
    ev.says.insert(causes_are_rows ? CsvOrientation::CausesAsRows : CsvOrientation::EffectsAsRows);
    ev.items.push_back(model::in_quotes(t) + " in line " + std::to_string(sheet.rows[r].line) + ", column " +
                       std::to_string(sheet.column_of(col)));
  };
  // A label (an attribute's header, such as "Effect description", is evidence
  // of its own kind below).
  auto kind_of = [](const std::string& t) {
    return corner_label_like(t) && !attribute_of_header(t) ? label_kind(t) : Kind::None;
  };
  for (std::size_t r = 0; r < shape.first_data_row; ++r) {
    // A band of labels over the data columns (`EFFECTS` over the effects) names them.
    const bool header = std::find(shape.header_rows.begin(), shape.header_rows.end(), r) != shape.header_rows.end();
    for (std::size_t col = shape.first_data_column; !header && col < sheet.rows[r].fields.size(); ++col)
      if (const Kind kind = kind_of(cell_text(sheet.rows[r], col)); kind != Kind::None)
        item(cell_text(sheet.rows[r], col), r, col, kind == Kind::Effects);
    // A banner: labels of one kind, then of the other, along one row
    // (`CAUSES` over the label columns, `EFFECTS` over the data): the left
    // kind names the rows, whatever the distances.
    Kind left = Kind::None;
    {
      std::map<Kind, std::pair<std::size_t, std::size_t>> span;  // first, last column of each kind
      for (std::size_t col = 0; !header && col < sheet.rows[r].fields.size(); ++col)
        if (const Kind kind = kind_of(cell_text(sheet.rows[r], col)); kind != Kind::None) {
          auto [it, fresh] = span.emplace(kind, std::make_pair(col, col));
          if (!fresh) it->second.second = col;
        }
      if (span.size() == 2) {
        const auto& c = span[Kind::Causes];
        const auto& e = span[Kind::Effects];
        left = c.second < e.first ? Kind::Causes : e.second < c.first ? Kind::Effects : Kind::None;
      }
    }
    for (std::size_t col = 0; col < shape.first_data_column; ++col) {
      const std::string t = cell_text(sheet.rows[r], col);
      const Kind kind = kind_of(t);
      if (kind == Kind::None) continue;
      const std::size_t across = shape.first_data_column - 1 - col;  // to the column headers
      const std::size_t down = shape.first_data_row - 1 - r;          // to the row headers
      // A banner (`CAUSES` over the label columns, `EFFECTS` over the data on
      // the same row): the label left of the data names the rows.
      if (left != Kind::None) {
        const bool names_rows = kind == left;
        item(t, r, col, names_rows ? kind == Kind::Causes : kind == Kind::Effects);
        continue;
      }
      if (across == down) continue;  // diagonal to both: names neither axis
      const bool names_columns = across < down;
      item(t, r, col, (kind == Kind::Causes) != names_columns);
    }
  }
  // A band of labels beside the data rows (`CAUSES` merged down the causes)
  // names them.
  for (std::size_t col = 0; col < shape.first_data_column; ++col) {
    if (std::find(shape.label_columns.begin(), shape.label_columns.end(), col) != shape.label_columns.end()) continue;
    for (std::size_t r = shape.first_data_row; r < sheet.rows.size(); ++r)
      if (const Kind kind = kind_of(cell_text(sheet.rows[r], col)); kind != Kind::None)
        item(cell_text(sheet.rows[r], col), r, col, kind == Kind::Causes);
  }
  return ev;
}

// The headers of the attributes: a cause's attribute (setpoint, unit, voting,
// trip side) or a header naming causes on an axis says the causes are there;
// an effect's (action) or a header naming effects says the effects are.
Evidence attribute_headers(const Sheet& sheet, const Shape& shape) {
  Evidence ev;
  if (shape.given) return ev;  // the layout gave the places, and with them the orientation
  auto read = [&](const std::vector<Slot>& slots, bool rows) {
    for (const auto& slot : slots) {
      const auto m = slot.by_header ? attribute_of_header(slot.label) : std::nullopt;
      if (!m) continue;
      ElementKind kind = m->kind;
      if (kind == ElementKind::Unknown) {
        const SheetAttribute a = m->attribute;
        if (a == SheetAttribute::Setpoint || a == SheetAttribute::Unit || a == SheetAttribute::Voting ||
            a == SheetAttribute::TripSide)
          kind = ElementKind::Cause;
        else if (a == SheetAttribute::Action)
          kind = ElementKind::Effect;
      }
      if (kind == ElementKind::Unknown) continue;
      ev.says.insert((kind == ElementKind::Cause) == rows ? CsvOrientation::CausesAsRows : CsvOrientation::EffectsAsRows);
      ev.items.push_back(model::in_quotes(slot.label) +
                         (rows ? " over column " + std::to_string(sheet.column_of(slot.index))
                               : " left of row " + std::to_string(sheet.rows[slot.index].line)));
    }
  };
  read(shape.row_slots, true);
  read(shape.column_slots, false);
  return ev;
}

// The kind most ids of an axis show, with the pattern they share.
std::pair<Kind, std::string> axis_ids(const std::vector<std::string>& ids) {
  std::map<Kind, int> kinds;
  std::map<std::string, int> patterns;
  for (const auto& id : ids) {
    ++kinds[id_kind(id)];
    ++patterns[pattern_of(id)];
  }
  const int n = static_cast<int>(ids.size());
  Kind kind = Kind::None;
  if (kinds[Kind::Causes] * 2 > n && kinds[Kind::Effects] == 0) kind = Kind::Causes;
  if (kinds[Kind::Effects] * 2 > n && kinds[Kind::Causes] == 0) kind = Kind::Effects;
  std::string pattern;
  int best = 0;
  for (const auto& [p, count] : patterns)
    if (count > best) best = count, pattern = p;
  // A pattern only when ids share it (TMA-D-<n>); else an example.
  if (best < 2 && !ids.empty()) pattern = "such as " + model::in_quotes(ids.front());
  return {kind, pattern};
}

Evidence id_patterns(const Sheet& sheet, const Shape& shape) {
  Evidence ev;
  std::vector<std::string> column_ids, row_ids;
  const CsvRecord& id_row = sheet.rows[shape.id_row];
  for (std::size_t i = shape.first_data_column; i < shape.column_end; ++i)
    if (auto t = cell_text(id_row, i); !t.empty()) column_ids.push_back(t);
  if (shape.id_column)
    for (std::size_t r = shape.first_data_row; r < sheet.rows.size(); ++r)
      if (auto t = cell_text(sheet.rows[r], *shape.id_column); !t.empty()) row_ids.push_back(t);
  const auto [row_kind, row_pattern] = axis_ids(row_ids);
  const auto [column_kind, column_pattern] = axis_ids(column_ids);
  if (row_kind != Kind::None) {
    ev.says.insert(row_kind == Kind::Causes ? CsvOrientation::CausesAsRows : CsvOrientation::EffectsAsRows);
    ev.items.push_back(std::string(row_kind == Kind::Causes ? "cause" : "effect") + " ids " + row_pattern +
                       " in column " + std::to_string(sheet.column_of(*shape.id_column)));
  }
  if (column_kind != Kind::None) {
    ev.says.insert(column_kind == Kind::Effects ? CsvOrientation::CausesAsRows : CsvOrientation::EffectsAsRows);
    ev.items.push_back(std::string(column_kind == Kind::Causes ? "cause" : "effect") + " ids " +
                       column_pattern + " in row " + std::to_string(id_row.line));
  }
  return ev;
}

std::string describe(const char* what, const Evidence& ev) {
  std::string list;
  for (const auto& item : ev.items) join_to(list, "; ", item);
  std::string says;
  for (auto o : ev.says) join_to(says, " and ", name_of(o));
  return std::string(what) + " (" + list + ") say " + says;
}

}  // namespace

OrientationDecision decide_orientation(const Sheet& sheet, const Shape& shape,
                                       CsvOrientation requested, const std::string& source,
                                       const std::string& given_by, bool over_labels) {
  const Evidence labels = corner_labels(sheet, shape);
  const Evidence ids = id_patterns(sheet, shape);
  const Evidence headers = attribute_headers(sheet, shape);
  std::set<CsvOrientation> says = labels.says;
  says.insert(ids.says.begin(), ids.says.end());
  says.insert(headers.says.begin(), headers.says.end());
  std::string found;
  if (!labels.items.empty()) join_to(found, "; ", describe("the corner labels", labels));
  if (!ids.items.empty()) join_to(found, "; ", describe("the id patterns", ids));
  if (!headers.items.empty()) join_to(found, "; ", describe("the attribute headers", headers));
  const int id_line = sheet.rows[shape.id_row].line;

  OrientationDecision decision;
  if (requested != CsvOrientation::Auto) {
    // The corner labels and the attribute headers are the sheet's own words
    // for its axes: read against all of them, every cause would become an
    // effect. Id patterns are only letters, and a given orientation may
    // overrule them.
    // A layout's orientation is there to say what the sheet cannot: it wins
    // over corner labels (a warning names them), not over attribute headers.
    std::set<CsvOrientation> words = over_labels ? std::set<CsvOrientation>{} : labels.says;
    words.insert(headers.says.begin(), headers.says.end());
    if (!words.empty() && !words.count(requested)) {
      std::string against;
      if (!labels.items.empty() && !over_labels) join_to(against, "; ", describe("the corner labels", labels));
      if (!headers.items.empty()) join_to(against, "; ", describe("the attribute headers", headers));
      throw LoadError({{where_of(source, id_line),
                        against + "; " + given_by + " " + name_of(requested) +
                            " would read every cause as an effect and every effect as a cause; drop " + given_by +
                            ", or correct the labels (docs/csv.md \"Orientation\")"}});
    }
    decision.orientation = requested;
    decision.evidence = "as given by " + given_by;
    const CsvOrientation other = requested == CsvOrientation::CausesAsRows ? CsvOrientation::EffectsAsRows
                                                                           : CsvOrientation::CausesAsRows;
    if (says.count(other))
      decision.disagreement =
          LoadIssue{where_of(source, id_line), found + "; read as " + name_of(requested) + " as " + given_by + " says" +
                                                   (over_labels && labels.says.count(other)
                                                        ? " (a layout wins over the corner labels)"
                                                        : "")};
    return decision;
  }
  if (says.size() != 1) {
    const std::string what =
        says.empty() ? "no corner label names an axis (words such as cause, detection, initiator or "
                       "trip; effect, actuation, action or final element) and no ids follow a cause "
                       "or effect pattern (such as TMA-D-1 or XV-101)"
                     : "the evidence conflicts: " + found;
    throw LoadError({{where_of(source, id_line),
                      "cannot tell whether the causes are the rows or the columns: " + what +
                          "; give --orientation causes-as-rows or effects-as-rows (docs/csv.md "
                          "\"Orientation\")"}});
  }
  decision.orientation = *says.begin();
  std::string from;
  if (!labels.items.empty()) {
    std::string list;
    for (const auto& item : labels.items) join_to(list, "; ", item);
    join_to(from, " and ", "the corner labels (" + list + ")");
  }
  if (!ids.items.empty()) {
    std::string list;
    for (const auto& item : ids.items) join_to(list, "; ", item);
    join_to(from, " and ", "the id patterns (" + list + ")");
  }
  if (!headers.items.empty()) {
    std::string list;
    for (const auto& item : headers.items) join_to(list, "; ", item);
    join_to(from, " and ", "the attribute headers (" + list + ")");
  }
  decision.evidence = "from " + from;
  return decision;
}

}  // namespace cemv::formats::grid
