// Office Open XML spreadsheets (ECMA-376 part 1, 18 "SpreadsheetML"): the
// package relationships lead from `_rels/.rels` to the workbook, from the
// workbook to its sheets and shared strings; each sheet's sheetData holds rows
// of cells typed by their `t` attribute.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <map>

#include "sheets/workbook_files.hpp"
#include "sheets/workbook_styles.hpp"

namespace cemv::formats::workbook {

namespace {

constexpr const char* kMainNs = "http://schemas.openxmlformats.org/spreadsheetml/2006/main";
constexpr const char* kRelNs = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";
constexpr const char* kPackageRelNs = "http://schemas.openxmlformats.org/package/2006/relationships";

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// An element name without its namespace prefix: Excel writes `<sheet>`, other
// writers `<x:sheet>`; both are the same element of the main namespace.
std::string_view local(const pugi::xml_node& n) { return local_name(n); }

pugi::xml_node child(const pugi::xml_node& parent, std::string_view name) {
  for (pugi::xml_node n : parent.children())
    if (n.type() == pugi::node_element && local(n) == name) return n;
  return {};
}

// A relationship id attribute (r:id, whatever the prefix).
const char* rel_id(const pugi::xml_node& n) {
  for (pugi::xml_attribute a : n.attributes()) {
    std::string_view name = a.name();
    if (name.size() > 3 && ends_with(name, ":id")) return a.value();
  }
  return "";
}

// The folder of a part ("xl/" of "xl/workbook.xml") and a target resolved
// against it ("/xl/x.xml" is absolute; "../" steps up).
std::string folder_of(const std::string& part) {
  auto slash = part.rfind('/');
  return slash == std::string::npos ? "" : part.substr(0, slash + 1);
}

std::string resolve(const std::string& folder, std::string target) {
  if (!target.empty() && target[0] == '/') return target.substr(1);
  std::string base = folder;
  while (target.rfind("../", 0) == 0) {
    target = target.substr(3);
    if (!base.empty()) base.pop_back();
    auto slash = base.rfind('/');
    base = slash == std::string::npos ? "" : base.substr(0, slash + 1);
  }
  return base + target;
}

// "BC12" -> (12, 55); false when it is no cell reference.
bool parse_reference(std::string_view ref, std::size_t& row, std::size_t& column) {
  std::size_t i = 0, c = 0, r = 0;
  while (i < ref.size() && ref[i] >= 'A' && ref[i] <= 'Z' && i < 4) c = c * 26 + static_cast<std::size_t>(ref[i++] - 'A' + 1);
  if (c == 0 || i == ref.size() || ref.size() - i > 8) return false;
  for (; i < ref.size(); ++i) {
    if (ref[i] < '0' || ref[i] > '9') return false;
    r = r * 10 + static_cast<std::size_t>(ref[i] - '0');
  }
  row = r;
  column = c;
  return true;
}

class XlsxReader {
 public:
  XlsxReader(ZipReader& zip, CellBudget& budget) : zip_(zip), budget_(budget) {}

  Workbook run() {
    std::string workbook_part = "xl/workbook.xml";
    for (const auto& [id, rel] : relationships("_rels/.rels", ""))
      if (ends_with(rel.first, "/officeDocument")) workbook_part = rel.second;
    auto text = zip_.read(workbook_part);
    if (!text) fail_entry(zip_, workbook_part, "missing; not an Office Open XML spreadsheet");
    pugi::xml_document doc;
    parse_xml(doc, *text, workbook_part, zip_);
    pugi::xml_node sheets = child(child(doc, "workbook"), "sheets");
    if (!sheets) fail_entry(zip_, workbook_part, "no <sheets>; not a spreadsheet workbook");
    const std::string rels_part = folder_of(workbook_part) + "_rels/" + workbook_part.substr(folder_of(workbook_part).size()) + ".rels";
    auto rels = relationships(rels_part, folder_of(workbook_part));
    for (const auto& [id, rel] : rels) {
      if (ends_with(rel.first, "/sharedStrings")) read_shared_strings(rel.second);
      if (ends_with(rel.first, "/styles")) read_styles(rel.second);
    }
    Workbook wb;
    for (pugi::xml_node s : sheets.children()) {
      if (local(s) != "sheet") continue;
      auto it = rels.find(rel_id(s));
      if (it == rels.end()) fail_entry(zip_, workbook_part, std::string("sheet '") + s.attribute("name").value() + "' has no relationship");
      Sheet& sheet = budget_.begin_sheet(wb, s.attribute("name").value());
      const std::string_view state = s.attribute("state").value();
      sheet.hidden = state == "hidden" || state == "veryHidden";
      read_sheet(it->second.second, sheet);
    }
    return wb;
  }

 private:
  // id -> (type, resolved target) of a relationships part (none when absent).
  std::map<std::string, std::pair<std::string, std::string>> relationships(const std::string& part, const std::string& folder) {
    std::map<std::string, std::pair<std::string, std::string>> out;
    auto text = zip_.read(part);
    if (!text) return out;
    pugi::xml_document doc;
    parse_xml(doc, *text, part, zip_);
    for (pugi::xml_node r : child(doc, "Relationships").children())
      if (local(r) == "Relationship")
        out[r.attribute("Id").value()] = {r.attribute("Type").value(), resolve(folder, r.attribute("Target").value())};
    return out;
  }

  // The text of a string item: its <t> elements, not the phonetic runs
  // (<rPh>); struck through when its rich-text runs with visible text all
  // are (Whole) or some are (Part).
  Strike string_item(const pugi::xml_node& node, std::string& out, const std::string& part) {
    bool struck = false, plain = false;
    auto visible = [](const char* t) {
      return std::string_view(t).find_first_not_of(" \t\r\n") != std::string_view::npos;
    };
    for (pugi::xml_node n : node.children()) {
      std::string_view name = local(n);
      if (name == "t") {
        out += n.child_value();
        plain = plain || visible(n.child_value());
      } else if (name == "r") {  // a rich-text run: its <t> (runs do not nest)
        const bool run_struck = xlsx_run_struck(child(n, "rPr"));
        for (pugi::xml_node t : n.children())
          if (local(t) == "t") {
            out += t.child_value();
            if (visible(t.child_value())) (run_struck ? struck : plain) = true;
          }
      }
      if (out.size() > kMaxCellBytes)
        fail_entry(zip_, part, "a string holds more than the limit of " + std::to_string(kMaxCellBytes) + " bytes");
    }
    return !struck ? Strike::None : plain ? Strike::Part : Strike::Whole;
  }

  void read_shared_strings(const std::string& part) {
    auto text = zip_.read(part);
    if (!text) return;
    pugi::xml_document doc;
    parse_xml(doc, *text, part, zip_);
    for (pugi::xml_node si : child(doc, "sst").children()) {
      if (local(si) != "si") continue;
      shared_.emplace_back();
      shared_strike_.push_back(string_item(si, shared_.back(), part));
    }
  }

  void read_styles(const std::string& part) {
    auto text = zip_.read(part);
    if (!text) return;
    pugi::xml_document doc;
    parse_xml(doc, *text, part, zip_);
    struck_formats_ = xlsx_struck_formats(doc);
  }

  // The cell format `s` strikes its text through.
  bool struck_format(const pugi::xml_node& c) const {
    const char* s = c.attribute("s").value();
    std::size_t index = 0;
    auto [end, ec] = std::from_chars(s, s + std::strlen(s), index);
    return ec == std::errc() && *end == '\0' && index < struck_formats_.size() && struck_formats_[index];
  }

  // <mergeCells>: the ranges whose first cell holds text (the sheet's cells
  // are sorted first, to be found).
  void read_merges(const pugi::xml_node& worksheet, Sheet& sheet) {
    sheet.sort();
    for (pugi::xml_node m : child(worksheet, "mergeCells").children()) {
      if (local(m) != "mergeCell") continue;
      std::string_view ref = m.attribute("ref").value();
      const auto colon = ref.find(':');
      std::size_t r1 = 0, c1 = 0, r2 = 0, c2 = 0;
      if (colon == std::string_view::npos || !parse_reference(ref.substr(0, colon), r1, c1) ||
          !parse_reference(ref.substr(colon + 1), r2, c2))
        budget_.fail(&sheet, 0, 0, "mergeCell '" + std::string(ref.substr(0, 40)) + "' is not a range of cells");
      const CellRange range = budget_.merge(sheet, r1, c1, r2, c2);
      if (sheet.find(r1, c1)) sheet.merges.push_back(range);
    }
  }

  void read_sheet(const std::string& part, Sheet& sheet) {
    auto text = zip_.read(part);
    if (!text) fail_entry(zip_, part, "missing (sheet '" + sheet.name + "')");
    pugi::xml_document doc;
    parse_xml(doc, *text, part, zip_);
    std::size_t row = 0;
    const pugi::xml_node worksheet = child(doc, "worksheet");
    for (pugi::xml_node r : child(worksheet, "sheetData").children()) {
      if (local(r) != "row") continue;
      std::size_t n = 0;
      const char* rr = r.attribute("r").value();
      auto [end, ec] = std::from_chars(rr, rr + std::strlen(rr), n);
      row = ec == std::errc() && *end == '\0' && n > row ? n : row + 1;
      std::size_t column = 0;
      for (pugi::xml_node c : r.children()) {
        if (local(c) != "c") continue;
        std::size_t cr = 0, cc = 0;
        if (parse_reference(c.attribute("r").value(), cr, cc) && cr == row && cc > column)
          column = cc;
        else
          ++column;
        budget_.check_position(sheet, row, column);
        cell(c, sheet, row, column);
      }
    }
    read_merges(worksheet, sheet);
  }

  void cell(const pugi::xml_node& c, Sheet& sheet, std::size_t row, std::size_t column) {
    std::string_view t = c.attribute("t").value();
    const char* v = child(c, "v").child_value();
    const Strike format = struck_format(c) ? Strike::Whole : Strike::None;
    if (t == "s") {
      std::size_t index = 0;
      auto [end, ec] = std::from_chars(v, v + std::strlen(v), index);
      if (ec != std::errc() || *end != '\0' || index >= shared_.size())
        budget_.fail(&sheet, row, column, std::string("shared string index '") + std::string(v).substr(0, 20) + "' does not exist");
      budget_.add(sheet, row, column, shared_[index], CellKind::Text, std::max(format, shared_strike_[index]));
    } else if (t == "inlineStr") {
      std::string text;
      const Strike runs = string_item(child(c, "is"), text, "sheet " + sheet.name);
      budget_.add(sheet, row, column, text, CellKind::Text, std::max(format, runs));
    } else if (t == "b") {
      if (*v) budget_.add(sheet, row, column, std::string_view(v) == "1" ? "true" : "false", CellKind::Boolean, format);
    } else if (t == "str" || t == "e" || t == "d") {
      budget_.add(sheet, row, column, v, CellKind::Text, format);
    } else if (*v) {
      double d = 0;
      auto [end, ec] = std::from_chars(v, v + std::strlen(v), d);
      if (ec == std::errc() && *end == '\0')
        budget_.add(sheet, row, column, number_text(d), CellKind::Number, format);
      else
        budget_.add(sheet, row, column, v, CellKind::Text, format);
    }
  }

  ZipReader& zip_;
  CellBudget& budget_;
  std::vector<std::string> shared_;
  std::vector<Strike> shared_strike_;  // of each shared string's runs
  std::vector<bool> struck_formats_;   // of each cell format (cellXfs)
};

pugi::xml_node start(pugi::xml_document& doc, const char* root, const char* ns) {
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  decl.append_attribute("standalone") = "yes";
  pugi::xml_node r = doc.append_child(root);
  r.append_attribute("xmlns") = ns;
  return r;
}

void relationship(pugi::xml_node rels, const std::string& id, const std::string& type, const std::string& target) {
  pugi::xml_node r = rels.append_child("Relationship");
  r.append_attribute("Id") = id.c_str();
  r.append_attribute("Type") = (std::string(kRelNs) + "/" + type).c_str();
  r.append_attribute("Target") = target.c_str();
}

std::string worksheet(const Sheet& sheet) {
  pugi::xml_document doc;
  pugi::xml_node ws = start(doc, "worksheet", kMainNs);
  if (!sheet.widths.empty()) {
    pugi::xml_node cols = ws.append_child("cols");
    for (const auto& [column, width] : sheet.widths) {
      pugi::xml_node col = cols.append_child("col");
      col.append_attribute("min") = static_cast<unsigned long long>(column);
      col.append_attribute("max") = static_cast<unsigned long long>(column);
      col.append_attribute("width") = width;
      col.append_attribute("customWidth") = "1";
    }
  }
  pugi::xml_node data = ws.append_child("sheetData");
  pugi::xml_node row;
  std::size_t current = 0;
  for (const Cell& c : sheet.cells) {
    if (c.row != current) {
      row = data.append_child("row");
      row.append_attribute("r") = static_cast<unsigned long long>(c.row);
      current = c.row;
    }
    pugi::xml_node cell = row.append_child("c");
    cell.append_attribute("r") = cell_address(c.row, c.column).c_str();
    if (c.grey) cell.append_attribute("s") = "1";
    if (c.kind == CellKind::Number) {
      cell.append_child("v").text() = c.text.c_str();
    } else if (c.kind == CellKind::Boolean) {
      cell.append_attribute("t") = "b";
      cell.append_child("v").text() = c.text == "true" ? "1" : "0";
    } else {
      cell.append_attribute("t") = "inlineStr";
      pugi::xml_node t = cell.append_child("is").append_child("t");
      t.append_attribute("xml:space") = "preserve";
      t.text() = c.text.c_str();
    }
  }
  return xml_text(doc);
}

}  // namespace

Workbook read_xlsx(ZipReader& zip, CellBudget& budget) { return XlsxReader(zip, budget).run(); }

std::string write_xlsx(const Workbook& wb) {
  ZipWriter zip;
  {
    pugi::xml_document doc;
    pugi::xml_node types = start(doc, "Types", "http://schemas.openxmlformats.org/package/2006/content-types");
    auto def = [&](const char* ext, const char* type) {
      pugi::xml_node d = types.append_child("Default");
      d.append_attribute("Extension") = ext;
      d.append_attribute("ContentType") = type;
    };
    auto over = [&](const std::string& part, const char* type) {
      pugi::xml_node o = types.append_child("Override");
      o.append_attribute("PartName") = part.c_str();
      o.append_attribute("ContentType") = type;
    };
    def("rels", "application/vnd.openxmlformats-package.relationships+xml");
    def("xml", "application/xml");
    over("/xl/workbook.xml", "application/vnd.openxmlformats-officedocument.spreadsheetml.sheet.main+xml");
    over("/xl/styles.xml", "application/vnd.openxmlformats-officedocument.spreadsheetml.styles+xml");
    for (std::size_t i = 1; i <= wb.sheets.size(); ++i)
      over("/xl/worksheets/sheet" + std::to_string(i) + ".xml",
           "application/vnd.openxmlformats-officedocument.spreadsheetml.worksheet+xml");
    zip.add("[Content_Types].xml", xml_text(doc));
  }
  {
    pugi::xml_document doc;
    relationship(start(doc, "Relationships", kPackageRelNs), "rId1", "officeDocument", "xl/workbook.xml");
    zip.add("_rels/.rels", xml_text(doc));
  }
  {
    pugi::xml_document doc;
    pugi::xml_node book = start(doc, "workbook", kMainNs);
    book.append_attribute("xmlns:r") = kRelNs;
    pugi::xml_node sheets = book.append_child("sheets");
    for (std::size_t i = 1; i <= wb.sheets.size(); ++i) {
      pugi::xml_node s = sheets.append_child("sheet");
      s.append_attribute("name") = wb.sheets[i - 1].name.c_str();
      s.append_attribute("sheetId") = static_cast<unsigned long long>(i);
      s.append_attribute("r:id") = ("rId" + std::to_string(i)).c_str();
    }
    zip.add("xl/workbook.xml", xml_text(doc));
  }
  {
    pugi::xml_document doc;
    pugi::xml_node rels = start(doc, "Relationships", kPackageRelNs);
    for (std::size_t i = 1; i <= wb.sheets.size(); ++i)
      relationship(rels, "rId" + std::to_string(i), "worksheet", "worksheets/sheet" + std::to_string(i) + ".xml");
    relationship(rels, "rId" + std::to_string(wb.sheets.size() + 1), "styles", "styles.xml");
    zip.add("xl/_rels/workbook.xml.rels", xml_text(doc));
  }
  // Style 1: information only, grey fill (6.6.2).
  zip.add("xl/styles.xml",
          "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"yes\"?>\n"
          "<styleSheet xmlns=\"http://schemas.openxmlformats.org/spreadsheetml/2006/main\">"
          "<fonts count=\"1\"><font><sz val=\"11\"/><name val=\"Calibri\"/></font></fonts>"
          "<fills count=\"3\"><fill><patternFill patternType=\"none\"/></fill><fill><patternFill patternType=\"gray125\"/></fill>"
          "<fill><patternFill patternType=\"solid\"><fgColor rgb=\"FFD9D9D9\"/><bgColor indexed=\"64\"/></patternFill></fill></fills>"
          "<borders count=\"1\"><border><left/><right/><top/><bottom/><diagonal/></border></borders>"
          "<cellStyleXfs count=\"1\"><xf numFmtId=\"0\" fontId=\"0\" fillId=\"0\" borderId=\"0\"/></cellStyleXfs>"
          "<cellXfs count=\"2\"><xf numFmtId=\"0\" fontId=\"0\" fillId=\"0\" borderId=\"0\" xfId=\"0\"/>"
          "<xf numFmtId=\"0\" fontId=\"0\" fillId=\"2\" borderId=\"0\" xfId=\"0\" applyFill=\"1\"/></cellXfs>"
          "<cellStyles count=\"1\"><cellStyle name=\"Normal\" xfId=\"0\" builtinId=\"0\"/></cellStyles>"
          "</styleSheet>\n");
  for (std::size_t i = 1; i <= wb.sheets.size(); ++i)
    zip.add("xl/worksheets/sheet" + std::to_string(i) + ".xml", worksheet(wb.sheets[i - 1]));
  return zip.finish();
}

}  // namespace cemv::formats::workbook
