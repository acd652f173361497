#include "sheets/workbook_tags.hpp"

#include <cctype>

namespace cemv::formats::workbook {

namespace {

bool iequal(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// "[12]" at `s`: the length, 0 when none (1-3 digits, as 6.1.3 numbers go).
std::size_t bracket(std::string_view s) {
  if (s.empty() || s[0] != '[') return 0;
  std::size_t i = 1;
  while (i < s.size() && i <= 3 && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  return i > 1 && i < s.size() && s[i] == ']' ? i + 1 : 0;
}

// `cause[x]`, `effect[x]`, `effect[x][y]` in any letter case: the spelling of
// 6.1.3; empty when `name` is no such reference.
std::string reference_spelling(std::string_view name) {
  for (std::string_view word : {std::string_view("Cause"), std::string_view("Effect")}) {
    if (name.size() <= word.size() || !iequal(name.substr(0, word.size()), word)) continue;
    std::string_view rest = name.substr(word.size());
    std::size_t first = bracket(rest);
    if (first == 0) continue;
    std::size_t second = word == "Effect" ? bracket(rest.substr(first)) : 0;
    if (first + second != rest.size()) continue;
    return std::string(word) + std::string(rest);
  }
  return "";
}

}  // namespace

TagCell read_tag_cell(std::string_view text) {
  TagCell cell;
  bool seen_at = false, seen_tilde = false, seen_star = false;
  while (!text.empty()) {
    if (text[0] == '@' && !seen_at) {
      seen_at = true;
      cell.ignored.push_back("'@' used externally");
    } else if (text[0] == '~' && !seen_tilde) {
      seen_tilde = true;
      cell.ignored.push_back("'~' customized");
    } else if (text[0] == '*' && !seen_star) {
      seen_star = true;
      cell.ignored.push_back("'*' with preprocessing");
    } else {
      break;
    }
    text.remove_prefix(1);
  }
  cell.name = std::string(text);
  std::string reference = reference_spelling(text);
  if (!reference.empty() && reference != cell.name) {
    cell.normalized = reference;
    cell.name = reference;
  }
  return cell;
}

std::string tag_cell_text(std::string_view name) {
  if (!name.empty() && name[0] == '*') return "*" + std::string(name);
  return std::string(name);
}

}  // namespace cemv::formats::workbook
