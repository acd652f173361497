// Small text helpers shared by the CSV readers and writers (formats/csv*.cpp
// and the grid's, sheets/csv_grid*.cpp); not part of the public interface.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace cemv::formats::csv_text {

// Appends item to a separated list (not `s += (s.empty() ? "" : sep) + item`,
// which trips GCC 12's -Wrestrict false positive at -O3).
inline void join_to(std::string& list, std::string_view separator, const std::string& item) {
  if (!list.empty()) list += separator;
  list += item;
}

inline std::string_view trim(std::string_view s) {
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

inline std::string lower(std::string_view s) {
  std::string out(s);
  for (auto& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

// "FILE: line L, column C" (the column left out when 0).
inline std::string where_of(const std::string& source, int line, int column = 0) {
  std::string w;
  if (!source.empty()) w = source + ": ";
  w += "line " + std::to_string(line);
  if (column > 0) w += ", column " + std::to_string(column);
  return w;
}

// "3-12, 14, 16-19" from a sorted list of numbers.
inline std::string number_ranges(const std::vector<int>& numbers) {
  std::string out;
  for (std::size_t i = 0; i < numbers.size();) {
    std::size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += std::to_string(numbers[i]);
    if (j > i) out += "-" + std::to_string(numbers[j]);
    i = j + 1;
  }
  return out;
}

// Cuts UTF-8 text to at most n characters (code points, as the loader counts).
inline std::string truncate_utf8(std::string_view s, std::size_t n) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) != 0x80 && chars++ == n) return std::string(s.substr(0, i));
  }
  return std::string(s);
}

// Free text of a hand-made sheet: control characters (line breaks inside a
// quoted cell) become blanks, since the format allows none in text (docs/format.md).
inline std::string one_line(std::string_view s) {
  std::string out;
  for (char c : s) {
    auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7f) ? ' ' : c;
  }
  return out;
}

}  // namespace cemv::formats::csv_text
