// Load issues and the guarded reading of input files (every format).
#include "formats/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>

#include "model/text.hpp"

namespace cemv::formats {

using model::in_quotes;
using model::printable;

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

std::string member_path(const std::string& parent, std::string_view key) {
  bool identifier = !key.empty() && key.size() <= 48 &&
                    (std::isalpha(static_cast<unsigned char>(key[0])) || key[0] == '_');
  for (unsigned char c : key) identifier = identifier && (std::isalnum(c) || c == '_');
  std::string segment = identifier ? std::string(key) : "[" + in_quotes(key) + "]";
  if (parent.empty()) return segment;
  return identifier ? parent + "." + segment : parent + segment;
}

std::string element_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

namespace {

using InJson = nlohmann::ordered_json;

// No object of the format has more than 64 members (sif_groups); the bound
// keeps every per-object key lookup cheap on hostile input.
constexpr std::size_t kMaxObjectMembers = 256;

// Runs before the JSON parser so that hostile or non-JSON input gets a precise
// position: nesting deeper than kMaxJsonDepth (neither the parser nor the DOM
// must ever be given a million levels), objects with more than
// kMaxObjectMembers members, numbers that overflow a double (1e999), and the
// non-JSON words NaN / Infinity. Returns false when the text must not be
// handed to the parser. Anything else that is wrong is the parser's to report.
bool prescan(std::string_view text, std::vector<LoadIssue>& issues) {
  bool ok = true;
  struct Level {
    bool object;
    std::size_t members;
  };
  std::vector<Level> levels;
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    char c = text[i];
    if (c == '"') {
      for (++i; i < n && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    } else if (c == '{' || c == '[') {
      if (levels.size() == static_cast<std::size_t>(kMaxJsonDepth)) {
        issues.push_back({line_column(text, i), "JSON nesting deeper than " + std::to_string(kMaxJsonDepth) +
                                                    " levels (a matrix needs 5)"});
        return false;
      }
      levels.push_back({c == '{', 1});
    } else if (c == '}' || c == ']') {
      if (!levels.empty()) levels.pop_back();
    } else if (c == ',') {
      if (!levels.empty() && levels.back().object && ++levels.back().members > kMaxObjectMembers) {
        issues.push_back({line_column(text, i), "object with more than " + std::to_string(kMaxObjectMembers) +
                                                    " members (no object of a matrix has that many)"});
        return false;
      }
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i;
      bool digits = false;
      while (end < n && (std::isdigit(static_cast<unsigned char>(text[end])) || text[end] == '-' ||
                         text[end] == '+' || text[end] == '.' || text[end] == 'e' || text[end] == 'E')) {
        digits = digits || std::isdigit(static_cast<unsigned char>(text[end]));
        ++end;
      }
      if (digits) {
        std::string token(text.substr(i, end - i));
        errno = 0;
        double v = std::strtod(token.c_str(), nullptr);
        if (errno == ERANGE && std::isinf(v)) {
          ok = false;
          issues.push_back({line_column(text, i), "number " + in_quotes(token) +
                                                      " is out of range (overflows a double)"});
        }
      }
      i = end - 1;
    } else if (std::isalpha(static_cast<unsigned char>(c))) {
      std::size_t end = i;
      while (end < n && std::isalnum(static_cast<unsigned char>(text[end]))) ++end;
      std::string word(text.substr(i, end - i));
      std::string lower = word;
      for (auto& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      if (lower == "nan" || lower == "inf" || lower == "infinity") {
        ok = false;
        issues.push_back({line_column(text, i), in_quotes(word) +
                                                    " is not a JSON number (JSON has no NaN or Infinity)"});
      }
      i = end - 1;
    }
  }
  return ok;
}

// Builds the insertion-ordered DOM (nlohmann's own SAX DOM builder) and reports
// keys repeated within one object, which the DOM would silently collapse to
// one value: an assessor reading the file might see the other.
class DomBuilder {
 public:
  using Dom = nlohmann::detail::json_sax_dom_parser<InJson>;
  DomBuilder(InJson& root, std::vector<LoadIssue>& issues) : dom_(root, true), issues_(issues) {}

  bool null() { return scalar() && dom_.null(); }
  bool boolean(bool v) { return scalar() && dom_.boolean(v); }
  bool number_integer(InJson::number_integer_t v) { return scalar() && dom_.number_integer(v); }
  bool number_unsigned(InJson::number_unsigned_t v) { return scalar() && dom_.number_unsigned(v); }
  bool number_float(InJson::number_float_t v, const std::string& s) { return scalar() && dom_.number_float(v, s); }
  bool string(std::string& v) { return scalar() && dom_.string(v); }
  bool binary(InJson::binary_t& v) { return scalar() && dom_.binary(v); }
  bool start_object(std::size_t n) {
    frames_.push_back({true, 0, {}});
    return dom_.start_object(n);
  }
  bool key(std::string& k) {
    auto& keys = frames_.back().keys;
    if (std::find(keys.begin(), keys.end(), k) != keys.end() && issues_.size() < kMaxIssues)
      issues_.push_back({member_path(path(), k), "duplicate key (a key may appear once per object)"});
    keys.push_back(k);
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object() && scalar();
  }
  bool start_array(std::size_t n) {
    frames_.push_back({false, 0, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array() && scalar();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& e) {
    return dom_.parse_error(position, token, e);
  }

 private:
  struct Frame {
    bool object;
    std::size_t index;               // arrays: index of the next element
    std::vector<std::string> keys;   // objects: keys so far, the last one current
  };
  // A value (or a whole container) is complete: advance the enclosing array.
  bool scalar() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }
  // Path of the innermost open container.
  std::string path() const {
    std::string p;
    for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
      p = frames_[i].object ? member_path(p, frames_[i].keys.back()) : element_path(p, frames_[i].index);
    return p;
  }
  Dom dom_;
  std::vector<LoadIssue>& issues_;
  std::vector<Frame> frames_;
};

// nlohmann's message without its prefix and position (we give our own).
std::string parse_error_text(const std::string& what) {
  std::size_t col = what.find("column ");
  std::size_t colon = col == std::string::npos ? std::string::npos : what.find(": ", col);
  if (colon != std::string::npos) return printable(what.substr(colon + 2));
  std::size_t bracket = what.find("] ");
  return printable(bracket == std::string::npos ? what : what.substr(bracket + 2));
}

}  // namespace

std::optional<nlohmann::ordered_json> parse_guarded_json(std::string_view text, const std::string& source_name,
                                                         std::vector<LoadIssue>& issues) {
  if (!prescan(text, issues)) return std::nullopt;
  InJson root;
  try {
    DomBuilder builder(root, issues);
    InJson::sax_parse(text.begin(), text.end(), &builder);
  } catch (const InJson::parse_error& e) {
    std::size_t index = e.byte == 0 ? 0 : e.byte - 1;
    issues.push_back({line_column(text, index), parse_error_text(e.what())});
    return std::nullopt;
  } catch (const InJson::exception& e) {
    issues.push_back({source_name, parse_error_text(e.what())});
    return std::nullopt;
  }
  return root;
}

}  // namespace cemv::formats
