// The cells of a C&E grid (docs/csv.md "Marks", "Warnings"): one intersection
// per mark (6.5.2), its footnotes as the intersection's note; a voting group's
// rows give it once. A mark nobody gave a meaning is an error, never dropped;
// other text outside the grid is reported.
#include <algorithm>
#include <map>
#include <set>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;
using model::Intersection;
using model::IntersectionType;

namespace {

// The intersection type of an upper-case mark letter (6.5.2).
IntersectionType type_of(char letter) {
  switch (letter) {
    case 'N': return IntersectionType::N;
    case 'S': return IntersectionType::S;
    case 'V': return IntersectionType::V;
    case 'R': return IntersectionType::R;
    case 'X': return IntersectionType::X;
    default: return IntersectionType::Note;  // '*'
  }
}

class CellReader {
 public:
  CellReader(const Sheet& sheet, const Shape& shape, const GridAxes& axes, const MarkTable& marks,
             const std::map<std::string, std::string>& legend, GridWarnings& warnings, GridErrors& errors)
      : sheet_(sheet), shape_(shape), axes_(axes), marks_(marks), legend_(legend), warnings_(warnings),
        errors_(errors), column_kind(axes.causes_are_rows ? "effect" : "cause") {}

  std::vector<Intersection> run() {
    const std::size_t end = shape_.column_end;
    for (const auto& [r, element] : axes_.rows.element_of) {
      if (element == kDeletedLine) continue;
      const CsvRecord& row = sheet_.rows[r];
      for (std::size_t i = shape_.first_data_column; i < std::max(row.fields.size(), end); ++i) read_cell(row, i, element);
      if (row.fields.size() < end) {
        const int last = sheet_.column_of(row.fields.size() - 1);
        warnings_.at(row.line, last,
                     "row ends after column " + std::to_string(last) + " of " +
                         std::to_string(sheet_.column_of(end - 1)) + "; the missing cells read as no intersection");
      }
    }
    report_cell_styles();
    if (!unexplained_.empty()) {
      std::string list;
      for (const auto& k : unexplained_) join_to(list, ", ", k);
      warnings_.at(first_row_line(), 0,
                   "footnotes " + list +
                       (legend_.empty() ? " are referenced but the file has no legend rows" : " have no legend entry") +
                       "; kept as notes on their intersections");
    }
    std::vector<Intersection> out;
    for (auto& [key, x] : found_) out.push_back(std::move(x.intersection));
    return out;
  }

 private:
  int first_row_line() const {
    for (const auto& [r, element] : axes_.rows.element_of)
      if (element != kDeletedLine) return sheet_.rows[r].line;
    return sheet_.rows[shape_.first_data_row].line;
  }

  void read_cell(const CsvRecord& row, std::size_t i, int row_element) {
    const int column = sheet_.column_of(i);
    if (i >= row.fields.size()) {
      styles_.push_back({row.line, column, CellStyle::Missing});
      return;
    }
    const std::string& raw = row.fields[i].text;
    const std::string t(trim(raw));
    if (i >= shape_.column_end) {
      if (t.empty()) return;
      if (marks_.read(t).type)
        errors_.at(row.line, column, "mark " + model::in_quotes(t) + " right of the last " + column_kind +
                                         " column, under no " + column_kind + " id or description: the " +
                                         column_kind + " it trips is not in the sheet");
      else
        warnings_.at(row.line, column,
                     "stray value " + model::in_quotes(t) + " right of the last " + column_kind + " column; ignored");
      return;
    }
    if (t.empty()) {
      styles_.push_back({row.line, column, raw.empty() ? CellStyle::Empty : CellStyle::Blank});
      return;
    }
    const auto across = axes_.columns.element_of.find(i);
    if (across == axes_.columns.element_of.end() || across->second == kDeletedLine) return;  // a deleted column
    const auto& r = axes_.rows.elements[static_cast<std::size_t>(row_element)];
    const auto& c = axes_.columns.elements[static_cast<std::size_t>(across->second)];
    const auto& cause = axes_.causes_are_rows ? r : c;
    const auto& effect = axes_.causes_are_rows ? c : r;
    const std::string at = "cause " + cause.name + " / effect " + effect.name;
    const MarkTable::Reading mark = marks_.read(t);
    if (!mark.known) {
      errors_.at(row.line, column,
                 "mark " + model::in_quotes(t) + " at " + at +
                     " has no meaning: it is not N, S, V, R, X or * (with footnotes like R(1) or S*) and the "
                     "layout's \"marks\" do not give it one; give its meaning there (docs/csv.md \"Marks\"), "
                     "nothing is dropped");
      return;
    }
    if (sheet_.extras.struck.count({row.line, column}) || sheet_.extras.partly_struck.count({row.line, column})) {
      errors_.at(row.line, column, "mark " + model::in_quotes(t) + " at " + at +
                                       " is struck through, but neither its cause nor its effect is deleted: cemv "
                                       "cannot tell whether the intersection is");
      return;
    }
    if (mark.lower_case)
      warnings_.at(row.line, column,
                   "lower-case mark " + model::in_quotes(t) + " read as " + model::in_quotes(upper_first(t)));
    if (!mark.type) return;  // a mark of no intersection (NP)
    Intersection x;
    x.cause = cause.id;
    x.effect = effect.id;
    x.type = *mark.type;
    for (const auto& key : mark.footnotes) {
      std::string text = key;
      if (auto l = legend_.find(key); l == legend_.end()) unexplained_.insert(key);
      else if (!l->second.empty()) text += " " + l->second;
      join_to(x.note, "; ", text);
    }
    add(row.line, column, t, std::move(x));
  }

  // One intersection per cause and effect: the rows of a voting group may
  // repeat a mark (unmerged), never differ.
  void add(int line, int column, const std::string& text, Intersection x) {
    auto [it, fresh] = found_.try_emplace({x.cause, x.effect}, Found{x, line, column, text});
    if (fresh) return;
    const Found& first = it->second;
    if (first.intersection.type != x.type || first.intersection.note != x.note)
      errors_.at(line, column, "mark " + model::in_quotes(text) + " differs from " + model::in_quotes(first.text) +
                                   " in line " + std::to_string(first.line) + ", column " +
                                   std::to_string(first.column) +
                                   ": the rows of a voting group are one cause, with one mark per effect");
  }

  static std::string upper_first(const std::string& t) {
    std::string u = t;
    if (!u.empty() && u[0] >= 'a' && u[0] <= 'z') u[0] = static_cast<char>(u[0] - 'a' + 'A');
    return u.substr(0, 1);
  }

  // A grid should say "no intersection" one way. Cells that differ from the
  // grid's usual way (empty vs. a space) are reported per row: they read the same,
  // but a mixed sheet often means rows pasted from another version.
  void report_cell_styles() {
    std::size_t empty = 0, blank = 0;
    for (const auto& s : styles_) {
      if (s.style == CellStyle::Empty) ++empty;
      if (s.style == CellStyle::Blank) ++blank;
    }
    if (empty == 0 || blank == 0) return;
    CellStyle odd = blank >= empty ? CellStyle::Empty : CellStyle::Blank;
    std::string usual = odd == CellStyle::Empty ? "a space (' ')" : "an empty cell";
    std::string what = odd == CellStyle::Empty ? "empty cell" : "space-only cell";
    std::map<int, std::vector<int>> by_line;
    for (const auto& s : styles_)
      if (s.style == odd) by_line[s.line].push_back(s.column);
    for (auto& [line, cols] : by_line) {
      std::string text = (cols.size() == 1 ? what : std::to_string(cols.size()) + " " + what + "s") +
                         " where the grid otherwise uses " + usual +
                         " for no intersection; read as no intersection";
      if (cols.size() == 1) warnings_.at(line, cols.front(), text);
      else warnings_.at_columns(line, cols, text);
    }
  }

  enum class CellStyle { Empty, Blank, Missing };
  struct StyledCell {
    int line;
    int column;
    CellStyle style;
  };
  struct Found {
    Intersection intersection;
    int line, column;
    std::string text;
  };

  const Sheet& sheet_;
  const Shape& shape_;
  const GridAxes& axes_;
  const MarkTable& marks_;
  const std::map<std::string, std::string>& legend_;
  GridWarnings& warnings_;
  GridErrors& errors_;
  const std::string column_kind;
  std::map<std::pair<int, int>, Found> found_;  // by (cause, effect)
  std::vector<StyledCell> styles_;
  std::set<std::string> unexplained_;
};

}  // namespace

MarkTable::Reading MarkTable::read(const std::string& text) const {
  Reading r;
  if (auto it = layout_.find(text); it != layout_.end()) {
    r.known = true;
    r.type = it->second.type;
    if (!it->second.footnote.empty()) r.footnotes.push_back(it->second.footnote);
    return r;
  }
  const auto mark = parse_mark(text);
  if (!mark) return r;
  r.known = true;
  char letter = mark->letter;
  if (letter >= 'a' && letter <= 'z') {
    letter = static_cast<char>(letter - 'a' + 'A');
    r.lower_case = true;
  }
  r.type = type_of(letter);
  r.footnotes = mark->footnotes;
  return r;
}

std::vector<Intersection> read_intersections(const Sheet& sheet, const Shape& shape, const GridAxes& axes,
                                             const MarkTable& marks, const std::map<std::string, std::string>& legend,
                                             GridWarnings& warnings, GridErrors& errors) {
  return CellReader(sheet, shape, axes, marks, legend, warnings, errors).run();
}

}  // namespace cemv::formats::grid
