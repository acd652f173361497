// Text helpers of every message: quoting, typo hints, float text. One
// definition each, so that a hint or a quoted name reads the same whichever
// file (matrix, scenario, CSV) or check (validation) produced it.
#include "model/text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <limits>

namespace cemv::model {

// A user-supplied text as it can be shown in a message: quoted, bytes outside
// printable ASCII escaped (a message must never carry control characters or
// broken UTF-8 to the terminal), long texts shortened.
std::string in_quotes(std::string_view s, std::size_t max_chars) {
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
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates) {
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

std::string did_you_mean(std::string_view word, const std::vector<std::string>& candidates) {
  return did_you_mean(word, std::vector<std::string_view>(candidates.begin(), candidates.end()));
}

std::string float_text(float v) {
  char buf[64];
  auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

}  // namespace cemv::model
