// Load issues and the guarded reading of input files (every format).
#include "formats/diagnostics.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>

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

std::pair<std::size_t, std::size_t> line_and_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  std::string_view before = text.substr(0, index);
  std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  std::size_t last_newline = before.rfind('\n');
  std::size_t column = last_newline == std::string_view::npos ? index + 1 : index - last_newline;
  return {line, column};
}

std::string line_column(std::string_view text, std::size_t index) {
  auto [line, column] = line_and_column(text, index);
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

namespace {

// Digits at text[i...]: the number and the index after it; nullopt when none.
std::optional<std::size_t> digits_at(std::string_view text, std::size_t& i) {
  std::size_t start = i, value = 0;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && i - start < 12)
    value = value * 10 + static_cast<std::size_t>(text[i++] - '0');
  if (i == start) return std::nullopt;
  return value;
}

// "[SOURCE: ]line L[, column C][REST]" -> SOURCE, L, C, REST (REST without a
// leading ", " or " "); false when `where` has another form.
bool split_line_column(std::string_view where, std::string& source, std::size_t& line, std::size_t& column,
                       std::string& rest) {
  std::size_t at = where.rfind("line ");
  while (at != std::string_view::npos) {
    if (at == 0 || (at >= 2 && where.substr(at - 2, 2) == ": ")) break;
    at = at == 0 ? std::string_view::npos : where.rfind("line ", at - 1);
  }
  if (at == std::string_view::npos) return false;
  std::size_t i = at + 5;
  auto l = digits_at(where, i);
  if (!l || *l == 0) return false;
  column = 0;
  if (where.substr(i, 9) == ", column ") {
    std::size_t j = i + 9;
    if (auto c = digits_at(where, j)) {
      column = *c;
      i = j;
    }
  }
  if (i < where.size() && where[i] != ',' && where[i] != ' ') return false;
  source = std::string(at == 0 ? std::string_view() : where.substr(0, at - 2));
  line = *l;
  std::string_view r = where.substr(i);
  while (!r.empty() && (r.front() == ',' || r.front() == ' ')) r.remove_prefix(1);
  rest = std::string(r);
  return true;
}

// "FILE:LINE:COL" (the property parser's places).
bool is_file_line_column(std::string_view where) {
  auto digits_before = [&](std::size_t end) {
    std::size_t i = end;
    while (i > 0 && std::isdigit(static_cast<unsigned char>(where[i - 1]))) --i;
    return i < end && i > 0 && where[i - 1] == ':' ? i - 1 : std::string_view::npos;
  };
  std::size_t col = digits_before(where.size());
  if (col == std::string_view::npos) return false;
  std::size_t line = digits_before(col);
  return line != std::string_view::npos && line > 0;
}

std::string position_text(std::size_t line, std::size_t column) {
  std::string s = ":" + std::to_string(line);
  if (column > 0) s += ":" + std::to_string(column);
  return s;
}

}  // namespace

std::string LoadIssue::message(std::string_view severity) const {
  const std::string sev(severity);
  std::string source = file, detail = where, rest;
  std::size_t l = line, c = column;
  std::string parsed_source;
  std::size_t pl = 0, pc = 0;
  if (split_line_column(where, parsed_source, pl, pc, rest)) {
    // The place is a position (with or without its file): use it unless the
    // issue already has one.
    if (source.empty()) source = parsed_source;
    if (l == 0) {
      l = pl;
      c = pc;
    }
    detail = rest;
  } else if (source.empty() && is_file_line_column(where)) {
    return where + ": " + sev + ": " + what;
  } else if (source.empty()) {
    // A place that names no file is the file itself (read errors), or a path.
    if (where.empty()) return sev + ": " + what;
    return where + ": " + sev + ": " + what;
  }
  if (detail == source) detail.clear();
  std::string out = source;
  if (l > 0) out += position_text(l, c);
  out += (out.empty() ? "" : ": ") + sev + ": ";
  if (!detail.empty()) out += detail + ": ";
  return out + what;
}

LoadError LoadError::in_file(const std::string& file) const {
  std::vector<LoadIssue> issues = issues_;
  for (auto& i : issues) {
    if (!i.file.empty() || is_file_line_column(i.where)) continue;
    std::string source, rest;
    std::size_t l = 0, c = 0;
    // A place that starts with its own file name keeps it.
    if (split_line_column(i.where, source, l, c, rest) && !source.empty()) continue;
    if (i.where.rfind(file, 0) == 0) continue;
    i.file = file;
  }
  return LoadError(std::move(issues));
}

std::string read_text_file(const std::filesystem::path& file) {
  const std::string where = file.string();
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw LoadError({{where, "is a directory, not a file", where}});
  std::ifstream in(file, std::ios::binary);
  if (!in) throw LoadError({{where, std::string("cannot open: ") + std::strerror(errno), where}});
  auto size = std::filesystem::file_size(file, ec);
  if (!ec && size > kMaxFileBytes)
    throw LoadError({{where,
                      "file is " + std::to_string(size) + " bytes, larger than the limit of " +
                          std::to_string(kMaxFileBytes) + " bytes",
                      where}});
  // Read with a cap as well: pipes and devices have no size to check first.
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxFileBytes)
      throw LoadError(
          {{where, "file is larger than the limit of " + std::to_string(kMaxFileBytes) + " bytes", where}});
  }
  if (in.bad()) throw LoadError({{where, std::string("cannot read: ") + std::strerror(errno), where}});
  return text;
}

namespace {

using InJson = nlohmann::ordered_json;

// Index of the first byte that does not belong to a well-formed UTF-8
// sequence (no overlongs, no surrogates, nothing above U+10FFFF), or npos.
std::size_t first_invalid_utf8(std::string_view s) {
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n;) {
    auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x80) {
      ++i;
      continue;
    }
    std::size_t len = (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 0;
    if (len == 0 || i + len > n) return i;
    std::uint32_t cp = len == 2 ? (b & 0x1F) : len == 3 ? (b & 0x0F) : (b & 0x07);
    for (std::size_t k = 1; k < len; ++k) {
      auto c = static_cast<unsigned char>(s[i + k]);
      if ((c & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (c & 0x3F);
    }
    static const std::uint32_t min_for_length[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < min_for_length[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
    i += len;
  }
  return std::string_view::npos;
}

// Runs before the JSON parser so that hostile or non-JSON input gets a precise
// position: nesting deeper than kMaxJsonDepth (neither the parser nor the DOM
// must ever be given a million levels), objects with more than
// limits.max_members members, numbers that overflow a double (1e999), and the
// non-JSON words NaN / Infinity. Returns false when the text must not be
// handed to the parser. Anything else that is wrong is the parser's to report.
bool prescan(std::string_view text, std::vector<LoadIssue>& issues, const JsonLimits& limits) {
  const std::string document(limits.document);
  bool ok = true;
  struct Level {
    bool object;
    std::size_t members;
  };
  std::vector<Level> levels;
  const std::size_t n = text.size();
  // Issues are placed through one LineIndex: a file of many bad numbers has
  // an issue each, and counting the lines before each one was quadratic.
  std::optional<LineIndex> lines;
  auto place = [&](std::size_t index) {
    if (!lines) lines.emplace(text);
    return lines->line_column(index);
  };
  // Beyond kMaxIssues such a file is clearly not what it should be (as in the loaders).
  auto too_many = [&] {
    if (issues.size() < kMaxIssues) return false;
    issues.push_back({"", "too many problems; the rest are not listed"});
    return true;
  };
  // JSON is UTF-8 text (RFC 8259 section 8.1): say where it is not, in words
  // of our own, before the parser does in its own.
  if (std::size_t bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(text[bad]));
    issues.push_back({place(bad), std::string("invalid UTF-8: byte ") + hex +
                                                  " does not belong here (a " + document +
                                                  " is UTF-8 text; save it as UTF-8)"});
    return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    char c = text[i];
    if (c == '"') {
      for (++i; i < n && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    } else if (c == '{' || c == '[') {
      if (levels.size() == static_cast<std::size_t>(kMaxJsonDepth)) {
        issues.push_back({place(i), "JSON nesting deeper than " + std::to_string(kMaxJsonDepth) +
                                                    " levels (a " + document + " needs " +
                                                    std::to_string(limits.depth_needed) + ")"});
        return false;
      }
      levels.push_back({c == '{', 1});
    } else if (c == '}' || c == ']') {
      if (!levels.empty()) levels.pop_back();
    } else if (c == ',') {
      if (!levels.empty() && levels.back().object && ++levels.back().members > limits.max_members) {
        issues.push_back({place(i), "object with more than " + std::to_string(limits.max_members) +
                                                    " members (no object of a " + document +
                                                    " has that many)"});
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
          if (too_many()) return false;
          issues.push_back({place(i), "number " + in_quotes(token) +
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
        if (too_many()) return false;
        issues.push_back({place(i), in_quotes(word) +
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
                                                         std::vector<LoadIssue>& issues, const JsonLimits& limits) {
  const std::size_t first = issues.size();
  // Every issue found here is placed: the scan's and the parser's by byte
  // offset, a repeated key by its path.
  auto place = [&](bool parsed) {
    for (std::size_t k = first; k < issues.size(); ++k) {
      LoadIssue& i = issues[k];
      if (i.file.empty()) i.file = source_name;
      std::string src, rest;
      if (i.line == 0 && split_line_column(i.where, src, i.line, i.column, rest)) continue;
      if (parsed && i.line == 0) {
        std::vector<LoadIssue> one{i};
        locate_issues(text, source_name, one);
        i = one.front();
      }
    }
  };
  if (!prescan(text, issues, limits)) {
    place(false);
    return std::nullopt;
  }
  InJson root;
  try {
    DomBuilder builder(root, issues);
    InJson::sax_parse(text.begin(), text.end(), &builder);
  } catch (const InJson::parse_error& e) {
    std::size_t index = e.byte == 0 ? 0 : e.byte - 1;
    issues.push_back({line_column(text, index), parse_error_text(e.what())});
    place(false);
    return std::nullopt;
  } catch (const InJson::exception& e) {
    issues.push_back({source_name, parse_error_text(e.what())});
    place(false);
    return std::nullopt;
  }
  place(true);
  return root;
}

}  // namespace cemv::formats
