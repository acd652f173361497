// What the workbook readers take from a cell besides its text (docs/workbook.md
// "Vendor C&E workbooks"): merged ranges, struck-through text (by the cell's
// style or by every run of it) and hidden sheets, in ODS and XLSX alike; and
// that hostile merges are refused within the limits.
#include <gtest/gtest.h>

#include "sheets/workbook_files.hpp"
#include "vendor_workbooks.hpp"

namespace cemv::formats {

using namespace cemv::formats::workbook;
using namespace cemv::formats::testing;
namespace {

Workbook read(const std::string& bytes, bool ods) {
  ZipReader zip(bytes, ods ? "t.ods" : "t.xlsx");
  CellBudget budget(zip.file());
  Workbook wb = ods ? read_ods(zip, budget) : read_xlsx(zip, budget);
  for (Sheet& s : wb.sheets) s.sort();
  return wb;
}

const Cell& at(const Sheet& s, std::size_t row, std::size_t column) {
  const Cell* c = s.find(row, column);
  if (!c) throw std::logic_error("no cell " + cell_address(row, column));
  return *c;
}

std::string refusal(const std::string& bytes, bool ods) {
  try {
    read(bytes, ods);
  } catch (const LoadError& e) {
    return e.issues().front().message();
  }
  return "";
}

// The same sheet in both formats: A1:B1 merged ("Group"), A2:A4 merged over
// three rows, B2 struck by its cell style, B3 struck by its one text run, B4
// struck in part (one run of two), C2 plain; a second sheet hidden.
std::string ods_sample() {
  const std::string styles =
      "<style:style style:name=\"ce1\" style:family=\"table-cell\" style:parent-style-name=\"Deleted\"/>"
      "<style:style style:name=\"T1\" style:family=\"text\"><style:text-properties "
      "style:text-line-through-style=\"solid\" style:text-line-through-type=\"single\"/></style:style>"
      "<style:style style:name=\"ta2\" style:family=\"table\"><style:table-properties table:display=\"false\"/>"
      "</style:style>";
  // A common style with the strikethrough, that the automatic style ce1 derives from.
  const std::string common =
      "<style:style style:name=\"Deleted\" style:family=\"table-cell\"><style:text-properties "
      "style:text-line-through-style=\"solid\"/></style:style>";
  const std::string matrix =
      "<table:table table:name=\"SIS\">"
      "<table:table-row>" + ods_cell("Group", " table:number-columns-spanned=\"2\" table:number-rows-spanned=\"1\"") +
      "<table:covered-table-cell/></table:table-row>"
      "<table:table-row>" + ods_cell("1", " table:number-rows-spanned=\"3\"") +
      ods_cell("PT-1", " table:style-name=\"ce1\"") + ods_cell("plain") + "</table:table-row>"
      "<table:table-row><table:covered-table-cell/>"
      "<table:table-cell office:value-type=\"string\"><text:p><text:span text:style-name=\"T1\">PT-2</text:span> "
      "</text:p></table:table-cell></table:table-row>"
      "<table:table-row><table:covered-table-cell/>"
      "<table:table-cell office:value-type=\"string\"><text:p><text:span text:style-name=\"T1\">PT-3</text:span> "
      "new</text:p></table:table-cell></table:table-row>"
      "</table:table>";
  const std::string hidden = "<table:table table:name=\"Lists\" table:style-name=\"ta2\"><table:table-row>" +
                             ods_cell("x") + "</table:table-row></table:table>";
  return ods_file(matrix + hidden, styles, common);
}

std::string xlsx_sample() {
  const std::string fonts = "<font/><font><strike/></font><font><strike val=\"0\"/></font>";
  const std::string xfs = "<xf fontId=\"0\"/><xf fontId=\"1\"/><xf fontId=\"2\"/>";
  const std::string shared =
      "<si><r><rPr><strike/></rPr><t>PT-2</t></r><r><t xml:space=\"preserve\"> </t></r></si>"
      "<si><r><rPr><strike/></rPr><t>PT-3</t></r><r><t xml:space=\"preserve\"> new</t></r></si>";
  const std::string body =
      "<sheetData><row r=\"1\">" + xlsx_cell("A1", "Group") + "</row>"
      "<row r=\"2\">" + xlsx_cell("A2", "1") + xlsx_cell("B2", "PT-1", " s=\"1\"") + xlsx_cell("C2", "plain", " s=\"2\"") +
      "</row><row r=\"3\"><c r=\"B3\" t=\"s\"><v>0</v></c></row>"
      "<row r=\"4\"><c r=\"B4\" t=\"s\"><v>1</v></c></row></sheetData>"
      "<mergeCells count=\"3\"><mergeCell ref=\"A1:B1\"/><mergeCell ref=\"A2:A4\"/><mergeCell ref=\"D5:E6\"/></mergeCells>";
  return xlsx_file({{"SIS", body}, {"Lists", "<sheetData><row r=\"1\">" + xlsx_cell("A1", "x") + "</row></sheetData>",
                                    "hidden"}},
                   shared, fonts, xfs);
}

class WorkbookFormats : public ::testing::TestWithParam<bool> {};

TEST_P(WorkbookFormats, MergesStrikethroughAndHiddenSheets) {
  const bool ods = GetParam();
  const Workbook wb = read(ods ? ods_sample() : xlsx_sample(), ods);
  ASSERT_EQ(wb.sheets.size(), 2u);
  const Sheet& s = wb.sheets[0];
  EXPECT_FALSE(s.hidden);
  EXPECT_TRUE(wb.sheets[1].hidden);
  // The merges whose first cell holds text (D5:E6 of the XLSX is empty formatting).
  ASSERT_EQ(s.merges.size(), 2u);
  EXPECT_EQ(s.merges[0].first_row, 1u);
  EXPECT_EQ(s.merges[0].last_column, 2u);
  EXPECT_EQ(s.merges[1].first_column, 1u);
  EXPECT_EQ(s.merges[1].last_row, 4u);
  EXPECT_EQ(at(s, 2, 2).strike, Strike::Whole);  // the cell's style (ODS: by its parent style)
  EXPECT_EQ(at(s, 2, 3).strike, Strike::None);
  EXPECT_EQ(at(s, 3, 2).strike, Strike::Whole);  // its one visible run
  EXPECT_EQ(at(s, 3, 2).text, "PT-2 ");
  EXPECT_EQ(at(s, 4, 2).strike, Strike::Part);   // one run of two
  EXPECT_EQ(at(s, 2, 1).text, "1");
  EXPECT_EQ(s.find(3, 1), nullptr);  // covered by the merge: no text of its own
}

TEST_P(WorkbookFormats, HostileMergesAreRefused) {
  const bool ods = GetParam();
  std::string bytes;
  if (ods)
    bytes = ods_file("<table:table table:name=\"S\"><table:table-row>" +
                     ods_cell("x", " table:number-rows-spanned=\"99999999999\"") + "</table:table-row></table:table>");
  else
    bytes = xlsx_file({{"S", "<sheetData><row r=\"1\">" + xlsx_cell("A1", "x") +
                                 "</row></sheetData><mergeCells><mergeCell ref=\"A1:A9999999\"/></mergeCells>"}});
  EXPECT_NE(refusal(bytes, ods).find("row number"), std::string::npos) << refusal(bytes, ods);
  if (!ods) {
    const std::string reversed = xlsx_file({{"S", "<sheetData><row r=\"1\">" + xlsx_cell("B2", "x") +
                                                      "</row></sheetData><mergeCells><mergeCell ref=\"B2:A1\"/>"
                                                      "</mergeCells>"}});
    EXPECT_NE(refusal(reversed, false).find("the merged range B2:A1 ends before it starts"), std::string::npos);
    const std::string garbage = xlsx_file({{"S", "<sheetData/><mergeCells><mergeCell ref=\"A1\"/></mergeCells>"}});
    EXPECT_NE(refusal(garbage, false).find("mergeCell 'A1' is not a range of cells"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(OdsAndXlsx, WorkbookFormats, ::testing::Values(true, false),
                         [](const auto& info) { return std::string(info.param ? "ods" : "xlsx"); });

}  // namespace
}  // namespace cemv::formats
