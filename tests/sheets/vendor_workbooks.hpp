// Small ODS and XLSX files written by hand for the tests of vendor workbooks:
// merged ranges, struck-through text, hidden sheets, several sheets. The XML
// is what LibreOffice and Excel write, cut to what the readers look at.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sheets/workbook_zip.hpp"

namespace cemv::formats::testing {

// An ODS: `tables` is the XML of the table:table elements, `styles` of the
// automatic styles of content.xml, `common` of the office:styles of styles.xml.
inline std::string ods_file(const std::string& tables, const std::string& styles = "",
                            const std::string& common = "") {
  const std::string ns =
      " xmlns:office=\"urn:oasis:names:tc:opendocument:xmlns:office:1.0\""
      " xmlns:style=\"urn:oasis:names:tc:opendocument:xmlns:style:1.0\""
      " xmlns:text=\"urn:oasis:names:tc:opendocument:xmlns:text:1.0\""
      " xmlns:table=\"urn:oasis:names:tc:opendocument:xmlns:table:1.0\"";
  workbook::ZipWriter zip;
  zip.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  zip.add("content.xml", "<office:document-content" + ns + "><office:automatic-styles>" + styles +
                             "</office:automatic-styles><office:body><office:spreadsheet>" + tables +
                             "</office:spreadsheet></office:body></office:document-content>");
  if (!common.empty())
    zip.add("styles.xml", "<office:document-styles" + ns + "><office:styles>" + common +
                              "</office:styles></office:document-styles>");
  return zip.finish();
}

// One ODS cell: a text, with optional attributes (style, spans).
inline std::string ods_cell(const std::string& text, const std::string& attributes = "") {
  if (text.empty()) return "<table:table-cell" + attributes + "/>";
  return "<table:table-cell office:value-type=\"string\"" + attributes + "><text:p>" + text +
         "</text:p></table:table-cell>";
}

// An XLSX: each sheet a (name, worksheet XML body: sheetData and after), with
// an optional state (hidden); shared strings as <si> elements; the styles.xml
// fonts and cellXfs.
struct XlsxSheet {
  std::string name;
  std::string body;
  std::string state = "visible";
};

inline std::string xlsx_file(const std::vector<XlsxSheet>& sheets, const std::string& shared_items = "",
                             const std::string& fonts = "<font/>", const std::string& xfs = "<xf fontId=\"0\"/>") {
  const std::string main = "http://schemas.openxmlformats.org/spreadsheetml/2006/main";
  const std::string rel = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";
  workbook::ZipWriter zip;
  zip.add("[Content_Types].xml", "<Types/>");
  zip.add("_rels/.rels", "<Relationships><Relationship Id=\"r\" Type=\"" + rel +
                             "/officeDocument\" Target=\"xl/workbook.xml\"/></Relationships>");
  std::string book = "<workbook xmlns=\"" + main + "\" xmlns:r=\"" + rel + "\"><sheets>";
  std::string rels = "<Relationships>";
  for (std::size_t i = 0; i < sheets.size(); ++i) {
    const std::string id = "rId" + std::to_string(i + 1);
    book += "<sheet name=\"" + sheets[i].name + "\" sheetId=\"" + std::to_string(i + 1) + "\" state=\"" +
            sheets[i].state + "\" r:id=\"" + id + "\"/>";
    rels += "<Relationship Id=\"" + id + "\" Type=\"" + rel + "/worksheet\" Target=\"worksheets/s" +
            std::to_string(i + 1) + ".xml\"/>";
    zip.add("xl/worksheets/s" + std::to_string(i + 1) + ".xml",
            "<worksheet xmlns=\"" + main + "\">" + sheets[i].body + "</worksheet>");
  }
  rels += "<Relationship Id=\"rS\" Type=\"" + rel + "/sharedStrings\" Target=\"strings.xml\"/>";
  rels += "<Relationship Id=\"rT\" Type=\"" + rel + "/styles\" Target=\"styles.xml\"/></Relationships>";
  zip.add("xl/workbook.xml", book + "</sheets></workbook>");
  zip.add("xl/_rels/workbook.xml.rels", rels);
  zip.add("xl/strings.xml", "<sst xmlns=\"" + main + "\">" + shared_items + "</sst>");
  zip.add("xl/styles.xml", "<styleSheet xmlns=\"" + main + "\"><fonts>" + fonts + "</fonts><cellXfs>" + xfs +
                               "</cellXfs></styleSheet>");
  return zip.finish();
}

// An inline-string XLSX cell.
inline std::string xlsx_cell(const std::string& ref, const std::string& text, const std::string& attributes = "") {
  return "<c r=\"" + ref + "\" t=\"inlineStr\"" + attributes + "><is><t>" + text + "</t></is></c>";
}

}  // namespace cemv::formats::testing
