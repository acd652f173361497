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

std::optional<model::Matrix> load_valid_matrix(const std::string& path, const std::string& purpose) {
  model::Matrix m = path == "-" ? formats::parse_matrix(read_input(path), kStdinName)
                                : formats::load_matrix(path);
  auto diags = model::validate(m);
  if (!model::has_errors(diags)) return m;
  std::cerr << "error: " << input_name(path) << ": the matrix has validation errors; it cannot be "
            << purpose << ":\n";
  for (const auto& d : diags)
    if (d.severity == model::Severity::Error)
      std::cerr << "  " << d.rule << " " << d.element << " (" << d.section << "): " << d.message
                << "\n";
  return std::nullopt;
}

}  // namespace cemv::cli
