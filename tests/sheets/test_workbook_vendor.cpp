// Vendor C&E workbooks (docs/workbook.md "Vendor C&E workbooks"): the matrix
// sheet among several, named or found; a voting group merged over its rows;
// a deleted row struck through; a struck mark or a part of a text refused; the
// footnotes of a remarks sheet. Each in ODS and in XLSX, built by hand.
#include <gtest/gtest.h>

#include <map>

#include "sheets/workbook.hpp"
#include "sheets/workbook_sheet.hpp"
#include "vendor_workbooks.hpp"

namespace cemv::formats {

using namespace cemv::formats::testing;
using workbook::cell_address;
namespace {

struct TestCell {
  int row, column;
  std::string text;
  bool struck = false;
};
struct Merge {
  int first_row, first_column, last_row, last_column;
};
struct TestSheet {
  std::string name;
  std::vector<TestCell> cells;
  std::vector<Merge> merges;
  bool hidden = false;
};

std::string ods_of(const std::vector<TestSheet>& sheets) {
  std::string tables;
  for (const auto& s : sheets) {
    int rows = 0, columns = 0;
    std::map<std::pair<int, int>, const TestCell*> at;
    for (const auto& c : s.cells) {
      at[{c.row, c.column}] = &c;
      rows = std::max(rows, c.row);
      columns = std::max(columns, c.column);
    }
    tables += "<table:table table:name=\"" + s.name + "\"" + (s.hidden ? " table:style-name=\"hid\"" : "") + ">";
    for (int r = 1; r <= rows; ++r) {
      tables += "<table:table-row>";
      for (int c = 1; c <= columns; ++c) {
        bool covered = false;
        std::string span;
        for (const auto& m : s.merges) {
          if (m.first_row == r && m.first_column == c)
            span = " table:number-rows-spanned=\"" + std::to_string(m.last_row - m.first_row + 1) +
                   "\" table:number-columns-spanned=\"" + std::to_string(m.last_column - m.first_column + 1) + "\"";
          else if (r >= m.first_row && r <= m.last_row && c >= m.first_column && c <= m.last_column)
            covered = true;
        }
        const auto it = at.find({r, c});
        if (covered) tables += "<table:covered-table-cell/>";
        else if (it == at.end()) tables += "<table:table-cell" + span + "/>";
        else tables += ods_cell(it->second->text, span + (it->second->struck ? " table:style-name=\"del\"" : ""));
      }
      tables += "</table:table-row>";
    }
    tables += "</table:table>";
  }
  return ods_file(tables,
                  "<style:style style:name=\"del\" style:family=\"table-cell\"><style:text-properties "
                  "style:text-line-through-style=\"solid\"/></style:style>"
                  "<style:style style:name=\"hid\" style:family=\"table\"><style:table-properties "
                  "table:display=\"false\"/></style:style>");
}

std::string xlsx_of(const std::vector<TestSheet>& sheets) {
  std::vector<XlsxSheet> out;
  for (const auto& s : sheets) {
    std::map<int, std::string> rows;
    for (const auto& c : s.cells)
      rows[c.row] += xlsx_cell(cell_address(static_cast<std::size_t>(c.row), static_cast<std::size_t>(c.column)), c.text,
                               c.struck ? " s=\"1\"" : "");
    std::string body = "<sheetData>";
    for (const auto& [r, cells] : rows) body += "<row r=\"" + std::to_string(r) + "\">" + cells + "</row>";
    body += "</sheetData><mergeCells>";
    for (const auto& m : s.merges)
      body += "<mergeCell ref=\"" +
              cell_address(static_cast<std::size_t>(m.first_row), static_cast<std::size_t>(m.first_column)) + ":" +
              cell_address(static_cast<std::size_t>(m.last_row), static_cast<std::size_t>(m.last_column)) + "\"/>";
    out.push_back({s.name, body + "</mergeCells>", s.hidden ? "hidden" : "visible"});
  }
  return xlsx_file(out, "", "<font/><font><strike/></font>", "<xf fontId=\"0\"/><xf fontId=\"1\"/>");
}

// A small SIS matrix: a 2oo3 group over rows 3-5, merged in its id,
// description and voting cells and in its marks.
TestSheet matrix(const std::string& name = "SIS") {
  TestSheet s{name, {}, {}, false};
  auto put = [&](int r, int c, const std::string& t) { s.cells.push_back({r, c, t}); };
  put(1, 5, "Close valve");
  put(1, 6, "Stop pump");
  const char* headers[] = {"Item", "Description", "Tag", "Voting"};
  for (int c = 1; c <= 4; ++c) put(2, c, headers[c - 1]);
  put(2, 5, "1");
  put(2, 6, "2");
  put(3, 1, "1");
  put(3, 2, "Pressure high");
  put(3, 3, "PT-1A");
  put(4, 3, "PT-1B");
  put(5, 3, "PT-1C");
  put(3, 4, "2oo3");
  put(3, 5, "S");
  put(3, 6, "N");
  for (int c : {1, 2, 4, 5, 6}) s.merges.push_back({3, c, 5, c});
  put(6, 1, "2");
  put(6, 2, "Level low");
  put(6, 3, "LT-2");
  put(6, 4, "1oo1");
  put(6, 6, "N");
  return s;
}

TestSheet text_sheet(const std::string& name, const std::string& text) { return {name, {{1, 1, text}, {2, 1, "C"}}, {}, false}; }

class VendorWorkbook : public ::testing::TestWithParam<bool> {
 protected:
  std::string file() const { return GetParam() ? "v.ods" : "v.xlsx"; }
  std::string bytes(const std::vector<TestSheet>& sheets) const { return GetParam() ? ods_of(sheets) : xlsx_of(sheets); }
  WorkbookImportResult read(const std::vector<TestSheet>& sheets, WorkbookImportOptions options = {}) const {
    return import_workbook(bytes(sheets), file(), options);
  }
  std::string refusal(const std::vector<TestSheet>& sheets, WorkbookImportOptions options = {}) const {
    try {
      read(sheets, options);
    } catch (const LoadError& e) {
      std::string all;
      for (const auto& i : e.issues()) all += i.message() + "\n";
      return all;
    }
    return "";
  }
};

TEST_P(VendorWorkbook, TheMergedGroupIsOneCause) {
  const auto r = read({text_sheet("Cover", "Feed drum SIS"), matrix(), text_sheet("History", "Rev A")});
  ASSERT_EQ(r.matrix.causes.size(), 2u);
  const auto& c1 = r.matrix.causes[0];
  EXPECT_EQ(c1.function, model::CauseFunction::TwoOoThree);
  ASSERT_EQ(c1.tags.size(), 3u);
  EXPECT_EQ(c1.tags[2].name, "PT-1C");
  EXPECT_EQ(r.matrix.intersections.size(), 3u);
  EXPECT_NE(r.summary.find("sheet 'SIS' (the one sheet with a grid; 'Cover' and 'History' hold none) read as a C&E grid"),
            std::string::npos)
      << r.summary;
  EXPECT_NE(r.summary.find("voting groups: rows 3-5 (2oo3)"), std::string::npos) << r.summary;
  ASSERT_TRUE(r.layout_used.has_value());
  EXPECT_EQ(r.layout_used->sheet, "SIS");
  // Merged over two rows where the voting says three: refused at the voting cell.
  TestSheet two = matrix();
  for (auto& m : two.merges) m.last_row = 4;
  std::erase_if(two.cells, [](const TestCell& c) { return c.row == 5; });
  const std::string msg = refusal({two});
  EXPECT_NE(msg.find(file() + ":SIS:3:4: error: D3: voting '2oo3' of cause '1' over 2 tags (rows 3-4)"), std::string::npos)
      << msg;
}

TEST_P(VendorWorkbook, TheMatrixSheetIsFoundOrNamed) {
  TestSheet hidden = matrix("Old rev B");
  hidden.hidden = true;
  const std::vector<TestSheet> two{text_sheet("Cover", "x"), matrix("SIS"), hidden};
  EXPECT_NE(refusal(two).find("the workbook holds C&E grids on 2 sheets, 'SIS' and 'Old rev B' (hidden): name the "
                              "matrix with --sheet NAME"),
            std::string::npos)
      << refusal(two);
  WorkbookImportOptions by_name;
  by_name.sheet = "old REV b";
  EXPECT_NE(read(two, by_name).summary.find("sheet 'Old rev B' (as --sheet says) read as a C&E grid"), std::string::npos);
  WorkbookImportOptions by_number;
  by_number.sheet = "2";
  EXPECT_EQ(read(two, by_number).matrix.causes.size(), 2u);
  by_number.sheet = "4";
  EXPECT_NE(refusal(two, by_number).find("no sheet '4' in the workbook; its sheets are 'Cover', 'SIS' and 'Old rev B' "
                                         "(hidden) (or give a number 1-3)"),
            std::string::npos);
  WorkbookImportOptions both;
  both.sheet = "SIS";
  both.sheet_layout = SheetLayout{};
  both.sheet_layout->sheet = "Old rev B";
  EXPECT_NE(refusal(two, both).find("--sheet 'SIS' and the layout's sheet 'Old rev B' differ"), std::string::npos);
  const std::string none = refusal({text_sheet("Cover", "x"), text_sheet("Remarks", "y")});
  EXPECT_NE(none.find("no sheet holds a C&E grid (header rows of ids above rows of marks N, S, V, R, X or *): 'Cover' "
                      "and 'Remarks'"),
            std::string::npos)
      << none;
}

TEST_P(VendorWorkbook, StruckThroughRowsAreDeletedAndOtherStrikesRefused) {
  TestSheet s = matrix();
  for (auto& c : s.cells)
    if (c.row == 6) c.struck = true;  // the whole row, and no word says so
  const auto r = read({s});
  EXPECT_EQ(r.matrix.causes.size(), 1u);
  EXPECT_EQ(r.matrix.intersections.size(), 2u);
  EXPECT_NE(r.summary.find("left out 1 deleted cause: row 6 (id '2': 'Level low', struck through)"), std::string::npos)
      << r.summary;
  // The layout may say strikethrough is no deletion: then a struck cell is refused.
  WorkbookImportOptions keep;
  keep.sheet_layout = SheetLayout{};
  keep.sheet_layout->deleted.strikethrough = false;
  EXPECT_NE(refusal({s}, keep).find(file() + ":SIS:6:1: error: A6: '2' is struck through, but its row is not deleted"),
            std::string::npos)
      << refusal({s}, keep);
  // A struck mark of a live row: cemv cannot tell whether the intersection is deleted.
  TestSheet mark = matrix();
  for (auto& c : mark.cells)
    if (c.row == 6 && c.column == 6) c.struck = true;
  EXPECT_NE(refusal({mark}).find(file() + ":SIS:6:6: error: F6: mark 'N' at cause C_2 / effect E_2 is struck through, "
                                          "but neither its cause nor its effect is deleted"),
            std::string::npos)
      << refusal({mark});
}

TEST_P(VendorWorkbook, TheRemarksSheetGivesTheFootnotes) {
  TestSheet s = matrix();
  for (auto& c : s.cells)
    if (c.row == 6 && c.column == 6) c.text = "N*";
  TestSheet remarks{"Remarks", {{1, 1, "Notes"}, {3, 1, "*"}, {3, 2, "Bypassed in start-up"}, {4, 1, "NP"}, {4, 2, "x"}},
                    {}, false};
  WorkbookImportOptions opt;
  opt.sheet_layout = SheetLayout{};
  opt.sheet_layout->remarks_sheet = "Remarks";
  const auto r = read({s, remarks}, opt);
  EXPECT_EQ(r.matrix.find_intersection(2, 2)->note, "* Bypassed in start-up");
  EXPECT_EQ(r.layout_used->footnotes.at("*"), "Bypassed in start-up");
  EXPECT_NE(r.summary.find("footnotes from sheet 'Remarks' (1)"), std::string::npos) << r.summary;
  opt.sheet_layout->remarks_sheet = "Notes";
  EXPECT_NE(refusal({s, remarks}, opt).find("no sheet 'Notes' in the workbook"), std::string::npos);
  // A text in the layout that differs from the remarks sheet's: refused.
  opt.sheet_layout->remarks_sheet = "Remarks";
  opt.sheet_layout->footnotes["*"] = "Bypassed in shutdown";
  EXPECT_NE(refusal({s, remarks}, opt).find("footnote * reads 'Bypassed in shutdown' here and 'Bypassed in start-up' in "
                                            "sheet 'Remarks'"),
            std::string::npos)
      << refusal({s, remarks}, opt);
}

TEST_P(VendorWorkbook, NoSheetOrLayoutForTheSixTables) {
  model::Matrix m;
  m.name = "T";
  m.causes.push_back({});
  m.causes[0].id = 1;
  m.causes[0].name = "C1";
  m.causes[0].tags = {{"T1", false, true}};
  const std::string tables = export_workbook(m, GetParam() ? WorkbookFormat::Ods : WorkbookFormat::Xlsx);
  WorkbookImportOptions opt;
  opt.sheet = "Causes configuration";
  try {
    import_workbook(tables, file(), opt);
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_NE(e.issues()[0].what.find("holds the six tables of 6.6.2"), std::string::npos);
  }
  WorkbookImportOptions oriented;
  oriented.orientation = CsvOrientation::EffectsAsRows;
  try {
    import_workbook(tables, file(), oriented);
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_NE(e.issues()[0].what.find("a sheet, an orientation or a layout description is for a C&E grid"),
              std::string::npos);
  }
}

// import-workbook --orientation (docs/csv.md "Orientation"): a contractor
// sheet with `EFFECTS` over its attribute columns, its stacked effect header
// unlabelled (SIL, tag, action, description), read as given; the layout's
// orientation must agree; the six tables take none.
TEST_P(VendorWorkbook, TheOrientationIsGivenAsForACsv) {
  TestSheet s{"SIS rev C", {}, {}, false};
  const std::vector<std::vector<std::string>> rows{
      {"EFFECTS"},
      {"", "", "", "", "", "", "", "SIL 2", "SIL 1"},
      {"", "", "", "", "", "", "", "XV-301", "P-302"},
      {"", "", "", "", "", "", "", "CLOSE", "STOP"},
      {"", "", "", "", "", "", "", "Close inlet valve", "Stop feed pump"},
      {"Item", "Description", "Instrument Tag", "Trip setting", "EU", "Vote", "SIL"},
      {"1", "Feed drum pressure high-high", "PT-101", "45", "barg", "1oo1", "2", "S", "N"},
      {"2", "Feed drum level low-low", "LT-102", "20", "%", "1oo1", "2", "N", ""},
      {"3", "Manual shutdown", "HS-103", "-", "-", "1oo1", "1", "S", "S"}};
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      if (!rows[r][c].empty()) s.cells.push_back({static_cast<int>(r + 1), static_cast<int>(c + 1), rows[r][c]});
  EXPECT_NE(refusal({s}).find("the evidence conflicts"), std::string::npos) << refusal({s});
  WorkbookImportOptions opt;
  opt.orientation = CsvOrientation::CausesAsRows;
  const auto r = read({s}, opt);
  ASSERT_EQ(r.matrix.effects.size(), 2u) << r.summary;
  EXPECT_EQ(r.matrix.effects[0].tags.at(0).name, "XV-301");
  EXPECT_EQ(r.matrix.effects[0].sil, 2);
  EXPECT_EQ(r.matrix.effects[1].description, "Stop feed pump");
  EXPECT_NE(r.summary.find("orientation causes-as-rows as given by --orientation"), std::string::npos) << r.summary;
  SheetLayout layout;
  layout.orientation = CsvOrientation::EffectsAsRows;
  opt.sheet_layout = layout;
  EXPECT_NE(refusal({s}, opt).find("--orientation causes-as-rows and the layout's effects-as-rows disagree; give one"),
            std::string::npos)
      << refusal({s}, opt);
}

INSTANTIATE_TEST_SUITE_P(OdsAndXlsx, VendorWorkbook, ::testing::Values(true, false),
                         [](const auto& info) { return std::string(info.param ? "ods" : "xlsx"); });

}  // namespace
}  // namespace cemv::formats
