// Load issues and the guarded reading of input files (every format).
#include "formats/diagnostics.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace cemv::formats {

namespace {

std::string summary_of(const std::vector<LoadIssue>& issues) {
  if (issues.empty()) return "invalid input";
  std::string s = issues.front().str();
  if (issues.size() > 1) s += " (and " + std::to_string(issues.size() - 1) + " more)";
  return s;
}

}  // namespace

LoadError::LoadError(std::vector<LoadIssue> issues)
    : std::runtime_error(summary_of(issues)), issues_(std::move(issues)) {}

std::string line_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  std::string_view before = text.substr(0, index);
  std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  std::size_t last_newline = before.rfind('\n');
  std::size_t column = last_newline == std::string_view::npos ? index + 1 : index - last_newline;
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string read_text_file(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw LoadError({{where, "is a directory, not a file"}});
  std::ifstream in(file, std::ios::binary);
  if (!in) throw LoadError({{where, std::string("cannot open: ") + std::strerror(errno)}});
  auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxFileBytes)
    throw LoadError({{where, "file is " + std::to_string(size) + " bytes, larger than the limit of " +
                                 std::to_string(kMaxFileBytes) + " bytes"}});
  // Read with a cap as well: pipes and devices have no size to check first.
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes)
      throw LoadError({{where, "file is larger than the limit of " + std::to_string(kMaxFileBytes) + " bytes"}});
  }
  if (in.bad()) throw LoadError({{where, "read error"}});
  return text;
}

}  // namespace cemv::formats
