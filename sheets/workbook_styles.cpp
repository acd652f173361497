#include "sheets/workbook_styles.hpp"

#include <charconv>
#include <cstring>

namespace cemv::formats::workbook {

namespace {

// Style chains are short (a cell style, its parent, Default); a longer one is
// a loop in a hostile file.
constexpr int kMaxStyleDepth = 16;

// ODF 1.2 part 1, 20.370/20.371: a line-through style other than "none", and
// a type other than "none", strikes the text through.
int line_through(const pugi::xml_node& text_properties) {
  if (!text_properties) return -1;
  pugi::xml_attribute style = text_properties.attribute("style:text-line-through-style");
  pugi::xml_attribute type = text_properties.attribute("style:text-line-through-type");
  if (!style && !type) return -1;
  if (style && std::string_view(style.value()) == "none") return 0;
  if (type && std::string_view(type.value()) == "none") return 0;
  return style ? 1 : -1;
}

pugi::xml_node child_named(const pugi::xml_node& parent, std::string_view name) {
  for (pugi::xml_node n : parent.children())
    if (n.type() == pugi::node_element && local_name(n) == name) return n;
  return {};
}

// An OOXML boolean property (<strike/>, <strike val="0"/>): true unless its
// val says false.
bool on(const pugi::xml_node& property) {
  if (!property) return false;
  std::string_view v = property.attribute("val").value();
  return v != "0" && v != "false";
}

}  // namespace

std::string_view local_name(const pugi::xml_node& n) {
  std::string_view name = n.name();
  auto colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string OdsStyles::key(std::string_view family, std::string_view name) {
  std::string k(family);
  k += '\n';  // in neither a family nor a style name
  k += name;
  return k;
}

void OdsStyles::read(const pugi::xml_node& styles) {
  for (pugi::xml_node s : styles.children("style:style")) {
    Style style;
    style.parent = s.attribute("style:parent-style-name").value();
    style.struck = line_through(s.child("style:text-properties"));
    style.hidden = std::string_view(s.child("style:table-properties").attribute("table:display").value()) == "false";
    styles_[key(s.attribute("style:family").value(), s.attribute("style:name").value())] = std::move(style);
  }
}

bool OdsStyles::struck(const char* family, std::string_view name) const {
  for (int depth = 0; depth < kMaxStyleDepth && !name.empty(); ++depth) {
    auto it = styles_.find(key(family, name));
    if (it == styles_.end()) return false;
    if (it->second.struck >= 0) return it->second.struck == 1;
    name = it->second.parent;
  }
  return false;
}

bool OdsStyles::table_hidden(std::string_view name) const {
  auto it = styles_.find(key("table", name));
  return it != styles_.end() && it->second.hidden;
}

std::vector<bool> xlsx_struck_formats(const pugi::xml_document& styles) {
  pugi::xml_node sheet = child_named(styles, "styleSheet");
  std::vector<bool> fonts;
  for (pugi::xml_node f : child_named(sheet, "fonts").children())
    if (local_name(f) == "font") fonts.push_back(on(child_named(f, "strike")));
  std::vector<bool> formats;
  for (pugi::xml_node xf : child_named(sheet, "cellXfs").children()) {
    if (local_name(xf) != "xf") continue;
    const char* id = xf.attribute("fontId").value();
    std::size_t font = 0;
    auto [end, ec] = std::from_chars(id, id + std::strlen(id), font);
    formats.push_back(ec == std::errc() && font < fonts.size() && fonts[font]);
  }
  return formats;
}

bool xlsx_run_struck(const pugi::xml_node& run_properties) {
  return on(child_named(run_properties, "strike"));
}

}  // namespace cemv::formats::workbook
