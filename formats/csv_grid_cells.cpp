// The cells of a C&E grid (docs/csv.md "Shape", "Warnings"): one intersection
// per mark (6.5.2), its footnotes as the intersection's note; anything else in a
// cell is a stray value, reported and never guessed.
#include <algorithm>
#include <map>
#include <set>

#include "formats/csv_grid.hpp"
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
  CellReader(const Sheet& sheet, const Shape& shape, const GridAxes& axes,
             const std::map<std::string, std::string>& legend, GridWarnings& warnings)
      : sheet_(sheet), shape_(shape), axes_(axes), legend_(legend), warnings_(warnings),
        column_kind(axes.causes_are_rows ? "effect" : "cause") {}

  // Reads one intersection cell: a type letter, optionally followed by footnote
  // references `(n)`. Anything else is a stray value: reported, never guessed.
  std::vector<Intersection> run() {
    std::set<std::string> unexplained;
    const std::size_t c0 = shape_.first_data_column, end = shape_.column_end;
    for (std::size_t k = 0; k < axes_.rows.size(); ++k) {
      const CsvRecord& row = sheet_.rows[axes_.sheet_rows[k]];
      for (std::size_t i = c0; i < std::max(row.fields.size(), end); ++i) {
        int column = sheet_.column_of(i);
        if (i >= row.fields.size()) {
          styles_.push_back({row.line, column, CellStyle::Missing});
          continue;
        }
        const std::string& raw = row.fields[i].text;
        std::string t(trim(raw));
        if (i >= end) {
          if (!t.empty())
            warnings_.at(row.line, column,
                 "stray value " + model::in_quotes(t) + " right of the last " + column_kind + " column; ignored");
          continue;
        }
        if (t.empty()) {
          styles_.push_back({row.line, column, raw.empty() ? CellStyle::Empty : CellStyle::Blank});
          continue;
        }
        const auto& across = axes_.columns[i - c0];
        const auto& cause = axes_.causes_are_rows ? axes_.rows[k] : across;
        const auto& effect = axes_.causes_are_rows ? across : axes_.rows[k];
        const auto mark = parse_mark(t);
        if (!mark) {
          warnings_.at(row.line, column,
               "stray value " + model::in_quotes(t) + " at cause " + cause.name + " / effect " + effect.name +
                   " is not N, S, V, R, X or * (with optional footnotes like R(1)); ignored: no "
                   "intersection imported");
          continue;
        }
        char letter = mark->letter;
        if (letter >= 'a' && letter <= 'z') {
          letter = static_cast<char>(letter - 'a' + 'A');
          warnings_.at(row.line, column,
               "lower-case mark " + model::in_quotes(t) + " read as " + model::in_quotes(std::string(1, letter)));
        }
        Intersection x;
        x.cause = cause.id;
        x.effect = effect.id;
        x.type = type_of(letter);
        for (const auto& number : mark->footnotes) {
          std::string key(1, '(');
          key += number;
          key += ')';
          std::string text = key;
          if (auto l = legend_.find(key); l == legend_.end()) unexplained.insert(key);
          else if (!l->second.empty()) text += " " + l->second;
          join_to(x.note, "; ", text);
        }
        intersections_.push_back(std::move(x));
      }
      if (row.fields.size() < end) {
        const int last = sheet_.column_of(row.fields.size() - 1);
        warnings_.at(row.line, last,
             "row ends after column " + std::to_string(last) + " of " +
                 std::to_string(sheet_.column_of(end - 1)) + "; the missing cells read as no intersection");
      }
    }
    report_cell_styles();
    if (!unexplained.empty()) {
      std::string list;
      for (const auto& k : unexplained) join_to(list, ", ", k);
      warnings_.at(sheet_.rows[axes_.sheet_rows.front()].line, 0,
           "footnotes " + list +
               (legend_.empty() ? " are referenced but the file has no legend rows"
                                : " have no legend entry") +
               "; kept as notes on their intersections");
    }
    return std::move(intersections_);
  }

 private:
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

  const Sheet& sheet_;
  const Shape& shape_;
  const GridAxes& axes_;
  const std::map<std::string, std::string>& legend_;
  GridWarnings& warnings_;
  const std::string column_kind;
  std::vector<Intersection> intersections_;
  std::vector<StyledCell> styles_;
};

}  // namespace

std::vector<Intersection> read_intersections(const Sheet& sheet, const Shape& shape, const GridAxes& axes,
                                             const std::map<std::string, std::string>& legend,
                                             GridWarnings& warnings) {
  return CellReader(sheet, shape, axes, legend, warnings).run();
}

}  // namespace cemv::formats::grid
