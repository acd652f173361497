// The grid layout of real C&E spreadsheets (docs/csv.md): the published LSST TMA
// interlock table imported as it is, and small grids for each defect rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <set>
#include <tuple>

#include "sheets/csv.hpp"
#include "tests/support/external_tables.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"

namespace cemv::formats {

using namespace cemv::model;
namespace {

// The published LSST TMA interlock table, where it is published beside the
// project (CEMV_LSST_DIR, tests/CMakeLists.txt): not copied, it has no licence.
const std::filesystem::path kExternal = std::filesystem::path(CEMV_LSST_DIR);

CsvImportResult import_file(const std::filesystem::path& p) {
  return import_csv(read_text_file(p), p.filename().string());
}

bool has_warning(const CsvImportResult& r, const std::string& where, const std::string& what) {
  return std::any_of(r.warnings.begin(), r.warnings.end(), [&](const LoadIssue& w) {
    return w.where.find(where) != std::string::npos && w.what.find(what) != std::string::npos;
  });
}

std::string warnings_text(const CsvImportResult& r) {
  std::string s;
  for (const auto& w : r.warnings) s += w.str() + "\n";
  return s;
}

class LsstGrid : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    result_ = new CsvImportResult(import_file(cemv::test::lsst_table(kExternal, "lsst-tma-interlock-table.csv")));
  }
  static void TearDownTestSuite() { delete result_; }
  static CsvImportResult* result_;
};
CsvImportResult* LsstGrid::result_ = nullptr;

// The sheet has 36 cause rows (35 distinct ids: TMA-D-40 twice) and 17 effect
// columns (TMA-A-1 .. TMA-A-17). Both TMA-D-40 rows are kept.
TEST_F(LsstGrid, ImportsEveryRowAndColumn) {
  const Matrix& m = result_->matrix;
  EXPECT_EQ(result_->layout, CsvLayoutKind::Grid);
  EXPECT_EQ(m.causes.size(), 36u);
  EXPECT_EQ(m.effects.size(), 17u);
  EXPECT_EQ(m.intersections.size(), 102u);
  // Ids follow the sheet's numbers; names and tags are the sanitized ids.
  const Cause* c1 = m.find_cause(1);
  ASSERT_NE(c1, nullptr);
  EXPECT_EQ(c1->name, "TMA_D_1");
  ASSERT_EQ(c1->tags.size(), 1u);
  EXPECT_EQ(c1->tags[0].name, "TMA_D_1");
  EXPECT_EQ(c1->input, InputKind::Discrete);
  EXPECT_EQ(c1->description, "Azimuth axis CW travel limit AND topple block pos A");
  const Effect* e17 = m.find_effect(17);
  ASSERT_NE(e17, nullptr);
  EXPECT_EQ(e17->name, "TMA_A_17");
  EXPECT_EQ(e17->tags[0].name, "TMA_A_17");
  EXPECT_EQ(e17->description, "SOS OSS (Slow pressure off)");  // column 15, out of order
}

TEST_F(LsstGrid, DuplicatedCauseIdKeptAsTwoCausesAndReported) {
  const Matrix& m = result_->matrix;
  const Cause* first = m.find_cause(40);
  const Cause* second = m.find_cause(44);
  ASSERT_NE(first, nullptr);
  ASSERT_NE(second, nullptr);
  EXPECT_EQ(first->name, "TMA_D_40");
  EXPECT_EQ(first->description, "Platform extension NO inserted");
  EXPECT_EQ(second->name, "TMA_D_40_2");
  EXPECT_EQ(second->tags[0].name, "TMA_D_40_2");
  EXPECT_EQ(second->description, "GIS Discharge Capacitors Bank");
  EXPECT_NE(second->note.find("TMA-D-40"), std::string::npos);
  EXPECT_TRUE(has_warning(*result_, "line 35, column 2", "cause id 'TMA-D-40' repeats line 25"))
      << warnings_text(*result_);
  EXPECT_TRUE(has_warning(*result_, "line 35, column 2", "both rows are kept as separate causes"));
  // Each keeps its own intersections.
  EXPECT_NE(m.find_intersection(40, 1), nullptr);
  EXPECT_EQ(m.find_intersection(44, 1), nullptr);
  ASSERT_NE(m.find_intersection(44, 11), nullptr);
  EXPECT_EQ(m.find_intersection(44, 11)->type, IntersectionType::N);
}

TEST_F(LsstGrid, FootnotesAreKeptAsIntersectionNotes) {
  const Matrix& m = result_->matrix;
  const Intersection* r1 = m.find_intersection(1, 1);
  ASSERT_NE(r1, nullptr);
  EXPECT_EQ(r1->type, IntersectionType::R);
  EXPECT_EQ(r1->note, "(1)");
  const Intersection* s2 = m.find_intersection(4, 12);  // TMA-D-4 x TMA-A-12: S(2)
  ASSERT_NE(s2, nullptr);
  EXPECT_EQ(s2->type, IntersectionType::S);
  EXPECT_EQ(s2->note, "(2)");
  const Intersection* n3 = m.find_intersection(12, 6);  // N(3)
  ASSERT_NE(n3, nullptr);
  EXPECT_EQ(n3->note, "(3)");
  EXPECT_EQ(m.find_intersection(3, 1)->note, "");
  EXPECT_TRUE(has_warning(*result_, "line 3", "footnotes (1), (2), (3), (4), (5)"));
}

TEST_F(LsstGrid, SheetDefectsAreWarningsWithLineAndColumn) {
  const auto& r = *result_;
  // Blank vs space: the grid writes ' ' for "no intersection", some cells are empty.
  EXPECT_TRUE(has_warning(r, "line 13, column 10", "empty cell where the grid otherwise uses a space"))
      << warnings_text(r);
  EXPECT_TRUE(has_warning(r, "line 23, column 8", "empty cell"));
  EXPECT_TRUE(has_warning(r, "line 37, columns 5-19", "15 empty cells"));
  // Effect ids out of order: TMA-A-17 stands between TMA-A-12 and TMA-A-13.
  EXPECT_TRUE(has_warning(r, "line 2, column 15", "effect id 'TMA-A-17' out of order"));
  EXPECT_FALSE(has_warning(r, "line 2, column 16", "out of order"));
  EXPECT_TRUE(has_warning(r, "line 25, column 2", "cause id 'TMA-D-40' out of order"));
  // Warnings come in file order.
  EXPECT_TRUE(std::is_sorted(r.warnings.begin(), r.warnings.end(), [](const LoadIssue& a, const LoadIssue& b) {
    auto line = [](const LoadIssue& w) { return std::stoi(w.where.substr(w.where.find("line ") + 5)); };
    return line(a) < line(b);
  }));
}

TEST_F(LsstGrid, LoadsAndValidateReportsEveryMissingOverrideTime) {
  const Matrix& m = result_->matrix;
  const Matrix again = parse_matrix(to_canonical_json(m), "lsst.json");
  EXPECT_EQ(to_canonical_json(again), to_canonical_json(m));
  std::set<int> need;  // effects with V or R intersections: the grid states no override time
  for (const auto& x : m.intersections)
    if (x.type == IntersectionType::R || x.type == IntersectionType::V) need.insert(x.effect);
  EXPECT_EQ(need, (std::set<int>{1, 2, 4, 5}));
  for (const auto& e : m.effects) EXPECT_FALSE(e.override_time.has_value()) << e.name;
  const auto diags = validate(m);
  EXPECT_TRUE(has_errors(diags));
  std::set<std::string> reported;
  for (const auto& d : diags)
    if (d.severity == Severity::Error && d.message.find("override") != std::string::npos)
      reported.insert(d.element);
  ASSERT_EQ(reported.size(), need.size());
  for (int id : need) {
    const std::string name = m.find_effect(id)->name;
    EXPECT_TRUE(std::any_of(reported.begin(), reported.end(),
                            [&](const std::string& el) { return el.find(name) != std::string::npos; }))
        << name;
  }
}

TEST_F(LsstGrid, ImportIsDeterministic) {
  auto again = import_file(cemv::test::lsst_table(kExternal, "lsst-tma-interlock-table.csv"));
  EXPECT_EQ(to_canonical_json(again.matrix), to_canonical_json(result_->matrix));
  EXPECT_EQ(warnings_text(again), warnings_text(*result_));
}

TEST_F(LsstGrid, OlderVersionDiffersByExactlyOneIntersection) {
  auto old = import_file(cemv::test::lsst_table(kExternal, "lsst-tma-interlock-table-2023-10-05.csv"));
  const Matrix& a = result_->matrix;
  const Matrix& b = old.matrix;
  ASSERT_EQ(a.causes.size(), b.causes.size());
  ASSERT_EQ(a.effects.size(), b.effects.size());
  for (std::size_t i = 0; i < a.causes.size(); ++i) EXPECT_EQ(a.causes[i].name, b.causes[i].name);
  using Key = std::tuple<int, int, IntersectionType, std::string>;
  std::set<Key> ka, kb, only_a, only_b;
  for (const auto& x : a.intersections) ka.insert({x.cause, x.effect, x.type, x.note});
  for (const auto& x : b.intersections) kb.insert({x.cause, x.effect, x.type, x.note});
  std::set_difference(ka.begin(), ka.end(), kb.begin(), kb.end(), std::inserter(only_a, only_a.end()));
  std::set_difference(kb.begin(), kb.end(), ka.begin(), ka.end(), std::inserter(only_b, only_b.end()));
  EXPECT_TRUE(only_a.empty());
  ASSERT_EQ(only_b.size(), 1u);
  // 2023-10-05: TMA-D-17 (retracted elevation locking pins) also tripped TMA-A-5.
  EXPECT_EQ(*only_b.begin(), (Key{17, 5, IntersectionType::N, ""}));
}

TEST_F(LsstGrid, SurvivesTheRecordLayoutRoundTrip) {
  auto back = import_csv(export_csv(result_->matrix), "lsst-records.csv");
  EXPECT_EQ(to_canonical_json(back.matrix), to_canonical_json(result_->matrix));
}

// ---- small grids, one rule each --------------------------------------------------------------

const char* kHeader =
    ";Effects;Close valve;Stop pump\n"
    "Causes;;E-1;E-2\n";

TEST(GridImport, LegendRowsExplainFootnotes) {
  auto r = import_csv(std::string(kHeader) +
                          "High level;C-1;R(1);N(1)(2)\n"
                          "Low flow;C-2;;S\n"
                          "\n"
                          "(1);Override with key switch\n"
                          "(2);Only in mode B;see procedure\n",
                      "legend.csv");
  const Matrix& m = r.matrix;
  ASSERT_EQ(m.causes.size(), 2u);
  EXPECT_EQ(m.find_intersection(1, 1)->note, "(1) Override with key switch");
  EXPECT_EQ(m.find_intersection(1, 2)->note, "(1) Override with key switch; (2) Only in mode B see procedure");
  EXPECT_FALSE(has_warning(r, "", "footnotes"));
}

TEST(GridImport, MarksWithoutMeaningAreRefusedNeverDropped) {
  // A cell that is no mark may be a trip the sheet writes its own way (S*,
  // NP, Yes): refused at its cell, every one of them, never dropped.
  const std::string stray = std::string(kHeader) +
                            "High level;C-1;Yes;n;extra\n"
                            "Low flow;C-2;R 1;S ( 2 )\n";
  try {
    import_csv(stray, "stray.csv");
    FAIL() << "a mark without a meaning";
  } catch (const LoadError& e) {
    ASSERT_EQ(e.issues().size(), 2u);
    EXPECT_EQ(e.issues()[0].where, "stray.csv: line 3, column 3");
    EXPECT_NE(e.issues()[0].what.find("mark 'Yes' at cause C_1 / effect E_1 has no meaning"), std::string::npos);
    EXPECT_EQ(e.issues()[1].where, "stray.csv: line 4, column 3");
    EXPECT_NE(e.issues()[1].what.find("mark 'R 1'"), std::string::npos);
  }
  // The layout gives them a meaning: read.
  CsvImportOptions opt;
  opt.sheet_layout = SheetLayout{};
  opt.sheet_layout->marks["Yes"] = MarkMeaning{IntersectionType::N, ""};
  opt.sheet_layout->marks["R 1"] = MarkMeaning{IntersectionType::R, "(1)"};
  auto r = import_csv(stray, "stray.csv", opt);
  EXPECT_TRUE(has_warning(r, "line 3, column 4", "lower-case mark 'n' read as 'N'"));
  EXPECT_TRUE(has_warning(r, "line 3, column 5", "stray value 'extra' right of the last effect column"));
  EXPECT_EQ(r.matrix.intersections.size(), 4u);
  EXPECT_EQ(r.matrix.find_intersection(1, 1)->type, IntersectionType::N);
  EXPECT_EQ(r.matrix.find_intersection(1, 2)->type, IntersectionType::N);
  EXPECT_EQ(r.matrix.find_intersection(2, 1)->note, "(1)");
  EXPECT_EQ(r.matrix.find_intersection(2, 2)->note, "(2)");  // blanks around a footnote are fine
  // A mark right of the last effect column trips an effect the sheet does not have.
  const std::string beyond = std::string(kHeader) + "High level;C-1;N;;S\n";
  try {
    import_csv(beyond, "beyond.csv");
    FAIL() << "a mark under no effect";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues()[0].where, "beyond.csv: line 3, column 5");
    EXPECT_NE(e.issues()[0].what.find("right of the last effect column, under no effect id"), std::string::npos);
  }
}

TEST(GridImport, LongDescriptionsAreTruncatedWithTheFullTextInTheNote) {
  const std::string longtext(95, 'x');
  auto r = import_csv(std::string(kHeader) + longtext + ";C-1;N;\n", "long.csv");
  const Cause& c = r.matrix.causes.at(0);
  EXPECT_EQ(c.description, std::string(80, 'x'));
  EXPECT_NE(c.note.find(longtext), std::string::npos);
  EXPECT_TRUE(has_warning(r, "line 3, column 1", "description of 95 characters truncated to 80"));
}

TEST(GridImport, DuplicateEffectIdsAndUnnumberedIds) {
  auto r = import_csv(
      ";;Open;Close;Vent\n"
      ";;XV-A;XV-B;XV-A\n"
      "Trip;PB;N;S;N\n",
      "ids.csv");
  const Matrix& m = r.matrix;
  ASSERT_EQ(m.effects.size(), 3u);
  EXPECT_EQ(m.effects[0].name, "XV_A");
  EXPECT_EQ(m.effects[2].name, "XV_A_2");
  EXPECT_TRUE(has_warning(r, "line 2, column 3", "numbered by their position")) << warnings_text(r);
  EXPECT_TRUE(has_warning(r, "line 2, column 5", "effect id 'XV-A' repeats line 2"));
  EXPECT_EQ(m.causes[0].name, "PB");
  EXPECT_EQ(m.causes[0].id, 1);
}

TEST(GridImport, CommaSeparatedGridAndForcedLayout) {
  CsvImportOptions opt;
  opt.layout = CsvLayoutKind::Grid;
  const std::string grid = ",,A,B\n,,1,2\nc one,10,N,\"V(3)\"\n";
  // No corner labels and plain numbers as ids: nothing says which axis holds the causes.
  EXPECT_THROW(import_csv(grid, "comma.csv", opt), LoadError);
  opt.orientation = CsvOrientation::CausesAsRows;
  auto r = import_csv(grid, "comma.csv", opt);
  EXPECT_EQ(r.matrix.effects.size(), 2u);
  EXPECT_EQ(r.matrix.causes.at(0).id, 10);
  EXPECT_EQ(r.matrix.causes.at(0).name, "C_10");  // a leading digit gets a letter
  EXPECT_EQ(r.matrix.find_intersection(10, 2)->note, "(3)");
  EXPECT_TRUE(has_warning(r, "line 2", "no maximum override time"));
}

TEST(GridImport, MatrixNameFromTheFileOrTheOption) {
  const std::string grid = std::string(kHeader) + "High level;C-1;N;\n";
  EXPECT_EQ(import_csv(grid, "dir/my-plant.v2.csv").matrix.name, "my_plant_v2");
  EXPECT_EQ(import_csv(grid, "dir/my-plant.v2.csv").matrix.title, "my-plant.v2");
  CsvImportOptions opt;
  opt.matrix_name = "TMA_IS";
  EXPECT_EQ(import_csv(grid, "x.csv", opt).matrix.name, "TMA_IS");
  opt.matrix_name = "NAME;WITH;SEMICOLONS";  // checked by the loader (6.1.2)
  EXPECT_THROW(import_csv(grid, "x.csv", opt), LoadError);
}

TEST(GridImport, MoreThanTheLimitsOf34IsAnError) {
  std::string descriptions = ";", ids = ";";
  for (int i = 1; i <= 129; ++i) {
    descriptions += ";d" + std::to_string(i);
    ids += ";E" + std::to_string(i);
  }
  try {
    import_csv(descriptions + "\n" + ids + "\nc;C1;N\n", "wide.csv");
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues()[0].where, "wide.csv: line 2");
    EXPECT_NE(e.issues()[0].what.find("129 effect columns"), std::string::npos);
  }
  std::string rows = std::string(kHeader);
  for (int i = 1; i <= 129; ++i) rows += "c;C" + std::to_string(i) + ";N;\n";
  EXPECT_THROW(import_csv(rows, "tall.csv"), LoadError);
}

TEST(GridImport, UnreadableGridsAreErrors) {
  EXPECT_THROW(import_csv("just one line\n", "one.csv"), LoadError);
  EXPECT_THROW(import_csv("x;y\n;;\nc;1;N\n", "noids.csv"), LoadError);
  EXPECT_THROW(import_csv(";;A\n;;E1\n", "nocauses.csv"), LoadError);
  EXPECT_THROW(import_csv(";;A\n;;E1\nc;1;\"N\n", "quote.csv"), LoadError);
}

// Never a crash: seeded byte mutations of both layouts either import or throw
// LoadError (run under the sanitizer build as well).
TEST(CsvImportRobustness, MutatedInputsImportOrFailCleanly) {
  const std::string grid = read_text_file(cemv::test::lsst_table(kExternal, "lsst-tma-interlock-table.csv"));
  const std::string records = export_csv(import_csv(grid, "lsst.csv").matrix);
  const std::string alphabet = ";,\"\n\r (1)NSVRX*#-_a9\t\x01\xff";
  std::mt19937 rng(20241121);
  int imported = 0, rejected = 0;
  for (const std::string* base : {&grid, &records}) {
    for (int round = 0; round < 100; ++round) {
      std::string text = *base;
      const int edits = 1 + static_cast<int>(rng() % 6);
      for (int k = 0; k < edits && !text.empty(); ++k) {
        std::size_t at = rng() % text.size();
        char c = alphabet[rng() % alphabet.size()];
        switch (rng() % 3) {
          case 0: text[at] = c; break;
          case 1: text.insert(text.begin() + static_cast<long>(at), c); break;
          default: text.erase(at, 1 + rng() % 40); break;
        }
      }
      try {
        // What import_csv returns went through the JSON loader already.
        import_csv(text, "mutant.csv");
        ++imported;
      } catch (const LoadError& e) {
        EXPECT_FALSE(e.issues().empty());
        ++rejected;
      }
    }
  }
  EXPECT_GT(imported, 0);
  EXPECT_GT(rejected, 0);
}

}  // namespace
}  // namespace cemv::formats
