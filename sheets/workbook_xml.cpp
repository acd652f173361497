// The XML helpers of the two workbook formats (workbook_files.hpp).
#include <sstream>

#include "sheets/workbook_files.hpp"

namespace cemv::formats::workbook {

void fail_entry(const ZipReader& zip, const std::string& entry, const std::string& what) {
  LoadIssue issue;
  issue.file = zip.file();
  issue.what = "zip entry " + entry + ": " + what;
  throw LoadError({issue});
}

void parse_xml(pugi::xml_document& doc, const std::string& text, const std::string& entry, const ZipReader& zip) {
  // parse_ws_pcdata keeps text that is only blanks (a cell of one blank, a
  // blank between two spans): it is part of the cell's value.
  pugi::xml_parse_result r = doc.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_ws_pcdata,
                                             pugi::encoding_utf8);
  if (!r) fail_entry(zip, entry, std::string("malformed XML at byte ") + std::to_string(r.offset) + ": " + r.description());
}

std::string xml_text(const pugi::xml_document& doc) {
  std::ostringstream out;
  doc.save(out, "", pugi::format_raw, pugi::encoding_utf8);
  return out.str();
}

}  // namespace cemv::formats::workbook
