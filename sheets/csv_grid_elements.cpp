// The elements of each axis of a C&E grid (docs/csv.md "Elements", "Voting
// groups", "Setpoints", "Deleted rows"): one per data row (column) with an id
// or marks, its attributes read from the label columns (header rows); a voting
// group's rows (merged in a workbook, or without id and description under a
// voting in a CSV) are one cause with a tag per row; a deleted row is left out
// and listed. What cannot be read right is an error naming its cell.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "sheets/csv_grid.hpp"
#include "sheets/csv_grid_values.hpp"
#include "formats/csv_text.hpp"
#include "model/names.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::grid {

using namespace csv_text;
using model::in_quotes;

namespace {

// A cell under one slot of a data row (column).
struct SlotCell {
  const Slot* slot = nullptr;
  std::string text;
  int line = 0, column = 0;
  bool struck = false, partly_struck = false;
};

// One data row (or column) as its slots see it.
struct Line {
  std::size_t index = 0;  // Sheet::rows index, or field index
  int position = 0;       // its file line (rows) or column (columns)
  int line = 0, column = 0;  // of its id cell
  std::vector<SlotCell> cells;
  std::string label_text;  // every text left of the data (rows)
  bool data = false;       // any text right of the label columns (rows)
  int span = 1;            // merged over this many lines at its id, description or voting cell
  const SlotCell* cell(SheetAttribute a) const {
    for (const auto& c : cells)
      if (c.slot->attribute == a) return &c;
    return nullptr;
  }
  std::string text(SheetAttribute a) const {
    const SlotCell* c = cell(a);
    return c ? c->text : "";
  }
};

// The rows (columns) of an open voting group, or of a deleted element.
struct Group {
  int element = kDeletedLine;
  Line first;
  int expected = 1;     // lines it spans (merge) or its voting's N
  bool by_merge = false;
  bool open_ended = false;  // AND / OR without a merge: as many rows as follow, up to 3
  int lines = 1;
  std::optional<Voting> voting;
  SlotCell voting_cell;
};

std::string upper(std::string s) {
  for (auto& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return s;
}

class AxisReader {
 public:
  AxisReader(const Sheet& sheet, const Shape& shape, bool rows, AxisContext ctx)
      : sheet_(sheet), shape_(shape), rows_(rows), ctx_(ctx),
        kind_(ctx.kind == ElementKind::Cause ? "cause" : "effect") {}

  AxisElements run(const std::vector<Line>& lines) {
    for (const Line& line : lines) {
      if (group_ && continues(line)) {
        attach(line);
        continue;
      }
      close_group();
      start(line);
    }
    close_group();
    return std::move(out_);
  }

 private:
  bool cause() const { return ctx_.kind == ElementKind::Cause; }
  std::string where(const Line& l) const {
    return (rows_ ? "row " : "column ") + std::to_string(l.position);
  }
  std::string span_text(int first, int last) const {
    return (rows_ ? "rows " : "columns ") + std::to_string(first) + "-" + std::to_string(last);
  }
  void error(int line, int column, std::string what) { ctx_.errors.at(line, column, std::move(what)); }
  void warn(int line, int column, std::string what) { ctx_.warnings.at(line, column, std::move(what)); }

  bool continues(const Line& l) const {
    const Group& g = *group_;
    if (g.by_merge) return l.position < g.first.position + g.expected;
    if (!l.text(SheetAttribute::Id).empty() || !l.text(SheetAttribute::Description).empty()) return false;
    if (g.open_ended) return g.lines < model::kMaxCauseTags && !l.text(SheetAttribute::Tag).empty();
    return g.lines < g.expected;
  }

  bool deleted(const Line& l, std::string& why) const {
    const DeletedRule& rule = ctx_.layout.deleted;
    for (SheetAttribute a : {SheetAttribute::Id, SheetAttribute::Description})
      if (const SlotCell* c = l.cell(a); rule.strikethrough && c && c->struck && !c->text.empty()) {
        why = "struck through";
        return true;
      }
    for (const auto& c : l.cells)
      for (const auto& w : rule.words)
        if (has_word(c.text, {w})) {
          why = in_quotes(w) + " in " + (rows_ ? "column " + std::to_string(c.column) : "row " + std::to_string(c.line));
          return true;
        }
    return false;
  }

  void start(const Line& l) {
    if (l.label_text.empty() && !l.data) return;  // an empty row or column
    std::string why;
    if (deleted(l, why)) {
      out_.element_of[l.index] = kDeletedLine;
      std::string what = where(l);
      std::string id = l.text(SheetAttribute::Id), text = l.text(SheetAttribute::Description);
      std::string named = id.empty() ? "" : "id " + in_quotes(id);
      if (!text.empty()) join_to(named, ": ", in_quotes(text));
      out_.deleted.push_back(what + " (" + (named.empty() ? "" : named + ", ") + why + ")");
      open_group(l, kDeletedLine);
      return;
    }
    const std::string id = l.text(SheetAttribute::Id);
    // Below (or among) the rows, a note in one cell (`Notes: see sheet
    // Remarks`) is text, not an element, even in the id column.
    const bool one_text = l.label_text.find(' ') != std::string::npos &&
                          std::count_if(l.cells.begin(), l.cells.end(), [](const SlotCell& c) { return !c.text.empty(); }) <= 1;
    if (!l.data && ((rows_ && id.empty()) || one_text)) {
      warn(l.line, rows_ ? sheet_.column_of(0) : l.column,
           std::string(rows_ ? "text row" : "text column") + " without " +
               (cause() ? "a cause" : "an effect") + " id or intersections ignored: " +
               in_quotes(l.label_text));
      return;
    }
    const int limit = cause() ? model::kMaxCauses : model::kMaxEffects;
    if (out_.elements.size() == static_cast<std::size_t>(limit))
      throw LoadError({{where_of(ctx_.source, l.line),
                        "more than " + std::to_string(limit) + " " + kind_ + " " + (rows_ ? "rows" : "columns") +
                            "; a matrix holds at most " + std::to_string(limit) + " " + kind_ + "s (3.4)"}});
    out_.element_of[l.index] = static_cast<int>(out_.elements.size());
    out_.elements.push_back(make_element(l));
    open_group(l, static_cast<int>(out_.elements.size()) - 1);
  }

  SheetElement make_element(const Line& l) {
    SheetElement e;
    e.sheet_id = l.text(SheetAttribute::Id);
    e.line = l.line;
    e.column = l.column;
    e.first_line = e.last_line = l.position;
    if (e.sheet_id.empty()) {
      e.unnamed = upper(kind_) + (rows_ ? "_LINE_" : "_COL_") + std::to_string(l.position);
      warn(l.line, l.column,
           rows_ ? kind_ + " row without an id; imported, named after its line (" + e.unnamed + ")"
                 : kind_ + " column without an id; named after its column (" + e.unnamed + ")");
    }
    for (const SlotCell& c : l.cells) {
      if (c.text.empty()) continue;
      if (!struck_cell_is_read(c)) continue;
      switch (c.slot->attribute) {
        case SheetAttribute::Id: break;
        case SheetAttribute::Description: describe(e, c); break;
        case SheetAttribute::Tag: add_tags(e, c); break;
        case SheetAttribute::Sil:
          if (auto sil = parse_sil(c.text)) e.sil = *sil;
          else error(c.line, c.column, "SIL " + in_quotes(c.text) + " is not a safety integrity level 0-4");
          break;
        case SheetAttribute::Voting:
        case SheetAttribute::Setpoint:
        case SheetAttribute::Unit:
        case SheetAttribute::TripSide: break;  // read with the group (close_group)
        case SheetAttribute::Action:
        case SheetAttribute::Note: note(e, c); break;
      }
    }
    return e;
  }

  // A struck-through cell of an element that is not deleted: cemv cannot tell
  // what the strike means (a deleted value? a deleted tag of a group?).
  bool struck_cell_is_read(const SlotCell& c) {
    if (c.partly_struck) {
      error(c.line, c.column, "part of " + in_quotes(truncate_utf8(c.text, 40)) +
                                  " is struck through: cemv cannot tell what is deleted; strike the whole row (or "
                                  "the cell) or none of it");
      return false;
    }
    if (c.struck) {
      error(c.line, c.column, in_quotes(truncate_utf8(c.text, 40)) + " is struck through, but its " +
                                  (rows_ ? "row" : "column") +
                                  " is not deleted (its id and description are not struck through): cemv cannot "
                                  "tell what is deleted");
      return false;
    }
    return true;
  }

  void describe(SheetElement& e, const SlotCell& c) {
    const std::string text = one_line(c.text);
    e.text = text;
    if (model::utf8_length(text) > model::kMaxDescriptionLength) {
      e.text = truncate_utf8(text, model::kMaxDescriptionLength);
      join_to(e.note, "; ", "description: " + text);
      warn(c.line, c.column,
           kind_ + " description of " + std::to_string(model::utf8_length(text)) + " characters truncated to " +
               std::to_string(model::kMaxDescriptionLength) + "; the full text is kept in the note");
    }
  }

  void note(SheetElement& e, const SlotCell& c) {
    std::string label = c.slot->label;
    if (label.empty())
      label = c.slot->attribute == SheetAttribute::Action ? "Action" : "line " + std::to_string(c.line);
    join_to(e.note, "; ", label + ": " + one_line(c.text));
  }

  void add_tags(SheetElement& e, const SlotCell& c) {
    for (const std::string& tag : split_tags(c.text)) {
      if (auto problem = model::tag_name_problem(tag)) {
        warn(c.line, c.column, kind_ + " tag " + in_quotes(tag) + " is not a tag name (6.1.4: " + *problem +
                                   "); the tag is named after the id");
        continue;
      }
      e.tags.push_back(tag);
    }
  }

  void open_group(const Line& l, int element) {
    Group g;
    g.element = element;
    g.first = l;
    g.expected = l.span;
    g.by_merge = l.span > 1;
    if (const SlotCell* v = l.cell(SheetAttribute::Voting); v && !v->text.empty() && cause()) {
      std::string problem;
      g.voting = parse_voting(v->text, problem);
      g.voting_cell = *v;
      if (!g.voting && element != kDeletedLine) error(v->line, v->column, "voting " + in_quotes(v->text) + ": " + problem);
      if (g.voting && !g.by_merge) {
        g.open_ended = g.voting->word.has_value();
        g.expected = g.voting->tags;
        // Every tag in the first row's cell (`BS-7020A, BS-7020B, BS-7020C`):
        // the group is that row; the rows below are not its.
        const SlotCell* t = l.cell(SheetAttribute::Tag);
        if (t && !g.open_ended && split_tags(t->text).size() >= static_cast<std::size_t>(g.expected)) g.expected = 1;
      }
    }
    group_ = g;
  }

  void attach(const Line& l) {
    Group& g = *group_;
    ++g.lines;
    out_.element_of[l.index] = g.element;
    if (g.element == kDeletedLine) return;
    SheetElement& e = out_.elements[static_cast<std::size_t>(g.element)];
    e.last_line = l.position;
    bool tagged = false;
    for (const SlotCell& c : l.cells) {
      if (c.text.empty() || !struck_cell_is_read(c)) continue;
      const SheetAttribute a = c.slot->attribute;
      if (a == SheetAttribute::Tag) {
        add_tags(e, c);
        tagged = true;
      } else if (a == SheetAttribute::Note || a == SheetAttribute::Action) {
        note(e, c);
      } else if (c.text != g.first.text(a)) {
        const std::string first = g.first.text(a);
        error(c.line, c.column,
              in_quotes(c.text) + " differs from the group's " + (first.empty() ? "empty cell" : in_quotes(first)) +
                  " in " + where(g.first) + ": the rows of a voting group (" +
                  span_text(g.first.position, g.first.position + g.expected - 1) + ") are one " + kind_ +
                  " with one " + to_string(a));
      }
    }
    if (!tagged && shape_has(SheetAttribute::Tag))
      error(l.line, l.column, where(l) + " of the voting group of " + label_of(g) + " has no tag: each row of a " +
                                  "group holds one of its tags");
  }

  bool shape_has(SheetAttribute a) const {
    const auto& slots = rows_ ? shape_.row_slots : shape_.column_slots;
    return std::any_of(slots.begin(), slots.end(), [&](const Slot& s) { return s.attribute == a; });
  }
  std::string label_of(const Group& g) const {
    const std::string id = g.first.text(SheetAttribute::Id);
    return kind_ + " " + (id.empty() ? where(g.first) : in_quotes(id));
  }

  void close_group();
  void read_setpoint(SheetElement& e, const Group& g);

  const Sheet& sheet_;
  const Shape& shape_;
  bool rows_;
  AxisContext ctx_;
  std::string kind_;
  AxisElements out_;
  std::optional<Group> group_;

};

void AxisReader::close_group() {
  if (!group_) return;
  const Group g = std::move(*group_);
  group_.reset();
  if (g.element == kDeletedLine) return;
  SheetElement& e = out_.elements[static_cast<std::size_t>(g.element)];
  const int tags = std::max<int>(1, static_cast<int>(e.tags.size()));
  const std::string lines = g.lines > 1 ? span_text(e.first_line, e.last_line) : where(g.first);
  if (!cause()) {
    if (tags > model::kMaxEffectTags)
      error(e.line, e.column, "the effect has " + std::to_string(tags) + " tags (" + lines + "); an effect has at most " +
                                  std::to_string(model::kMaxEffectTags) + " (3.4)");
    return;
  }
  if (g.voting) {
    const auto function = function_of(*g.voting, tags);
    const SlotCell& v = g.voting_cell;
    if (!function) {
      std::string why;
      if (g.voting->word) why = "AND and OR take 2 or 3 tags (6.3.1)";
      else if (g.voting->tags != tags) why = "it needs " + std::to_string(g.voting->tags) + " tags";
      else why = "a cause has at most 3 tags and the functions normal, AND, OR and 2oo3 (3.4, 6.3.1)";
      error(v.line, v.column, "voting " + in_quotes(v.text) + " of " + label_of(g) + " over " + std::to_string(tags) +
                                  " tag" + (tags == 1 ? "" : "s") + " (" + lines + "): " + why +
                                  "; a voting group has one row per tag, merged or under the voting row");
    } else {
      e.function = function;
      if (tags > 1) out_.groups.push_back(lines + " (" + v.text + ")");
    }
  } else if (tags > 1) {
    error(e.line, e.column, label_of(g) + " has " + std::to_string(tags) + " tags (" + lines +
                                ") but no voting: give it (1oo2, 2oo2, 2oo3, AND, OR) in its voting column");
  }
  read_setpoint(e, g);
}

void AxisReader::read_setpoint(SheetElement& e, const Group& g) {
  const SlotCell* sp_cell = g.first.cell(SheetAttribute::Setpoint);
  std::string unit = g.first.text(SheetAttribute::Unit);
  const std::string side_text = g.first.text(SheetAttribute::TripSide);
  const std::string text = sp_cell ? sp_cell->text : "";
  const auto sp = parse_setpoint(text);
  if (!sp) {  // no setpoint, or a switch state (`closed`): a discrete cause
    if (!text.empty()) join_to(e.note, "; ", "Setpoint: " + one_line(text));
    if (!unit.empty()) join_to(e.note, "; ", "Unit: " + one_line(unit));
    if (!side_text.empty()) join_to(e.note, "; ", "Trip side: " + one_line(side_text));
    return;
  }
  if (!sp->rest.empty() && !unit.empty() && sp->rest != unit) {
    error(sp_cell->line, sp_cell->column, "setpoint " + in_quotes(text) + " names the unit " + in_quotes(sp->rest) +
                                              ", the unit column " + in_quotes(unit));
    return;
  }
  if (unit.empty()) unit = sp->rest;
  std::vector<std::pair<model::LimitType, std::string>> said;  // the side, and who says it
  if (auto it = ctx_.layout.trip_sides.find(e.sheet_id); it != ctx_.layout.trip_sides.end())
    said.push_back({it->second, "the layout's trip_sides"});
  for (const std::string& key : {e.sheet_id, e.text})
    if (auto it = ctx_.parameter_trip_sides.find(key); !key.empty() && it != ctx_.parameter_trip_sides.end()) {
      said.push_back({it->second, "the parameters' causes." + key + ".analog.limit_type"});
      break;
    }
  if (!side_text.empty()) {
    const SlotCell* c = g.first.cell(SheetAttribute::TripSide);
    if (auto side = parse_trip_side(side_text)) said.push_back({*side, "the trip side " + in_quotes(side_text)});
    else error(c->line, c->column, "trip side " + in_quotes(side_text) + " is not high or low (H, HH, HIGH, >; L, LL, LOW, <)");
  }
  if (sp->side) said.push_back({*sp->side, "the setpoint " + in_quotes(text)});
  bool both = false;
  if (auto side = side_of_words(e.text, both)) said.push_back({*side, "the description"});
  auto name = [](model::LimitType t) { return t == model::LimitType::High ? "high" : "low"; };
  std::string who;
  for (const auto& [side, source] : said) join_to(who, ", ", source + " says " + name(side));
  const std::string of = "setpoint " + in_quotes(text) + " of " + label_of(g);
  if (std::any_of(said.begin(), said.end(), [&](const auto& s) { return s.first != said.front().first; })) {
    error(sp_cell->line, sp_cell->column, of + ": " + who + "; which side trips must be said once, or alike");
    return;
  }
  if (said.empty()) {
    error(sp_cell->line, sp_cell->column,
          of + ": nothing says which side trips, high or low" +
              (both ? std::string(" (the description names both)") : std::string()) +
              ": not the layout's trip_sides, a trip-side column, the setpoint ('> 45', '45 HH') nor the "
              "description (high, low, HH, LL, ...); give \"trip_sides\": {\"" + e.sheet_id + "\"" +
              ": \"high\"|\"low\"} in the layout (docs/csv.md \"Setpoints\"), or "
              "\"causes\": {\"" + e.sheet_id + "\": {\"analog\": {\"limit_type\": ...}}} in the plant parameters "
              "(--params, docs/params.md)");
    return;
  }
  const float limit = static_cast<float>(sp->value);
  if (!std::isfinite(limit)) {
    error(sp_cell->line, sp_cell->column, of + " is beyond the single-precision range of a REAL (6.3.1)");
    return;
  }
  e.analog = model::AnalogParams{said.front().first, limit, 0.0f, std::nullopt, 0.0f, one_line(unit)};
  ++out_.analog;
}

SlotCell slot_cell(const Sheet& sheet, const Slot& slot, std::size_t row, std::size_t field) {
  SlotCell c;
  c.slot = &slot;
  c.text = cell_text(sheet.rows[row], field);
  // A dash (or n/a) in a value's cell says it has none; an id or a
  // description is taken as written.
  const SheetAttribute a = slot.attribute;
  if (a != SheetAttribute::Id && a != SheetAttribute::Description && a != SheetAttribute::Note && nil_value(c.text))
    c.text.clear();
  c.line = sheet.rows[row].line;
  c.column = sheet.column_of(field);
  c.struck = sheet.extras.struck.count({c.line, c.column}) > 0;
  c.partly_struck = sheet.extras.partly_struck.count({c.line, c.column}) > 0;
  return c;
}

// How many lines (rows, or columns) the merge at the line's id, description or
// voting cell spans: a voting group, merged.
int span_of(const Sheet& sheet, const Line& l, bool rows) {
  int span = 1;
  for (SheetAttribute a : {SheetAttribute::Id, SheetAttribute::Description, SheetAttribute::Voting})
    if (const SlotCell* c = l.cell(a))
      if (auto it = sheet.extras.merges.find({c->line, c->column}); it != sheet.extras.merges.end()) {
        const Range& m = it->second;
        span = std::max(span, rows ? m.last_line - m.first_line + 1 : m.last_column - m.first_column + 1);
      }
  return span;
}

std::vector<Line> row_lines(const Sheet& sheet, const Shape& shape) {
  std::vector<Line> lines;
  const std::size_t c0 = shape.first_data_column;
  for (std::size_t r = shape.first_data_row; r < sheet.rows.size(); ++r) {
    const CsvRecord& row = sheet.rows[r];
    Line l;
    l.index = r;
    l.position = l.line = row.line;
    l.column = sheet.column_of(shape.id_column ? *shape.id_column : c0 - 1);
    for (const Slot& slot : shape.row_slots) l.cells.push_back(slot_cell(sheet, slot, r, slot.index));
    for (std::size_t i = 0; i < c0; ++i)
      if (auto t = cell_text(row, i); !t.empty()) join_to(l.label_text, " ", t);
    for (std::size_t i = c0; i < row.fields.size() && !l.data; ++i) l.data = !cell_text(row, i).empty();
    l.span = span_of(sheet, l, true);
    lines.push_back(std::move(l));
  }
  return lines;
}

std::vector<Line> column_lines(const Sheet& sheet, const Shape& shape) {
  std::vector<Line> lines;
  for (std::size_t i = shape.first_data_column; i < shape.column_end; ++i) {
    Line l;
    l.index = i;
    l.position = l.column = sheet.column_of(i);
    l.line = sheet.rows[shape.id_row].line;
    for (const Slot& slot : shape.column_slots) l.cells.push_back(slot_cell(sheet, slot, slot.index, i));
    for (std::size_t r = 0; r < shape.first_data_row; ++r)
      if (auto t = cell_text(sheet.rows[r], i); !t.empty()) join_to(l.label_text, " ", t);
    for (std::size_t r = shape.first_data_row; r < sheet.rows.size() && !l.data; ++r)
      l.data = !cell_text(sheet.rows[r], i).empty();
    l.span = span_of(sheet, l, false);
    lines.push_back(std::move(l));
  }
  return lines;
}

}  // namespace

AxisElements read_row_elements(const Sheet& sheet, const Shape& shape, AxisContext context) {
  AxisElements out = AxisReader(sheet, shape, true, context).run(row_lines(sheet, shape));
  if (out.elements.empty())
    throw LoadError({{where_of(context.source, sheet.rows.back().line),
                      std::string("not a C&E grid: no ") + (context.kind == ElementKind::Cause ? "cause" : "effect") +
                          " rows after the header rows (docs/csv.md)"}});
  return out;
}

AxisElements read_column_elements(const Sheet& sheet, const Shape& shape, AxisContext context) {
  const int limit = context.kind == ElementKind::Cause ? model::kMaxCauses : model::kMaxEffects;
  const std::size_t columns = shape.column_end - shape.first_data_column;
  const char* kind = context.kind == ElementKind::Cause ? "cause" : "effect";
  if (columns > static_cast<std::size_t>(limit) && sheet.extras.merges.empty())
    throw LoadError({{where_of(context.source, sheet.rows[shape.id_row].line),
                      "the grid has " + std::to_string(columns) + " " + kind + " columns; a matrix holds at most " +
                          std::to_string(limit) + " " + kind + "s (3.4)"}});
  return AxisReader(sheet, shape, false, context).run(column_lines(sheet, shape));
}

}  // namespace cemv::formats::grid
