// cemv-matrix/1: the loader (structural checks only; plausibility is
// validate.cpp), the canonical writer and the signature. docs/format.md is the
// field-by-field description of what this file accepts.
#include "model/format.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <unordered_set>

#include "model/io.hpp"

namespace cemv::model {

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

namespace {

// The loader reads into an insertion-ordered DOM so that issues come out in
// file order; the writer uses the sorted one so that keys come out sorted.
using InJson = nlohmann::ordered_json;
using OutJson = nlohmann::json;

// Beyond this many issues a file is clearly not a matrix: stop listing.
constexpr std::size_t kMaxIssues = 100;

// ---- Text helpers ------------------------------------------------------------

// A user-supplied text as it can be shown in a message: quoted, bytes outside
// printable ASCII escaped (a message must never carry control characters or
// broken UTF-8 to the terminal), long texts shortened.
std::string in_quotes(std::string_view s, std::size_t max_chars = 48) {
  std::string out = "'";
  std::size_t shown = 0;
  for (unsigned char c : s) {
    if (shown == max_chars) {
      out += "...";
      break;
    }
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
    ++shown;
  }
  return out + "'";
}

// Same escaping for texts we did not write (nlohmann's messages quote input).
std::string printable(std::string_view s) {
  std::string q = in_quotes(s, 200);
  return q.substr(1, q.size() - 2);
}

// 1-based line and column (in bytes) of a 0-based byte index.
std::string line_column(std::string_view text, std::size_t index) {
  index = std::min(index, text.size());
  std::string_view before = text.substr(0, index);
  std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
  std::size_t last_newline = before.rfind('\n');
  std::size_t column = last_newline == std::string_view::npos ? index + 1 : index - last_newline;
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

std::size_t utf8_length(std::string_view s) {
  return static_cast<std::size_t>(
      std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                  std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// " (did you mean 'x'?)" when one candidate is a plausible typo of `word`.
std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates) {
  if (word.size() > 64) return "";
  std::string_view best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (auto c : candidates) {
    std::size_t d = edit_distance(word, c);
    // A truncated key ("cycle" for "cycle_ms") is a typo too.
    if (word.size() >= 4 && word.size() < c.size() && edit_distance(word, c.substr(0, word.size())) == 0) d = 1;
    if (d < best_distance) best_distance = d, best = c;
  }
  std::size_t allowed = best.size() <= 3 ? 1 : best.size() <= 8 ? 2 : 3;
  if (best.empty() || best_distance > allowed) return "";
  return " (did you mean '" + std::string(best) + "'?)";
}

// ---- Lexical pre-scan ----------------------------------------------------------

// Runs before the JSON parser so that hostile or non-JSON numbers get a precise
// position: nesting deeper than kMaxJsonDepth (the parser and the destructor
// of a DOM must never be given a million levels), numbers that overflow a
// double (1e999), and the non-JSON words NaN / Infinity. Returns false when
// the text must not be handed to the parser.
bool prescan(std::string_view text, std::vector<LoadIssue>& issues) {
  bool ok = true;
  int depth = 0;
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n; ++i) {
    char c = text[i];
    if (c == '"') {
      for (++i; i < n && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth) {
        issues.push_back({line_column(text, i), "JSON nesting deeper than " +
                                                     std::to_string(kMaxJsonDepth) +
                                                     " levels (a matrix needs 5)"});
        return false;
      }
    } else if (c == '}' || c == ']') {
      if (depth > 0) --depth;
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

// Reports keys repeated within one object, which nlohmann would silently
// collapse to the last value: an assessor reading the file might see the first.
class DuplicateKeyFinder {
 public:
  explicit DuplicateKeyFinder(std::vector<LoadIssue>& issues) : issues_(issues) {}

  bool operator()(int, InJson::parse_event_t event, InJson& parsed) {
    using E = InJson::parse_event_t;
    switch (event) {
      case E::object_start:
      case E::array_start: {
        std::string path = frames_.empty() ? "" : child_path(frames_.back());
        frames_.push_back(Frame{event == E::object_start, std::move(path), {}, 0, {}});
        break;
      }
      case E::key: {
        Frame& f = frames_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second && issues_.size() < kMaxIssues)
          issues_.push_back({member_path(f.path, f.key), "duplicate key (a key may appear once per object)"});
        break;
      }
      case E::value:
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        break;
      case E::object_end:
      case E::array_end:
        frames_.pop_back();
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        break;
    }
    return true;
  }

 private:
  struct Frame {
    bool object = false;
    std::string path;
    std::string key;
    std::size_t index = 0;
    std::unordered_set<std::string> keys;
  };
  static std::string child_path(const Frame& f) {
    return f.object ? member_path(f.path, f.key) : element_path(f.path, f.index);
  }
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

// ---- Enumerations ----------------------------------------------------------------

template <class E>
struct EnumNames {
  std::vector<E> values;
  std::vector<std::string_view> names() const {
    std::vector<std::string_view> out;
    for (E v : values) out.push_back(to_string(v));
    return out;
  }
};

const EnumNames<InputKind> kInputKinds{{InputKind::Discrete, InputKind::Analog}};
const EnumNames<CauseFunction> kCauseFunctions{{CauseFunction::Normal, CauseFunction::And, CauseFunction::Or,
                                                CauseFunction::TwoOoThree, CauseFunction::Comment}};
const EnumNames<LimitType> kLimitTypes{{LimitType::High, LimitType::Low}};
const EnumNames<BadQuality> kBadQualities{{BadQuality::Ignore, BadQuality::Trip, BadQuality::Degrade}};
const EnumNames<TimeMode> kTimeModes{{TimeMode::None, TimeMode::OnDelay, TimeMode::OffDelay, TimeMode::Timed}};
const EnumNames<EffectFunction> kEffectFunctions{{EffectFunction::Normal, EffectFunction::Comment}};
const EnumNames<IntersectionType> kIntersectionTypes{
    {IntersectionType::N, IntersectionType::S, IntersectionType::V, IntersectionType::R, IntersectionType::X,
     IntersectionType::Note}};

// ---- The reader --------------------------------------------------------------

// Walks the DOM, converting into the model while recording every problem with
// its JSON path. Each typed read returns false (leaving the target untouched)
// after recording why the value was not accepted.
class Reader {
 public:
  explicit Reader(std::vector<LoadIssue>& issues) : issues_(issues) {}

  void error(const std::string& where, std::string what) {
    if (issues_.size() < kMaxIssues) {
      issues_.push_back({where, std::move(what)});
    } else if (issues_.size() == kMaxIssues) {
      issues_.push_back({"", "too many problems; the rest are not listed"});
    }
  }

  using Handler = std::function<void(const InJson&, const std::string&)>;
  struct Field {
    std::string_view key;
    bool required;
    Handler read;
  };

  // Members in file order: a known key goes to its handler, an unknown one is
  // an error (a misspelt optional key must never pass as "absent"). Missing
  // required keys are reported after the members. Returns false when `j` is not
  // an object at all.
  bool object(const InJson& j, const std::string& path, const std::vector<Field>& fields) {
    if (!j.is_object()) {
      error(path, "expected an object, got " + describe(j));
      return false;
    }
    std::vector<bool> seen(fields.size(), false);
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::string& key = it.key();
      auto field = std::find_if(fields.begin(), fields.end(), [&](const Field& f) { return f.key == key; });
      if (field == fields.end()) {
        std::vector<std::string_view> known;
        for (const auto& f : fields) known.push_back(f.key);
        error(member_path(path, key), "unknown key" + suggestion(key, known));
        continue;
      }
      seen[static_cast<std::size_t>(field - fields.begin())] = true;
      field->read(it.value(), member_path(path, key));
    }
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (fields[i].required && !seen[i]) error(member_path(path, fields[i].key), "required key is missing");
    return true;
  }

  bool boolean(const InJson& j, const std::string& path, bool& out) {
    if (!j.is_boolean()) {
      error(path, "expected true or false, got " + describe(j));
      return false;
    }
    out = j.get<bool>();
    return true;
  }

  // Integers accept integral-valued floats (2.0) but nothing else.
  template <class T>
  bool integer(const InJson& j, const std::string& path, long long lo, long long hi, T& out,
               std::string_view why = "") {
    long long v = 0;
    if (j.is_number_unsigned()) {
      auto u = j.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(hi)) return out_of_range(path, j.dump(), lo, hi, why);
      v = static_cast<long long>(u);
    } else if (j.is_number_integer()) {
      v = j.get<std::int64_t>();
    } else if (j.is_number_float()) {
      double d = j.get<double>();
      if (!std::isfinite(d) || std::trunc(d) != d) {
        error(path, "expected an integer, got " + describe(j));
        return false;
      }
      if (d < static_cast<double>(lo) || d > static_cast<double>(hi))
        return out_of_range(path, j.dump(), lo, hi, why);
      v = static_cast<long long>(d);
    } else {
      error(path, "expected an integer, got " + describe(j));
      return false;
    }
    if (v < lo || v > hi) return out_of_range(path, std::to_string(v), lo, hi, why);
    out = static_cast<T>(v);
    return true;
  }

  // IEEE single precision (REAL, 6.3.1): a value that would round to infinity
  // is rejected rather than silently saturated.
  bool real(const InJson& j, const std::string& path, float& out) {
    if (!j.is_number()) {
      error(path, "expected a number, got " + describe(j));
      return false;
    }
    double d = j.get<double>();
    // Half an ulp above FLT_MAX: anything from here on rounds to infinity.
    constexpr double kFloatOverflow = 0x1.ffffffp+127;
    if (!std::isfinite(d) || std::fabs(d) >= kFloatOverflow) {
      error(path, j.dump() + " is out of the range of a single-precision REAL (about +/-3.4e38, 6.3.1)");
      return false;
    }
    out = static_cast<float>(d);
    if (out == 0.0f) out = 0.0f;  // -0 and 0 are one value; keep the canonical form unique
    return true;
  }

  // Free text: no control characters (they would corrupt reports), at most
  // max_chars characters (UTF-8 code points).
  bool text(const InJson& j, const std::string& path, std::string& out,
            std::size_t max_chars = std::string::npos, std::string_view why = "") {
    if (!j.is_string()) {
      error(path, "expected a string, got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    for (unsigned char c : s) {
      if (c < 0x20 || c == 0x7f) {
        error(path, in_quotes(s) + " contains a control character");
        return false;
      }
    }
    if (max_chars != std::string::npos && utf8_length(s) > max_chars) {
      error(path, in_quotes(s) + " is longer than " + std::to_string(max_chars) + " characters" +
                      (why.empty() ? "" : " (" + std::string(why) + ")"));
      return false;
    }
    out = s;
    return true;
  }

  bool tag(const InJson& j, const std::string& path, std::string& out) {
    if (!j.is_string()) {
      error(path, "expected a tag name (string), got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    if (auto problem = tag_name_problem(s)) {
      error(path, *problem);
      return false;
    }
    out = s;
    return true;
  }

  // Optional tag: null and absence both mean "no tag".
  bool optional_tag(const InJson& j, const std::string& path, std::optional<std::string>& out) {
    if (j.is_null()) {
      out.reset();
      return true;
    }
    std::string s;
    if (!tag(j, path, s)) return false;
    out = std::move(s);
    return true;
  }

  bool element_name(const InJson& j, const std::string& path, std::string& out) {
    if (!j.is_string()) {
      error(path, "expected a name (string), got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    if (auto problem = element_name_problem(s)) {
      error(path, *problem);
      return false;
    }
    out = s;
    return true;
  }

  template <class E>
  bool enumeration(const InJson& j, const std::string& path, const EnumNames<E>& names, E& out) {
    std::string list;
    for (auto n : names.names()) list += (list.empty() ? "'" : ", '") + std::string(n) + "'";
    if (!j.is_string()) {
      error(path, "expected one of " + list + ", got " + describe(j));
      return false;
    }
    const auto& s = j.get_ref<const std::string&>();
    for (E v : names.values) {
      if (s == to_string(v)) {
        out = v;
        return true;
      }
    }
    error(path, in_quotes(s) + " is not one of " + list + suggestion(s, names.names()));
    return false;
  }

  static std::string describe(const InJson& j) {
    switch (j.type()) {
      case InJson::value_t::object: return "an object";
      case InJson::value_t::array: return "an array";
      case InJson::value_t::string: return "the string " + in_quotes(j.get_ref<const std::string&>());
      case InJson::value_t::null: return "null";
      default: return printable(j.dump());
    }
  }

 private:
  bool out_of_range(const std::string& path, const std::string& shown, long long lo, long long hi,
                    std::string_view why) {
    error(path, shown + " is out of range " + std::to_string(lo) + "-" + std::to_string(hi) +
                    (why.empty() ? "" : " (" + std::string(why) + ")"));
    return false;
  }

  std::vector<LoadIssue>& issues_;
};

constexpr long long kU32Max = std::numeric_limits<std::uint32_t>::max();

// Reads a JSON array whose elements `read_one` converts; `limit` (of 3.4) is
// checked on the count first so that the message names the limit.
template <class T, class ReadOne>
void read_array(Reader& r, const InJson& j, const std::string& path, std::vector<T>& out, std::size_t limit,
                const std::string& limit_text, ReadOne read_one) {
  if (!j.is_array()) {
    r.error(path, "expected an array, got " + Reader::describe(j));
    return;
  }
  if (j.size() > limit) r.error(path, std::to_string(j.size()) + " entries, more than " + limit_text);
  for (std::size_t i = 0; i < j.size(); ++i) {
    T item;
    if (read_one(j[i], element_path(path, i), item)) out.push_back(std::move(item));
  }
}

// `sif`: up to 4 group numbers of 1-64 (6.3, 6.4 "SIF Grouping"; 6.1 properties).
void read_sif_list(Reader& r, const InJson& j, const std::string& path, std::vector<int>& out) {
  std::vector<int> groups;
  read_array(r, j, path, groups, kMaxSifPerElement, "the 4 SIF groups an element can belong to (6.3.6)",
             [&](const InJson& v, const std::string& p, int& g) {
               return r.integer(v, p, 1, kMaxSifGroups, g, "SIF groups are numbered 1-64");
             });
  std::sort(groups.begin(), groups.end());
  auto dup = std::adjacent_find(groups.begin(), groups.end());
  if (dup != groups.end()) r.error(path, "lists SIF group " + std::to_string(*dup) + " twice");
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  out = std::move(groups);
}

void read_description(Reader& r, const InJson& j, const std::string& path, std::string& out) {
  r.text(j, path, out, kMaxDescriptionLength, "descriptions, 6.3.4 and 6.4.4");
}

Cause read_cause(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Cause c;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, c.id, "causes are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, c.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, c.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, c.sil, "0 = not stated"); }},
      {"input", false, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kInputKinds, c.input); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kCauseFunctions, c.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, c.tags, kMaxCauseTags, "the 3 input tags of a cause (3.4)",
                    [&](const InJson& t, const std::string& tp, CauseTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                          {"soft_bypass_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.soft_bypass_allowed); }},
                      });
                      return named;
                    });
       }},
      {"analog", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         AnalogParams a;
         bool read = r.object(v, p, {
             {"limit_type", true, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kLimitTypes, a.limit_type); }},
             {"limit", true, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.limit); }},
             {"hysteresis", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.hysteresis); }},
             {"prewarning", false,
              [&](const InJson& v2, const std::string& p2) {
                float f = 0.0f;
                if (!v2.is_null() && r.real(v2, p2, f)) a.prewarning = f;
              }},
             {"delta", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.delta); }},
             {"unit", false, [&](const InJson& v2, const std::string& p2) { r.text(v2, p2, a.unit); }},
         });
         if (read) c.analog = a;
       }},
      {"bad_quality", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kBadQualities, c.bad_quality); }},
      {"time", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"mode", false, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kTimeModes, c.time.mode); }},
             {"ms", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.time.ms); }},
         });
       }},
      {"auto_ack", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.auto_ack); }},
      {"soft_bypass", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"allowed", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, c.soft_bypass.allowed); }},
             {"max_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.max_s); }},
             {"prealarm_s", false,
              [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.prealarm_s); }},
         });
       }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.bypass_tag); }},
      {"inhibit_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.inhibit_tag); }},
      {"first_out_group", false,
       [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 0, kMaxFirstOutGroup, c.first_out_group, "0 = none, groups 1-15");
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, c.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, c.note); }},
  });
  if (!ok) return c;
  // 3.4: 1-3 input tags; a comment-only cause is not processed and may have none.
  if (c.function != CauseFunction::Comment && c.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "a cause needs 1-3 input tags (3.4), got none");
  }
  if (c.input == InputKind::Analog && (!j.contains("analog") || j.at("analog").is_null()))
    r.error(member_path(path, "analog"), "required for an analog cause (limit_type and limit, 6.3.5)");
  return c;
}

Effect read_effect(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Effect e;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, e.id, "effects are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, e.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, e.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, e.sil, "0 = not stated"); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kEffectFunctions, e.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, e.tags, kMaxEffectTags, "the 4 output tags of an effect (3.4)",
                    [&](const InJson& t, const std::string& tp, EffectTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                      });
                      return named;
                    });
       }},
      {"output_delay_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, e.output_delay_ms); }},
      {"soft_bypass_allowed", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.soft_bypass_allowed); }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.bypass_tag); }},
      {"reset_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.reset_tag); }},
      {"override", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         Override o;
         bool read = r.object(v, p, {
             {"max_s", true, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.max_s); }},
             {"prealarm_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.prealarm_s); }},
         });
         if (read) e.override_time = o;
       }},
      {"process_data", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         ProcessData d;
         bool read = r.object(v, p, {
             {"tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.tag); }},
             {"pass_through", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, d.pass_through); }},
             {"mask_tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.mask_tag); }},
         });
         if (read) e.process_data = d;
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, e.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, e.note); }},
  });
  if (!ok) return e;
  // 3.4: 1-4 output tags; a comment-only effect drives nothing and may have none.
  if (e.function != EffectFunction::Comment && e.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "an effect needs 1-4 output tags (3.4), got none");
  }
  return e;
}

Intersection read_intersection(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Intersection x;
  ok = r.object(j, path, {
      {"cause", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, x.cause, "causes are numbered 1-128, 3.4");
       }},
      {"effect", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, x.effect, "effects are numbered 1-128, 3.4");
       }},
      {"type", true, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kIntersectionTypes, x.type); }},
      {"xoon", false,
       [&](const InJson& v, const std::string& p) {
         int k = 0;
         if (!v.is_null() && r.integer(v, p, kMinXooN, kMaxXooN, k, "the X of XooN, 6.5.2")) x.xoon = k;
       }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, x.note); }},
  });
  return x;
}

void read_matrix(Reader& r, const InJson& root, Matrix& m) {
  if (!root.is_object()) {
    r.error("", "the top level must be a JSON object (a cemv-matrix/1 document), got " + Reader::describe(root));
    return;
  }
  // A different format would drown the real problem in unknown keys.
  if (!root.contains("format")) {
    r.error("format", "required key is missing (expected '" + std::string(kMatrixFormat) + "')");
  } else {
    const auto& f = root["format"];
    if (!f.is_string() || f.get_ref<const std::string&>() != kMatrixFormat) {
      r.error("format", (f.is_string() ? in_quotes(f.get_ref<const std::string&>()) : Reader::describe(f)) +
                            " is not a supported format; expected '" + kMatrixFormat + "'");
      return;
    }
  }
  r.object(root, "", {
      {"format", false, [](const InJson&, const std::string&) {}},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, m.name); }},
      {"title", false, [&](const InJson& v, const std::string& p) { r.text(v, p, m.title); }},
      {"cycle_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 1, kU32Max, m.cycle_ms, "must be positive"); }},
      {"sif_groups", false,
       [&](const InJson& v, const std::string& p) {
         if (!v.is_object()) {
           r.error(p, "expected an object mapping group numbers to names, got " + Reader::describe(v));
           return;
         }
         for (auto it = v.begin(); it != v.end(); ++it) {
           const std::string& key = it.key();
           std::string kp = member_path(p, key);
           int number = 0;
           auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), number);
           bool canonical = ec == std::errc{} && end == key.data() + key.size() && key[0] != '0';
           if (!canonical || number < 1 || number > kMaxSifGroups) {
             r.error(kp, "SIF group numbers are 1-64 written without leading zeros, got " + in_quotes(key));
             continue;
           }
           std::string name;
           if (r.text(it.value(), kp, name)) m.sif_groups[number] = name;
         }
       }},
      {"secure_write", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         SecureWrite s;
         if (r.object(v, p, {{"enable_tag", true,
                              [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, s.enable_tag); }}}))
           m.secure_write = s;
       }},
      {"group_deactivation", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         GroupDeactivation g;
         bool read = r.object(v, p, {
             {"enable_tag", true, [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, g.enable_tag); }},
             {"set_tag", true, [&](const InJson& v2, const std::string& p2) { r.tag(v2, p2, g.set_tag); }},
         });
         if (read) m.group_deactivation = g;
       }},
      {"causes", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.causes, kMaxCauses, "the 128 causes of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Cause& c) {
                      bool ok = false;
                      c = read_cause(r, e, ep, ok);
                      return ok;
                    });
       }},
      {"effects", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.effects, kMaxEffects, "the 128 effects of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Effect& x) {
                      bool ok = false;
                      x = read_effect(r, e, ep, ok);
                      return ok;
                    });
       }},
      {"intersections", false,
       [&](const InJson& v, const std::string& p) {
         read_array(r, v, p, m.intersections, kMaxIntersections, "the 1024 intersections of a matrix (3.4)",
                    [&](const InJson& e, const std::string& ep, Intersection& x) {
                      bool ok = false;
                      x = read_intersection(r, e, ep, ok);
                      return ok;
                    });
       }},
  });
}

// Elements in id order so that Matrix::find_* (binary search) work; stable so
// that duplicates (validate() reports them) keep their file order.
void sort_elements(Matrix& m) {
  std::stable_sort(m.causes.begin(), m.causes.end(), [](const Cause& a, const Cause& b) { return a.id < b.id; });
  std::stable_sort(m.effects.begin(), m.effects.end(), [](const Effect& a, const Effect& b) { return a.id < b.id; });
  std::stable_sort(m.intersections.begin(), m.intersections.end(), [](const Intersection& a, const Intersection& b) {
    return std::pair{a.cause, a.effect} < std::pair{b.cause, b.effect};
  });
}

// ---- The canonical writer -------------------------------------------------------

OutJson optional_text(const std::optional<std::string>& s) { return s ? OutJson(*s) : OutJson(nullptr); }

// Floats travel through the DOM as the double of the float; emit() prints them
// with float_text, so every REAL is written in its shortest single form.
OutJson real_value(float f) {
  if (!std::isfinite(f)) throw std::invalid_argument("a matrix value is NaN or infinite; it has no JSON form");
  return OutJson(static_cast<double>(f == 0.0f ? 0.0f : f));
}

OutJson sorted_sif(std::vector<int> sif) {
  std::sort(sif.begin(), sif.end());
  return OutJson(sif);
}

OutJson cause_json(const Cause& c) {
  OutJson tags = OutJson::array();
  for (const auto& t : c.tags)
    tags.push_back({{"name", t.name}, {"ett", t.ett}, {"soft_bypass_allowed", t.soft_bypass_allowed}});
  OutJson analog = nullptr;
  if (c.analog) {
    const auto& a = *c.analog;
    analog = {{"limit_type", to_string(a.limit_type)},
              {"limit", real_value(a.limit)},
              {"hysteresis", real_value(a.hysteresis)},
              {"prewarning", a.prewarning ? real_value(*a.prewarning) : OutJson(nullptr)},
              {"delta", real_value(a.delta)},
              {"unit", a.unit}};
  }
  return {{"id", c.id},
          {"name", c.name},
          {"description", c.description},
          {"sil", c.sil},
          {"input", to_string(c.input)},
          {"function", to_string(c.function)},
          {"tags", tags},
          {"analog", analog},
          {"bad_quality", to_string(c.bad_quality)},
          {"time", {{"mode", to_string(c.time.mode)}, {"ms", c.time.ms}}},
          {"auto_ack", c.auto_ack},
          {"soft_bypass",
           {{"allowed", c.soft_bypass.allowed}, {"max_s", c.soft_bypass.max_s}, {"prealarm_s", c.soft_bypass.prealarm_s}}},
          {"bypass_tag", optional_text(c.bypass_tag)},
          {"inhibit_tag", optional_text(c.inhibit_tag)},
          {"first_out_group", c.first_out_group},
          {"mutually_locked_maintenance", c.mutually_locked_maintenance},
          {"sif", sorted_sif(c.sif)},
          {"note", c.note}};
}

OutJson effect_json(const Effect& e) {
  OutJson tags = OutJson::array();
  for (const auto& t : e.tags) tags.push_back({{"name", t.name}, {"ett", t.ett}});
  OutJson override_json = nullptr;
  if (e.override_time) override_json = {{"max_s", e.override_time->max_s}, {"prealarm_s", e.override_time->prealarm_s}};
  OutJson process = nullptr;
  if (e.process_data)
    process = {{"tag", optional_text(e.process_data->tag)},
               {"pass_through", e.process_data->pass_through},
               {"mask_tag", optional_text(e.process_data->mask_tag)}};
  return {{"id", e.id},
          {"name", e.name},
          {"description", e.description},
          {"sil", e.sil},
          {"function", to_string(e.function)},
          {"tags", tags},
          {"output_delay_ms", e.output_delay_ms},
          {"soft_bypass_allowed", e.soft_bypass_allowed},
          {"bypass_tag", optional_text(e.bypass_tag)},
          {"reset_tag", optional_text(e.reset_tag)},
          {"override", override_json},
          {"process_data", process},
          {"mutually_locked_maintenance", e.mutually_locked_maintenance},
          {"sif", sorted_sif(e.sif)},
          {"note", e.note}};
}

OutJson matrix_json(const Matrix& m) {
  Matrix sorted = m;
  sort_elements(sorted);
  OutJson groups = OutJson::object();
  for (const auto& [number, name] : sorted.sif_groups) groups[std::to_string(number)] = name;
  OutJson causes = OutJson::array(), effects = OutJson::array(), intersections = OutJson::array();
  for (const auto& c : sorted.causes) causes.push_back(cause_json(c));
  for (const auto& e : sorted.effects) effects.push_back(effect_json(e));
  for (const auto& x : sorted.intersections)
    intersections.push_back({{"cause", x.cause},
                             {"effect", x.effect},
                             {"type", to_string(x.type)},
                             {"xoon", x.xoon ? OutJson(*x.xoon) : OutJson(nullptr)},
                             {"note", x.note}});
  OutJson secure = nullptr, group = nullptr;
  if (sorted.secure_write) secure = {{"enable_tag", sorted.secure_write->enable_tag}};
  if (sorted.group_deactivation)
    group = {{"enable_tag", sorted.group_deactivation->enable_tag}, {"set_tag", sorted.group_deactivation->set_tag}};
  return {{"format", kMatrixFormat},
          {"name", sorted.name},
          {"title", sorted.title},
          {"cycle_ms", sorted.cycle_ms},
          {"sif_groups", groups},
          {"secure_write", secure},
          {"group_deactivation", group},
          {"causes", causes},
          {"effects", effects},
          {"intersections", intersections}};
}

std::string scalar_text(const OutJson& j) {
  if (j.is_number_float()) return float_text(static_cast<float>(j.get<double>()));
  // Strings from a loaded file are valid UTF-8; anything else is replaced
  // deterministically rather than thrown on.
  return j.dump(-1, ' ', false, OutJson::error_handler_t::replace);
}

// nlohmann::json keeps object keys in a std::map, so they come out sorted by
// bytes; each element on its own line, two spaces per level.
void emit(const OutJson& j, int indent, std::string& out) {
  std::string pad(static_cast<std::size_t>(indent + 2), ' ');
  if (j.is_object() && !j.empty()) {
    out += "{\n";
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
      out += pad + OutJson(it.key()).dump(-1, ' ', false, OutJson::error_handler_t::replace) + ": ";
      emit(it.value(), indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
  } else if (j.is_array() && !j.empty()) {
    out += "[\n";
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += pad;
      emit(j[i], indent + 2, out);
      out += i + 1 < j.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
  } else if (j.is_object()) {
    out += "{}";
  } else if (j.is_array()) {
    out += "[]";
  } else {
    out += scalar_text(j);
  }
}

}  // namespace

// ---- Names (6.1.4, 3.4) -------------------------------------------------------------

std::optional<std::string> tag_name_problem(std::string_view name) {
  if (name.empty()) return "tag name is empty";
  // Internal references are names of their own kind (6.1.3, 6.1.4).
  if (parse_internal_ref(name)) return std::nullopt;
  const std::string q = in_quotes(name);
  if (name.size() > kMaxTagNameLength)
    return q + " is longer than " + std::to_string(kMaxTagNameLength) + " characters";
  for (char c : name) {
    if (c == '"' || c == '%' || c == '~') return q + " contains '" + std::string(1, c) + "', which tag names must not use";
    auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u > 0x7a) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "0x%02X", u);
      return q + " contains the byte " + buf + ", outside the permitted characters 0x20-0x7A";
    }
  }
  if (name.front() == ' ') return q + " starts with a blank";
  if (name.back() == ' ') return q + " ends with a blank";
  if (name.back() == '\'') return q + " ends with an inverted comma (')";
  if (name.front() == '@') return q + " starts with '@', which marks an external address";
  const bool prefix = name.front() == '#';
  const bool suffix = name.back() == '#';
  if (!prefix && !suffix) return std::nullopt;
  // A chart connection: the extra rules of CFC chart inputs apply. With both
  // marks the suffix is dropped at transfer (6.1.3), so the prefix rules apply.
  std::string_view body = name.substr(prefix ? 1 : 0);
  if (suffix && !body.empty()) body.remove_suffix(1);
  if (body.empty()) return q + " has no name besides '#'";
  auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  if (prefix && !(letter(body.front()) || body.front() == '_'))
    return q + " must start with a letter or '_' after the '#' prefix";
  if (!prefix && !(letter(body.front()) || digit(body.front())))
    return q + " must start with a letter or a digit before the '#' suffix";
  for (char c : body)
    if (!(letter(c) || digit(c) || c == '_' || c == ' '))
      return q + " contains '" + std::string(1, c) +
             "'; chart connection names ('#') allow only letters, digits, '_' and blanks";
  if (body.find("__") != std::string_view::npos) return q + " repeats '_'";
  if (body.back() == '_') return q + " ends with '_'";
  if (body.back() == ' ') return q + " has a blank before the '#' suffix";
  return std::nullopt;
}

std::optional<std::string> element_name_problem(std::string_view name) {
  if (name.empty()) return "name is empty";
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      return in_quotes(name) + " contains " + in_quotes(std::string_view(&c, 1)) +
             "; names allow only letters, digits and '_' (6.3.4)";
  if (name.size() > kMaxElementNameLength)
    return in_quotes(name) + " is longer than " + std::to_string(kMaxElementNameLength) + " characters (6.3.4)";
  return std::nullopt;
}

// ---- Public API ---------------------------------------------------------------------

Matrix parse_matrix(std::string_view json_text, const std::string& source_name) {
  std::vector<LoadIssue> issues;
  if (json_text.size() > kMaxFileBytes)
    throw LoadError({{source_name, "input is " + std::to_string(json_text.size()) + " bytes, larger than the limit of " +
                                       std::to_string(kMaxFileBytes) + " bytes"}});
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-matrix/1 JSON object)"}});
  if (!prescan(json_text, issues)) throw LoadError(std::move(issues));

  InJson root;
  try {
    DuplicateKeyFinder finder(issues);
    root = InJson::parse(json_text.begin(), json_text.end(), std::ref(finder));
  } catch (const InJson::parse_error& e) {
    std::size_t index = e.byte == 0 ? 0 : e.byte - 1;
    issues.push_back({line_column(json_text, index), parse_error_text(e.what())});
    throw LoadError(std::move(issues));
  } catch (const InJson::exception& e) {
    issues.push_back({source_name, parse_error_text(e.what())});
    throw LoadError(std::move(issues));
  }

  Matrix m;
  Reader reader(issues);
  read_matrix(reader, root, m);
  if (!issues.empty()) throw LoadError(std::move(issues));
  sort_elements(m);
  return m;
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

Matrix load_matrix(const std::filesystem::path& file) {
  return parse_matrix(read_text_file(file), file.string());
}

std::string float_text(float v) {
  char buf[64];
  auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

std::string to_canonical_json(const Matrix& m) {
  std::string out;
  emit(matrix_json(m), 0, out);
  out += "\n";
  return out;
}

void save_matrix(const Matrix& m, const std::filesystem::path& file) {
  std::string text = to_canonical_json(m);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error(file.string() + ": cannot write: " + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw std::runtime_error(file.string() + ": write failed");
}

std::string signature(const Matrix& m) {
  std::string text = to_canonical_json(m);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(text.data(), text.size(), digest, &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256 failed (OpenSSL EVP_Digest)");
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 0xF];
  }
  return out;
}

}  // namespace cemv::model
