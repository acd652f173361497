#include "reports/sarif.hpp"

#include "formats/matrix_json.hpp"

namespace cemv::reports {

std::string uri_of_path(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                 c == '.' || c == '_' || c == '~' || c == '/';
    if (plain) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

MatrixLines::MatrixLines(std::string_view matrix_text) : text_(matrix_text) {
  if (!text_.empty()) positions_.emplace(text_);
}

namespace {

// "intersection[3,2]" -> "intersection cause[3]/effect[2]"; anything else as it is.
std::string element_name(std::string_view element) {
  constexpr std::string_view kKey = "intersection[";
  if (element.substr(0, kKey.size()) != kKey || element.back() != ']') return std::string(element);
  std::string_view inside = element.substr(kKey.size(), element.size() - kKey.size() - 1);
  std::size_t comma = inside.find(',');
  if (comma == std::string_view::npos) return std::string(element);
  return "intersection cause[" + std::string(inside.substr(0, comma)) + "]/effect[" +
         std::string(inside.substr(comma + 1)) + "]";
}

}  // namespace

std::optional<std::pair<std::size_t, std::size_t>> MatrixLines::find(std::string_view element) const {
  if (!positions_) return std::nullopt;
  // An option of an element ("cause[1].bypass_tag") is placed at the element.
  std::string name = element_name(element);
  if (name.rfind("cause[", 0) == 0 || name.rfind("effect[", 0) == 0) name = name.substr(0, name.find(']') + 1);
  auto offset = formats::element_offset(*positions_, name);
  if (!offset) return std::nullopt;
  return formats::line_and_column(text_, *offset);
}

}  // namespace cemv::reports
