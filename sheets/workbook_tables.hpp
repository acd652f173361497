// The six tables of a Safety Matrix workbook (6.6.2), internal to formats/:
// the matrix as sheets of cells and back. docs/workbook.md gives every column
// with its meaning; the column headers here are the contract.
#pragma once

#include <string>
#include <vector>

#include "formats/diagnostics.hpp"
#include "sheets/workbook_sheet.hpp"
#include "model/matrix.hpp"

namespace cemv::formats::workbook {

// The sheets, in the order of 6.6.2.
inline constexpr const char* kPropertiesSheet = "Matrix properties";
inline constexpr const char* kAlarmSheet = "Alarm profiles";
inline constexpr const char* kCausesSheet = "Causes configuration";
inline constexpr const char* kOverviewSheet = "Intersections overview";
inline constexpr const char* kEffectsSheet = "Effects configuration";
inline constexpr const char* kLegendSheet = "Legend";

// Matrix properties: one property per row, its label in column A.
inline constexpr const char* kPropName = "Name";
inline constexpr const char* kPropTitle = "Title";
inline constexpr const char* kPropCycle = "Cycle (ms)";
inline constexpr const char* kPropWatchdog = "Watchdog (ms)";
inline constexpr const char* kPropSecureWrite = "Secure write enable tag";
inline constexpr const char* kPropGdmEnable = "Group deactivation enable tag";
inline constexpr const char* kPropGdmSet = "Group deactivation set tag";
inline constexpr const char* kPropSifGroup = "SIF group";  // "SIF group 3"

// The header row (row 1) of the causes and effects tables; the columns are
// found by these headers, in any order. The Options column is information only.
std::vector<std::string> cause_headers();
std::vector<std::string> effect_headers();
inline constexpr const char* kOptionsHeader = "Options";
std::string tag_header(int k, const char* field = "");  // "Tag 2", "Tag 2 ETT"
inline constexpr const char* kTagEtt = " ETT";
inline constexpr const char* kTagSoftBypass = " soft bypass allowed";

// Intersections overview: effect names (grey) in row 1, effect numbers in row
// 2 from column C, cause numbers in column A from row 3, cause names (grey) in
// column B; a mark is `TYPE[ XooN][; NOTE]` (6.5.2).
inline constexpr std::size_t kOverviewNumberRow = 2;
inline constexpr std::size_t kOverviewFirstColumn = 3;
inline constexpr std::size_t kOverviewFirstRow = 3;

Workbook matrix_to_workbook(const model::Matrix& m);

struct TablesImport {
  model::Matrix matrix;
  std::vector<LoadIssue> warnings;
  std::string summary;
};

// Whether a workbook is one of the six tables (it has the causes table).
bool has_tables(const Workbook& wb);

// Reads the six tables (Alarm profiles and Legend are information only and may
// be missing). Throws LoadError with every problem at FILE:SHEET:ROW:COLUMN;
// the matrix has passed the JSON loader's checks.
TablesImport workbook_to_matrix(const Workbook& wb, const std::string& file);

// The options of a cause or effect as the Safety Matrix abbreviates them in its
// Matrix view and Legend (6.2.x "Show options"): information only.
std::string cause_options(const model::Cause& c);
std::string effect_options(const model::Effect& e);

}  // namespace cemv::formats::workbook
