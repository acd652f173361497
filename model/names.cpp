// The name rules of the manual: tag names (6.1.4), cause and effect names
// (6.3.4, 6.4.4). The loaders and the CSV import both apply them.
#include "model/names.hpp"

#include <cctype>
#include <cstdio>

#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::model {

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

}  // namespace cemv::model
