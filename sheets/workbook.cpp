// Workbook import and export (workbook.hpp): the file format told by the
// content, the cells read under the limits, then either the six tables or, on
// a workbook without them, a C&E grid on one of its sheets through the CSV
// grid reader (workbook_grid.cpp: a grid reads alike from CSV and from a
// spreadsheet).
#include "sheets/workbook.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "sheets/workbook_files.hpp"
#include "sheets/workbook_grid.hpp"
#include "sheets/workbook_rows.hpp"
#include "sheets/workbook_tables.hpp"

namespace cemv::formats {

using namespace workbook;


std::optional<WorkbookFormat> workbook_format_of(std::string_view file_name) {
  auto dot = file_name.rfind('.');
  if (dot == std::string_view::npos) return std::nullopt;
  std::string ext(file_name.substr(dot + 1));
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "ods") return WorkbookFormat::Ods;
  if (ext == "xlsx") return WorkbookFormat::Xlsx;
  return std::nullopt;
}

WorkbookImportResult import_workbook(std::string_view bytes, const std::string& file_name,
                                     const WorkbookImportOptions& options) {
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
    if (!options.sheet.empty() || options.sheet_layout || options.orientation != CsvOrientation::Auto) {
      LoadIssue issue;
      issue.file = file_name;
      issue.what = "the workbook holds the six tables of 6.6.2 (sheet '" + std::string(kCausesSheet) +
                   "'), which say where everything is; a sheet, an orientation or a layout description is for a C&E grid";
      throw LoadError({issue});
    }
    TablesImport t = workbook_to_matrix(wb, file_name);
    return {std::move(t.matrix), std::move(t.warnings), std::move(t.summary), std::nullopt};
  }
  return import_grid_workbook(wb, file_name, options);
}

model::Matrix parse_workbook(std::string_view bytes, std::string_view file_name) {
  return import_workbook(bytes, std::string(file_name)).matrix;
}

std::string export_workbook(const model::Matrix& m, WorkbookFormat format) {
  Workbook wb = matrix_to_workbook(m);
  return format == WorkbookFormat::Ods ? write_ods(wb) : write_xlsx(wb);
}

}  // namespace cemv::formats
