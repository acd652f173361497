// The layouts the LSST TMA interlock table was actually published in, built from
// the shared table (docs/csv.md "Shape", "Orientation", "Header alignment"):
// each is read with exactly the table's intersections under the right ids and
// descriptions, or refused with a message that names the line. Also --strict
// and the grid export.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <set>
#include <sstream>
#include <tuple>

#include "sheets/csv.hpp"
#include "tests/support/external_tables.hpp"
#include "model/matrix.hpp"
#include "tests/formats/test_csv_support.hpp"

namespace cemv::formats {

using namespace cemv::model;
namespace {

// The published tables, read beside the project (CEMV_LSST_DIR).
const std::filesystem::path kLsst = std::filesystem::path(CEMV_LSST_DIR);

using Table = std::vector<std::vector<std::string>>;

// The shared data beside the checkout (../shared/external), where the issues
// point every test of the published tables.
const std::filesystem::path kShared =
    std::filesystem::path(CEMV_SOURCE_DIR).parent_path() / "shared" / "external";

// The published table split into cells (';', no quoted fields in it).
Table split_table(const std::string& text) {
  Table t;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::vector<std::string> row;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= line.size(); ++i)
      if (i == line.size() || line[i] == ';') {
        row.push_back(line.substr(start, i - start));
        start = i + 1;
      }
    t.push_back(row);
  }
  return t;
}

Table read_table(const std::string& file) {
  return split_table(read_text_file(cemv::test::lsst_table(kLsst, file)));
}
Table read_shared_table(const std::string& file) { return split_table(read_text_file(kShared / file)); }

std::string join(const Table& t) {
  std::string s;
  for (const auto& row : t) {
    for (std::size_t i = 0; i < row.size(); ++i) s += (i ? ";" : "") + row[i];
    s += "\n";
  }
  return s;
}

// Effects as rows, causes as columns: the corner now says 'Causes/Detection'
// left of the cause descriptions and 'Effects/Actuation' above the effect
// descriptions. The trailing empty column of the table becomes nothing.
Table transpose(const Table& t) {
  std::size_t width = 0;
  for (const auto& r : t) width = std::max(width, r.size());
  Table out;
  for (std::size_t c = 0; c + 1 < width; ++c) {
    std::vector<std::string> row;
    for (const auto& r : t) row.push_back(c < r.size() ? r[c] : "");
    out.push_back(row);
  }
  return out;
}

using Key = std::tuple<std::string, std::string, IntersectionType, std::string>;

// Intersections by the names of their cause and effect (names are the sheet's
// ids), so that two readings compare whatever the orientation.
std::set<Key> intersections_by_name(const Matrix& m) {
  std::set<Key> keys;
  for (const auto& x : m.intersections)
    keys.insert({m.find_cause(x.cause)->name, m.find_effect(x.effect)->name, x.type, x.note});
  return keys;
}

std::set<std::tuple<int, int, IntersectionType>> intersections_by_id(const Matrix& m) {
  std::set<std::tuple<int, int, IntersectionType>> keys;
  for (const auto& x : m.intersections) keys.insert({x.cause, x.effect, x.type});
  return keys;
}

bool has_warning(const CsvImportResult& r, const std::string& where, const std::string& what) {
  for (const auto& w : r.warnings)
    if (w.where.find(where) != std::string::npos && w.what.find(what) != std::string::npos) return true;
  return false;
}

// The message of the LoadError that importing text throws ("" when none).
std::string refusal(const std::string& text, const std::string& name, CsvImportOptions opt = {}) {
  try {
    import_csv(text, name, opt);
  } catch (const LoadError& e) {
    return e.issues().front().str();
  }
  return "";
}

// The same reading as the table as published: every cause and effect with its
// description, and the same intersections under the same ids.
void expect_same_reading(const Matrix& got, const Matrix& published, std::size_t intersections) {
  EXPECT_EQ(got.intersections.size(), intersections);
  EXPECT_EQ(intersections_by_name(got), intersections_by_name(published));
  EXPECT_EQ(intersections_by_id(got), intersections_by_id(published));
  ASSERT_EQ(got.causes.size(), published.causes.size());
  ASSERT_EQ(got.effects.size(), published.effects.size());
  for (const auto& c : published.causes) {
    const Cause* g = got.find_cause(c.id);
    ASSERT_NE(g, nullptr) << c.name;
    EXPECT_EQ(g->name, c.name);
    EXPECT_EQ(g->description, c.description) << c.name;
  }
  for (const auto& e : published.effects) {
    const Effect* g = got.find_effect(e.id);
    ASSERT_NE(g, nullptr) << e.name;
    EXPECT_EQ(g->name, e.name);
    EXPECT_EQ(g->description, e.description) << e.name;
  }
}

// Both published versions: today's table (102 intersections) and the one of
// 2023-10-05 (103: TMA-D-17 also trips TMA-A-5).
class LsstLayouts : public ::testing::TestWithParam<std::pair<const char*, std::size_t>> {
 protected:
  void SetUp() override {
    table_ = read_table(GetParam().first);
    published_ = import_csv(join(table_), "lsst.csv").matrix;
    ASSERT_EQ(published_.intersections.size(), GetParam().second);
  }
  std::size_t count() const { return GetParam().second; }
  Table table_;
  Matrix published_;
};

TEST_P(LsstLayouts, TransposedIsReadFromTheCornerLabelsAndIdPatterns) {
  const auto r = import_csv(join(transpose(table_)), "transposed.csv");
  EXPECT_EQ(r.orientation, CsvOrientation::EffectsAsRows);
  expect_same_reading(r.matrix, published_, count());
  EXPECT_NE(r.summary.find("read 36 causes (columns 3-38, ids in row 2), 17 effects (rows 3-19, ids in "
                           "column 2), " + std::to_string(count()) + " intersections; orientation "
                           "effects-as-rows from the corner labels ('Causes/Detection' in line 1, column 2; "
                           "'Effects/Actuation' in line 2, column 1) and the id patterns"),
            std::string::npos)
      << r.summary;
  // Defects are reported where they are in this file: TMA-D-40 repeats in column 35.
  EXPECT_TRUE(has_warning(r, "line 2, column 35", "cause id 'TMA-D-40' repeats line 2"));
}

TEST_P(LsstLayouts, OrientationOptionReadsTheTransposedTable) {
  CsvImportOptions opt;
  opt.orientation = CsvOrientation::EffectsAsRows;
  const auto r = import_csv(join(transpose(table_)), "transposed.csv", opt);
  expect_same_reading(r.matrix, published_, count());
  EXPECT_NE(r.summary.find("orientation effects-as-rows as given by --orientation"), std::string::npos);
  // Forced the other way, against the corner labels: refused, since every
  // cause would be read as an effect.
  opt.orientation = CsvOrientation::CausesAsRows;
  const std::string wrong = refusal(join(transpose(table_)), "transposed.csv", opt);
  EXPECT_NE(wrong.find("transposed.csv: line 2: the corner labels ('Causes/Detection' in line 1, column 2; "
                       "'Effects/Actuation' in line 2, column 1) say effects-as-rows; --orientation "
                       "causes-as-rows would read every cause as an effect"),
            std::string::npos)
      << wrong;
  // Against the id patterns alone, a given orientation is read, with a warning
  // (an error under --strict): ids are only letters.
  Table unlabelled = transpose(table_);
  unlabelled[0][1] = "";
  unlabelled[1][0] = "";
  const auto r2 = import_csv(join(unlabelled), "unlabelled.csv", opt);
  EXPECT_TRUE(has_warning(r2, "line 2", "say effects-as-rows; read as causes-as-rows as --orientation says"));
  opt.strict = true;
  EXPECT_NE(refusal(join(unlabelled), "unlabelled.csv", opt).find("--orientation"), std::string::npos);
}

// The layout the table was first published in (2023-10-05, before it was
// transposed): effects as rows behind an empty first row and column, a blank
// in B2, the corner labels 'Causes/Detection' (C2) and 'Effects/Actuation'
// (B3) one cell apart, and a lone `N` between them in C3. Rebuilt here from
// the shared table (which carries no licence, so the project keeps no copy of
// this layout): the header block is found from the corner labels and the id
// patterns, so the table reads right whether the orientation is found or given.
Table first_published(const Table& published) {
  Table t = transpose(published);
  t[0][0] = " ";
  t[1][1] = "N";
  Table out;
  const std::size_t width = t[0].size() + 1;
  out.push_back(std::vector<std::string>(width, ""));
  for (const auto& row : t) {
    std::vector<std::string> padded{""};
    padded.insert(padded.end(), row.begin(), row.end());
    out.push_back(padded);
  }
  out.push_back(std::vector<std::string>(width, ""));
  return out;
}

TEST_P(LsstLayouts, FirstPublishedLayoutIsReadRightInEitherWay) {
  // From the shared table itself, as the issue asks (../shared/external).
  const Table shared = read_shared_table(GetParam().first);
  ASSERT_EQ(join(shared), join(table_));
  const std::string text = join(first_published(shared));
  ASSERT_EQ(text.rfind(std::string(38, ';') + "\n; ;Causes/Detection;Azimuth axis CW", 0), 0u) << text.substr(0, 80);
  const std::string expected_summary =
      "read 36 causes (columns 4-39, ids in row 3), 17 effects (rows 4-20, ids in column 3), " +
      std::to_string(count()) + " intersections; orientation effects-as-rows ";
  const auto found = import_csv(text, "first.csv");
  EXPECT_EQ(found.orientation, CsvOrientation::EffectsAsRows);
  expect_same_reading(found.matrix, published_, count());
  EXPECT_NE(found.summary.find(expected_summary + "from the corner labels ('Causes/Detection' in line 2, "
                               "column 3; 'Effects/Actuation' in line 3, column 2) and the id patterns"),
            std::string::npos)
      << found.summary;
  CsvImportOptions opt;
  opt.orientation = CsvOrientation::EffectsAsRows;
  const auto given = import_csv(text, "first.csv", opt);
  expect_same_reading(given.matrix, published_, count());
  EXPECT_NE(given.summary.find(expected_summary + "as given by --orientation"), std::string::npos) << given.summary;
  for (const auto& w : given.warnings) EXPECT_EQ(w.what.find("stray value"), std::string::npos) << w.str();
  opt.orientation = CsvOrientation::CausesAsRows;
  EXPECT_NE(refusal(text, "first.csv", opt).find("first.csv: line 3: the corner labels"), std::string::npos);
}

TEST_P(LsstLayouts, CornerBlockIsNeverData) {
  // The transposed table with a third header row and label column, and a lone
  // `N` in the corner, where a reader with a fixed corner would find a 104th intersection.
  Table t = transpose(table_);
  Table corner;
  for (std::size_t r = 0; r < t.size(); ++r) {
    std::vector<std::string> row(t[r].begin(), t[r].begin() + 2);
    row.push_back(r == 1 ? t[r][1] : "");
    row.insert(row.end(), t[r].begin() + 2, t[r].end());
    if (r == 1) row[1] = "";
    corner.push_back(row);
    if (r == 1) {
      std::vector<std::string> labels(row.size(), "");
      labels[1] = "";
      labels[2] = "N";
      corner.push_back(labels);
    }
  }
  corner[0][2] = "";
  corner[1][2] = "Causes/Detection";
  corner[1][0] = "";
  corner[2][1] = "Effects/Actuation";
  const auto r = import_csv(join(corner), "corner.csv");
  EXPECT_EQ(r.orientation, CsvOrientation::EffectsAsRows);
  expect_same_reading(r.matrix, published_, count());
  EXPECT_NE(r.summary.find("(columns 4-39, ids in row 2), 17 effects (rows 4-20"), std::string::npos) << r.summary;
}

TEST_P(LsstLayouts, DescriptionRowOneFieldShortIsRefused) {
  Table t = table_;
  t[0].erase(t[0].begin());  // the published row 1 without its leading empty field
  const std::string msg = refusal(join(t), "short.csv");
  EXPECT_NE(msg.find("short.csv: line 1: the description row (line 1, 19 fields"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the id row (line 2, 20 fields"), std::string::npos) << msg;
  EXPECT_NE(msg.find("the descriptions would be misaligned"), std::string::npos) << msg;
  EXPECT_NE(msg.find("id 'TMA-A-1' under 'STO Elevation Drives"), std::string::npos) << msg;
  // One field long, with text at its end: refused the same way.
  t = table_;
  t[0].insert(t[0].begin(), "");
  EXPECT_NE(refusal(join(t), "long.csv").find("line 1: the description row (line 1, 21 fields"), std::string::npos);
  // The same for the cause descriptions over the cause ids of the transposed table.
  t = transpose(table_);
  t[0].erase(t[0].begin());
  const std::string transposed = refusal(join(t), "short-transposed.csv");
  EXPECT_NE(transposed.find("line 1: the description row (line 1, 37 fields"), std::string::npos) << transposed;
  EXPECT_NE(transposed.find("id 'TMA-D-1' under 'Azimuth axis CCW"), std::string::npos) << transposed;
}

TEST_P(LsstLayouts, PaddingIsSkippedAndSaidInTheSummary) {
  Table t;
  t.push_back({});
  t.push_back({"", "", ""});
  for (const auto& row : table_) {
    std::vector<std::string> padded{"", ""};
    padded.insert(padded.end(), row.begin(), row.end());
    t.push_back(padded);
  }
  const auto r = import_csv(join(t), "padded.csv");
  expect_same_reading(r.matrix, published_, count());
  EXPECT_NE(r.summary.find("read 36 causes (rows 5-40, ids in column 4), 17 effects (columns 5-21, ids in row 4)"),
            std::string::npos)
      << r.summary;
  EXPECT_NE(r.summary.find("skipped 2 empty rows above and 2 empty columns left of the grid"), std::string::npos);
  EXPECT_TRUE(has_warning(r, "line 37, column 4", "cause id 'TMA-D-40' repeats line 27"));
}

TEST_P(LsstLayouts, TwoHeaderRowsAboveTheIdsGoToTagAndNote) {
  Table t = table_;
  std::vector<std::string> tags{"", "Output tag"}, actions{"", "Action"};
  for (std::size_t c = 2; c < table_[1].size(); ++c) {
    const std::string id = table_[1][c];
    tags.push_back(id.empty() ? "" : "XS_" + id.substr(4, 1) + id.substr(6));
    actions.push_back(id.empty() ? "" : "trip");
  }
  t.insert(t.begin() + 1, actions);
  t.insert(t.begin() + 1, tags);
  const auto r = import_csv(join(t), "headers.csv");
  expect_same_reading(r.matrix, published_, count());
  const Effect* e1 = r.matrix.find_effect(1);
  ASSERT_NE(e1, nullptr);
  EXPECT_EQ(e1->tags.at(0).name, "XS_A1");
  EXPECT_NE(e1->note.find("Action: trip"), std::string::npos) << e1->note;
  EXPECT_NE(r.summary.find("ids in row 4"), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("header row 2 'Output tag' read as the effect tags"), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("header row 3 'Action' kept in the effect notes"), std::string::npos) << r.summary;
}

INSTANTIATE_TEST_SUITE_P(BothVersions, LsstLayouts,
                         ::testing::Values(std::pair{"lsst-tma-interlock-table.csv", std::size_t{102}},
                                           std::pair{"lsst-tma-interlock-table-2023-10-05.csv",
                                                     std::size_t{103}}));

TEST(GridOrientation, ConflictingOrMissingEvidenceIsRefused) {
  // The corner labels say causes are rows; the ids say the rows are actuations.
  const std::string conflict =
      ";Effects;Close;Stop\n"
      "Causes;;D-1;D-2\n"
      "Level high;A-1;N;S\n";
  const std::string msg = refusal(conflict, "conflict.csv");
  EXPECT_NE(msg.find("conflict.csv: line 2: cannot tell whether the causes are the rows or the columns: "
                     "the evidence conflicts: the corner labels ('Effects' in line 1, column 2; 'Causes' "
                     "in line 2, column 1) say causes-as-rows; the id patterns"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("give --orientation"), std::string::npos);
  const std::string none = ";;Close;Stop\n;;1;2\nLevel high;7;N;S\n";
  EXPECT_NE(refusal(none, "none.csv").find("none.csv: line 2: cannot tell"), std::string::npos);
  CsvImportOptions opt;
  opt.orientation = CsvOrientation::EffectsAsRows;
  const auto r = import_csv(none, "none.csv", opt);
  EXPECT_EQ(r.matrix.causes.size(), 2u);  // the columns
  EXPECT_EQ(r.matrix.effects.size(), 1u);
  ASSERT_NE(r.matrix.find_intersection(2, 7), nullptr);
  EXPECT_EQ(r.matrix.find_intersection(2, 7)->type, IntersectionType::S);
}

TEST(GridStrict, PassesACleanGridAndRefusesTheLsstTable) {
  CsvImportOptions strict;
  strict.strict = true;
  const std::string clean =
      ";Effects;Close inlet;Stop pump\n"
      "Causes;;XV-1;P-2\n"
      "Level high-high;LT-1;S;N\n"
      "Emergency stop;HS-2;S;S\n";
  const auto r = import_csv(clean, "clean.csv", strict);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.matrix.intersections.size(), 4u);
  try {
    import_csv(read_text_file(cemv::test::lsst_table(kLsst, "lsst-tma-interlock-table.csv")), "lsst.csv", strict);
    FAIL() << "the LSST table has warnings";
  } catch (const LoadError& e) {
    const auto& issues = e.issues();
    ASSERT_GT(issues.size(), 1u);
    EXPECT_NE(issues.back().what.find("are an error under --strict"), std::string::npos);
    bool duplicate = false;
    for (const auto& i : issues) duplicate = duplicate || i.str().find("line 35, column 2: cause id 'TMA-D-40'") != std::string::npos;
    EXPECT_TRUE(duplicate);
  }
}

// Every field set, in both orientations: the grid gives back the same intersections.
TEST(GridExport, RoundTripKeepsTheIntersections) {
  const Matrix m = model::testing::every_field_matrix();
  for (auto o : {CsvOrientation::CausesAsRows, CsvOrientation::EffectsAsRows}) {
    const std::string grid = export_csv_grid(m, o);
    const auto r = import_csv(grid, "exported.csv");
    EXPECT_EQ(r.orientation, o) << grid;
    EXPECT_EQ(intersections_by_id(r.matrix), intersections_by_id(m)) << grid;
    // Descriptions come back trimmed, as the grid import reads every cell.
    EXPECT_EQ(r.matrix.find_cause(2)->description, "leading and trailing blanks");
    EXPECT_EQ(r.matrix.find_effect(1)->description, m.find_effect(1)->description);
    // Notes travel as footnotes with a legend: a note that already reads like a
    // footnote keeps its number, any other gets the next free one.
    EXPECT_EQ(r.matrix.find_intersection(1, 1)->note, m.find_intersection(1, 1)->note);
    EXPECT_EQ(r.matrix.find_intersection(2, 5)->note, "(3) note only, not processed");
    EXPECT_EQ(r.matrix.find_intersection(4, 2)->note, "(2)");  // a bare footnote, no legend row
    // Export, import, export again: the same sheet (once the blanks are trimmed).
    const std::string again = export_csv_grid(r.matrix, o);
    EXPECT_EQ(export_csv_grid(import_csv(again, "again.csv").matrix, o), again);
  }
  EXPECT_EQ(export_csv_grid(m).substr(0, 17), ",Effects,\"Close i");
}

// Never a crash: seeded mutations of the transposed table and of an exported
// grid either import or throw LoadError (run under the sanitizer build as well).
TEST(GridRobustness, MutatedLayoutsImportOrFailCleanly) {
  const std::string transposed = join(transpose(read_table("lsst-tma-interlock-table.csv")));
  const std::string exported =
      export_csv_grid(model::testing::every_field_matrix(), CsvOrientation::EffectsAsRows);
  const std::string alphabet = ";,\"\n\r (1)NSVRX*#-_a9\tCausesEffects/";
  std::mt19937 rng(20261123);
  int imported = 0, rejected = 0;
  for (const std::string* base : {&transposed, &exported}) {
    for (int round = 0; round < 150; ++round) {
      std::string text = *base;
      const int edits = 1 + static_cast<int>(rng() % 6);
      for (int k = 0; k < edits && !text.empty(); ++k) {
        const std::size_t at = rng() % text.size();
        const char c = alphabet[rng() % alphabet.size()];
        switch (rng() % 3) {
          case 0: text[at] = c; break;
          case 1: text.insert(text.begin() + static_cast<long>(at), c); break;
          default: text.erase(at, 1 + rng() % 40); break;
        }
      }
      try {
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
