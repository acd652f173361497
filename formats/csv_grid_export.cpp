// The matrix as a C&E grid (docs/csv.md "Grid export"): the sheet an engineer
// reviews, in either orientation. It holds what a grid can hold (ids,
// descriptions, the intersection types of 6.5.2 and their notes as footnotes);
// reading it back gives the same intersections.
#include <map>
#include <optional>

#include "formats/csv_grid.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

namespace {

// The id written into the grid: one that ends in the element's number, so that
// the import numbers it the same (docs/csv.md "Numbers"). The id the element
// was read from (its note says "sheet id: TMA-D-40") when it still does, else
// the name when it does, else the name with the number appended.
std::string sheet_id(const std::string& name, const std::string& note, int id, const char* letter) {
  static const std::string key = "sheet id: ";
  if (note.rfind(key, 0) == 0) {
    const std::string written = note.substr(key.size(), note.find(';') - key.size());
    if (grid::trailing_number(written) == id) return written;
  }
  if (grid::trailing_number(name) == id) return name;
  return (name.empty() ? std::string(letter) : name) + "-" + std::to_string(id);
}

struct Header {
  int id;
  std::string sheet_id;
  std::string description;
};

void write_row(std::string& out, const std::vector<std::string>& fields) {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    out += csv_quote(fields[i], ',');
  }
  out += "\r\n";
}

}  // namespace

std::string export_csv_grid(const model::Matrix& m, CsvOrientation orientation) {
  std::vector<Header> causes, effects;
  for (const auto& c : m.causes) causes.push_back({c.id, sheet_id(c.name, c.note, c.id, "C"), c.description});
  for (const auto& e : m.effects) effects.push_back({e.id, sheet_id(e.name, e.note, e.id, "E"), e.description});

  // Intersection notes become footnotes (n) explained in legend rows, one
  // number per distinct note in the order the notes first appear.
  std::map<std::string, int> footnote;
  std::vector<std::string> legend;
  std::map<std::pair<int, int>, std::string> cell;  // (cause, effect) -> mark
  for (const auto& x : m.intersections) {
    std::string mark = model::to_string(x.type);
    if (!x.note.empty()) {
      auto [it, fresh] = footnote.emplace(x.note, static_cast<int>(legend.size() + 1));
      if (fresh) legend.push_back(x.note);
      mark += "(" + std::to_string(it->second) + ")";
    }
    cell[{x.cause, x.effect}] = mark;
  }

  const bool causes_are_rows = orientation != CsvOrientation::EffectsAsRows;
  const auto& rows = causes_are_rows ? causes : effects;
  const auto& columns = causes_are_rows ? effects : causes;
  // The corner labels say which axis is which (docs/csv.md "Orientation").
  std::vector<std::string> descriptions{"", causes_are_rows ? "Effects" : "Causes"};
  std::vector<std::string> ids{causes_are_rows ? "Causes" : "Effects", ""};
  for (const auto& c : columns) {
    descriptions.push_back(c.description);
    ids.push_back(c.sheet_id);
  }
  std::string out;
  write_row(out, descriptions);
  write_row(out, ids);
  for (const auto& r : rows) {
    std::vector<std::string> fields{r.description, r.sheet_id};
    for (const auto& c : columns) {
      auto it = cell.find(causes_are_rows ? std::pair{r.id, c.id} : std::pair{c.id, r.id});
      fields.push_back(it == cell.end() ? "" : it->second);
    }
    write_row(out, fields);
  }
  if (!legend.empty()) out += "\r\n";
  for (std::size_t k = 0; k < legend.size(); ++k)
    write_row(out, {"(" + std::to_string(k + 1) + ")", legend[k]});
  return out;
}

}  // namespace cemv::formats
