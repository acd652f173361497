// Workbooks from outside (docs/workbook.md "Errors", "Limits"): every
// malformed table, archive and XML is refused with its FILE:SHEET:ROW:COLUMN
// place, and the enormous ones (a zip bomb, a million rows, a 100 MB string)
// within the limits, never inflated or built in memory.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <regex>
#include <sstream>

#include "formats/matrix_json.hpp"
#include "sheets/workbook.hpp"
#include "sheets/workbook_files.hpp"
#include "sheets/workbook_tables.hpp"

namespace cemv::formats {

using namespace cemv::formats::workbook;
namespace {

model::Matrix example() {
  return load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
}

Sheet& sheet_of(Workbook& wb, const char* name) {
  for (Sheet& s : wb.sheets)
    if (s.name == name) return s;
  throw std::logic_error(name);
}

// Sets (or with "" clears) one cell of a sheet.
void set(Workbook& wb, const char* sheet, std::size_t row, std::size_t column, const std::string& text) {
  Sheet& s = sheet_of(wb, sheet);
  std::erase_if(s.cells, [&](const Cell& c) { return c.row == row && c.column == column; });
  s.put(row, column, text);
  s.sort();
}

std::size_t column_of(const Workbook& wb, const char* sheet, const std::string& header) {
  for (const Sheet& s : wb.sheets)
    if (s.name == sheet)
      for (const Cell* c : s.row(1))
        if (c->text == header) return c->column;
  throw std::logic_error(header);
}

std::string all_messages(const LoadError& e) {
  std::string out;
  for (const auto& i : e.issues()) out += i.message() + "\n";
  return out;
}

struct Case {
  const char* name;
  std::function<void(Workbook&)> edit;
  const char* expected;  // a regular expression one message must match
};

const Case kCases[] = {
    {"time_not_a_number",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, column_of(wb, kCausesSheet, "Time (ms)"), "abc"); },
     R"(^m\.(ods|xlsx):Causes configuration:2:\d+: error: [A-Z]+2 \(Time \(ms\)\): 'abc' is not a whole number 0-4294967295$)"},
    {"cause_number_text",
     [](Workbook& wb) { set(wb, kCausesSheet, 3, 1, "two"); },
     R"(^m\.\w+:Causes configuration:3:1: error: A3 \(No\.\): cause number 'two' is not a whole number 1-128$)"},
    {"cause_number_129",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, 1, "129"); },
     R"(:Causes configuration:2:1: error: A2 \(No\.\): cause number '129' is not a whole number 1-128$)"},
    {"unknown_column",
     [](Workbook& wb) { set(wb, kCausesSheet, 1, column_of(wb, kCausesSheet, "Bypass tag"), "Bypas tag"); },
     R"(:Causes configuration:1:\d+: error: [A-Z]+1: unknown column 'Bypas tag' \(did you mean 'Bypass tag'\?\)$)"},
    {"missing_column",
     [](Workbook& wb) { set(wb, kEffectsSheet, 1, column_of(wb, kEffectsSheet, "Reset tag"), ""); },
     R"(^m\.\w+:Effects configuration:1: error: column 'Reset tag' is missing from the header row$)"},
    {"bad_enum",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, column_of(wb, kCausesSheet, "Function"), "2003"); },
     R"(:Causes configuration:2:\d+: error: [A-Z]+2 \(Function\): '2003' is not one of .* \(did you mean '2oo3'\?\)$)"},
    {"bad_boolean",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, column_of(wb, kCausesSheet, "Auto ack"), "maybe"); },
     R"(:Causes configuration:2:\d+: error: [A-Z]+2 \(Auto ack\): 'maybe' is not true or false$)"},
    {"bad_real",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, column_of(wb, kCausesSheet, "Limit"), "1e99"); },
     R"(:Causes configuration:2:\d+: error: [A-Z]+2 \(Limit\): '1e99' is not a number in the range of IEEE single)"},
    {"tag_gap",
     [](Workbook& wb) {
       set(wb, kEffectsSheet, 2, column_of(wb, kEffectsSheet, "Tag 2"), "XV_2");
       set(wb, kEffectsSheet, 2, column_of(wb, kEffectsSheet, "Tag 1"), "");
     },
     R"(:Effects configuration:2:\d+: error: [A-Z]+2 \(Tag 2\): tag 2 follows an empty tag)"},
    {"bad_tag_name_from_loader",
     [](Workbook& wb) { set(wb, kCausesSheet, 2, column_of(wb, kCausesSheet, "Tag 1"), "#TIC__543"); },
     R"(^m\.\w+:Causes configuration:2:\d+: error: [A-Z]+2 \(Tag 1\) \[causes\[0\]\.tags\[0\]\.name\]: '#TIC__543' repeats '_'$)"},
    {"bad_matrix_name_from_loader",
     [](Workbook& wb) { set(wb, kPropertiesSheet, 2, 2, "has blanks"); },
     R"(^m\.\w+:Matrix properties:2:2: error: B2 \(Name\) \[name\]: )"},
    {"unknown_property",
     [](Workbook& wb) { set(wb, kPropertiesSheet, 3, 1, "Titel"); },
     R"(:Matrix properties:3:1: error: A3: unknown property 'Titel' \(did you mean 'Title'\?\))"},
    {"bad_mark",
     [](Workbook& wb) { set(wb, kOverviewSheet, kOverviewFirstRow, kOverviewFirstColumn, "Q"); },
     R"(^m\.\w+:Intersections overview:3:3: error: C3: 'Q' is no intersection type N, S, V, R, X or \*$)"},
    {"bad_xoon",
     [](Workbook& wb) { set(wb, kOverviewSheet, kOverviewFirstRow, kOverviewFirstColumn, "N 2oo5"); },
     R"(:Intersections overview:3:3: error: C3: 2oo5, but effect \d+ has 1 intersections with XooN \(6\.5\.2\)$)"},
    {"duplicate_effect_column",
     [](Workbook& wb) { set(wb, kOverviewSheet, kOverviewNumberRow, kOverviewFirstColumn + 1, "1"); },
     R"(:Intersections overview:2:4: error: D2 \(Effect No\.\): effect 1 has a column already \(C2\)$)"},
    {"missing_sheet",
     [](Workbook& wb) { std::erase_if(wb.sheets, [](const Sheet& s) { return s.name == kEffectsSheet; }); },
     R"(^m\.\w+: error: the workbook has no sheet 'Effects configuration')"},
    {"analog_value_without_type",
     [](Workbook& wb) {
       for (std::size_t c : {column_of(wb, kCausesSheet, "Limit type")}) set(wb, kCausesSheet, 2, c, "");
     },
     R"(:Causes configuration:2:\d+: error: [A-Z]+2 \(Limit\): an analog value without a Limit type)"},
};

TEST(WorkbookMalformed, EachCaseIsPlacedAtItsCell) {
  for (const Case& c : kCases) {
    for (WorkbookFormat f : {WorkbookFormat::Ods, WorkbookFormat::Xlsx}) {
      Workbook wb = matrix_to_workbook(example());
      c.edit(wb);
      const char* file = f == WorkbookFormat::Ods ? "m.ods" : "m.xlsx";
      try {
        import_workbook(f == WorkbookFormat::Ods ? write_ods(wb) : write_xlsx(wb), file);
        ADD_FAILURE() << c.name << ": accepted";
      } catch (const LoadError& e) {
        bool found = false;
        for (const auto& i : e.issues()) found = found || std::regex_search(i.message(), std::regex(c.expected));
        EXPECT_TRUE(found) << c.name << " (" << file << "): expected /" << c.expected << "/, got\n" << all_messages(e);
      }
    }
  }
}

std::string error_of(const std::string& bytes, const std::string& file) {
  try {
    import_workbook(bytes, file);
  } catch (const LoadError& e) {
    return all_messages(e);
  }
  return "accepted";
}

TEST(WorkbookMalformed, NotAWorkbook) {
  EXPECT_NE(error_of("", "e.xlsx").find("e.xlsx: error: not a workbook: the file is empty"), std::string::npos);
  EXPECT_NE(error_of("PK\x03\x04 garbage", "g.ods").find("g.ods: error: not a workbook"), std::string::npos);
  ZipWriter z;
  z.add("hello.txt", "hi");
  EXPECT_NE(error_of(z.finish(), "h.ods").find("h.ods: error: not a workbook: the zip archive holds neither an OpenDocument spreadsheet"), std::string::npos);
}

TEST(WorkbookMalformed, BrokenXml) {
  ZipWriter z;
  z.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  z.add("content.xml", "<office:document-content><office:body>");
  EXPECT_NE(error_of(z.finish(), "x.ods").find("x.ods: error: zip entry content.xml: malformed XML at byte"),
            std::string::npos);
  ZipWriter y;
  y.add("[Content_Types].xml", "<Types/>");
  y.add("xl/workbook.xml", "<workbook><sheets><sheet name=\"a\" r:id=\"rId9\"/></sheets></workbook>");
  EXPECT_NE(error_of(y.finish(), "y.xlsx").find("sheet 'a' has no relationship"), std::string::npos);
}

// ---- Limits -------------------------------------------------------------------

// A zip bomb: 64 MiB of blanks deflate to 64 KiB; the directory's size refuses
// it before anything is inflated.
TEST(WorkbookLimits, ZipBombIsRefusedFromTheDirectory) {
  ZipWriter z;
  z.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  z.add("content.xml", std::string(64u << 20, ' '));
  std::string bomb = z.finish();
  EXPECT_LT(bomb.size(), 1u << 20);
  EXPECT_NE(error_of(bomb, "bomb.ods").find("bomb.ods: error: zip entry content.xml would inflate to 67108864 bytes, "
                                            "more than the limit of 8 MiB per entry (refused without inflating it)"),
            std::string::npos)
      << error_of(bomb, "bomb.ods");
}

// A directory that understates the size: the inflated bytes are counted too.
TEST(WorkbookLimits, LyingDirectoryIsRefused) {
  ZipWriter z;
  z.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  z.add("content.xml", std::string(100000, ' '));
  std::string bytes = z.finish();
  // The uncompressed size of content.xml in its local header (offset 22) and
  // in the central directory (offset 24) set to 10.
  for (std::size_t at = 0; (at = bytes.find("content.xml", at)) != std::string::npos; ++at) {
    std::size_t header = bytes.rfind("PK", at);
    std::size_t offset = bytes[header + 2] == '\x01' ? 24 : 22;
    bytes[header + offset] = 10;
    for (int k = 1; k < 4; ++k) bytes[header + offset + k] = 0;
  }
  std::string message = error_of(bytes, "lie.ods");
  EXPECT_NE(message.find("lie.ods: error: "), std::string::npos) << message;
  EXPECT_EQ(message.find("accepted"), std::string::npos);
}

std::string ods_with_rows(const std::string& rows) {
  ZipWriter z;
  z.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  z.add("content.xml",
        "<office:document-content><office:body><office:spreadsheet><table:table table:name=\"Causes configuration\">" +
            rows + "</table:table></office:spreadsheet></office:body></office:document-content>");
  return z.finish();
}

// A million rows, as ODS repeats them: refused at the content-row limit; a
// million empty rows (LibreOffice writes those below the data) cost nothing.
TEST(WorkbookLimits, MillionRows) {
  std::string row = "<table:table-row table:number-rows-repeated=\"1000000\"><table:table-cell office:value-type=\"float\" "
                    "office:value=\"1\"><text:p>1</text:p></table:table-cell></table:table-row>";
  EXPECT_NE(error_of(ods_with_rows(row), "rows.ods").find(
                "rows.ods:Causes configuration:4097:1: error: A4097: more than 4096 rows hold something"),
            std::string::npos)
      << error_of(ods_with_rows(row), "rows.ods");
  std::string empty = "<table:table-row table:number-rows-repeated=\"1048576\"><table:table-cell "
                      "table:number-columns-repeated=\"16384\"/></table:table-row>";
  EXPECT_NE(error_of(ods_with_rows(empty), "empty.ods").find("empty.ods: error: the workbook has no sheet 'Matrix properties'"), std::string::npos);
  // The same million rows written out in XLSX: 30 MB of XML, refused from the zip directory.
  std::string data;
  for (int r = 1; r <= 1000000; ++r) data += "<row><c><v>1</v></c></row>";
  ZipWriter z;
  z.add("[Content_Types].xml", "<Types/>");
  z.add("xl/workbook.xml", "<workbook><sheets><sheet name=\"a\" r:id=\"rId1\"/></sheets></workbook>");
  z.add("xl/_rels/workbook.xml.rels", "<Relationships><Relationship Id=\"rId1\" Target=\"worksheets/sheet1.xml\"/></Relationships>");
  z.add("xl/worksheets/sheet1.xml", "<worksheet><sheetData>" + data + "</sheetData></worksheet>");
  EXPECT_NE(error_of(z.finish(), "rows.xlsx").find("zip entry xl/worksheets/sheet1.xml would inflate to"), std::string::npos);
}

// A 100 MB string: refused from the directory; a 1 MB one in a cell, at the cell.
TEST(WorkbookLimits, HugeStrings) {
  ZipWriter z;
  z.add("[Content_Types].xml", "<Types/>");
  z.add("xl/workbook.xml", "<workbook><sheets/></workbook>");
  z.add("xl/_rels/workbook.xml.rels",
        "<Relationships><Relationship Id=\"rId1\" Type=\"http://schemas.openxmlformats.org/officeDocument/2006/"
        "relationships/sharedStrings\" Target=\"sharedStrings.xml\"/></Relationships>");
  z.add("xl/sharedStrings.xml", "<sst><si><t>" + std::string(100u << 20, 'x') + "</t></si></sst>");
  std::string message = error_of(z.finish(), "s.xlsx");
  EXPECT_NE(message.find("s.xlsx: error: zip entry xl/sharedStrings.xml would inflate to 1048576"), std::string::npos)
      << message;
  std::string cell = "<table:table-row><table:table-cell office:value-type=\"string\"><text:p>" +
                     std::string(1u << 20, 'x') + "</text:p></table:table-cell></table:table-row>";
  EXPECT_NE(error_of(ods_with_rows(cell), "c.ods").find(
                "c.ods:Causes configuration:1:1: error: A1: the cell holds more than the limit of 32768 bytes of text"),
            std::string::npos)
      << error_of(ods_with_rows(cell), "c.ods");
}

// Deep nesting of spans (each would be a recursion level) is refused.
TEST(WorkbookLimits, DeepSpans) {
  std::string open, close;
  for (int i = 0; i < 100000; ++i) open += "<text:span>", close += "</text:span>";
  std::string cell = "<table:table-row><table:table-cell><text:p>" + open + "x" + close +
                     "</text:p></table:table-cell></table:table-row>";
  EXPECT_NE(error_of(ods_with_rows(cell), "d.ods").find("text spans nested deeper than 32"), std::string::npos);
}

// The table of malformed workbook files (workbook_malformed/EXPECTED.tsv): each
// is refused with a LoadError whose lines, named as the file's name, match.
TEST(WorkbookMalformed, FilesOfTheTable) {
  const std::filesystem::path dir = std::filesystem::path(CEMV_SOURCE_DIR) / "tests/sheets/workbook_malformed";
  std::ifstream table(dir / "EXPECTED.tsv");
  std::string line;
  std::size_t rows = 0;
  while (std::getline(table, line)) {
    if (line.empty() || line[0] == '#') continue;
    auto tab = line.find('\t');
    ASSERT_NE(tab, std::string::npos) << line;
    const std::string file = line.substr(0, tab);
    std::ifstream in(dir / file, std::ios::binary);
    ASSERT_TRUE(in) << file;
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    const std::string messages = error_of(bytes, file);
    bool found = false;
    std::istringstream lines(messages);
    for (std::string m; std::getline(lines, m);) found = found || std::regex_search(m, std::regex(line.substr(tab + 1)));
    EXPECT_TRUE(found) << file << ": expected /" << line.substr(tab + 1) << "/, got\n" << messages;
    ++rows;
  }
  EXPECT_GE(rows, 12u);
}

}  // namespace
}  // namespace cemv::formats
