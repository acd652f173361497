// A workbook that holds a C&E grid rather than the six tables (internal to
// formats/, docs/workbook.md "Vendor C&E workbooks"): which sheet it is, and
// that sheet read through the CSV grid reader with what the workbook adds
// (merged ranges, struck-through cells, the footnotes of a remarks sheet).
#pragma once

#include <string>

#include "sheets/workbook.hpp"
#include "sheets/workbook_sheet.hpp"

namespace cemv::formats::workbook {

WorkbookImportResult import_grid_workbook(const Workbook& wb, const std::string& file,
                                          const WorkbookImportOptions& options);

}  // namespace cemv::formats::workbook
