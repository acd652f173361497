// The two file formats of a workbook (internal to formats/): OpenDocument
// spreadsheet (`*.ods`, the Safety Matrix's own format, 6.6.1) and Office Open
// XML (`*.xlsx`, what DeltaV and Triconex users keep in Excel), each read into
// and written from the cells of workbook_sheet.hpp. The XML is pugixml's.
#pragma once

#include <string>
#include <string_view>

#include <pugixml.hpp>

#include "sheets/workbook_sheet.hpp"
#include "sheets/workbook_zip.hpp"

namespace cemv::formats::workbook {

// Parses one XML entry of the archive; malformed XML is a LoadError naming the
// file, the entry and the byte offset. pugixml expands no entities beyond the
// five predefined ones and character references (no DTD processing), so no
// "billion laughs" input can grow in memory.
void parse_xml(pugi::xml_document& doc, const std::string& text, const std::string& entry, const ZipReader& zip);

// The document as UTF-8 text with its XML declaration, no indentation.
std::string xml_text(const pugi::xml_document& doc);

// Throws a LoadError that names the file and the entry.
[[noreturn]] void fail_entry(const ZipReader& zip, const std::string& entry, const std::string& what);

Workbook read_ods(ZipReader& zip, CellBudget& budget);
std::string write_ods(const Workbook& wb);

Workbook read_xlsx(ZipReader& zip, CellBudget& budget);
std::string write_xlsx(const Workbook& wb);

}  // namespace cemv::formats::workbook
