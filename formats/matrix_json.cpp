// cemv-matrix/1: the loader's entry points (docs/format.md): the text checked
// and parsed, the document read (matrix_json_read.cpp), issues placed at their
// line and column; and the valid matrix a command needs.
#include "formats/matrix_json.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "formats/matrix_json_reader.hpp"
#include "model/validate.hpp"

namespace cemv::formats {

using namespace cemv::model;
using matrix_json_detail::InJson;
using matrix_json_detail::Reader;

// A text that is not JSON and does not even start like a JSON object: one
// issue that names none of its bytes (it may be any file a path in an input
// names), with the command that reads it when it is a spreadsheet.
static std::optional<LoadIssue> not_a_json_object(std::string_view text, const std::string& source_name) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && text[first] == '{') return std::nullopt;
  auto ends_with = [&](std::string_view suffix) {
    if (source_name.size() < suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(source_name[source_name.size() - suffix.size() + i])) != suffix[i])
        return false;
    return true;
  };
  const std::string_view first_line = text.substr(0, text.find('\n'));
  std::string what = "syntax error: not a JSON object (a cemv-matrix/1 file is one, docs/format.md)";
  if (text.substr(0, 4) == std::string_view("PK\x03\x04", 4) || ends_with(".ods") || ends_with(".xlsx"))
    what = "not a cemv-matrix/1 file but a zip archive, as ODS and XLSX workbooks are: convert a workbook with "
           "`cemv import-workbook FILE -o matrix.json` (docs/workbook.md)";
  else if (ends_with(".csv") || ends_with(".tsv") || first_line.find_first_of(",;\t") != std::string_view::npos)
    what = "not a cemv-matrix/1 file but a table (CSV): convert it with `cemv import-csv FILE -o matrix.json` "
           "(docs/csv.md)";
  const auto [line, column] = line_and_column(text, first == std::string_view::npos ? 0 : first);
  return LoadIssue{"line " + std::to_string(line) + ", column " + std::to_string(column), what, source_name, line,
                   column};
}

// ---- Public API ---------------------------------------------------------------------

Matrix parse_matrix(std::string_view json_text, const std::string& source_name) {
  std::vector<LoadIssue> issues;
  if (json_text.size() > kMaxFileBytes)
    throw LoadError({{source_name,
                      "input is " + std::to_string(json_text.size()) + " bytes, larger than the limit of " +
                          std::to_string(kMaxFileBytes) + " bytes",
                      source_name}});
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-matrix/1 JSON object)", source_name}});
  std::optional<InJson> parsed = parse_guarded_json(json_text, source_name, issues);
  if (!parsed) {
    // The parser's syntax messages quote what it last read: not for a text
    // that does not even start like a matrix. (Its limits quote nothing.)
    const bool quoting = std::any_of(issues.begin(), issues.end(), [](const LoadIssue& i) {
      return i.what.find("syntax error") != std::string::npos || i.what.find("invalid UTF-8") != std::string::npos;
    });
    if (quoting)
      if (auto issue = not_a_json_object(json_text, source_name)) throw LoadError({*issue});
    throw LoadError(std::move(issues));
  }
  const InJson& root = *parsed;

  Matrix m;
  Reader reader(issues);
  read_matrix(reader, root, m);
  if (!issues.empty()) {
    locate_issues(json_text, source_name, issues);
    throw LoadError(std::move(issues));
  }
  m.sort_by_id();
  return m;
}

Matrix load_matrix(const std::filesystem::path& file) {
  return parse_matrix(read_text_file(file), file.string());
}

Matrix parse_valid_matrix(std::string_view json_text, const std::string& source_name, const std::string& use) {
  Matrix m = parse_matrix(json_text, source_name);
  auto diagnostics = validate(m);
  if (!has_errors(diagnostics)) return m;
  const std::string& where = source_name;
  std::vector<LoadIssue> issues{{where, "the matrix has validation errors; it cannot be " + use, where}};
  JsonPositions positions(json_text);
  for (const auto& d : diagnostics) {
    if (d.severity != Severity::Error) continue;
    LoadIssue issue{where, d.rule + " " + d.element + " (" + d.section + "): " + d.message, where};
    if (auto at = element_offset(positions, d.element))
      std::tie(issue.line, issue.column) = line_and_column(json_text, *at);
    issues.push_back(std::move(issue));
  }
  throw LoadError(std::move(issues));
}

Matrix load_valid_matrix(const std::filesystem::path& file, const std::string& use) {
  return parse_valid_matrix(read_text_file(file), file.string(), use);
}

}  // namespace cemv::formats
