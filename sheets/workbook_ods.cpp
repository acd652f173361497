// OpenDocument spreadsheets (ODF 1.2 part 1, 9 "Tables"): the `content.xml`
// of the archive holds one table:table per sheet, rows and cells with repeat
// counts, cell values typed by office:value-type, texts as text:p paragraphs.
#include <algorithm>
#include <charconv>
#include <cstring>

#include "sheets/workbook_files.hpp"
#include "sheets/workbook_styles.hpp"

namespace cemv::formats::workbook {

namespace {

constexpr const char* kMimeType = "application/vnd.oasis.opendocument.spreadsheet";
// Nesting of spans and links inside a paragraph; LibreOffice writes 1 or 2.
constexpr int kMaxTextDepth = 32;

// A repeat count (number-rows-repeated, number-columns-repeated): 1 when
// absent; values beyond the sheet maxima are clamped, the reader refuses
// content there anyway.
std::size_t repeat_of(const pugi::xml_node& node, const char* attribute, std::size_t max) {
  const char* text = node.attribute(attribute).value();
  if (!*text) return 1;
  std::size_t n = 0;
  auto [end, ec] = std::from_chars(text, text + std::strlen(text), n);
  if (ec == std::errc::result_out_of_range) return max + 1;
  if (ec != std::errc() || n == 0) return 1;
  return std::min(n, max + 1);
}

class OdsReader {
 public:
  OdsReader(ZipReader& zip, CellBudget& budget) : zip_(zip), budget_(budget) {}

  Workbook run() {
    if (auto mime = zip_.read("mimetype"); mime && *mime != kMimeType)
      fail_entry(zip_, "mimetype", "'" + mime->substr(0, 80) + "' is not an OpenDocument spreadsheet");
    auto content = zip_.read("content.xml");
    if (!content) fail_entry(zip_, "content.xml", "missing; not an OpenDocument spreadsheet");
    pugi::xml_document doc;
    parse_xml(doc, *content, "content.xml", zip_);
    pugi::xml_node root = doc.child("office:document-content");
    pugi::xml_node spreadsheet = root.child("office:body").child("office:spreadsheet");
    if (!spreadsheet) fail_entry(zip_, "content.xml", "no office:spreadsheet; not a spreadsheet document");
    read_styles(root);
    Workbook wb;
    for (pugi::xml_node table : spreadsheet.children("table:table")) {
      Sheet& sheet = budget_.begin_sheet(wb, table.attribute("table:name").value());
      sheet.hidden = styles_.table_hidden(table.attribute("table:style-name").value());
      read_column_styles(table);
      std::size_t row = 1;
      read_rows(table, sheet, row, 0);
    }
    return wb;
  }

 private:
  // The common styles of styles.xml (a cell style may be one, or derive from
  // one), then the automatic styles of content.xml.
  void read_styles(const pugi::xml_node& content_root) {
    if (auto text = zip_.read("styles.xml")) {
      pugi::xml_document styles;
      parse_xml(styles, *text, "styles.xml", zip_);
      styles_.read(styles.child("office:document-styles").child("office:styles"));
    }
    styles_.read(content_root.child("office:automatic-styles"));
  }

  // The default cell style of each column (a cell without a style of its own,
  // in a row without a default, has its column's): runs of (first column, style).
  void read_column_styles(const pugi::xml_node& table) {
    column_styles_.clear();
    std::size_t column = 1;
    read_columns(table, column, 0);
  }
  void read_columns(const pugi::xml_node& parent, std::size_t& column, int depth) {
    for (pugi::xml_node n : parent.children()) {
      std::string_view name = n.name();
      if (name == "table:table-column") {
        column_styles_.push_back({column, n.attribute("table:default-cell-style-name").value()});
        column = std::min(column + repeat_of(n, "table:number-columns-repeated", kMaxColumnNumber),
                          kMaxColumnNumber + 1);
      } else if ((name == "table:table-column-group" || name == "table:table-columns" ||
                  name == "table:table-header-columns") && depth < kMaxTextDepth) {
        read_columns(n, column, depth + 1);
      }
    }
  }
  std::string_view column_style(std::size_t column) const {
    auto it = std::upper_bound(column_styles_.begin(), column_styles_.end(), column,
                               [](std::size_t c, const auto& run) { return c < run.first; });
    return it == column_styles_.begin() ? std::string_view() : std::string_view((it - 1)->second);
  }

  // Rows directly in the table or in its groups (header rows, row groups).
  void read_rows(const pugi::xml_node& parent, Sheet& sheet, std::size_t& row, int depth) {
    for (pugi::xml_node n : parent.children()) {
      std::string_view name = n.name();
      if (name == "table:table-row") {
        std::size_t repeat = repeat_of(n, "table:number-rows-repeated", kMaxRowNumber);
        read_row(n, sheet, row, repeat);
        row += repeat;
        if (row > kMaxRowNumber + 1) row = kMaxRowNumber + 1;
      } else if (name == "table:table-header-rows" || name == "table:table-row-group" || name == "table:table-rows") {
        if (depth >= kMaxTextDepth) budget_.fail(&sheet, row, 0, "row groups nested deeper than " + std::to_string(kMaxTextDepth));
        read_rows(n, sheet, row, depth + 1);
      }
    }
  }

  // A cell as read once, before its row and column repeats.
  struct Value {
    std::string text;
    CellKind kind = CellKind::Text;
    Strike strike = Strike::None;
    std::size_t rows = 1, columns = 1;  // merged over (number-rows/columns-spanned)
  };

  void read_row(const pugi::xml_node& row_node, Sheet& sheet, std::size_t row, std::size_t repeat) {
    // Cells of the row once, then the row as often as it repeats: an empty
    // row repeated a million times (LibreOffice writes those) costs nothing.
    // (column, index into values): a text repeated over many columns is held once.
    std::vector<Value> values;
    std::vector<std::pair<std::size_t, std::size_t>> cells;
    std::size_t column = 1;
    const std::string_view row_style = row_node.attribute("table:default-cell-style-name").value();
    for (pugi::xml_node c : row_node.children()) {
      std::string_view name = c.name();
      if (name != "table:table-cell" && name != "table:covered-table-cell") continue;
      std::size_t n = repeat_of(c, "table:number-columns-repeated", kMaxColumnNumber);
      if (name == "table:table-cell") {
        std::string_view style = c.attribute("table:style-name").value();
        if (style.empty()) style = row_style.empty() ? column_style(column) : row_style;
        Value value = value_of(c, sheet, row, column, styles_.cell_struck(style));
        if (!value.text.empty()) {
          values.push_back(std::move(value));
          for (std::size_t k = 0; k < n; ++k) {
            budget_.check_position(sheet, row, column + k);
            cells.push_back({column + k, values.size() - 1});
          }
        }
      }
      column = std::min(column + n, kMaxColumnNumber + 1);
    }
    if (cells.empty()) return;
    for (std::size_t r = 0; r < repeat; ++r)
      for (const auto& [col, t] : cells) {
        const Value& v = values[t];
        budget_.add(sheet, row + r, col, v.text, v.kind, v.strike);
        if (v.rows > 1 || v.columns > 1)
          sheet.merges.push_back(budget_.merge(sheet, row + r, col, row + r + v.rows - 1, col + v.columns - 1));
      }
  }

  Value value_of(const pugi::xml_node& c, const Sheet& sheet, std::size_t row, std::size_t column, bool struck) {
    Value value;
    value.rows = repeat_of(c, "table:number-rows-spanned", kMaxRowNumber);
    value.columns = repeat_of(c, "table:number-columns-spanned", kMaxColumnNumber);
    value.strike = struck ? Strike::Whole : Strike::None;
    std::string_view type = c.attribute("office:value-type").value();
    if (type == "float" || type == "percentage" || type == "currency") {
      const char* v = c.attribute("office:value").value();
      double d = 0;
      auto [end, ec] = std::from_chars(v, v + std::strlen(v), d);
      if (ec == std::errc() && *end == '\0') {
        value.text = number_text(d);
        value.kind = CellKind::Number;
        return value;
      }
    }
    if (type == "boolean") {
      std::string_view v = c.attribute("office:boolean-value").value();
      value.text = v == "true" ? "true" : "false";
      value.kind = CellKind::Boolean;
      return value;
    }
    bool first = true;
    Paragraph para{value.text, true, sheet, row, column};
    for (pugi::xml_node p : c.children("text:p")) {
      if (!first) value.text += '\n';
      first = false;
      para.blank = true;  // at the start of a paragraph: leading blanks are ignored
      paragraph(p, para, struck, 0);
    }
    // Struck text runs (spans) over all of the text strike the cell through.
    if (!struck && para.struck_chars > 0)
      value.strike = para.plain_chars == 0 ? Strike::Whole : Strike::Part;
    return value;
  }

  // What paragraph() reads into: the text, and how many visible characters
  // of it are struck through and how many not.
  struct Paragraph {
    std::string& out;
    bool blank;
    const Sheet& sheet;
    std::size_t row, column;
    std::size_t struck_chars = 0, plain_chars = 0;
  };

  // ODF 1.2 part 1, 6.1.2 "White Space Characters": in character data, a run
  // of blanks, tabs and line ends is one blank, ignored at the start of the
  // paragraph; text:s stands for c literal blanks, text:tab and
  // text:line-break for a tab and a line end.
  void paragraph(const pugi::xml_node& node, Paragraph& p, bool struck, int depth) {
    if (depth > kMaxTextDepth)
      budget_.fail(&p.sheet, p.row, p.column, "text spans nested deeper than " + std::to_string(kMaxTextDepth));
    std::string& out = p.out;
    bool& blank = p.blank;
    for (pugi::xml_node n : node.children()) {
      if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata) {
        for (const char* s = n.value(); *s; ++s) {
          bool ws = *s == ' ' || *s == '\t' || *s == '\n' || *s == '\r';
          if (ws) {
            if (!blank) out += ' ';
            blank = true;
          } else {
            out += *s;
            blank = false;
            ++(struck ? p.struck_chars : p.plain_chars);
          }
        }
      } else if (n.type() == pugi::node_element) {
        std::string_view name = n.name();
        if (name == "text:s") {
          std::size_t count = repeat_of(n, "text:c", kMaxCellBytes);
          out.append(std::min(count, kMaxCellBytes + 1), ' ');
          blank = false;  // text:s blanks are literal; a blank after them is kept
        } else if (name == "text:tab") {
          out += '\t';
          blank = false;
        } else if (name == "text:line-break") {
          out += '\n';
          blank = false;
        } else if (name != "office:annotation") {
          const bool span_struck = struck || styles_.text_struck(n.attribute("text:style-name").value());
          paragraph(n, p, span_struck, depth + 1);
        }
      }
      if (out.size() > kMaxCellBytes)
        budget_.fail(&p.sheet, p.row, p.column, "the cell holds more than the limit of " +
                                                    std::to_string(kMaxCellBytes) + " bytes of text");
    }
  }

  ZipReader& zip_;
  CellBudget& budget_;
  OdsStyles styles_;
  std::vector<std::pair<std::size_t, std::string>> column_styles_;  // of the current table
};

// Writes a text as ODF character data: blanks that a reader would collapse or
// drop (a leading blank, a blank after a blank) as text:s.
void write_text(pugi::xml_node p, std::string_view text) {
  std::string run;
  std::size_t i = 0;
  auto flush = [&] {
    if (!run.empty()) p.append_child(pugi::node_pcdata).set_value(run.c_str());
    run.clear();
  };
  while (i < text.size()) {
    if (text[i] == ' ' && (i == 0 || text[i - 1] == ' ')) {
      std::size_t n = 0;
      while (i < text.size() && text[i] == ' ') ++n, ++i;
      flush();
      pugi::xml_node s = p.append_child("text:s");
      if (n > 1) s.append_attribute("text:c") = static_cast<unsigned long long>(n);
      continue;
    }
    run += text[i++];
  }
  flush();
}

}  // namespace

Workbook read_ods(ZipReader& zip, CellBudget& budget) { return OdsReader(zip, budget).run(); }

std::string write_ods(const Workbook& wb) {
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node root = doc.append_child("office:document-content");
  root.append_attribute("xmlns:office") = "urn:oasis:names:tc:opendocument:xmlns:office:1.0";
  root.append_attribute("xmlns:style") = "urn:oasis:names:tc:opendocument:xmlns:style:1.0";
  root.append_attribute("xmlns:text") = "urn:oasis:names:tc:opendocument:xmlns:text:1.0";
  root.append_attribute("xmlns:table") = "urn:oasis:names:tc:opendocument:xmlns:table:1.0";
  root.append_attribute("xmlns:fo") = "urn:oasis:names:tc:opendocument:xmlns:xsl-fo-compatible:1.0";
  root.append_attribute("office:version") = "1.2";
  pugi::xml_node styles = root.append_child("office:automatic-styles");
  // ce1: information only (grey background, 6.6.2).
  pugi::xml_node grey = styles.append_child("style:style");
  grey.append_attribute("style:name") = "ce1";
  grey.append_attribute("style:family") = "table-cell";
  grey.append_child("style:table-cell-properties").append_attribute("fo:background-color") = "#d9d9d9";
  // One column style per width used (co<width in mm>).
  std::map<long, std::string> column_styles;
  for (const Sheet& sheet : wb.sheets)
    for (const auto& [column, width] : sheet.widths) column_styles[static_cast<long>(width * 2.0 + 0.5)];
  for (auto& [mm, name] : column_styles) {
    name = "co" + std::to_string(mm);
    pugi::xml_node s = styles.append_child("style:style");
    s.append_attribute("style:name") = name.c_str();
    s.append_attribute("style:family") = "table-column";
    s.append_child("style:table-column-properties").append_attribute("style:column-width") =
        (std::to_string(mm) + "mm").c_str();
  }
  pugi::xml_node spreadsheet = root.append_child("office:body").append_child("office:spreadsheet");
  for (const Sheet& sheet : wb.sheets) {
    pugi::xml_node table = spreadsheet.append_child("table:table");
    table.append_attribute("table:name") = sheet.name.c_str();
    std::size_t next_column = 1;
    for (const auto& [column, width] : sheet.widths) {
      if (column > next_column) {
        pugi::xml_node gap = table.append_child("table:table-column");
        if (column - next_column > 1) gap.append_attribute("table:number-columns-repeated") = static_cast<unsigned long long>(column - next_column);
      }
      table.append_child("table:table-column").append_attribute("table:style-name") =
          column_styles[static_cast<long>(width * 2.0 + 0.5)].c_str();
      next_column = column + 1;
    }
    if (sheet.widths.empty()) table.append_child("table:table-column");
    std::size_t next_row = 1;
    for (std::size_t i = 0; i < sheet.cells.size();) {
      std::size_t r = sheet.cells[i].row;
      if (r > next_row) {
        pugi::xml_node gap = table.append_child("table:table-row");
        if (r - next_row > 1) gap.append_attribute("table:number-rows-repeated") = static_cast<unsigned long long>(r - next_row);
        gap.append_child("table:table-cell");
      }
      pugi::xml_node row = table.append_child("table:table-row");
      std::size_t col = 1;
      for (; i < sheet.cells.size() && sheet.cells[i].row == r; ++i) {
        const Cell& c = sheet.cells[i];
        if (c.column > col) {
          pugi::xml_node gap = row.append_child("table:table-cell");
          if (c.column - col > 1) gap.append_attribute("table:number-columns-repeated") = static_cast<unsigned long long>(c.column - col);
        }
        pugi::xml_node cell = row.append_child("table:table-cell");
        if (c.grey) cell.append_attribute("table:style-name") = "ce1";
        if (c.kind == CellKind::Number) {
          cell.append_attribute("office:value-type") = "float";
          cell.append_attribute("office:value") = c.text.c_str();
        } else if (c.kind == CellKind::Boolean) {
          cell.append_attribute("office:value-type") = "boolean";
          cell.append_attribute("office:boolean-value") = c.text.c_str();
        } else {
          cell.append_attribute("office:value-type") = "string";
        }
        write_text(cell.append_child("text:p"), c.text);
        col = c.column + 1;
      }
      next_row = r + 1;
    }
    if (sheet.cells.empty()) table.append_child("table:table-row").append_child("table:table-cell");
  }

  const char* manifest =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<manifest:manifest xmlns:manifest=\"urn:oasis:names:tc:opendocument:xmlns:manifest:1.0\" manifest:version=\"1.2\">"
      "<manifest:file-entry manifest:full-path=\"/\" manifest:version=\"1.2\" "
      "manifest:media-type=\"application/vnd.oasis.opendocument.spreadsheet\"/>"
      "<manifest:file-entry manifest:full-path=\"content.xml\" manifest:media-type=\"text/xml\"/>"
      "</manifest:manifest>\n";
  ZipWriter zip;
  zip.add("mimetype", kMimeType, true);  // first and stored (ODF 1.2 part 3, 3.3)
  zip.add("META-INF/manifest.xml", manifest);
  zip.add("content.xml", xml_text(doc));
  return zip.finish();
}

}  // namespace cemv::formats::workbook
