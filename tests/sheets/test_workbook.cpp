// Workbooks (6.6, docs/workbook.md): the lossless round trip through ODS and
// XLSX on every example and on random matrices of every option; the tag-name
// conventions (6.6.2) and the row-import rule (6.6.3); grey cells ignored.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "formats/matrix_json.hpp"
#include "sheets/workbook.hpp"
#include "sheets/workbook_files.hpp"
#include "sheets/workbook_tables.hpp"
#include "sheets/workbook_tags.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv::formats {

using namespace cemv::formats::workbook;
namespace {

const WorkbookFormat kFormats[] = {WorkbookFormat::Ods, WorkbookFormat::Xlsx};
const char* name_of(WorkbookFormat f) { return f == WorkbookFormat::Ods ? "m.ods" : "m.xlsx"; }

std::string bytes_of(const Workbook& wb, WorkbookFormat f) { return f == WorkbookFormat::Ods ? write_ods(wb) : write_xlsx(wb); }

void expect_round_trip(const model::Matrix& m, const std::string& label) {
  const std::string canonical = to_canonical_json(m);
  for (WorkbookFormat f : kFormats) {
    const std::string bytes = export_workbook(m, f);
    EXPECT_EQ(bytes, export_workbook(m, f)) << label << ": export is not deterministic";
    WorkbookImportResult r = import_workbook(bytes, name_of(f));
    EXPECT_EQ(to_canonical_json(r.matrix), canonical) << label << " through " << name_of(f);
    EXPECT_EQ(signature(r.matrix), signature(m)) << label;
    for (const auto& w : r.warnings) ADD_FAILURE() << label << ": " << w.message("warning");
  }
}

TEST(WorkbookRoundTrip, EveryExample) {
  std::size_t n = 0;
  for (const auto& dir : std::filesystem::directory_iterator(std::filesystem::path(CEMV_SOURCE_DIR) / "examples")) {
    auto file = dir.path() / "matrix.json";
    if (!std::filesystem::exists(file)) continue;
    expect_round_trip(load_matrix(file), file.string());
    ++n;
  }
  EXPECT_GE(n, 4u);
}

// Between them the seeds use every option of cemv-matrix/1 (tests/support).
TEST(WorkbookRoundTrip, RandomMatricesOfEveryOption) {
  std::map<std::string, int> features;
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    model::Matrix m = testsupport::random_matrix(seed);
    for (const auto& [k, v] : testsupport::feature_counts(m)) features[k] += v;
    expect_round_trip(m, "seed " + std::to_string(seed));
  }
  for (const auto& f : testsupport::feature_names()) EXPECT_GT(features[f], 0) << "no seed uses " << f;
  expect_round_trip(testsupport::big_matrix(1), "big_matrix");
}

// What the random generator leaves alone: texts with blanks where ODF would
// collapse them, a tag beginning with '*', XooN with notes, timing keys,
// matrix-level fields, the extreme numbers.
TEST(WorkbookRoundTrip, EdgeValues) {
  model::Matrix m = load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
  m.title = "  two  blanks, leading and trailing  ";
  m.causes[0].description = " a  b ";
  m.causes[0].note = "x;y; (1)";
  m.causes[0].tags[0].name = "*STAR";
  m.causes[0].sensor_ms = 4294967295u;
  m.cycle_ms = 4294967295u;
  m.watchdog_ms = 250;
  m.sif_groups[64] = "";
  m.process_safety_time_ms[64] = 1;
  if (m.causes[0].analog) {
    m.causes[0].analog->limit = 3.4028235e38f;
    m.causes[0].analog->hysteresis = 1e-45f;
    m.causes[0].analog->prewarning = -0.1f;
  }
  for (auto& x : m.intersections) x.note = "  note ; with (2)";
  m.effects[0].process_data = model::ProcessData{};
  m.effects[0].override_time = model::Override{0, 0};
  const std::string canonical = to_canonical_json(m);
  for (WorkbookFormat f : kFormats) {
    WorkbookImportResult r = import_workbook(export_workbook(m, f), name_of(f));
    EXPECT_EQ(to_canonical_json(r.matrix), canonical) << name_of(f);
    // The '*' of the tag name reads back as the prefix of the preprocessing option, ignored.
    ASSERT_EQ(r.warnings.size(), 1u) << name_of(f);
    EXPECT_NE(r.warnings[0].what.find("'*' with preprocessing"), std::string::npos);
  }
}

TEST(WorkbookTags, PrefixesSuffixesAndReferences) {
  EXPECT_EQ(read_tag_cell("#TIC_1").name, "#TIC_1");  // external connection: part of the name
  EXPECT_EQ(read_tag_cell("E6.3#").name, "E6.3#");    // with monitoring: part of the name
  TagCell c = read_tag_cell("~@*XV_101");
  EXPECT_EQ(c.name, "XV_101");
  EXPECT_EQ(c.ignored.size(), 3u);
  EXPECT_EQ(read_tag_cell("**A").name, "*A");
  EXPECT_EQ(read_tag_cell("cause[12]").name, "Cause[12]");
  EXPECT_EQ(read_tag_cell("EFFECT[7][2]").name, "Effect[7][2]");
  EXPECT_TRUE(read_tag_cell("Effect[7][2]").normalized.empty());
  EXPECT_EQ(read_tag_cell("cause[1][2]").name, "cause[1][2]");  // no such reference: an ordinary name
  EXPECT_EQ(tag_cell_text("*A"), "**A");
}

// Grey cells are information only: whatever they say, the import is the same.
TEST(WorkbookTables, GreyCellsAreIgnored) {
  model::Matrix m = load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/burner-management/matrix.json");
  Workbook wb = matrix_to_workbook(m);
  std::size_t grey = 0;
  for (Sheet& s : wb.sheets)
    for (Cell& c : s.cells)
      if (c.grey && c.row > 1) {
        c.text = "garbage " + c.text;
        ++grey;
      }
  EXPECT_GT(grey, 50u);
  for (WorkbookFormat f : kFormats)
    EXPECT_EQ(to_canonical_json(import_workbook(bytes_of(wb, f), name_of(f)).matrix), to_canonical_json(m));
}

Sheet& sheet_of(Workbook& wb, const char* name) {
  for (Sheet& s : wb.sheets)
    if (s.name == name) return s;
  throw std::logic_error(name);
}

// 6.6.3: rows from the first number to the first empty number cell; the rest is a warning.
TEST(WorkbookTables, RowsEndAtTheFirstEmptyNumberCell) {
  model::Matrix m = load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
  ASSERT_GE(m.causes.size(), 3u);
  Workbook wb = matrix_to_workbook(m);
  Sheet& causes = sheet_of(wb, kCausesSheet);
  // Remove the number of the third cause (row 4): causes 3.. are not imported.
  causes.cells.erase(std::find_if(causes.cells.begin(), causes.cells.end(),
                                  [](const Cell& c) { return c.row == 4 && c.column == 1; }));
  // Their intersections then name causes without a row: remove those marks too.
  Sheet& overview = sheet_of(wb, kOverviewSheet);
  std::erase_if(overview.cells, [](const Cell& c) { return c.row >= kOverviewFirstRow + 2; });
  WorkbookImportResult r = import_workbook(write_xlsx(wb), "m.xlsx");
  EXPECT_EQ(r.matrix.causes.size(), 2u);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].message("warning"),
            "m.xlsx:Causes configuration:4:1: warning: A4 (No.): not imported: the import of this table ends at the "
            "empty cause number cell A4 (6.6.3); this row and any after it are left out");
}

TEST(WorkbookTables, AtMost128Causes) {
  model::Matrix m = testsupport::big_matrix(1);
  ASSERT_EQ(m.causes.size(), 128u);
  Workbook wb = matrix_to_workbook(m);
  Sheet& causes = sheet_of(wb, kCausesSheet);
  for (const Cell* c : causes.row(2)) causes.put(130, c->column, c->text, c->grey, c->kind);
  causes.sort();
  WorkbookImportResult r = import_workbook(write_ods(wb), "m.ods");
  EXPECT_EQ(r.matrix.causes.size(), 128u);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].message("warning").find(
                "m.ods:Causes configuration:130:1: warning: A130 (No.): not imported: at most 128 causes"),
            std::string::npos) << r.warnings[0].message("warning");
}

}  // namespace
}  // namespace cemv::formats
