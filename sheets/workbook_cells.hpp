// Reading typed values from the cells of a workbook table (internal to
// formats/): numbers, booleans, enumerations, tags, SIF lists, each problem an
// issue at FILE:SHEET:ROW:COLUMN, and every cell read remembered by the JSON
// path of the field it fills, so that what the JSON loader finds afterwards
// is placed at the cell too.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "formats/diagnostics.hpp"
#include "sheets/workbook_sheet.hpp"

namespace cemv::formats::workbook {

// A table whose columns are found by the headers of its row 1.
struct Table {
  const Sheet* sheet = nullptr;
  std::map<std::string, std::size_t> columns;  // header -> column
};

class CellReader {
 public:
  explicit CellReader(std::string file) : file_(std::move(file)) {}

  // Finds the columns of `headers` in row 1 (case-insensitive, blanks
  // trimmed). A missing header, a repeated one, or an unknown one that is not
  // `info_only` is an error (a misspelt column must never read as "absent").
  Table header(const Sheet& sheet, const std::vector<std::string>& headers, const std::string& info_only);

  // The field reading one cell: the cell's text (blanks trimmed unless
  // `keep_blanks`), "" when empty or the column is missing. Each remembers
  // `path` (when not empty) as the place of that field.
  std::string text(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                   bool keep_blanks = false);
  bool present(const Table& t, std::size_t row, const std::string& header);
  long long integer(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                    long long min, long long max, long long fallback);
  std::uint32_t u32(const Table& t, std::size_t row, const std::string& header, const std::string& path,
                    std::uint32_t fallback = 0) {
    return static_cast<std::uint32_t>(integer(t, row, header, path, 0, 4294967295LL, fallback));
  }
  float real(const Table& t, std::size_t row, const std::string& header, const std::string& path, float fallback);
  bool boolean(const Table& t, std::size_t row, const std::string& header, const std::string& path, bool fallback);
  // One of `names` (case-insensitive): its index, `fallback` when empty.
  int choice(const Table& t, std::size_t row, const std::string& header, const std::string& path,
             const std::vector<std::string>& names, int fallback);
  // A tag cell (6.6.2 conventions, workbook_tags.hpp); nullopt when empty.
  std::optional<std::string> tag(const Table& t, std::size_t row, const std::string& header, const std::string& path);
  std::vector<int> sif(const Table& t, std::size_t row, const std::string& header, const std::string& path);

  void error(const Sheet& sheet, std::size_t row, std::size_t column, const std::string& header, std::string what);
  void warn(const Sheet& sheet, std::size_t row, std::size_t column, const std::string& header, std::string what);
  void error_at(const Table& t, std::size_t row, const std::string& header, std::string what);
  // Remembers where a JSON path's value came from.
  void remember(const std::string& path, const Sheet& sheet, std::size_t row, std::size_t column, const std::string& header);
  // Renames remembered paths with prefix `from` to prefix `to` (after sorting).
  void rename(const std::map<std::string, std::string>& prefixes);

  // The place of a JSON path of the matrix (or of its closest remembered
  // parent); the issue unchanged when none.
  LoadIssue locate(const LoadIssue& loader_issue) const;

  std::vector<LoadIssue>& errors() { return errors_; }
  std::vector<LoadIssue>& warnings() { return warnings_; }
  const std::string& file() const { return file_; }

 private:
  struct Place {
    const Sheet* sheet;
    std::size_t row, column;
    std::string header;
  };
  std::string file_;
  std::vector<LoadIssue> errors_, warnings_;
  std::map<std::string, Place> places_;
};

// Blanks trimmed at both ends.
std::string trimmed(const std::string& s);

}  // namespace cemv::formats::workbook
