// The numbers and names of the elements of a C&E grid (docs/csv.md "Numbers",
// "Sanitizing ids", "Duplicated id"): the sheet's own numbering where it has
// one, so that evidence refers to the numbers the engineer sees.
#include <algorithm>
#include <map>
#include <set>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::grid {

using namespace csv_text;
using model::kMaxTagNameLength;
using model::tag_key;

namespace {

// An element whose number breaks the ascending order of the sheet: the ones
// outside a longest ascending run of numbers (so one moved column is reported,
// not every column after it).
void report_out_of_order(const std::vector<SheetElement>& elements,
                         const std::map<int, std::size_t>& first_by_number, const char* kind,
                         GridWarnings& warnings) {
  std::vector<std::size_t> order;  // first occurrences, in sheet order
  for (std::size_t i = 0; i < elements.size(); ++i) {
    auto it = first_by_number.find(elements[i].id);
    if (it != first_by_number.end() && it->second == i) order.push_back(i);
  }
  std::vector<std::size_t> tails;   // positions in `order`
  std::vector<long> prev(order.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) {
    int key = elements[order[k]].id;
    auto it = std::lower_bound(tails.begin(), tails.end(), key, [&](std::size_t t, int v) {
      return elements[order[t]].id < v;
    });
    if (it != tails.begin()) prev[k] = static_cast<long>(*(it - 1));
    if (it == tails.end()) tails.push_back(k);
    else *it = k;
  }
  std::vector<bool> in_run(order.size(), false);
  for (long k = tails.empty() ? -1 : static_cast<long>(tails.back()); k >= 0; k = prev[static_cast<std::size_t>(k)])
    in_run[static_cast<std::size_t>(k)] = true;
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (in_run[k]) continue;
    const auto& e = elements[order[k]];
    std::string place;
    if (order[k] > 0) place += "after " + model::in_quotes(elements[order[k] - 1].sheet_id);
    if (order[k] + 1 < elements.size())
      join_to(place, ", ", "before " + model::in_quotes(elements[order[k] + 1].sheet_id));
    warnings.at(e.line, e.column,
         std::string(kind) + " id " + model::in_quotes(e.sheet_id) + " out of order (" + place +
             "); it keeps its number (" + kind + " " + std::to_string(e.id) +
             ") and the matrix lists " + kind + "s by number");
  }
}

}  // namespace

// Numeric ids follow the sheet's own numbering (`TMA-D-40` -> 40) when every id
// ends in a number within the limits of 3.4, so evidence refers to the same
// numbers as the sheet; otherwise elements are numbered by position. A repeated
// id keeps both elements: the later one gets the next free number and the
// suffix _2, _3, ... (merging would silently drop one row's intersections).
void number_elements(std::vector<SheetElement>& elements, const char* kind, const char* prefix,
                   int limit, GridWarnings& warnings) {
  std::vector<std::optional<int>> nums;
  bool by_sheet = true;
  for (const auto& e : elements) {
    nums.push_back(e.sheet_id.empty() ? std::nullopt : trailing_number(e.sheet_id));
    by_sheet = by_sheet && nums.back() && *nums.back() >= 1 && *nums.back() <= limit;
  }
  std::set<int> used;
  int next_free = 0;
  if (by_sheet) {
    for (auto& n : nums) next_free = std::max(next_free, *n);
    ++next_free;
    std::set<int> seen;
    int extra = 0;
    for (auto& n : nums)
      if (!seen.insert(*n).second) ++extra;
    if (next_free + extra - 1 > limit) by_sheet = false;
  }
  if (!by_sheet && !elements.empty())
    warnings.at(elements.front().line, elements.front().column,
         std::string(kind) + " ids do not all end in a number 1-" + std::to_string(limit) +
             "; " + kind + "s are numbered by their position in the sheet");

  std::map<std::string, std::size_t> first_by_id;  // sheet id -> index of first element
  std::map<int, std::size_t> first_by_number;      // sheet number -> index of first element
  std::set<std::string> names;                     // tag_key() of each, for uniqueness
  for (std::size_t i = 0; i < elements.size(); ++i) {
    auto& e = elements[i];
    auto [first, fresh] = first_by_id.emplace(e.sheet_id, i);
    bool duplicate = !fresh && !e.sheet_id.empty();
    if (by_sheet) {
      auto [same_number, unused] = first_by_number.emplace(*nums[i], i);
      if (unused) {
        e.id = *nums[i];
      } else {
        e.id = next_free++;
        if (!duplicate)
          warnings.at(e.line, e.column,
               std::string(kind) + " id " + model::in_quotes(e.sheet_id) + " ends in the same number as " +
                   model::in_quotes(elements[same_number->second].sheet_id) + "; numbered " + std::to_string(e.id));
      }
    } else {
      e.id = static_cast<int>(i + 1);
    }
    std::string base = sanitize_identifier(e.sheet_id, kMaxTagNameLength - 3);
    if (base.empty())
      base = e.sheet_id.empty() ? e.unnamed : std::string(prefix) + "_" + std::to_string(e.id);
    else if (base[0] >= '0' && base[0] <= '9')
      base = std::string(prefix) + "_" + base;  // a leading letter keeps names identifier-like
    base = sanitize_identifier(base, kMaxTagNameLength - 3);
    std::string name = base;
    for (int k = 2; names.count(tag_key(name)); ++k) name = base + "_" + std::to_string(k);
    names.insert(tag_key(name));
    e.name = name;
    if (e.tags.empty()) e.tags.push_back(name);
    std::string origin = "sheet id: " + (e.sheet_id.empty() ? std::string("(none)") : e.sheet_id);
    e.note = e.note.empty() ? origin : origin + "; " + e.note;
    if (duplicate) {
      const auto& f = elements[first->second];
      warnings.at(e.line, e.column,
           std::string(kind) + " id " + model::in_quotes(e.sheet_id) + " repeats line " + std::to_string(f.line) +
               " (" + model::in_quotes(f.text) + "); both rows are kept as separate " + kind + "s: line " +
               std::to_string(f.line) + " is " + kind + " " + std::to_string(f.id) + " " + f.name +
               ", this one " + kind + " " + std::to_string(e.id) + " " + e.name +
               " (not merged: merging would lose one row's intersections; give it its own id "
               "in the sheet)");
      e.note += "; duplicate of the id of line " + std::to_string(f.line);
    }
  }
  if (by_sheet) report_out_of_order(elements, first_by_number, kind, warnings);
}

}  // namespace cemv::formats::grid

namespace cemv::formats {

// The identifier rule of the grid's ids and names (sheets/csv.hpp).
std::string sanitize_identifier(std::string_view text, std::size_t max_length) {
  std::string out;
  for (char c : text) {
    bool keep = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
    char ch = keep ? c : '_';
    if (ch == '_' && (out.empty() || out.back() == '_')) continue;
    out += ch;
  }
  if (out.size() > max_length) out.resize(max_length);
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

}  // namespace cemv::formats
