// The cells of a workbook as ODS and XLSX share them (internal to formats/):
// named sheets of sparse, non-empty cells, each a text and whether it is
// information only (written grey, 6.6.2). The two file formats read into and
// write from this, the six-table model (workbook_tables.*) reads and writes it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "formats/diagnostics.hpp"

namespace cemv::formats::workbook {

// Resource limits of every workbook read (docs/workbook.md "Limits"): checked
// before the work they bound, so a hostile file costs at most these.
inline constexpr std::size_t kMaxWorkbookBytes = kMaxFileBytes;   // the zip file itself
inline constexpr std::size_t kMaxEntryBytes = 8u << 20;           // one inflated zip entry
inline constexpr std::size_t kMaxTotalBytes = 32u << 20;          // every entry read, inflated
inline constexpr std::size_t kMaxCellBytes = 32u << 10;           // the text of one cell
inline constexpr std::size_t kMaxSheets = 64;
// Rows that hold something, per sheet. 6.6.3 imports at most 128 causes or
// effects; a sheet with more content rows than this is not a matrix.
inline constexpr std::size_t kMaxContentRows = 4096;
// Cells that hold something, per workbook (a 128 x 128 overview is 16 K).
inline constexpr std::size_t kMaxCells = 1u << 18;
// The texts of all cells together (a repeated cell counts each time).
inline constexpr std::size_t kMaxTextBytes = 16u << 20;
// Row and column numbers beyond these are refused (the XLSX and ODS maxima).
inline constexpr std::size_t kMaxRowNumber = 1u << 20;
inline constexpr std::size_t kMaxColumnNumber = 1u << 14;

// The kind of value a cell holds: spreadsheets keep numbers and booleans apart
// from texts; the importer reads each as text (a number in its shortest
// decimal form, a boolean as true/false).
enum class CellKind { Text, Number, Boolean };

// Whether a cell's text is struck through (how vendor workbooks keep a deleted
// row for the revision record): the whole text (by the cell's style, or every
// run of it), or only a part of it (some runs).
enum class Strike { None, Part, Whole };  // ordered: a struck format over struck runs is Whole

struct Cell {
  std::size_t row = 0;     // 1-based
  std::size_t column = 0;  // 1-based (A = 1)
  std::string text;
  CellKind kind = CellKind::Text;
  bool grey = false;       // information only (6.6.2)
  Strike strike = Strike::None;
};

// A merged range of cells, 1-based and inclusive; its text is the first cell's.
struct CellRange {
  std::size_t first_row = 0, first_column = 0, last_row = 0, last_column = 0;
};

struct Sheet {
  std::string name;
  std::vector<Cell> cells;  // row-major order, no empty texts
  // For writing: column widths in characters, by 1-based column (optional).
  std::map<std::size_t, double> widths;
  // Merged ranges whose first cell holds text (a merge of empty cells is only
  // formatting), in the order of the file.
  std::vector<CellRange> merges;
  bool hidden = false;      // hidden in the spreadsheet program (a hidden tab)

  // The cell at (row, column), or nullptr.
  const Cell* find(std::size_t row, std::size_t column) const;
  // The cells of one row, in column order (empty when none).
  std::vector<const Cell*> row(std::size_t row) const;
  std::size_t last_row() const { return cells.empty() ? 0 : cells.back().row; }

  // Writing: a text, a number or a boolean cell (an empty text adds nothing).
  void put(std::size_t row, std::size_t column, std::string text, bool grey = false,
           CellKind kind = CellKind::Text);
  void sort();  // row-major order, after puts in any order
};

struct Workbook {
  std::vector<Sheet> sheets;  // in the order of the file
  const Sheet* find(std::string_view name) const;  // case-insensitive
};

// "C5": the A1 address of a cell as spreadsheet programs show it.
std::string cell_address(std::size_t row, std::size_t column);

// A number as the cell text the importer reads: integral values in decimal
// ("128"), others in the shortest text that reads back as the same double.
std::string number_text(double value);

// The limits above as one guard, shared by the ODS and XLSX readers: every
// cell read passes through add(), which refuses what exceeds them with a
// LoadError naming the file, the sheet and the cell.
class CellBudget {
 public:
  explicit CellBudget(std::string file) : file_(std::move(file)) {}
  // Starts a new sheet (refuses more than kMaxSheets).
  Sheet& begin_sheet(Workbook& wb, std::string name);
  // Adds a non-empty cell to the current sheet (an empty text adds nothing),
  // row-major order; refuses a text longer than kMaxCellBytes before copying it.
  void add(Sheet& sheet, std::size_t row, std::size_t column, std::string_view text, CellKind kind,
           Strike strike = Strike::None);
  // Records a merged range (refuses one outside the row and column maxima, or
  // reversed); kept by the caller only when its first cell holds text.
  CellRange merge(const Sheet& sheet, std::size_t first_row, std::size_t first_column, std::size_t last_row,
                  std::size_t last_column) const;
  // Refuses a row or column number beyond the maxima (one of a repeated run).
  void check_position(const Sheet& sheet, std::size_t row, std::size_t column) const;
  [[noreturn]] void fail(const Sheet* sheet, std::size_t row, std::size_t column, std::string what) const;
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::size_t cells_ = 0;
  std::size_t text_bytes_ = 0;
  std::size_t rows_in_sheet_ = 0;
  std::size_t last_row_ = 0;
};

}  // namespace cemv::formats::workbook
