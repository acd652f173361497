// Diagnostics of every input format: the load issue (where, what), the
// error that carries them to the CLI (exit 2), positions in a text, and the
// guarded reading of a file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace cemv::formats {

// One problem with an input file: where (a JSON path such as
// `causes[3].tags[1].name`, or `line 4, column 7` for syntax and CSV) and what.
struct LoadIssue {
  std::string where;
  std::string what;
  std::string str() const { return where.empty() ? what : where + ": " + what; }
};

// Thrown when a file cannot be read or is not well-formed; carries every
// problem found, in file order. The CLI prints them and exits 2.
class LoadError : public std::runtime_error {
 public:
  explicit LoadError(std::vector<LoadIssue> issues);
  const std::vector<LoadIssue>& issues() const { return issues_; }

 private:
  std::vector<LoadIssue> issues_;
};

// Largest file the loaders accept, and deepest JSON nesting: guards against
// hostile inputs (a matrix of the 3.4 limits is well under 1 MiB).
inline constexpr std::size_t kMaxFileBytes = 16u << 20;
inline constexpr int kMaxJsonDepth = 64;

// Beyond this many issues a file is clearly not what it should be: stop listing.
inline constexpr std::size_t kMaxIssues = 100;

// JSON paths as messages give them, jq-like: `causes[3].tags[1].name`; a key
// that is not an identifier is written as `['key']`, quoted (model::in_quotes).
std::string member_path(const std::string& parent, std::string_view key);
std::string element_path(const std::string& parent, std::size_t index);

// The guarded JSON parse of the loaders: a lexical pre-scan first gives a
// position (FILE: line L, column C) for nesting deeper than kMaxJsonDepth,
// objects with more than 256 members, numbers that overflow a double and the
// non-JSON words NaN / Infinity, so hostile input never reaches the parser;
// then an insertion-ordered DOM is built (issues come out in file order), and
// a key repeated within one object is an issue (the parse goes on). Returns
// nullopt, with the reasons in `issues`, when the text is not JSON.
std::optional<nlohmann::ordered_json> parse_guarded_json(std::string_view text, const std::string& source_name,
                                                         std::vector<LoadIssue>& issues);

// "line L, column C": 1-based line and column (in bytes) of a 0-based byte index.
std::string line_column(std::string_view text, std::size_t index);

// Reads a whole file with the size guard (also for pipes and devices, which
// have no size to check first); refuses directories. Throws LoadError.
std::string read_text_file(const std::filesystem::path& file);

}  // namespace cemv::formats
