#include "sheets/csv_grid_values.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "formats/csv_text.hpp"

namespace cemv::formats::grid {

using csv_text::lower;
using csv_text::trim;
using model::CauseFunction;
using model::LimitType;

namespace {

bool alnum(char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// The words of a text, lower case: runs of letters and digits.
std::vector<std::string> words_of(std::string_view text) {
  std::vector<std::string> out;
  std::string w;
  for (char c : text) {
    if (alnum(c)) {
      w += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    } else if (!w.empty()) {
      out.push_back(w);
      w.clear();
    }
  }
  if (!w.empty()) out.push_back(w);
  return out;
}

std::optional<int> small_number(std::string_view s) {
  if (s.empty() || s.size() > 2) return std::nullopt;
  int v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<LimitType> side_word(const std::string& w) {
  static const char* high[] = {"h", "hh", "hhh", "hi", "hihi", "high", "highhigh", "max", "maximum", "over", "above"};
  static const char* low[] = {"l", "ll", "lll", "lo", "lolo", "low", "lowlow", "min", "minimum", "under", "below"};
  for (const char* h : high)
    if (w == h) return LimitType::High;
  for (const char* l : low)
    if (w == l) return LimitType::Low;
  return std::nullopt;
}

}  // namespace

std::optional<Voting> parse_voting(std::string_view text, std::string& problem) {
  const std::string t = lower(trim(text));
  if (t == "and") return Voting{0, 0, CauseFunction::And};
  if (t == "or") return Voting{1, 0, CauseFunction::Or};
  // X oo N, X out of N, X of N, X/N.
  std::size_t i = 0;
  while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
  const auto votes = small_number(std::string_view(t).substr(0, i));
  std::string_view rest = trim(std::string_view(t).substr(i));
  bool joined = false;
  for (std::string_view joiner : {"out of", "oo", "of", "/"})
    if (rest.substr(0, joiner.size()) == joiner) {
      rest = trim(rest.substr(joiner.size()));
      joined = true;
      break;
    }
  const auto tags = small_number(rest);
  if (!votes || !tags || !joined) {
    problem = "not a voting such as 1oo1, 1oo2, 2oo2, 2oo3, AND or OR";
    return std::nullopt;
  }
  if (*votes < 1 || *votes > *tags) {
    problem = "a voting XooN needs 1 <= X <= N";
    return std::nullopt;
  }
  return Voting{*votes, *tags, std::nullopt};
}

std::optional<CauseFunction> function_of(const Voting& v, int tags) {
  if (v.word) return tags >= 2 && tags <= 3 ? v.word : std::nullopt;
  if (v.tags != tags) return std::nullopt;
  if (tags == 1) return CauseFunction::Normal;
  if (tags > 3) return std::nullopt;  // at most 3 tags per cause (3.4)
  if (v.votes == 1) return CauseFunction::Or;
  if (v.votes == tags) return CauseFunction::And;
  return CauseFunction::TwoOoThree;   // 2oo3, the one majority of 6.3.1
}

std::optional<int> parse_sil(std::string_view text) {
  std::string t = lower(trim(text));
  if (t.empty() || nil_value(t)) return 0;
  if (t.rfind("sil", 0) == 0) t = std::string(trim(std::string_view(t).substr(3)));
  const auto v = small_number(t);
  if (!v || *v < 0 || *v > 4) return std::nullopt;
  return v;
}

std::optional<Setpoint> parse_setpoint(std::string_view text) {
  std::string_view t = trim(text);
  Setpoint sp;
  if (!t.empty() && (t[0] == '>' || t[0] == '<')) {
    sp.side = t[0] == '>' ? LimitType::High : LimitType::Low;
    t.remove_prefix(t.size() > 1 && t[1] == '=' ? 2 : 1);
    t = trim(t);
  }
  std::size_t end = 0;
  while (end < t.size() && (alnum(t[end]) ? t[end] <= '9' : (t[end] == '.' || t[end] == ',' || t[end] == '-' || t[end] == '+')))
    ++end;
  std::string number(t.substr(0, end));
  if (number.find('.') == std::string::npos && std::count(number.begin(), number.end(), ',') == 1)
    number[number.find(',')] = '.';  // a decimal comma
  const char* first = number.data() + (!number.empty() && number[0] == '+' ? 1 : 0);
  auto [stop, ec] = std::from_chars(first, number.data() + number.size(), sp.value);
  if (number.empty() || ec != std::errc() || stop != number.data() + number.size() || !std::isfinite(sp.value))
    return std::nullopt;
  const std::string_view after = trim(t.substr(end));
  const auto side = parse_trip_side(after);
  if (side && !sp.side) sp.side = side;
  else if (!after.empty()) sp.rest = std::string(after);
  return sp;
}

std::optional<LimitType> parse_trip_side(std::string_view text) {
  const std::string t = lower(trim(text));
  if (t == ">" || t == ">=") return LimitType::High;
  if (t == "<" || t == "<=") return LimitType::Low;
  const auto words = words_of(t);
  return words.size() == 1 ? side_word(words[0]) : std::nullopt;
}

std::optional<LimitType> side_of_words(std::string_view text, bool& both) {
  std::optional<LimitType> side;
  both = false;
  for (const auto& w : words_of(text)) {
    const auto s = side_word(w);
    if (!s) continue;
    if (side && side != s) both = true;
    side = s;
  }
  return both ? std::nullopt : side;
}

std::vector<std::string> split_tags(std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != ',' && text[i] != ';' && text[i] != '\n') continue;
    std::string_view item = trim(text.substr(start, i - start));
    start = i + 1;
    if (item.empty()) continue;
    std::vector<std::string> parts;
    std::size_t from = 0;
    for (std::size_t k = 0; k <= item.size(); ++k)
      if (k == item.size() || item[k] == '/') {
        parts.emplace_back(trim(item.substr(from, k - from)));
        from = k + 1;
      }
    bool suffixes = parts.size() > 1;
    for (std::size_t k = 1; k < parts.size(); ++k)
      suffixes = suffixes && !parts[k].empty() && parts[k].size() <= 2 && parts[k].size() < parts[0].size() &&
                 std::all_of(parts[k].begin(), parts[k].end(), alnum);
    for (std::size_t k = 0; k < parts.size(); ++k) {
      if (parts[k].empty()) continue;
      if (suffixes && k > 0) out.push_back(parts[0].substr(0, parts[0].size() - parts[k].size()) + parts[k]);
      else out.push_back(parts[k]);
    }
  }
  return out;
}

bool nil_value(std::string_view text) {
  const std::string t = lower(trim(text));
  return t == "-" || t == "--" || t == "\xE2\x80\x93" || t == "\xE2\x80\x94" || t == "n/a" || t == "na" ||
         t == "none";
}

bool has_word(std::string_view text, const std::vector<std::string>& words) {
  const auto found = words_of(text);
  for (const auto& w : words) {
    const auto wanted = words_of(w);
    if (wanted.empty()) continue;
    for (std::size_t i = 0; i + wanted.size() <= found.size(); ++i)
      if (std::equal(wanted.begin(), wanted.end(), found.begin() + static_cast<long>(i))) return true;
  }
  return false;
}

}  // namespace cemv::formats::grid
