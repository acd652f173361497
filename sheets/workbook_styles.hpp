// The cell formats a workbook import reads (internal to formats/): whether a
// cell's text is struck through, which is how vendor C&E workbooks keep a
// deleted row for the revision record, and whether a sheet is hidden. ODS
// keeps both in named styles (the automatic styles of content.xml, the common
// styles of styles.xml), XLSX in the fonts and cell formats of styles.xml and
// in the properties of rich-text runs.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

namespace cemv::formats::workbook {

// The styles of an OpenDocument spreadsheet, by family and name.
class OdsStyles {
 public:
  // Reads the style:style children of an office:automatic-styles or
  // office:styles element (the later read wins for a repeated name).
  void read(const pugi::xml_node& styles);
  // A table-cell style whose text is struck through (its own text properties
  // or, when they say nothing, its parent's).
  bool cell_struck(std::string_view name) const { return struck("table-cell", name); }
  // A text style (of a text:span) whose text is struck through.
  bool text_struck(std::string_view name) const { return struck("text", name); }
  // A table style that hides its sheet (table:display="false").
  bool table_hidden(std::string_view name) const;

 private:
  struct Style {
    std::string parent;
    int struck = -1;  // -1: not said here (the parent's), 0 no, 1 yes
    bool hidden = false;
  };
  bool struck(const char* family, std::string_view name) const;
  static std::string key(std::string_view family, std::string_view name);
  std::map<std::string, Style> styles_;  // by key(family, name)
};

// XLSX: for each cell format of styles.xml (cellXfs, indexed by a cell's `s`),
// whether its font strikes through.
std::vector<bool> xlsx_struck_formats(const pugi::xml_document& styles);

// XLSX: whether a rich-text run's properties (<rPr>) strike through.
bool xlsx_run_struck(const pugi::xml_node& run_properties);

// The element's name without its namespace prefix (`x:font` -> `font`).
std::string_view local_name(const pugi::xml_node& n);

}  // namespace cemv::formats::workbook
