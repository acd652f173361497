// The intersections overview: marks `TYPE[ XooN][; NOTE]` (6.5.2) at the
// crossings of numbered cause rows and effect columns (6.6.3).
#include "sheets/workbook_overview.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>

#include "sheets/workbook_rows.hpp"
#include "sheets/workbook_tables.hpp"
#include "model/text.hpp"

namespace cemv::formats::workbook {

namespace {

const model::IntersectionType kTypes[] = {model::IntersectionType::N, model::IntersectionType::S,
                                          model::IntersectionType::V, model::IntersectionType::R,
                                          model::IntersectionType::X, model::IntersectionType::Note};

// One mark of the overview: TYPE, then optionally ` XooN`, then optionally
// `; NOTE` (the note verbatim after one blank); `R(1)` footnotes as in C&E
// grids are a note too.
struct Mark {
  model::IntersectionType type = model::IntersectionType::N;
  std::optional<int> x, n;
  std::string note;
};
std::optional<Mark> mark(const std::string& text, std::string& why) {
  std::string t = text;
  std::size_t i = t.find_first_not_of(' ');
  if (i == std::string::npos) return std::nullopt;
  Mark m;
  char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(t[i])));
  std::string types = "NSVRX*";
  if (types.find(letter) == std::string::npos) {
    why = "is no intersection type N, S, V, R, X or *";
    return std::nullopt;
  }
  m.type = kTypes[types.find(letter)];
  std::string rest = t.substr(i + 1);
  std::string tr = trimmed(rest);
  if (!tr.empty() && tr[0] == '(' && tr.back() == ')') {
    m.note = tr;
    return m;
  }
  std::size_t j = rest.find_first_not_of(' ');
  if (j != std::string::npos && std::isdigit(static_cast<unsigned char>(rest[j]))) {
    std::size_t oo = rest.find("oo", j);
    std::size_t end = rest.find_first_of(" ;", j);
    long long x = 0, n = 0;
    if (oo == std::string::npos || (end != std::string::npos && oo > end) ||
        !whole_number(rest.substr(j, oo - j), 2, 15, x) ||
        !whole_number(rest.substr(oo + 2, (end == std::string::npos ? rest.size() : end) - oo - 2), 1, 1024, n)) {
      why = "has no XooN majority after its type (X 2-15, e.g. 'N 2oo3')";
      return std::nullopt;
    }
    m.x = static_cast<int>(x);
    m.n = static_cast<int>(n);
    rest = end == std::string::npos ? "" : rest.substr(end);
  }
  j = rest.find_first_not_of(' ');
  if (j == std::string::npos) return m;
  if (rest[j] != ';') {
    why = "is not TYPE[ XooN][; NOTE] (6.5.2; e.g. 'N', 'S 2oo3', 'R; see note 4')";
    return std::nullopt;
  }
  m.note = rest.substr(j + 1);
  if (!m.note.empty() && m.note[0] == ' ') m.note.erase(0, 1);
  return m;
}

}  // namespace

std::vector<model::Intersection> read_overview(const Sheet& s, const std::set<int>& causes,
                                                    const std::set<int>& effects, CellReader& reader) {
  auto& errors = reader.errors();
  auto& warnings = reader.warnings();
  auto effect_cols = numbered_lines(s, false, kOverviewNumberRow, kOverviewFirstColumn, "effect", "Effect No.",
                                    reader.file(), errors, warnings);
  auto cause_rows = numbered_lines(s, true, 1, kOverviewFirstRow, "cause", "Cause No.", reader.file(), errors, warnings);
  std::map<int, std::size_t> seen;
  for (const auto& l : effect_cols) {
    if (!seen.emplace(l.number, l.line).second)
      reader.error(s, kOverviewNumberRow, l.line, "Effect No.", "effect " + std::to_string(l.number) + " has a column already (" +
                                                                 cell_address(kOverviewNumberRow, seen[l.number]) + ")");
    else if (!effects.count(l.number))
      reader.warn(s, kOverviewNumberRow, l.line, "Effect No.", "effect " + std::to_string(l.number) + " has no row in " +
                                                                kEffectsSheet + "; its intersections are kept for validate");
  }
  seen.clear();
  for (const auto& l : cause_rows) {
    if (!seen.emplace(l.number, l.line).second)
      reader.error(s, l.line, 1, "Cause No.", "cause " + std::to_string(l.number) + " has a row already (" +
                                              cell_address(seen[l.number], 1) + ")");
    else if (!causes.count(l.number))
      reader.warn(s, l.line, 1, "Cause No.", "cause " + std::to_string(l.number) + " has no row in " + kCausesSheet +
                                             "; its intersections are kept for validate");
  }
  std::map<std::size_t, int> effect_of;
  for (const auto& l : effect_cols) effect_of[l.line] = l.number;
  struct Placed { model::Intersection x; std::size_t row, column; std::optional<int> n; };
  std::vector<Placed> placed;
  std::vector<model::Intersection> out;
  for (const auto& l : cause_rows) {
    for (const Cell* c : s.row(l.line)) {
      auto it = effect_of.find(c->column);
      if (it == effect_of.end()) continue;  // the number and the grey name
      std::string why;
      auto m = mark(c->text, why);
      if (!m) {
        if (!why.empty()) reader.error(s, l.line, c->column, "", model::in_quotes(c->text) + " " + why);
        continue;
      }
      model::Intersection x;
      x.cause = l.number;
      x.effect = it->second;
      x.type = m->type;
      x.xoon = m->x;
      x.note = m->note;
      placed.push_back({x, l.line, c->column, m->n});
    }
  }
  // The N of XooN is the number of the effect's intersections with XooN (6.5.2).
  std::map<int, int> xoon_count;
  for (const auto& p : placed) xoon_count[p.x.effect] += p.x.xoon ? 1 : 0;
  std::sort(placed.begin(), placed.end(), [](const Placed& a, const Placed& b) {
    return std::pair{a.x.cause, a.x.effect} < std::pair{b.x.cause, b.x.effect};
  });
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Placed& p = placed[i];
    if (p.n && *p.n != xoon_count[p.x.effect])
      reader.error(s, p.row, p.column, "", std::to_string(*p.x.xoon) + "oo" + std::to_string(*p.n) + ", but effect " +
                                           std::to_string(p.x.effect) + " has " + std::to_string(xoon_count[p.x.effect]) +
                                           " intersections with XooN (6.5.2)");
    reader.remember("intersections[" + std::to_string(i) + "]", s, p.row, p.column, "");
    out.push_back(p.x);
  }
  return out;
}


}  // namespace cemv::formats::workbook
