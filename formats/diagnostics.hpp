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
//
// `file`, `line` and `column` place the issue for the CLI's compiler-style
// message (`FILE:LINE:COL: error: ...`, which editors and CI log views jump
// to): the loaders fill them; an issue that names no file is placed by the
// command that knows which file it read (LoadError::in_file).
struct LoadIssue {
  std::string where;
  std::string what;
  std::string file = {};    // the file ("<stdin>" for standard input); empty when unknown
  std::size_t line = 0;     // 1-based position in the file; 0 when none
  std::size_t column = 0;   // 1-based, in bytes; 0 when none
  std::string str() const { return where.empty() ? what : where + ": " + what; }
  // The line the CLI prints: `FILE:LINE:COL: error: PATH: what`, `FILE: error:
  // PATH: what` without a position, `error: what` when nothing names a place.
  // A `where` of the form `[FILE: ]line L[, column C]` (the CSV reader's) and
  // one of the form `FILE:LINE:COL` (the property parser's) are placed the same way.
  std::string message(std::string_view severity = "error") const;
};

// Thrown when a file cannot be read or is not well-formed; carries every
// problem found, in file order. The CLI prints them and exits 2.
class LoadError : public std::runtime_error {
 public:
  explicit LoadError(std::vector<LoadIssue> issues);
  const std::vector<LoadIssue>& issues() const { return issues_; }
  // The same issues, each one that names no file now naming `file`.
  LoadError in_file(const std::string& file) const;

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
// Issues come back with `file` = source_name and their line and column set.
struct JsonLimits {
  std::size_t max_members = 256;        // per object
  std::string_view document = "matrix";  // named in the limit messages
  int depth_needed = 5;                 // the nesting the document needs
};
std::optional<nlohmann::ordered_json> parse_guarded_json(std::string_view text, const std::string& source_name,
                                                         std::vector<LoadIssue>& issues,
                                                         const JsonLimits& limits = {});

// Where each JSON path of a well-formed text starts: a member at its key, an
// array element at its value, paths spelt as member_path/element_path spell
// them. Lets issues named by path also get a line and column.
class JsonPositions {
 public:
  explicit JsonPositions(std::string_view text);
  // Byte offset of `path` (the last occurrence when `last`, for repeated keys).
  std::optional<std::size_t> find(const std::string& path, bool last = false) const;
  // The closest enclosing path that exists: `causes[0].id` when missing falls
  // back to `causes[0]`; nullopt when only the whole document contains it.
  std::optional<std::size_t> find_enclosing(std::string path, bool last = false) const;
  std::string_view text() const { return text_; }

 private:
  std::string_view text_;
  std::vector<std::pair<std::string, std::size_t>> positions_;  // sorted by path, then offset
};

// Sets `file` (when empty) and, for issues named by a JSON path of `text`, the
// line and column of that path (or of the closest enclosing one).
void locate_issues(std::string_view text, const std::string& file, std::vector<LoadIssue>& issues);

// 1-based line and column (in bytes) of a 0-based byte index.
std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t index);

// "line L, column C": 1-based line and column (in bytes) of a 0-based byte index.
std::string line_column(std::string_view text, std::size_t index);

// The same for many indexes of one text: the line breaks are found once, each
// index is then placed by binary search (line_and_column counts from the start
// every time, which is quadratic over the issues of a large file).
class LineIndex {
 public:
  explicit LineIndex(std::string_view text);
  std::pair<std::size_t, std::size_t> line_and_column(std::size_t index) const;
  std::string line_column(std::size_t index) const;

 private:
  std::size_t size_;
  std::vector<std::size_t> breaks_;  // offsets of '\n', ascending
};

// Reads a whole file with the size guard (also for pipes and devices, which
// have no size to check first); refuses directories. Throws LoadError.
std::string read_text_file(const std::filesystem::path& file);

}  // namespace cemv::formats
