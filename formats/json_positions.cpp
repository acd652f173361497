// Positions of JSON paths in a text (diagnostics.hpp, JsonPositions): the DOM
// the loaders read keeps no positions, so an issue named by its JSON path gets
// its line and column from this second, lexical pass over the same text.
#include <algorithm>
#include <cctype>

#include "formats/diagnostics.hpp"
#include "model/text.hpp"

namespace cemv::formats {

using model::in_quotes;

// Lines and JSON paths (declared in diagnostics.hpp) live here, beside the walk
// that uses them, so that diagnostics.cpp calls this file and not the reverse.

LineIndex::LineIndex(std::string_view text) : size_(text.size()) {
  for (std::size_t k = text.find('\n'); k != std::string_view::npos; k = text.find('\n', k + 1))
    breaks_.push_back(k);
}

std::pair<std::size_t, std::size_t> LineIndex::line_and_column(std::size_t index) const {
  index = std::min(index, size_);
  auto before = std::lower_bound(breaks_.begin(), breaks_.end(), index);  // the breaks before index
  std::size_t line = 1 + static_cast<std::size_t>(before - breaks_.begin());
  std::size_t column = before == breaks_.begin() ? index + 1 : index - *std::prev(before);
  return {line, column};
}

std::string LineIndex::line_column(std::size_t index) const {
  auto [line, column] = line_and_column(index);
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
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

// A recursive-descent walk over a text the guarded parser accepted (so it is
// JSON, nested at most kMaxJsonDepth deep); anything unexpected ends the walk
// early, which only leaves later paths without a position.
class Walker {
 public:
  Walker(std::string_view text, std::vector<std::pair<std::string, std::size_t>>& out) : t_(text), out_(out) {}

  void run() {
    ws();
    value("", 0);
  }

 private:
  std::string_view t_;
  std::vector<std::pair<std::string, std::size_t>>& out_;
  std::size_t i_ = 0;
  bool ok_ = true;

  void ws() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }
  bool at(char c) const { return ok_ && i_ < t_.size() && t_[i_] == c; }

  static void append_utf8(std::string& s, unsigned cp) {
    if (cp < 0x80) {
      s += static_cast<char>(cp);
    } else if (cp < 0x800) {
      s += static_cast<char>(0xC0 | (cp >> 6));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      s += static_cast<char>(0xE0 | (cp >> 12));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      s += static_cast<char>(0xF0 | (cp >> 18));
      s += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      s += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  unsigned hex4() {
    unsigned v = 0;
    for (int k = 0; k < 4; ++k) {
      if (i_ >= t_.size() || !std::isxdigit(static_cast<unsigned char>(t_[i_]))) {
        ok_ = false;
        return 0;
      }
      char c = static_cast<char>(std::tolower(static_cast<unsigned char>(t_[i_++])));
      v = v * 16 + static_cast<unsigned>(c <= '9' ? c - '0' : c - 'a' + 10);
    }
    return v;
  }

  // A string token at i_ (which is '"'), decoded.
  std::string string_token() {
    std::string s;
    ++i_;
    while (ok_ && i_ < t_.size() && t_[i_] != '"') {
      char c = t_[i_++];
      if (c != '\\') {
        s += c;
        continue;
      }
      if (i_ >= t_.size()) break;
      char e = t_[i_++];
      switch (e) {
        case 'b': s += '\b'; break;
        case 'f': s += '\f'; break;
        case 'n': s += '\n'; break;
        case 'r': s += '\r'; break;
        case 't': s += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00 && t_.substr(i_, 2) == "\\u") {
            i_ += 2;
            unsigned low = hex4();
            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          }
          append_utf8(s, cp);
          break;
        }
        default: s += e;
      }
    }
    if (i_ >= t_.size()) ok_ = false;
    ++i_;
    return s;
  }

  void value(const std::string& path, int depth) {
    if (!ok_ || i_ >= t_.size() || depth > kMaxJsonDepth) {
      ok_ = false;
      return;
    }
    char c = t_[i_];
    if (c == '{') {
      ++i_;
      ws();
      if (at('}')) {
        ++i_;
        return;
      }
      while (ok_) {
        ws();
        if (!at('"')) {
          ok_ = false;
          return;
        }
        std::size_t key_at = i_;
        std::string key = string_token();
        std::string child = member_path(path, key);
        out_.emplace_back(child, key_at);
        ws();
        if (!at(':')) {
          ok_ = false;
          return;
        }
        ++i_;
        ws();
        value(child, depth + 1);
        ws();
        if (at(',')) {
          ++i_;
          continue;
        }
        if (at('}')) ++i_;
        else ok_ = false;
        return;
      }
    } else if (c == '[') {
      ++i_;
      ws();
      if (at(']')) {
        ++i_;
        return;
      }
      for (std::size_t index = 0; ok_; ++index) {
        ws();
        std::string child = element_path(path, index);
        out_.emplace_back(child, i_);
        value(child, depth + 1);
        ws();
        if (at(',')) {
          ++i_;
          continue;
        }
        if (at(']')) ++i_;
        else ok_ = false;
        return;
      }
    } else if (c == '"') {
      string_token();
    } else {
      while (i_ < t_.size() && t_[i_] != ',' && t_[i_] != '}' && t_[i_] != ']' && t_[i_] != ' ' &&
             t_[i_] != '\n' && t_[i_] != '\r' && t_[i_] != '\t')
        ++i_;
    }
  }
};

// `path` without its last segment (`a.b[2]` -> `a.b`, `a['x.y']` -> `a`);
// empty when `path` has one segment.
std::string parent_path(const std::string& path) {
  if (path.empty()) return "";
  if (path.size() >= 2 && path.compare(path.size() - 2, 2, "']") == 0) {
    std::size_t open = path.rfind("['");
    return open == std::string::npos ? "" : path.substr(0, open);
  }
  if (path.back() == ']') {
    std::size_t open = path.rfind('[');
    return open == std::string::npos ? "" : path.substr(0, open);
  }
  std::size_t cut = path.find_last_of(".[");
  return cut == std::string::npos ? "" : path.substr(0, cut);
}

// A `where` that is a position or a file, not a JSON path.
bool is_path(const std::string& where, const std::string& file) {
  if (where.empty() || where == file) return false;
  if (where.rfind("line ", 0) == 0) return false;
  if (!file.empty() && where.rfind(file + ":", 0) == 0) return false;
  return true;
}

}  // namespace

JsonPositions::JsonPositions(std::string_view text) : text_(text) {
  Walker(text, positions_).run();
  std::stable_sort(positions_.begin(), positions_.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
}

std::optional<std::size_t> JsonPositions::find(const std::string& path, bool last) const {
  auto lo = std::lower_bound(positions_.begin(), positions_.end(), path,
                             [](const auto& p, const std::string& key) { return p.first < key; });
  if (lo == positions_.end() || lo->first != path) return std::nullopt;
  if (!last) return lo->second;
  auto hi = lo;
  while (hi + 1 != positions_.end() && (hi + 1)->first == path) ++hi;
  return hi->second;
}

std::optional<std::size_t> JsonPositions::find_enclosing(std::string path, bool last) const {
  for (bool first = true; !path.empty(); path = parent_path(path), first = false)
    if (auto at = find(path, first && last)) return at;
  return std::nullopt;
}

void locate_issues(std::string_view text, const std::string& file, std::vector<LoadIssue>& issues) {
  std::optional<JsonPositions> positions;
  // A loader may report an issue per element of a large file: the line breaks
  // are found once (placing each issue by counting them again was quadratic).
  std::optional<LineIndex> lines;
  for (auto& i : issues) {
    if (i.file.empty()) i.file = file;
    if (i.line > 0 || !is_path(i.where, i.file)) continue;
    if (!positions) {
      positions.emplace(text);
      lines.emplace(text);
    }
    bool repeated = i.what.rfind("duplicate key", 0) == 0;
    if (auto at = positions->find_enclosing(i.where, repeated)) {
      auto [line, column] = lines->line_and_column(*at);
      i.line = line;
      i.column = column;
    }
  }
}

}  // namespace cemv::formats
