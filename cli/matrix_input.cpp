#include "cli/matrix_input.hpp"

#include <iostream>
#include <iterator>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"

namespace cemv::cli {

std::string input_name(const std::string& path) { return path == "-" ? kStdinName : path; }

std::string read_input(const std::string& path) {
  if (path != "-") return formats::read_text_file(path);
  std::string text(std::istreambuf_iterator<char>(std::cin), {});
  if (std::cin.bad()) throw formats::LoadError({formats::LoadIssue{kStdinName, "cannot read standard input"}});
  return text;
}

model::Matrix load_valid_matrix(const std::string& path, const std::string& use) {
  if (path != "-") return formats::load_valid_matrix(path, use);
  // The same refusal as formats::load_valid_matrix, for a matrix that has no path.
  model::Matrix m = formats::parse_matrix(read_input(path), kStdinName);
  auto diagnostics = model::validate(m);
  if (!model::has_errors(diagnostics)) return m;
  std::vector<formats::LoadIssue> issues{
      {kStdinName, "the matrix has validation errors; it cannot be " + use}};
  for (const auto& d : diagnostics)
    if (d.severity == model::Severity::Error)
      issues.push_back({kStdinName, d.rule + " " + d.element + " (" + d.section + "): " + d.message});
  throw formats::LoadError(std::move(issues));
}

}  // namespace cemv::cli
