// The stacked effect header of contractor sheets (docs/csv.md "Stacked effect
// header"): rows of descriptions, actions, output tags and SIL above the
// effect columns, in any order, two to four of them, labelled or not, with a
// CAUSES/EFFECTS banner or none, and the causes' attribute headers spelled as
// contractors do ("Tag No.", "Instrument Tag", "Set point", "Trip setting",
// "EU", "Vote"), on a row of their own or sharing the last header row. Seeded
// variants: each is read with exactly the generated effects, or refused with
// its header cell named; none is read as another matrix.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "sheets/csv.hpp"
#include "sheets/csv_grid.hpp"

namespace cemv::formats {
namespace {

using model::Matrix;

enum class Row { Description, Action, Tag, Sil };

struct EffectSpec {
  std::string tag, action, description;
  int sil = 0;
};

struct Generated {
  std::string csv;
  std::vector<EffectSpec> effects;
  std::vector<Row> rows;  // the effect header rows, top to bottom
  std::vector<bool> labelled;
  int causes = 0;
  int intersections = 0;
  int first_header_line = 0;  // the line of the first effect header row
  std::string describe;       // the variant, for failure messages
};

template <typename T>
const T& pick(std::mt19937& rng, const std::vector<T>& v) {
  return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)];
}
bool coin(std::mt19937& rng, double p = 0.5) { return std::bernoulli_distribution(p)(rng); }

const std::vector<std::string> kDescriptions{"Close feed drum inlet valve", "Stop feed pump", "Open blowdown valve",
                                             "Isolate fuel gas supply", "Trip compressor motor",
                                             "Depressurise separator", "Close export line valve",
                                             "Stop injection pump 2", "Open flare header valve"};
const std::vector<std::string> kActions{"CLOSE", "OPEN", "STOP", "TRIP", "START", "DE-ENERGISE", "Close", "Shut",
                                        "De-energize", "STOPPED"};
const std::vector<std::string> kPrefixes{"XV", "P", "BDV", "SDV", "ESDV", "M", "HV"};

std::string label_of(Row r, std::mt19937& rng) {
  switch (r) {
    case Row::Description: return pick(rng, std::vector<std::string>{"Description", "Effect description", "Service"});
    case Row::Action: return pick(rng, std::vector<std::string>{"Action", "Final action", "Actions"});
    case Row::Tag:
      return pick(rng, std::vector<std::string>{"Tag No.", "Instrument Tag", "Output tag", "Final element tag"});
    case Row::Sil: return pick(rng, std::vector<std::string>{"SIL", "SIL rating", "Required SIL"});
  }
  return "";
}

std::string join(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
  return line + "\n";
}

// The header rows: the output tags and 1 to 3 of the others, in a random order.
std::vector<Row> header_rows(std::mt19937& rng) {
  std::vector<Row> rows{Row::Tag};
  for (Row r : {Row::Description, Row::Action, Row::Sil})
    if (coin(rng, 0.6)) rows.push_back(r);
  if (rows.size() == 1) rows.push_back(pick(rng, std::vector<Row>{Row::Description, Row::Action, Row::Sil}));
  std::shuffle(rows.begin(), rows.end(), rng);
  return rows;
}

// transposable: no banner, SIL as `SIL n`, the causes' headers on a row of
// their own (what the transposed sheet still says without row labels).
Generated generate(unsigned seed, std::vector<Row> rows = {}, bool transposable = false) {
  std::mt19937 rng(seed);
  Generated g;
  if (rows.empty()) rows = header_rows(rng);
  g.rows = rows;
  const int effects = std::uniform_int_distribution<int>(3, 8)(rng);
  g.causes = std::uniform_int_distribution<int>(5, 9)(rng);
  std::vector<int> numbers;
  for (int k = 0; k < effects; ++k) numbers.push_back(300 + 7 * k + std::uniform_int_distribution<int>(0, 6)(rng));
  for (int k = 0; k < effects; ++k) {
    EffectSpec e;
    e.tag = pick(rng, kPrefixes) + (coin(rng, 0.8) ? "-" : "_") + std::to_string(numbers[k]) + (coin(rng, 0.2) ? "A" : "");
    e.action = pick(rng, kActions);
    e.description = kDescriptions[static_cast<std::size_t>(k) % kDescriptions.size()];
    e.sil = std::uniform_int_distribution<int>(0, 3)(rng);
    g.effects.push_back(e);
  }
  const bool banner = coin(rng) && !transposable;
  const bool shared = coin(rng, 0.4) && !transposable;  // the causes' headers share the last effect header row
  const bool bare_sil = coin(rng, 0.3) && !transposable;
  const std::vector<std::string> cause_headers{
      pick(rng, std::vector<std::string>{"Item", "Item No.", "No."}),
      pick(rng, std::vector<std::string>{"Description", "Cause description", "Service"}),
      pick(rng, std::vector<std::string>{"Tag No.", "Instrument Tag", "Tag"}),
      pick(rng, std::vector<std::string>{"Set point", "Trip setting", "Setpoint"}),
      pick(rng, std::vector<std::string>{"EU", "Unit", "Units"}),
      pick(rng, std::vector<std::string>{"Vote", "Voting"}),
      "SIL"};
  const std::size_t labels = cause_headers.size();
  int line = 0;
  if (banner) {
    std::vector<std::string> f(labels + static_cast<std::size_t>(effects));
    f[0] = "CAUSES";
    f[labels] = "EFFECTS";
    g.csv += join(f);
    ++line;
  }
  g.first_header_line = line + 1;
  g.describe = std::string(banner ? "banner" : "no banner") + (shared ? ", shared header row" : "") + ", rows:";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const bool last = k + 1 == rows.size();
    const bool label = !(shared && last) && coin(rng, 0.6);
    g.labelled.push_back(label);
    std::vector<std::string> f(labels);
    if (shared && last) f = cause_headers;
    const std::string l = label ? label_of(rows[k], rng) : "";
    if (label) f[0] = l;
    for (const EffectSpec& e : g.effects) {
      switch (rows[k]) {
        case Row::Description: f.push_back(e.description); break;
        case Row::Action: f.push_back(e.action); break;
        case Row::Tag: f.push_back(e.tag); break;
        case Row::Sil: f.push_back(label && bare_sil ? std::to_string(e.sil) : "SIL " + std::to_string(e.sil)); break;
      }
    }
    const char* names[] = {"description", "action", "tag", "SIL"};
    g.describe += std::string(" ") + names[static_cast<int>(rows[k])] + (label ? " '" + l + "'" : "");
    g.csv += join(f);
    ++line;
  }
  if (!shared) g.csv += join(cause_headers);
  for (int c = 1; c <= g.causes; ++c) {
    const bool high = coin(rng);
    std::vector<std::string> f{std::to_string(c), std::string("Feed drum pressure ") + (high ? "high-high" : "low-low"),
                               "PT-" + std::to_string(100 + c), std::to_string(10 + c), "barg", "1oo1",
                               std::to_string(c % 3)};
    for (int e = 0; e < effects; ++e) {
      const int r = std::uniform_int_distribution<int>(0, 3)(rng);
      f.push_back(r == 0 ? "S" : r == 1 ? "N" : "");
      g.intersections += r <= 1 ? 1 : 0;
    }
    g.csv += join(f);
  }
  return g;
}

CsvImportResult import(const std::string& text, std::optional<SheetLayout> layout = std::nullopt) {
  CsvImportOptions opt;
  opt.sheet_layout = std::move(layout);
  return import_csv(text, "contractor.csv", opt);
}

std::string refusal(const std::string& text, std::optional<SheetLayout> layout = std::nullopt) {
  try {
    import(text, std::move(layout));
  } catch (const LoadError& e) {
    std::string all;
    for (const auto& i : e.issues()) all += i.str() + "\n";
    return all;
  }
  return "";
}

bool has(const std::vector<Row>& rows, Row r) { return std::find(rows.begin(), rows.end(), r) != rows.end(); }

// The effects read are exactly the generated ones, in column order.
void expect_effects(const Matrix& m, const Generated& g) {
  ASSERT_EQ(m.effects.size(), g.effects.size()) << g.describe << "\n" << g.csv;
  ASSERT_EQ(m.causes.size(), static_cast<std::size_t>(g.causes)) << g.describe;
  EXPECT_EQ(m.intersections.size(), static_cast<std::size_t>(g.intersections)) << g.describe;
  for (std::size_t k = 0; k < g.effects.size(); ++k) {
    const EffectSpec& want = g.effects[k];
    const model::Effect& got = m.effects[k];
    ASSERT_EQ(got.tags.size(), 1u) << g.describe;
    EXPECT_EQ(got.tags[0].name, want.tag) << g.describe << "\n" << g.csv;
    EXPECT_EQ(got.name, sanitize_identifier(want.tag, 32)) << g.describe;
    EXPECT_EQ(got.sil, has(g.rows, Row::Sil) ? want.sil : 0) << g.describe;
    EXPECT_EQ(got.description, has(g.rows, Row::Description) ? want.description : "") << g.describe;
    if (has(g.rows, Row::Action))
      EXPECT_NE(got.note.find(": " + want.action), std::string::npos) << got.note << "\n" << g.describe;
    else
      EXPECT_EQ(got.note, "sheet id: " + want.tag) << g.describe;
  }
}

// The five header variants of issue 37, each written out.
TEST(StackedHeader, TheFiveContractorVariantsReadRight) {
  const std::vector<std::vector<Row>> variants{
      {Row::Description, Row::Action, Row::Tag, Row::Sil},
      {Row::Sil, Row::Tag, Row::Action, Row::Description},
      {Row::Tag, Row::Description, Row::Sil},
      {Row::Action, Row::Tag},
      {Row::Description, Row::Tag, Row::Action, Row::Sil},
  };
  for (std::size_t v = 0; v < variants.size(); ++v)
    for (unsigned seed = 1; seed <= 8; ++seed) {
      const Generated g = generate(static_cast<unsigned>(100 * v) + seed, variants[v]);
      CsvImportResult r;
      try {
        r = import(g.csv);
      } catch (const LoadError& e) {
        ADD_FAILURE() << g.describe << " refused: " << e.what() << "\n" << g.csv;
        continue;
      }
      expect_effects(r.matrix, g);
    }
}

// The five variants as docs/csv.md "Stacked effect header" shows them
// (tests/sheets/stacked_cases/, also read as XLSX and ODS by
// stacked_workbooks.sh).
TEST(StackedHeader, TheDocumentedVariantsReadAsDocumented) {
  struct Want {
    const char* file;
    std::vector<EffectSpec> effects;  // tag, action, description, SIL
  };
  const std::vector<Want> wants{
      {"1-banner-labelled.csv", {{"XV-301", "CLOSE", "Close inlet valve", 2}, {"P-302", "STOP", "Stop pump", 1}}},
      {"2-unlabelled.csv", {{"XV-301", "OPEN", "Open vent", 2}, {"P-302", "TRIP", "Trip pump", 1}}},
      {"3-shared-row.csv", {{"XV-301", "", "Close inlet valve", 2}, {"P_302", "", "Stop pump", 1}}},
      {"4-two-rows.csv", {{"SDV-310", "DE-ENERGISE", "", 0}, {"XV-311A", "CLOSE", "", 0}}},
      {"5-other-spellings.csv", {{"ESDV-401", "Shut", "Isolate fuel gas", 3}, {"P-402", "Stop", "Stop pump", 2}}},
  };
  for (const Want& w : wants) {
    const std::string path = std::string(CEMV_SOURCE_DIR) + "/tests/sheets/stacked_cases/" + w.file;
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CsvImportResult r;
    try {
      r = import(text);
    } catch (const LoadError& e) {
      ADD_FAILURE() << w.file << " refused: " << e.what();
      continue;
    }
    const Matrix& m = r.matrix;
    ASSERT_EQ(m.causes.size(), 3u) << w.file;
    ASSERT_EQ(m.effects.size(), w.effects.size()) << w.file;
    EXPECT_EQ(m.intersections.size(), 5u) << w.file;
    EXPECT_EQ(m.causes[0].tags.at(0).name, "PT-101") << w.file;
    ASSERT_TRUE(m.causes[0].analog.has_value()) << w.file;
    EXPECT_EQ(m.causes[0].analog->limit, 45.0f) << w.file;
    for (std::size_t k = 0; k < w.effects.size(); ++k) {
      const auto& want = w.effects[k];
      const model::Effect& got = m.effects[k];
      EXPECT_EQ(got.tags.at(0).name, want.tag) << w.file;
      EXPECT_EQ(got.name, sanitize_identifier(want.tag, 32)) << w.file;
      EXPECT_EQ(got.sil, want.sil) << w.file;
      EXPECT_EQ(got.description, want.description) << w.file;
      if (!want.action.empty()) {
        EXPECT_NE(got.note.find(": " + want.action), std::string::npos) << got.note;
      }
    }
  }
}

TEST(StackedHeader, SeededVariantsReadRight) {
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const Generated g = generate(seed);
    CsvImportResult r;
    try {
      r = import(g.csv);
    } catch (const LoadError& e) {
      ADD_FAILURE() << "seed " << seed << " (" << g.describe << ") refused: " << e.what() << "\n" << g.csv;
      continue;
    }
    expect_effects(r.matrix, g);
  }
}

// The sheet with rows and columns swapped: the effects on the rows, their
// tag, action, SIL and description in label columns.
std::string transposed(const std::string& csv) {
  std::vector<std::vector<std::string>> cells;
  std::size_t width = 0;
  std::size_t start = 0;
  while (start < csv.size()) {
    const std::size_t end = csv.find('\n', start);
    std::vector<std::string> row;
    std::string cell;
    for (char ch : csv.substr(start, end - start) + ",") {
      if (ch == ',') row.push_back(cell), cell.clear();
      else cell += ch;
    }
    width = std::max(width, row.size());
    cells.push_back(row);
    start = end + 1;
  }
  std::string out;
  for (std::size_t c = 0; c < width; ++c) {
    std::vector<std::string> row;
    for (const auto& r : cells) row.push_back(c < r.size() ? r[c] : "");
    out += join(row);
  }
  return out;
}

TEST(StackedHeader, TransposedVariantsReadRight) {
  for (unsigned seed = 1; seed <= 60; ++seed) {
    const Generated g = generate(1000 + seed, {}, true);
    CsvImportResult r;
    try {
      r = import(transposed(g.csv));
    } catch (const LoadError& e) {
      ADD_FAILURE() << "seed " << seed << " (" << g.describe << ") refused: " << e.what() << "\n" << transposed(g.csv);
      continue;
    }
    EXPECT_EQ(r.orientation, CsvOrientation::EffectsAsRows) << g.describe;
    expect_effects(r.matrix, g);
  }
}

// Without a tag row, a stacked header is refused at its first row, every
// seed: never an effect named after its SIL, action or description.
TEST(StackedHeader, SeededVariantsWithoutTagsAreRefused) {
  for (unsigned seed = 1; seed <= 60; ++seed) {
    std::mt19937 rng(seed);
    std::vector<Row> rows{Row::Description};
    rows.push_back(coin(rng) ? Row::Action : Row::Sil);
    if (coin(rng)) rows.push_back(rows.back() == Row::Action ? Row::Sil : Row::Action);
    std::shuffle(rows.begin(), rows.end(), rng);
    const Generated g = generate(2000 + seed, rows);
    const std::string all = refusal(g.csv);
    // At the first value of the first header row (column 8, or further right
    // when the first effects are never marked).
    const std::regex place("^contractor\\.csv: line " + std::to_string(g.first_header_line) +
                           ", column [0-9]+: no row holds the tags or ids of the elements on the columns");
    EXPECT_TRUE(std::regex_search(all, place)) << "seed " << seed << " (" << g.describe << "): " << all << "\n" << g.csv;
  }
}

// The summary names each header row and why it was read so.
TEST(StackedHeader, TheSummaryGivesTheEvidence) {
  const Generated g = generate(7, {Row::Sil, Row::Action, Row::Tag, Row::Description});
  const auto r = import(g.csv);
  const std::string first = "header row " + std::to_string(g.first_header_line);
  EXPECT_NE(r.summary.find(first), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("read as the effect SIL (" + std::string(g.labelled[0] ? "its label and " : "") + "SIL levels"),
            std::string::npos)
      << r.summary;
  EXPECT_NE(r.summary.find("read as the effect tags ("), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("tag-shaped values '" + g.effects[0].tag + "'"), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("no id row: the tags name the elements on the columns"), std::string::npos) << r.summary;
  EXPECT_NE(r.summary.find("action verbs '" + g.effects[0].action + "'"), std::string::npos) << r.summary;
}

// What cannot be told is refused at the header cell, the candidates named.
TEST(StackedHeader, TwoTagRowsAreRefusedNamingBoth) {
  const std::string csv =
      ",,,E-01,E-02,E-03\n"
      ",,,Close inlet valve,Stop feed pump,Open vent\n"
      ",,,XV-301,P-302,XV-303\n"
      "Item,Description,Tag No.,,,\n"
      "1,Pressure high-high,PT-101,S,N,\n"
      "2,Level low-low,LT-102,,N,S\n";
  const std::string all = refusal(csv);
  EXPECT_NE(all.find("contractor.csv: line 1, column 4: two or more header rows could each be the tag row: header "
                     "row 1 (tag-shaped values 'E-01', 'E-02', 'E-03'); header row 3 (tag-shaped values 'XV-301', "
                     "'P-302', 'XV-303')"),
            std::string::npos)
      << all;
  // Labelled, the tag row is the tag row, and the other the ids.
  std::string labelled = csv;
  labelled.insert(labelled.find(",,,XV-301"), "Tag No.");
  const auto r = import(labelled);
  ASSERT_EQ(r.matrix.effects.size(), 3u);
  EXPECT_EQ(r.matrix.effects[1].name, "E_02");
  EXPECT_EQ(r.matrix.effects[1].tags[0].name, "P-302");
  EXPECT_EQ(r.matrix.effects[1].description, "Stop feed pump");
}

TEST(StackedHeader, AStackedHeaderWithoutTagsOrIdsIsRefused) {
  std::string csv =
      ",,Close inlet valve,Stop feed pump\n"
      ",,CLOSE,STOP\n"
      ",,SIL 2,SIL 1\n"
      "Item,Description,,\n"
      "1,Pressure high-high,S,N\n"
      "2,Level low-low,,N\n";
  const std::string all = refusal(csv);
  EXPECT_NE(all.find("contractor.csv: line 1, column 3: no row holds the tags or ids of the elements on the columns"),
            std::string::npos)
      << all;
}

TEST(StackedHeader, ALabelAgainstItsValuesIsRefused) {
  std::string csv =
      ",,,Close inlet valve,Stop feed pump\n"
      "SIL,,,XV-301,P-302\n"
      "Item,Description,Tag No.,,\n"
      "1,Pressure high-high,PT-101,S,N\n"
      "2,Level low-low,LT-102,,N\n";
  const std::string all = refusal(csv);
  EXPECT_NE(all.find("contractor.csv: line 2, column 4: header row 2 is labelled 'SIL' (sil) but holds tag-shaped "
                     "values 'XV-301', 'P-302'"),
            std::string::npos)
      << all;
}

TEST(StackedHeader, BareRepeatedSmallNumbersWithoutALabelAreRefused) {
  std::string csv =
      ",,,Close inlet valve,Stop feed pump,Open vent\n"
      ",,,XV-301,P-302,XV-303\n"
      ",,,2,2,1\n"
      "Item,Description,Tag No.,,,\n"
      "1,Pressure high-high,PT-101,S,N,\n"
      "2,Level low-low,LT-102,,N,S\n";
  const std::string all = refusal(csv);
  EXPECT_NE(all.find("contractor.csv: line 3, column 4: cannot tell whether header row 3 holds SIL levels or ids"),
            std::string::npos)
      << all;
  // Labelled SIL, the same numbers are SIL levels.
  const auto r = import(std::string(csv).replace(csv.find(",,,2,2,1"), 0, "SIL"));
  EXPECT_EQ(r.matrix.effects[0].sil, 2);
  EXPECT_EQ(r.matrix.effects[2].sil, 1);
  EXPECT_EQ(r.matrix.effects[2].tags[0].name, "XV-303");
}

// The verb vocabulary of the action row.
TEST(StackedHeader, ActionVerbsAndTagShapes) {
  for (const char* verb : {"CLOSE", "closed", "Shut", "OPEN", "STOP", "TRIP", "START", "DE-ENERGISE", "de-energize",
                           "De energised"})
    EXPECT_TRUE(grid::action_word(verb)) << verb;
  for (const char* other : {"Close valve", "N", "XV-301", "SIL 2", "HOLD"}) EXPECT_FALSE(grid::action_word(other)) << other;
  for (const char* tag : {"XV-301", "P_302", "BDV-323A", "21-XV-301", "ESDV-1001"}) EXPECT_TRUE(grid::tag_shaped(tag)) << tag;
  for (const char* other : {"TMA-A-1", "A-1", "SIL 2", "Pump 302", "XV301", "1"})
    EXPECT_FALSE(grid::tag_shaped(other)) << other;
}

}  // namespace
}  // namespace cemv::formats

namespace cemv::formats {
namespace {

// A contractor sheet with `EFFECTS` over its attribute columns: the label is
// nearer the rows, so it says the effects are the rows, against the
// attribute headers. A layout stating the orientation, or the whole effect
// header, is obeyed (docs/csv.md "Orientation"); the label is named in a
// warning.
const char* kEffectsLabelSheet =
    "EFFECTS,,,,,,,,\n"
    "Description,,,,,,,Close inlet valve,Stop feed pump\n"
    "Action,,,,,,,CLOSE,STOP\n"
    "Tag No.,,,,,,,XV-301,P-302\n"
    "SIL,,,,,,,2,1\n"
    "Item,Description,Tag No.,Set point,EU,Vote,SIL,,\n"
    "1,Feed drum pressure high-high,PT-101,45,barg,1oo1,2,S,N\n"
    "2,Feed drum level low-low,LT-102,20,%,1oo1,2,N,\n"
    "3,Manual shutdown,HS-103,-,-,1oo1,1,S,S\n";

void expect_contractor_effects(const CsvImportResult& r) {
  const Matrix& m = r.matrix;
  ASSERT_EQ(m.effects.size(), 2u) << r.summary;
  ASSERT_EQ(m.causes.size(), 3u) << r.summary;
  EXPECT_EQ(m.effects[0].tags.at(0).name, "XV-301");
  EXPECT_EQ(m.effects[0].name, "XV_301");
  EXPECT_EQ(m.effects[0].sil, 2);
  EXPECT_EQ(m.effects[0].description, "Close inlet valve");
  EXPECT_NE(m.effects[0].note.find("Action: CLOSE"), std::string::npos) << m.effects[0].note;
  EXPECT_EQ(m.effects[1].tags.at(0).name, "P-302");
  EXPECT_EQ(m.effects[1].sil, 1);
  EXPECT_EQ(m.intersections.size(), 5u);
}

bool warned(const CsvImportResult& r, const std::string& what) {
  return std::any_of(r.warnings.begin(), r.warnings.end(),
                     [&](const LoadIssue& w) { return w.str().find(what) != std::string::npos; });
}

TEST(StackedHeaderLayout, WithoutALayoutTheConflictIsRefused) {
  try {
    import_csv(kEffectsLabelSheet, "contractor.csv");
    ADD_FAILURE() << "read without an orientation";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("the evidence conflicts: the corner labels ('EFFECTS' in line 1, column 1) "
                                         "say effects-as-rows"),
              std::string::npos)
        << e.what();
  }
}

TEST(StackedHeaderLayout, TheLayoutsOrientationIsObeyed) {
  CsvImportOptions opt;
  SheetLayout layout;
  layout.orientation = CsvOrientation::CausesAsRows;
  opt.sheet_layout = layout;
  const auto r = import_csv(kEffectsLabelSheet, "contractor.csv", opt);
  expect_contractor_effects(r);
  EXPECT_TRUE(warned(r, "the corner labels ('EFFECTS' in line 1, column 1) say effects-as-rows"));
  EXPECT_TRUE(warned(r, "read as causes-as-rows as the layout's orientation says (a layout wins over the corner labels)"));
  // The option alone reads it too: the attribute headers are for it.
  CsvImportOptions option;
  option.orientation = CsvOrientation::CausesAsRows;
  expect_contractor_effects(import_csv(kEffectsLabelSheet, "contractor.csv", option));
}

TEST(StackedHeaderLayout, TheLayoutsEffectHeaderIsObeyed) {
  CsvImportOptions opt;
  SheetLayout layout;
  layout.orientation = CsvOrientation::CausesAsRows;
  layout.effects = {{SheetAttribute::Description, 2}, {SheetAttribute::Action, 3}, {SheetAttribute::Tag, 4},
                    {SheetAttribute::Sil, 5}};
  opt.sheet_layout = layout;
  const auto r = import_csv(kEffectsLabelSheet, "contractor.csv", opt);
  expect_contractor_effects(r);
  EXPECT_TRUE(warned(r, "'EFFECTS' in line 1, column 1) say effects-as-rows; read as causes-as-rows as the layout's "
                        "orientation says (a layout wins over the corner labels)"));
  // The row of the causes' headers below the places given is no cause.
  EXPECT_EQ(r.matrix.causes[0].tags.at(0).name, "PT-101");
  // Against the attribute headers, a layout's orientation is still refused.
  layout.effects.clear();
  layout.orientation = CsvOrientation::EffectsAsRows;
  opt.sheet_layout = layout;
  try {
    import_csv(kEffectsLabelSheet, "contractor.csv", opt);
    ADD_FAILURE() << "read against the attribute headers";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("the layout's orientation effects-as-rows would read every cause as an effect"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cemv::formats

namespace cemv::formats {
namespace {

// A banner row, `CAUSES` over few label columns and `EFFECTS` over the data,
// above a tall stacked header: the left label names the rows whatever the
// distances (it is nearer the column headers here). Found by the seeded
// contractor sheets of tests/sheetgen (seeds 4, 24, 29, 39, 43, ...).
TEST(StackedHeaderBanner, TheLeftLabelOfABannerNamesTheRows) {
  const std::string csv =
      "CAUSES,,,EFFECTS,,\n"
      "Description,,,Close inlet valve,Stop pump,Open vent\n"
      "Action,,,CLOSE,STOP,OPEN\n"
      "Tag No.,,,XV-301,P-302,XV-303\n"
      "SIL,,,2,1,1\n"
      "Item,Description,Tag No.,,,\n"
      "1,Pressure high-high,PT-101,S,N,\n"
      "2,Level low-low,LT-102,,N,S\n";
  const auto r = import_csv(csv, "banner.csv");
  EXPECT_EQ(r.orientation, CsvOrientation::CausesAsRows);
  ASSERT_EQ(r.matrix.effects.size(), 3u);
  EXPECT_EQ(r.matrix.effects[2].tags.at(0).name, "XV-303");
  EXPECT_NE(r.summary.find("from the corner labels ('EFFECTS' in line 1, column 4; 'CAUSES' in line 1, column 1)"),
            std::string::npos)
      << r.summary;
  // The labels in the other order name the other axis, against the attribute
  // headers: refused.
  std::string swapped = csv;
  swapped.replace(0, 17, "EFFECTS,,,CAUSES,");
  try {
    import_csv(swapped, "banner.csv");
    ADD_FAILURE() << "read against the banner";
  } catch (const LoadError& e) {
    EXPECT_NE(std::string(e.what()).find("the corner labels ('CAUSES' in line 1, column 4; 'EFFECTS' in line 1, "
                                         "column 1) say effects-as-rows"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cemv::formats

namespace cemv::formats {
namespace {

// A group's tags all in its first row's cell, an empty row below (tests/sheetgen
// seeds 92, 140, 187): the group is that row; the empty row is not one of its.
TEST(StackedHeaderGroups, AllTagsInOneCellMakeAGroupOfOneRow) {
  const std::string csv =
      ",,,,Close valve,Stop pump\n"
      "Item,Description,Tag,Voting,1,2\n"
      "1,Fire detected,\"BS-1A, BS-1B, BS-1C\",3oo3,S,N\n"
      ",,,,,\n"
      "2,Level low,LT-2,1oo1,,N\n";
  const auto r = import_csv(csv, "groups.csv");
  ASSERT_EQ(r.matrix.causes.size(), 2u) << r.summary;
  EXPECT_EQ(r.matrix.causes[0].tags.size(), 3u);
  EXPECT_EQ(r.matrix.causes[0].function, model::CauseFunction::And);
  EXPECT_EQ(r.matrix.intersections.size(), 3u);
}

}  // namespace
}  // namespace cemv::formats
