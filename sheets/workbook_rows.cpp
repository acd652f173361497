#include "sheets/workbook_rows.hpp"

#include <charconv>

#include "model/text.hpp"

namespace cemv::formats::workbook {

LoadIssue place(const std::string& file, const Sheet& sheet, std::size_t row, std::size_t column,
                const std::string& header, std::string what) {
  LoadIssue issue;
  issue.file = file + ":" + sheet.name;
  issue.line = row;
  issue.column = row > 0 ? column : 0;
  if (row > 0 && column > 0) issue.where = cell_address(row, column) + (header.empty() ? "" : " (" + header + ")");
  issue.what = std::move(what);
  return issue;
}

bool whole_number(const std::string& text, long long min, long long max, long long& out) {
  long long v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || v < min || v > max) return false;
  out = v;
  return true;
}

std::vector<NumberedLine> numbered_lines(const Sheet& sheet, bool rows, std::size_t fixed, std::size_t first,
                                         const std::string& kind, const std::string& header, const std::string& file,
                                         std::vector<LoadIssue>& errors, std::vector<LoadIssue>& warnings,
                                         std::size_t limit) {
  auto at = [&](std::size_t line) { return rows ? sheet.find(line, fixed) : sheet.find(fixed, line); };
  auto issue = [&](std::size_t line, std::string what) {
    return rows ? place(file, sheet, line, fixed, header, std::move(what))
                : place(file, sheet, fixed, line, header, std::move(what));
  };
  std::vector<NumberedLine> out;
  std::size_t line = first;
  for (;; ++line) {
    const Cell* c = at(line);
    if (!c) break;
    long long n = 0;
    if (!whole_number(c->text, 1, 128, n)) {
      errors.push_back(issue(line, kind + " number " + model::in_quotes(c->text) + " is not a whole number 1-128"));
      continue;
    }
    if (out.size() == limit) {
      warnings.push_back(issue(line, "not imported: at most " + std::to_string(limit) + " " + kind +
                                         "s are imported (6.6.3); this and the following numbered " +
                                         (rows ? "rows" : "columns") + " are left out"));
      while (at(line + 1)) ++line;
      ++line;
      break;
    }
    out.push_back({line, static_cast<int>(n)});
  }
  // 6.6.3: the import ends at the first empty number cell; say what it leaves
  // (the line of the empty cell itself may hold the rest of an element).
  const std::size_t end = line;
  std::size_t later = 0;
  for (const Cell& c : sheet.cells) {
    std::size_t l = rows ? c.row : c.column;
    bool in_table = rows || c.row >= fixed;
    if (l >= end && in_table && (later == 0 || l < later)) later = l;
  }
  if (later)
    warnings.push_back(issue(later, "not imported: the import of this table ends at the empty " + kind +
                                        " number cell " + (rows ? cell_address(end, fixed) : cell_address(fixed, end)) +
                                        " (6.6.3); this " + (rows ? "row" : "column") + " and any after it are left out"));
  return out;
}

}  // namespace cemv::formats::workbook
