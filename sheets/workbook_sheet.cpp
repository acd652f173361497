#include "sheets/workbook_sheet.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <tuple>

#include "model/text.hpp"

namespace cemv::formats::workbook {

namespace {

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    auto lower = [](char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c + 32) : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

}  // namespace

const Cell* Sheet::find(std::size_t r, std::size_t c) const {
  auto it = std::lower_bound(cells.begin(), cells.end(), std::pair{r, c}, [](const Cell& x, std::pair<std::size_t, std::size_t> k) {
    return std::tie(x.row, x.column) < std::tie(k.first, k.second);
  });
  return it != cells.end() && it->row == r && it->column == c ? &*it : nullptr;
}

std::vector<const Cell*> Sheet::row(std::size_t r) const {
  std::vector<const Cell*> out;
  auto it = std::lower_bound(cells.begin(), cells.end(), r, [](const Cell& x, std::size_t k) { return x.row < k; });
  for (; it != cells.end() && it->row == r; ++it) out.push_back(&*it);
  return out;
}

void Sheet::put(std::size_t r, std::size_t c, std::string text, bool grey, CellKind kind) {
  if (text.empty()) return;
  cells.push_back({r, c, std::move(text), kind, grey});
}

void Sheet::sort() {
  std::stable_sort(cells.begin(), cells.end(),
                   [](const Cell& a, const Cell& b) { return std::tie(a.row, a.column) < std::tie(b.row, b.column); });
}

const Sheet* Workbook::find(std::string_view name) const {
  for (const Sheet& s : sheets)
    if (same_name(s.name, name)) return &s;
  return nullptr;
}

std::string cell_address(std::size_t row, std::size_t column) {
  std::string letters;
  for (std::size_t c = column; c > 0; c = (c - 1) / 26) letters.insert(letters.begin(), static_cast<char>('A' + (c - 1) % 26));
  return letters + std::to_string(row);
}

std::string number_text(double value) {
  if (value == 0) return "0";  // also -0
  if (std::isfinite(value) && std::trunc(value) == value && std::fabs(value) < 9007199254740992.0) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, static_cast<long long>(value));
    return std::string(buf, end);
  }
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, end);
}

Sheet& CellBudget::begin_sheet(Workbook& wb, std::string name) {
  if (wb.sheets.size() >= kMaxSheets)
    fail(nullptr, 0, 0, "more than " + std::to_string(kMaxSheets) + " sheets; a matrix workbook has 6");
  if (name.size() > 256) name.resize(256);
  wb.sheets.push_back({std::move(name), {}, {}, {}, false});
  rows_in_sheet_ = 0;
  last_row_ = 0;
  return wb.sheets.back();
}

void CellBudget::check_position(const Sheet& sheet, std::size_t row, std::size_t column) const {
  if (row == 0 || row > kMaxRowNumber)
    fail(&sheet, 0, 0, "row number " + std::to_string(row) + " is outside 1-" + std::to_string(kMaxRowNumber));
  if (column == 0 || column > kMaxColumnNumber)
    fail(&sheet, row, 0, "column number " + std::to_string(column) + " is outside 1-" + std::to_string(kMaxColumnNumber));
}

CellRange CellBudget::merge(const Sheet& sheet, std::size_t first_row, std::size_t first_column, std::size_t last_row,
                            std::size_t last_column) const {
  check_position(sheet, first_row, first_column);
  check_position(sheet, last_row, last_column);
  if (last_row < first_row || last_column < first_column)
    fail(&sheet, first_row, first_column,
         "the merged range " + cell_address(first_row, first_column) + ":" + cell_address(last_row, last_column) +
             " ends before it starts");
  return {first_row, first_column, last_row, last_column};
}

void CellBudget::add(Sheet& sheet, std::size_t row, std::size_t column, std::string_view text, CellKind kind,
                     Strike strike) {
  if (text.empty()) return;
  check_position(sheet, row, column);
  if (text.size() > kMaxCellBytes)
    fail(&sheet, row, column, "the cell holds " + std::to_string(text.size()) + " bytes of text, more than the limit of " +
                                  std::to_string(kMaxCellBytes));
  if (row != last_row_) {
    if (++rows_in_sheet_ > kMaxContentRows)
      fail(&sheet, row, column, "more than " + std::to_string(kMaxContentRows) +
                                    " rows hold something; a matrix sheet has at most 128 (6.6.3) plus headers");
    last_row_ = row;
  }
  if (++cells_ > kMaxCells)
    fail(&sheet, row, column, "more than " + std::to_string(kMaxCells) + " cells hold something; not a matrix workbook");
  if ((text_bytes_ += text.size()) > kMaxTextBytes)
    fail(&sheet, row, column, "the cells hold more than " + std::to_string(kMaxTextBytes >> 20) +
                                  " MiB of text in all; not a matrix workbook");
  sheet.cells.push_back({row, column, std::string(text), kind, false, strike});
}

void CellBudget::fail(const Sheet* sheet, std::size_t row, std::size_t column, std::string what) const {
  LoadIssue issue;
  issue.file = sheet ? file_ + ":" + sheet->name : file_;
  issue.line = row;
  issue.column = row > 0 ? std::max<std::size_t>(column, 1) : 0;
  if (row > 0 && column > 0) issue.where = cell_address(row, column);
  issue.what = std::move(what);
  throw LoadError({issue});
}

}  // namespace cemv::formats::workbook
