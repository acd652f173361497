// Where a validation finding's element starts in a matrix text
// (matrix_json.hpp, element_offset): validate() works on the model, which keeps
// no positions, so the element is found again in the text by its id (and name).
#include <cctype>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/matrix_json.hpp"

namespace cemv::formats {

namespace {

// The unsigned integer value of the member whose key starts at `key_at`.
std::optional<long> integer_after_key(std::string_view text, std::size_t key_at) {
  std::size_t i = text.find(':', key_at);
  if (i == std::string_view::npos) return std::nullopt;
  ++i;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  long v = 0;
  std::size_t start = i;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i])) && i - start < 9)
    v = v * 10 + (text[i++] - '0');
  if (i == start || (i < text.size() && (text[i] == '.' || text[i] == 'e' || text[i] == 'E')))
    return std::nullopt;
  return v;
}

// "cause[12]..." at `s`: 12.
std::optional<long> bracketed_id(std::string_view s, std::string_view prefix) {
  if (s.substr(0, prefix.size()) != prefix) return std::nullopt;
  long v = 0;
  std::size_t i = prefix.size(), start = i;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && i - start < 9) v = v * 10 + (s[i++] - '0');
  if (i == start || i >= s.size() || s[i] != ']') return std::nullopt;
  return v;
}

// The string value (without escapes: names have none) of the member whose key starts at `key_at`.
std::optional<std::string_view> name_after_key(std::string_view text, std::size_t key_at) {
  std::size_t i = text.find(':', key_at);
  if (i == std::string_view::npos) return std::nullopt;
  ++i;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i >= text.size() || text[i] != '"') return std::nullopt;
  std::size_t end = text.find('"', i + 1);
  if (end == std::string_view::npos) return std::nullopt;
  return text.substr(i + 1, end - i - 1);
}

// The first element of `array` whose integer members have the given values
// and, when `name` is not empty, whose name is `name` (of two elements with
// one id, the finding names the one it is about); failing that, the first
// with the values alone.
std::optional<std::size_t> element_with(const JsonPositions& positions, const std::string& array,
                                        const std::vector<std::pair<std::string, long>>& keys,
                                        std::string_view name = {}) {
  std::optional<std::size_t> by_keys;
  for (std::size_t index = 0;; ++index) {
    std::string path = element_path(array, index);
    auto at = positions.find(path);
    if (!at) return by_keys;
    bool all = true;
    for (const auto& [key, want] : keys) {
      auto key_at = positions.find(member_path(path, key));
      all = all && key_at && integer_after_key(positions.text(), *key_at) == want;
    }
    if (!all) continue;
    if (name.empty()) return at;
    auto name_at = positions.find(member_path(path, "name"));
    if (name_at && name_after_key(positions.text(), *name_at) == name) return at;
    if (!by_keys) by_keys = at;
  }
}

// "cause[3] NAME": NAME ("" when the element text has no name).
std::string_view name_of_element(std::string_view element) {
  std::size_t space = element.find("] ");
  return space == std::string_view::npos ? std::string_view() : element.substr(space + 2);
}

}  // namespace

std::optional<std::size_t> element_offset(const JsonPositions& positions, std::string_view element) {
  if (element == "matrix") {
    std::size_t first = positions.text().find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return std::nullopt;
    return first;
  }
  if (auto id = bracketed_id(element, "cause["))
    return element_with(positions, "causes", {{"id", *id}}, name_of_element(element));
  if (auto id = bracketed_id(element, "effect["))
    return element_with(positions, "effects", {{"id", *id}}, name_of_element(element));
  constexpr std::string_view kIntersection = "intersection ";
  if (element.substr(0, kIntersection.size()) == kIntersection) {
    std::string_view rest = element.substr(kIntersection.size());
    auto cause = bracketed_id(rest, "cause[");
    std::size_t slash = rest.find('/');
    if (!cause || slash == std::string_view::npos) return std::nullopt;
    auto effect = bracketed_id(rest.substr(slash + 1), "effect[");
    if (!effect) return std::nullopt;
    return element_with(positions, "intersections", {{"cause", *cause}, {"effect", *effect}});
  }
  return std::nullopt;
}

}  // namespace cemv::formats
