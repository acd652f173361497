// Target (bench/README.md, issue 33 section 3): a vendor C&E workbook of 400
// rows x 100 columns with 3,000 merged ranges is read in under 2 s, as XLSX
// and as ODS. The workbook is generated here: a cover sheet, then the matrix
// (7 attribute columns and 93 effects; 7 header rows; 110 voting groups of
// three rows, merged in their attributes, marks and 15 empty mark cells
// each; 18 single causes; 45 struck-through deleted rows), so that its 128
// causes, 93 effects and 1024 marks are a valid matrix that every step of the
// grid import reads (sheet choice, merges, strikes, groups, setpoints).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "sheets/workbook.hpp"
#include "sheets/workbook_sheet.hpp"
#include "sheets/workbook_zip.hpp"

namespace {

using namespace cemv::formats;
using workbook::cell_address;

constexpr int kColumns = 100, kAttributes = 7, kEffects = kColumns - kAttributes, kHeaderRows = 7;
constexpr int kGroups = 110, kSingles = 18, kDeleted = 45;

struct Cell {
  std::string text;
  bool struck = false;
  int rows = 1, columns = 1;  // merged over
  bool covered = false;
};

struct Generated {
  std::map<std::pair<int, int>, Cell> cells;  // (row, column)
  int rows = 0, merges = 0, marks = 0;
  void put(int r, int c, std::string text, int rows = 1, int columns = 1, bool struck = false) {
    cells[{r, c}] = {std::move(text), struck, rows, columns, false};
    if (rows > 1 || columns > 1) ++merges;
    for (int i = r; i < r + rows; ++i)
      for (int j = c; j < c + columns; ++j)
        if (i != r || j != c) cells[{i, j}].covered = true;
    this->rows = std::max(this->rows, r + rows - 1);
  }
};

// Cause k's marks: 8 (or 7 for a group) spread over the effects, one a footnoted S*.
std::vector<int> mark_columns(int k, int count) {
  std::vector<int> out;
  for (int i = 0; i < count; ++i) out.push_back(kAttributes + 1 + (k * 11 + i * 13) % kEffects);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Generated matrix_sheet() {
  Generated g;
  g.put(1, 1, "CAUSE AND EFFECT MATRIX - SIS", 1, kColumns);
  g.put(2, 1, "CAUSES", 1, kAttributes);
  g.put(2, kAttributes + 1, "EFFECTS", 1, kEffects);
  const char* labels[] = {"Effect description", "Action", "Final element tag", "SIL"};
  for (int i = 0; i < 4; ++i) g.put(3 + i, 1, labels[i], 1, kAttributes);
  const char* headers[] = {"Item", "Cause description", "Tag", "Setpoint", "Unit", "Voting", "SIL"};
  for (int c = 1; c <= kAttributes; ++c) g.put(kHeaderRows, c, headers[c - 1]);
  for (int e = 1; e <= kEffects; ++e) {
    const int c = kAttributes + e;
    g.put(3, c, "Effect " + std::to_string(e) + " shutdown valve");
    g.put(4, c, e % 2 ? "CLOSE" : "STOP");
    g.put(5, c, "XV-" + std::to_string(1000 + e));
    g.put(6, c, std::to_string(1 + e % 3));
    g.put(kHeaderRows, c, std::to_string(e));
  }
  int row = kHeaderRows + 1, item = 0, cause = 0;
  for (int k = 0; k < kGroups + kSingles + kDeleted; ++k) {
    ++item;
    const bool deleted = k % 3 == 2 && k / 3 < kDeleted;
    const bool group = !deleted && cause < kGroups;
    const int n = group ? 3 : 1;
    const std::string id = std::to_string(item);
    g.put(row, 1, id, n, 1, deleted);
    g.put(row, 2, "Pressure " + id + " high", n, 1, deleted);
    for (int t = 0; t < n; ++t) g.put(row + t, 3, "PT-" + id + std::string(1, static_cast<char>('A' + t)), 1, 1, deleted);
    g.put(row, 4, std::to_string(10 + item), n, 1, deleted);
    g.put(row, 5, "barg", n, 1, deleted);
    g.put(row, 6, group ? "2oo3" : "1oo1", n, 1, deleted);
    g.put(row, 7, "2", n, 1, deleted);
    const auto marks = mark_columns(item, group ? 7 : 8);
    for (std::size_t i = 0; i < marks.size(); ++i) {
      g.put(row, marks[i], i == 0 ? "S*" : (i % 2 ? "N" : "S"), n, 1, deleted);
      if (!deleted) ++g.marks;
    }
    if (group)  // empty mark cells merged over the group, as the sheet's formatting
      for (int c = kAttributes + 1, merged = 0; c <= kColumns && merged < 15; ++c)
        if (!g.cells.count({row, c})) g.put(row, c, "", n), ++merged;
    if (!deleted) ++cause;
    row += n;
  }
  return g;
}

std::string xlsx_of(const Generated& g) {
  std::string data = "<sheetData>", merges;
  for (int r = 1; r <= g.rows; ++r) {
    data += "<row r=\"" + std::to_string(r) + "\">";
    for (auto it = g.cells.lower_bound({r, 0}); it != g.cells.end() && it->first.first == r; ++it) {
      const auto& [rc, c] = *it;
      const std::string ref = cell_address(static_cast<std::size_t>(rc.first), static_cast<std::size_t>(rc.second));
      if (c.rows > 1 || c.columns > 1)
        merges += "<mergeCell ref=\"" + ref + ":" +
                  cell_address(static_cast<std::size_t>(rc.first + c.rows - 1),
                               static_cast<std::size_t>(rc.second + c.columns - 1)) + "\"/>";
      if (c.text.empty()) continue;
      data += "<c r=\"" + ref + "\" t=\"inlineStr\"" + (c.struck ? " s=\"1\"" : "") + "><is><t>" + c.text + "</t></is></c>";
    }
    data += "</row>";
  }
  const std::string main = "http://schemas.openxmlformats.org/spreadsheetml/2006/main";
  const std::string rel = "http://schemas.openxmlformats.org/officeDocument/2006/relationships";
  workbook::ZipWriter zip;
  zip.add("[Content_Types].xml", "<Types/>");
  zip.add("_rels/.rels", "<Relationships><Relationship Id=\"r\" Type=\"" + rel +
                             "/officeDocument\" Target=\"xl/workbook.xml\"/></Relationships>");
  zip.add("xl/workbook.xml", "<workbook xmlns=\"" + main + "\" xmlns:r=\"" + rel +
                                 "\"><sheets><sheet name=\"Cover\" r:id=\"r1\"/><sheet name=\"SIS\" r:id=\"r2\"/>"
                                 "</sheets></workbook>");
  zip.add("xl/_rels/workbook.xml.rels",
          "<Relationships><Relationship Id=\"r1\" Type=\"" + rel + "/worksheet\" Target=\"s1.xml\"/>"
          "<Relationship Id=\"r2\" Type=\"" + rel + "/worksheet\" Target=\"s2.xml\"/>"
          "<Relationship Id=\"r3\" Type=\"" + rel + "/styles\" Target=\"styles.xml\"/></Relationships>");
  zip.add("xl/styles.xml", "<styleSheet xmlns=\"" + main + "\"><fonts><font/><font><strike/></font></fonts>"
                           "<cellXfs><xf fontId=\"0\"/><xf fontId=\"1\"/></cellXfs></styleSheet>");
  zip.add("xl/s1.xml", "<worksheet xmlns=\"" + main + "\"><sheetData><row r=\"1\"><c r=\"A1\" t=\"inlineStr\"><is><t>"
                       "Feed drum SIS</t></is></c></row></sheetData></worksheet>");
  zip.add("xl/s2.xml", "<worksheet xmlns=\"" + main + "\">" + data + "</sheetData><mergeCells>" + merges +
                           "</mergeCells></worksheet>");
  return zip.finish();
}

std::string ods_of(const Generated& g) {
  std::string rows;
  for (int r = 1; r <= g.rows; ++r) {
    rows += "<table:table-row>";
    for (int c = 1; c <= kColumns; ++c) {
      auto it = g.cells.find({r, c});
      if (it == g.cells.end()) {
        rows += "<table:table-cell/>";
        continue;
      }
      const Cell& x = it->second;
      if (x.covered) {
        rows += "<table:covered-table-cell/>";
        continue;
      }
      std::string a = x.struck ? " table:style-name=\"del\"" : "";
      if (x.rows > 1 || x.columns > 1)
        a += " table:number-rows-spanned=\"" + std::to_string(x.rows) + "\" table:number-columns-spanned=\"" +
             std::to_string(x.columns) + "\"";
      rows += x.text.empty() ? "<table:table-cell" + a + "/>"
                             : "<table:table-cell office:value-type=\"string\"" + a + "><text:p>" + x.text +
                                   "</text:p></table:table-cell>";
    }
    rows += "</table:table-row>";
  }
  workbook::ZipWriter zip;
  zip.add("mimetype", "application/vnd.oasis.opendocument.spreadsheet", true);
  zip.add("content.xml",
          "<office:document-content xmlns:office=\"urn:oasis:names:tc:opendocument:xmlns:office:1.0\" "
          "xmlns:style=\"urn:oasis:names:tc:opendocument:xmlns:style:1.0\" "
          "xmlns:text=\"urn:oasis:names:tc:opendocument:xmlns:text:1.0\" "
          "xmlns:table=\"urn:oasis:names:tc:opendocument:xmlns:table:1.0\"><office:automatic-styles>"
          "<style:style style:name=\"del\" style:family=\"table-cell\"><style:text-properties "
          "style:text-line-through-style=\"solid\"/></style:style></office:automatic-styles><office:body>"
          "<office:spreadsheet><table:table table:name=\"Cover\"><table:table-row><table:table-cell "
          "office:value-type=\"string\"><text:p>Feed drum SIS</text:p></table:table-cell></table:table-row>"
          "</table:table><table:table table:name=\"SIS\">" + rows +
          "</table:table></office:spreadsheet></office:body></office:document-content>");
  return zip.finish();
}

void BM_ImportVendorWorkbook(benchmark::State& state) {
  const bool ods = state.range(0) == 1;
  const Generated g = matrix_sheet();
  const std::string bytes = ods ? ods_of(g) : xlsx_of(g);
  // CEMV_BENCH_WORKBOOK_DIR=DIR keeps the workbook, to time `cemv import-workbook` on it.
  if (const char* dir = std::getenv("CEMV_BENCH_WORKBOOK_DIR"))
    std::ofstream(std::string(dir) + (ods ? "/vendor.ods" : "/vendor.xlsx"), std::ios::binary) << bytes;
  WorkbookImportOptions options;
  options.sheet_layout = SheetLayout{};
  options.sheet_layout->footnotes["*"] = "Bypassed during start-up";
  std::size_t causes = 0, intersections = 0;
  for (auto _ : state) {
    WorkbookImportResult r = import_workbook(bytes, ods ? "vendor.ods" : "vendor.xlsx", options);
    causes = r.matrix.causes.size();
    intersections = r.matrix.intersections.size();
    benchmark::DoNotOptimize(r.matrix.causes.data());
  }
  if (causes != 128 || intersections != static_cast<std::size_t>(g.marks))
    state.SkipWithError("the generated workbook did not read as intended");
  state.counters["rows"] = g.rows;
  state.counters["merges"] = g.merges;
  state.counters["causes"] = static_cast<double>(causes);
  state.counters["intersections"] = static_cast<double>(intersections);
  state.SetLabel(std::string(ods ? "ODS" : "XLSX") + ", target < 2 s; " + std::to_string(bytes.size() / 1024) + " KiB");
}
BENCHMARK(BM_ImportVendorWorkbook)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
