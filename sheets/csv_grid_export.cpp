// The matrix as a C&E grid (docs/csv.md "Grid export"): the sheet an engineer
// reviews, in either orientation. It holds what a grid can hold (ids,
// descriptions, the intersection types of 6.5.2 and their notes as footnotes);
// reading it back gives the same intersections.
#include <map>
#include <optional>
#include <regex>

#include "sheets/csv_grid.hpp"
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

// Intersection notes as footnotes `(n)` explained in legend rows. A note the
// grid import made ("(1) Override with cabinet switch": the footnote and its
// legend) keeps its number and its text, so a grid read and written again is
// the same sheet; other notes get the next free numbers.
class Footnotes {
 public:
  explicit Footnotes(const model::Matrix& m) {
    static const std::regex imported(R"(^\((\d{1,6})\)(?: (.*))?$)");
    std::vector<const std::string*> others;
    for (const auto& x : m.intersections) {
      if (x.note.empty() || number_.count(x.note)) continue;
      std::smatch mt;
      if (std::regex_match(x.note, mt, imported) && !legend_.count(std::stoi(mt[1].str()))) {
        const int n = std::stoi(mt[1].str());
        number_[x.note] = n;
        legend_[n] = mt[2].str();
      } else {
        others.push_back(&x.note);
      }
    }
    for (const std::string* note : others) {
      if (number_.count(*note)) continue;
      const int n = legend_.empty() ? 1 : legend_.rbegin()->first + 1;
      number_[*note] = n;
      legend_[n] = *note;
    }
  }
  int number_of(const std::string& note) const { return number_.at(note); }
  // An empty row, then `(n),text` per footnote that has a text.
  void write_legend(std::string& out) const {
    bool first = true;
    for (const auto& [n, text] : legend_) {
      if (text.empty()) continue;  // a bare (n), as the sheet had it
      if (first) out += "\r\n";
      first = false;
      write_row(out, {"(" + std::to_string(n) + ")", text});
    }
  }

 private:
  std::map<std::string, int> number_;
  std::map<int, std::string> legend_;
};

}  // namespace

std::string export_csv_grid(const model::Matrix& m, CsvOrientation orientation) {
  std::vector<Header> causes, effects;
  for (const auto& c : m.causes) causes.push_back({c.id, sheet_id(c.name, c.note, c.id, "C"), c.description});
  for (const auto& e : m.effects) effects.push_back({e.id, sheet_id(e.name, e.note, e.id, "E"), e.description});

  const Footnotes footnotes(m);
  std::map<std::pair<int, int>, std::string> cell;  // (cause, effect) -> mark
  for (const auto& x : m.intersections) {
    std::string mark = model::to_string(x.type);
    if (!x.note.empty()) mark += "(" + std::to_string(footnotes.number_of(x.note)) + ")";
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
  footnotes.write_legend(out);
  return out;
}

}  // namespace cemv::formats
