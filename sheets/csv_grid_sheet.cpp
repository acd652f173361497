// The sheet of a C&E grid (docs/csv.md "Shape"): its records split from the
// text, and the padding and legend rows around the grid set apart.
#include <algorithm>
#include <regex>

#include "sheets/csv_grid.hpp"
#include "formats/csv_text.hpp"

namespace cemv::formats::grid {

using namespace csv_text;

namespace {

// Which separator a hand-made grid uses: the most frequent of ; , TAB outside
// quotes in its first two lines (';' wins ties: the separator of spreadsheets
// in locales with a decimal comma, like the LSST table).
char detect_separator(std::string_view text) {
  std::size_t semi = 0, comma = 0, tab = 0;
  bool quoted = false;
  int lines = 0;
  for (std::size_t i = 0; i < text.size() && lines < 2; ++i) {
    char c = text[i];
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '\n') ++lines;
    semi += c == ';';
    comma += c == ',';
    tab += c == '\t';
  }
  if (tab > semi && tab > comma) return '\t';
  if (comma > semi) return ',';
  return ';';
}

std::size_t leading_blank_fields(const CsvRecord& r) {
  std::size_t n = 0;
  while (n < r.fields.size() && trim(r.fields[n].text).empty()) ++n;
  return n;
}

}  // namespace

bool blank_record(const CsvRecord& r) {
  return std::all_of(r.fields.begin(), r.fields.end(),
                     [](const CsvField& f) { return trim(f.text).empty(); });
}

std::string cell_text(const CsvRecord& row, std::size_t index) {
  return index < row.fields.size() ? one_line(trim(row.fields[index].text)) : std::string();
}

Sheet read_sheet(std::string_view text, char separator, const std::string& source) {
  Sheet sheet;
  sheet.rows = parse_csv(text, separator ? separator : detect_separator(text), false, source);
  while (!sheet.rows.empty() && blank_record(sheet.rows.back())) sheet.rows.pop_back();
  while (!sheet.rows.empty() && blank_record(sheet.rows.front())) {
    sheet.rows.erase(sheet.rows.begin());
    ++sheet.empty_rows_skipped;
  }
  std::size_t skip = std::string::npos;
  for (const auto& r : sheet.rows)
    if (!blank_record(r)) skip = std::min(skip, leading_blank_fields(r));
  if (skip == std::string::npos) skip = 0;
  sheet.empty_columns_skipped = skip;
  static const std::regex legend_key(R"(^(\(\s*\d+\s*\)|\*{1,3})$)");
  std::vector<CsvRecord> grid_rows;
  for (auto& r : sheet.rows) {
    r.fields.erase(r.fields.begin(), r.fields.begin() + static_cast<long>(std::min(skip, r.fields.size())));
    if (!grid_rows.empty() && std::regex_match(cell_text(r, 0), legend_key)) sheet.legend.push_back(std::move(r));
    else grid_rows.push_back(std::move(r));
  }
  sheet.rows = std::move(grid_rows);
  return sheet;
}

std::optional<std::size_t> Sheet::row_at(int line) const {
  auto it = std::lower_bound(rows.begin(), rows.end(), line, [](const CsvRecord& r, int l) { return r.line < l; });
  if (it == rows.end() || it->line != line) return std::nullopt;
  return static_cast<std::size_t>(it - rows.begin());
}

}  // namespace cemv::formats::grid
