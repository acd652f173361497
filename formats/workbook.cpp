// Workbook import and export (workbook.hpp): the file format told by the
// content, the cells read under the limits, then either the six tables or, on
// a workbook without them, a C&E grid on its first sheet through the CSV grid
// reader (so that a grid reads alike from CSV and from a spreadsheet).
#include "formats/workbook.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "formats/csv.hpp"
#include "formats/workbook_files.hpp"
#include "formats/workbook_rows.hpp"
#include "formats/workbook_tables.hpp"

namespace cemv::formats {

using namespace workbook;

namespace {

// The first sheet as CSV text, one record per row (row = line), so that the
// grid reader's lines and columns are the sheet's rows and columns. A line
// break inside a cell becomes a blank (as the grid reader does with one).
// Every row is as wide as the widest: a sheet has no row ends, its empty
// cells are empty fields.
std::string sheet_as_csv(const Sheet& sheet) {
  std::size_t width = 0;
  for (const Cell& c : sheet.cells) width = std::max(width, c.column);
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

// A C&E grid has at most 128 causes or effects across, plus label columns;
// wider sheets are refused before they are padded into CSV text.
constexpr std::size_t kMaxGridColumns = 1024;

WorkbookImportResult import_grid(const Sheet& sheet, const std::string& file) {
  std::size_t width = 0;
  for (const Cell& c : sheet.cells) width = std::max(width, c.column);
  if (width > kMaxGridColumns) {
    std::size_t row = 0;
    for (const Cell& c : sheet.cells)
      if (c.column == width) row = c.row;
    throw LoadError({place(file, sheet, row, width, "",
                           "the sheet is " + std::to_string(width) + " columns wide; a C&E grid has at most " +
                               std::to_string(kMaxGridColumns) + " (128 causes or effects and their labels)")});
  }
  CsvImportOptions options;
  options.layout = CsvLayoutKind::Grid;
  options.separator = ',';
  WorkbookImportResult out;
  out.grid = true;
  try {
    CsvImportResult r = import_csv(sheet_as_csv(sheet), file, options);
    out.matrix = std::move(r.matrix);
    for (const auto& w : r.warnings) out.warnings.push_back(on_sheet(w, file, sheet));
    out.summary = "no sheet '" + std::string(kCausesSheet) + "': sheet '" + sheet.name + "' read as a C&E grid; " + r.summary;
  } catch (const LoadError& e) {
    std::vector<LoadIssue> issues;
    for (const auto& i : e.issues()) issues.push_back(on_sheet(i, file, sheet));
    throw LoadError(issues);
  }
  return out;
}

}  // namespace

std::optional<WorkbookFormat> workbook_format_of(std::string_view file_name) {
  auto dot = file_name.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string ext(file_name.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "ods") return WorkbookFormat::Ods;
  if (ext == "xlsx") return WorkbookFormat::Xlsx;
  return std::nullopt;
}

WorkbookImportResult import_workbook(std::string_view bytes, const std::string& file_name) {
  ZipReader zip(bytes, file_name);
  CellBudget budget(file_name);
  Workbook wb;
  if (zip.has("content.xml") || zip.has("mimetype"))
    wb = read_ods(zip, budget);
  else if (zip.has("[Content_Types].xml") || zip.has("_rels/.rels") || zip.has("xl/workbook.xml"))
    wb = read_xlsx(zip, budget);
  else
    zip.fail("not a workbook: the zip archive holds neither an OpenDocument spreadsheet (content.xml) nor an "
             "Office Open XML one ([Content_Types].xml)");
  for (Sheet& s : wb.sheets) s.sort();
  if (has_tables(wb)) {
    TablesImport t = workbook_to_matrix(wb, file_name);
    return {std::move(t.matrix), std::move(t.warnings), std::move(t.summary)};
  }
  for (const Sheet& s : wb.sheets)
    if (!s.cells.empty()) return import_grid(s, file_name);
  LoadIssue issue;
  issue.file = file_name;
  issue.what = "the workbook has no sheet with content";
  throw LoadError({issue});
}

model::Matrix parse_workbook(std::string_view bytes, std::string_view file_name) {
  return import_workbook(bytes, std::string(file_name)).matrix;
}

std::string export_workbook(const model::Matrix& m, WorkbookFormat format) {
  Workbook wb = matrix_to_workbook(m);
  return format == WorkbookFormat::Ods ? write_ods(wb) : write_xlsx(wb);
}

}  // namespace cemv::formats
