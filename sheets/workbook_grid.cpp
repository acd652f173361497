#include "sheets/workbook_grid.hpp"

#include <algorithm>
#include <charconv>
#include <regex>

#include "sheets/csv.hpp"
#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"
#include "sheets/workbook_rows.hpp"
#include "sheets/workbook_tables.hpp"
#include "model/text.hpp"

namespace cemv::formats::workbook {

namespace {

// A C&E grid has at most 128 causes or effects across, plus label columns;
// wider sheets are refused before they are padded into CSV text.
constexpr std::size_t kMaxGridColumns = 1024;

std::size_t width_of(const Sheet& sheet) {
  std::size_t width = 0;
  for (const Cell& c : sheet.cells) width = std::max(width, c.column);
  return width;
}

// The sheet as CSV text, one record per row (row = line), so that the grid
// reader's lines and columns are the sheet's rows and columns. A line break
// inside a cell becomes a blank (as the grid reader does with one). Every row
// is as wide as the widest: a sheet has no row ends, its empty cells are empty
// fields.
std::string sheet_as_csv(const Sheet& sheet) {
  const std::size_t width = width_of(sheet);
  std::string out;
  std::size_t row = 1;
  for (std::size_t i = 0; i < sheet.cells.size();) {
    std::size_t r = sheet.cells[i].row;
    for (; row < r; ++row) out += "\n";
    std::size_t column = 1;
    std::string line;
    for (; i < sheet.cells.size() && sheet.cells[i].row == r; ++i) {
      const Cell& c = sheet.cells[i];
      for (; column < c.column; ++column) line += ",";
      std::string text = c.text;
      for (char& ch : text)
        if (ch == '\n' || ch == '\r') ch = ' ';
      line += csv_quote(text);
    }
    for (; column < width; ++column) line += ",";
    out += line + "\n";
    row = r + 1;
  }
  return out;
}

// "FILE: line L, column C: ..." of the grid reader as FILE:SHEET:L:C.
LoadIssue on_sheet(const LoadIssue& issue, const std::string& file, const Sheet& sheet) {
  std::string where = issue.where;
  if (where.rfind(file + ": ", 0) == 0) where = where.substr(file.size() + 2);
  std::size_t line = issue.line, column = issue.column;
  std::string rest;
  if (where.rfind("line ", 0) == 0) {
    const char* p = where.c_str() + 5;
    auto [e1, ec1] = std::from_chars(p, where.c_str() + where.size(), line);
    std::string_view tail(e1);
    if (tail.rfind(", column ", 0) == 0) {
      auto [e2, ec2] = std::from_chars(e1 + 9, where.c_str() + where.size(), column);
      tail = e2;
    }
    rest = std::string(tail);
    if (rest.rfind(", ", 0) == 0) rest.erase(0, 2);  // ", columns 3-12"
    if (rest.rfind(" ", 0) == 0) rest.erase(0, 1);
  } else {
    rest = where == file ? "" : where;
  }
  LoadIssue out = place(file, sheet, line, column, "", issue.what);
  if (!rest.empty()) out.where += (out.where.empty() ? "" : " ") + rest;
  return out;
}

LoadError on_sheet(const LoadError& e, const std::string& file, const Sheet& sheet) {
  std::vector<LoadIssue> issues;
  for (const auto& i : e.issues()) issues.push_back(on_sheet(i, file, sheet));
  return LoadError(issues);
}

[[noreturn]] void refuse(const std::string& file, std::string what) {
  LoadIssue issue;
  issue.file = file;
  issue.what = std::move(what);
  throw LoadError({issue});
}

std::string quoted_list(const std::vector<const Sheet*>& sheets) {
  std::string out;
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    if (i > 0) out += i + 1 == sheets.size() ? " and " : ", ";
    out += model::in_quotes(sheets[i]->name) + (sheets[i]->hidden ? " (hidden)" : "");
  }
  return out;
}

// Whether a sheet holds a C&E grid: header rows of ids above rows of marks,
// as the grid reader finds them (whether it then reads right is its own test).
bool holds_grid(const Sheet& sheet, const std::string& file) {
  if (sheet.cells.empty() || width_of(sheet) > kMaxGridColumns) return false;
  try {
    return grid::has_grid_shape(grid::read_sheet(sheet_as_csv(sheet), ',', file));
  } catch (const LoadError&) {
    return false;
  }
}

// The sheet the caller names (--sheet, or the layout's "sheet"): by its
// name in any letter case, else by its number.
const Sheet& named_sheet(const Workbook& wb, const std::string& name, const std::string& file) {
  if (const Sheet* s = wb.find(name)) return *s;
  long long n = 0;
  if (whole_number(name, 1, static_cast<long long>(wb.sheets.size()), n)) return wb.sheets[static_cast<std::size_t>(n - 1)];
  std::vector<const Sheet*> all;
  for (const Sheet& s : wb.sheets) all.push_back(&s);
  refuse(file, "no sheet " + model::in_quotes(name) + " in the workbook; its sheets are " + quoted_list(all) +
                   " (or give a number 1-" + std::to_string(wb.sheets.size()) + ")");
}

// The footnotes of a remarks sheet: rows whose first text is a footnote key
// (`*`, `**`, `(1)`), the text after it in the row.
std::map<std::string, std::string> read_remarks(const Sheet& sheet) {
  static const std::regex key(R"(^(\(\s*\d+\s*\)|\*{1,3})$)");
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < sheet.cells.size();) {
    const std::size_t r = sheet.cells[i].row;
    std::string first(csv_text::trim(sheet.cells[i].text)), text;
    for (++i; i < sheet.cells.size() && sheet.cells[i].row == r; ++i)
      csv_text::join_to(text, " ", csv_text::one_line(csv_text::trim(sheet.cells[i].text)));
    std::smatch m;
    if (!std::regex_match(first, m, key)) continue;
    first.erase(std::remove(first.begin(), first.end(), ' '), first.end());
    out.emplace(first, text);
  }
  return out;
}

// What the workbook says of the sheet's cells besides their texts.
grid::SheetExtras extras_of(const Sheet& sheet) {
  grid::SheetExtras x;
  auto at = [](std::size_t r, std::size_t c) { return std::pair<int, int>(static_cast<int>(r), static_cast<int>(c)); };
  for (const Cell& c : sheet.cells) {
    if (c.strike == Strike::Whole) x.struck.insert(at(c.row, c.column));
    if (c.strike == Strike::Part) x.partly_struck.insert(at(c.row, c.column));
  }
  for (const CellRange& m : sheet.merges)
    x.merges.emplace(at(m.first_row, m.first_column),
                     grid::Range{static_cast<int>(m.first_row), static_cast<int>(m.first_column),
                                 static_cast<int>(std::min(m.last_row, kMaxRowNumber)),
                                 static_cast<int>(std::min(m.last_column, kMaxColumnNumber))});
  return x;
}

// Which sheet holds the matrix, and why (the start of the summary).
const Sheet& choose_sheet(const Workbook& wb, const std::string& file, const WorkbookImportOptions& options,
                          std::string& why) {
  const std::string layout_sheet = options.sheet_layout ? options.sheet_layout->sheet : "";
  if (!options.sheet.empty() && !layout_sheet.empty() && wb.find(options.sheet) != wb.find(layout_sheet))
    refuse(file, "--sheet " + model::in_quotes(options.sheet) + " and the layout's sheet " +
                     model::in_quotes(layout_sheet) + " differ; give one");
  if (!options.sheet.empty() || !layout_sheet.empty()) {
    const Sheet& s = named_sheet(wb, options.sheet.empty() ? layout_sheet : options.sheet, file);
    why = "sheet " + model::in_quotes(s.name) + (options.sheet.empty() ? " (the layout's)" : " (as --sheet says)");
    return s;
  }
  std::vector<const Sheet*> with_content, grids, others;
  for (const Sheet& s : wb.sheets)
    if (!s.cells.empty()) with_content.push_back(&s);
  if (with_content.empty()) refuse(file, "the workbook has no sheet with content");
  if (with_content.size() == 1) {  // the one sheet there is: read it, and its refusal says why it is no grid
    why = "no sheet '" + std::string(kCausesSheet) + "': sheet " + model::in_quotes(with_content[0]->name);
    return *with_content[0];
  }
  for (const Sheet* s : with_content) (holds_grid(*s, file) ? grids : others).push_back(s);
  if (grids.size() > 1)
    refuse(file, "the workbook holds C&E grids on " + std::to_string(grids.size()) + " sheets, " + quoted_list(grids) +
                     ": name the matrix with --sheet NAME (or the layout's \"sheet\")");
  if (grids.empty())
    refuse(file, "no sheet holds a C&E grid (header rows of ids above rows of marks N, S, V, R, X or *): " +
                     quoted_list(with_content) + "; name the matrix sheet with --sheet to see why it is not read");
  why = "sheet " + model::in_quotes(grids[0]->name) + " (the one sheet with a grid; " + quoted_list(others) +
        (others.size() == 1 ? " holds" : " hold") + " none)";
  return *grids[0];
}

}  // namespace

WorkbookImportResult import_grid_workbook(const Workbook& wb, const std::string& file,
                                          const WorkbookImportOptions& options) {
  std::string why;
  const Sheet& sheet = choose_sheet(wb, file, options, why);
  const std::size_t width = width_of(sheet);
  if (width > kMaxGridColumns) {
    std::size_t row = 0;
    for (const Cell& c : sheet.cells)
      if (c.column == width) row = c.row;
    throw LoadError({place(file, sheet, row, width, "",
                           "the sheet is " + std::to_string(width) + " columns wide; a C&E grid has at most " +
                               std::to_string(kMaxGridColumns) + " (128 causes or effects and their labels)")});
  }
  CsvImportOptions csv;
  csv.layout = CsvLayoutKind::Grid;
  csv.separator = ',';
  csv.sheet_layout = options.sheet_layout;
  csv.orientation = options.orientation;
  csv.parameter_trip_sides = options.parameter_trip_sides;
  grid::SheetExtras extras = extras_of(sheet);
  const std::string remarks = options.sheet_layout ? options.sheet_layout->remarks_sheet : "";
  if (!remarks.empty()) {
    const Sheet& r = named_sheet(wb, remarks, file);
    extras.remarks = read_remarks(r);
    extras.remarks_place = "sheet " + model::in_quotes(r.name);
  }
  WorkbookImportResult out;
  out.grid = true;
  try {
    CsvImportResult r = grid::import_grid(sheet_as_csv(sheet), file, csv, extras);
    out.matrix = std::move(r.matrix);
    for (const auto& w : r.warnings) out.warnings.push_back(on_sheet(w, file, sheet));
    out.summary = why + " read as a C&E grid; " + r.summary;
    if (!remarks.empty())
      out.summary += "; footnotes from " + extras.remarks_place + " (" + std::to_string(extras.remarks.size()) + ")";
    r.layout_used.sheet = sheet.name;
    out.layout_used = std::move(r.layout_used);
  } catch (const LoadError& e) {
    throw on_sheet(e, file, sheet);
  }
  return out;
}

}  // namespace cemv::formats::workbook
