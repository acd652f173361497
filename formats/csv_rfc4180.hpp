// RFC 4180 text (docs/csv.md): the one tokenizer of CSV files, used by the
// record layout cemv-csv/1, the grid reader and the field checklist, and the
// quoting every CSV writer applies.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace cemv::formats {

struct CsvField {
  std::string text;
  int line = 0;     // 1-based physical line where the field starts
  int column = 0;   // 1-based field number within its record
  bool quoted = false;
};

struct CsvRecord {
  int line = 0;     // 1-based physical line where the record starts
  std::vector<CsvField> fields;
};

// Splits text into records (RFC 4180: `"` quoting with `""` escapes, records
// ending in CRLF or LF, line breaks allowed inside quoted fields, a UTF-8 BOM
// skipped). Strict mode rejects a quote inside an unquoted field and text after a
// closing quote; lenient mode (for hand-made grids) keeps them literally. An
// unterminated quote is always an error. Errors are LoadIssues at `line L,
// column C`; reading continues so every error is reported; throws LoadError.
std::vector<CsvRecord> parse_csv(std::string_view text, char separator, bool strict,
                                 const std::string& source_name = "");

// One field as RFC 4180 writes it: quoted when it holds the separator, a quote,
// CR/LF, or leading/trailing blanks; quotes doubled.
std::string csv_quote(std::string_view field, char separator = ',');

}  // namespace cemv::formats
