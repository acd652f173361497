#include "cli/matrix_input.hpp"

#include <iostream>
#include <iterator>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::cli {

std::string input_name(const std::string& path) { return path == "-" ? kStdinName : path; }

std::string read_input(const std::string& path) {
  if (path != "-") return formats::read_text_file(path);
  std::string text(std::istreambuf_iterator<char>(std::cin), {});
  if (std::cin.bad())
    throw formats::LoadError({formats::LoadIssue{kStdinName, "cannot read standard input", kStdinName}});
  if (text.size() > formats::kMaxFileBytes)
    throw formats::LoadError({formats::LoadIssue{
        kStdinName, "input is larger than the limit of " + std::to_string(formats::kMaxFileBytes) + " bytes",
        kStdinName}});
  return text;
}

model::Matrix load_matrix_input(const std::string& path) {
  return formats::parse_matrix(read_input(path), input_name(path));
}

model::Matrix load_valid_matrix(const std::string& path, const std::string& use) {
  return formats::parse_valid_matrix(read_input(path), input_name(path), use);
}

}  // namespace cemv::cli
