// Spreadsheet import/export (6.6, docs/csv.md): RFC 4180 reading, the lossless
// round trip of the record layout, malformed input with line/column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "sheets/csv.hpp"
#include "model/names.hpp"
#include "formats/matrix_json.hpp"
#include "test_csv_support.hpp"

namespace cemv::formats {

using namespace cemv::model;
namespace {

std::string canonical(const Matrix& m) { return to_canonical_json(parse_matrix(to_canonical_json(m))); }

// ---- RFC 4180 ---------------------------------------------------------------------------

TEST(CsvParse, QuotesEscapesAndLineBreaksInsideFields) {
  auto rows = parse_csv("a,\"b,1\",\"say \"\"hi\"\"\"\r\n\"multi\nline\",x\n,\n", ',', true);
  ASSERT_EQ(rows.size(), 3u);
  ASSERT_EQ(rows[0].fields.size(), 3u);
  EXPECT_EQ(rows[0].fields[1].text, "b,1");
  EXPECT_TRUE(rows[0].fields[1].quoted);
  EXPECT_EQ(rows[0].fields[2].text, "say \"hi\"");
  EXPECT_EQ(rows[1].fields[0].text, "multi\nline");
  EXPECT_EQ(rows[1].line, 2);
  EXPECT_EQ(rows[1].fields[1].line, 3);  // the field after the quoted line break
  EXPECT_EQ(rows[2].line, 4);
  ASSERT_EQ(rows[2].fields.size(), 2u);
  EXPECT_EQ(rows[2].fields[1].column, 2);
}

TEST(CsvParse, ByteOrderMarkAndMissingFinalNewline) {
  auto rows = parse_csv("\xEF\xBB\xBFx;y;", ';', false);
  ASSERT_EQ(rows.size(), 1u);
  ASSERT_EQ(rows[0].fields.size(), 3u);
  EXPECT_EQ(rows[0].fields[0].text, "x");
  EXPECT_EQ(rows[0].fields[2].text, "");
}

TEST(CsvParse, StrictModeRejectsStrayQuotesWithLineAndColumn) {
  try {
    parse_csv("a,b\nc,d\"e\n", ',', true, "f.csv");
    FAIL() << "accepted a quote inside an unquoted field";
  } catch (const LoadError& e) {
    ASSERT_EQ(e.issues().size(), 1u);
    EXPECT_EQ(e.issues()[0].where, "f.csv: line 2, column 2");
  }
  try {
    parse_csv("\"a\"x,b\n", ',', true);
    FAIL() << "accepted text after a closing quote";
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues()[0].where, "line 1, column 1");
  }
  // Lenient (grid) mode keeps them literally.
  auto rows = parse_csv("c;d\"e\n", ';', false);
  EXPECT_EQ(rows[0].fields[1].text, "d\"e");
}

TEST(CsvParse, UnterminatedQuoteNamesTheLineWhereItOpened) {
  try {
    parse_csv("a,b\nc,\"open\nmore\nlines\n", ',', true);
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues()[0].where, "line 2, column 2");
    EXPECT_NE(e.issues()[0].what.find("never closed"), std::string::npos);
  }
}

TEST(CsvQuote, QuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csv_quote("plain"), "plain");
  EXPECT_EQ(csv_quote("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_quote("a\"b"), "\"a\"\"b\"");
  EXPECT_EQ(csv_quote("a\nb"), "\"a\nb\"");
  EXPECT_EQ(csv_quote(" lead"), "\" lead\"");
  EXPECT_EQ(csv_quote("a;b"), "a;b");
  EXPECT_EQ(csv_quote("a;b", ';'), "\"a;b\"");
}

TEST(SanitizeIdentifier, FollowsTheNameAndTagRules) {
  EXPECT_EQ(sanitize_identifier("TMA-D-1", 24), "TMA_D_1");
  EXPECT_EQ(sanitize_identifier("  a--b  c ", 24), "a_b_c");
  EXPECT_EQ(sanitize_identifier("__x__", 24), "x");
  EXPECT_EQ(sanitize_identifier("abcdefgh_ijk", 9), "abcdefgh");
  EXPECT_EQ(sanitize_identifier("---", 24), "");
  for (auto s : {"TMA-D-40 (2)", "A.B/C", "x#y%z~"}) {
    auto id = sanitize_identifier(s, 24);
    EXPECT_FALSE(tag_name_problem(id).has_value()) << id;
    EXPECT_FALSE(element_name_problem(id).has_value()) << id;
  }
}

// ---- the record layout: round trip ----------------------------------------------------------

TEST(CsvRoundTrip, EveryFieldSurvivesExportThenImport) {
  const Matrix m = testing::every_field_matrix();
  const std::string expected = canonical(m);
  const std::string csv = export_csv(m);
  // The texts that need quoting are quoted (RFC 4180).
  EXPECT_NE(csv.find("\"note with ; and , and \"\"quotes\"\" and 'single'\""), std::string::npos);
  EXPECT_NE(csv.find("\" leading and trailing blanks \""), std::string::npos);
  EXPECT_NE(csv.find("0.1,0.3,0.05,0.001"), std::string::npos);  // shortest float text
  auto result = import_csv(csv, "rt.csv");
  EXPECT_EQ(result.layout, CsvLayoutKind::Records);
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(to_canonical_json(result.matrix), expected);
  EXPECT_EQ(signature(result.matrix), signature(m));
  // And the export of the import is byte-identical.
  EXPECT_EQ(export_csv(result.matrix), csv);
}

TEST(CsvRoundTrip, EmptyMatrixAndOptionalBlocksAbsent) {
  Matrix m;
  m.name = "EMPTY";
  const std::string csv = export_csv(m);
  auto result = import_csv(csv, "empty.csv");
  EXPECT_EQ(to_canonical_json(result.matrix), canonical(m));
  EXPECT_FALSE(result.matrix.secure_write.has_value());
  EXPECT_FALSE(result.matrix.group_deactivation.has_value());
}

TEST(CsvRoundTrip, EveryBundledExample) {
  const std::filesystem::path root = CEMV_SOURCE_DIR;
  int checked = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root / "examples")) {
    if (entry.path().filename() != "matrix.json") continue;
    const Matrix m = load_matrix(entry.path());
    auto result = import_csv(export_csv(m), entry.path().string());
    EXPECT_EQ(to_canonical_json(result.matrix), to_canonical_json(m)) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

TEST(CsvImport, AcceptsLfLineEndsReorderedColumnsAndBlankDefaults) {
  const std::string csv =
      "#property,value,key\n"
      "property,cemv-matrix/1,format\n"
      "property,SMALL,name\n"
      "\n"
      "#cause,name,id,description,sil,input,function,bad_quality,time_mode,time_ms,auto_ack,"
      "soft_bypass_allowed,soft_bypass_max_s,soft_bypass_prealarm_s,bypass_tag,inhibit_tag,"
      "first_out_group,mutually_locked_maintenance,sif,analog_limit_type,analog_limit,"
      "analog_hysteresis,analog_prewarning,analog_delta,analog_unit,note\n"
      "cause,C1,1,,,,,,,,,,,,,,,,,,,,,,,\n"
      "#cause_tag,cause,position,name,ett,soft_bypass_allowed\n"
      "cause_tag,1,1,T1,,\n"
      "#effect,id,name,description,sil,function,output_delay_ms,soft_bypass_allowed,bypass_tag,"
      "reset_tag,override_max_s,override_prealarm_s,process_data_tag,process_data_pass_through,"
      "process_data_mask_tag,mutually_locked_maintenance,sif,note\n"
      "effect,1,E1,,,,,,,,,,,,,,,\n"
      "#effect_tag,effect,position,name,ett\n"
      "effect_tag,1,1,O1,TRUE\n"
      "#intersection,cause,effect,type,xoon,note\n"
      "intersection,1,1,s,,\n";
  auto m = import_csv(csv, "small.csv").matrix;
  ASSERT_EQ(m.causes.size(), 1u);
  EXPECT_EQ(m.name, "SMALL");
  EXPECT_EQ(m.cycle_ms, 100u);
  EXPECT_EQ(m.causes[0].bad_quality, BadQuality::Trip);
  EXPECT_TRUE(m.causes[0].auto_ack);
  EXPECT_TRUE(m.causes[0].tags[0].soft_bypass_allowed);
  EXPECT_TRUE(m.effects[0].tags[0].ett);
  EXPECT_EQ(m.intersections[0].type, IntersectionType::S);
}

// ---- the record layout: malformed input -----------------------------------------------------

struct BadCase {
  const char* name;
  std::string from;  // text of the valid export to replace (first occurrence)
  std::string to;
  std::string where; // expected location (regex)
  std::string what;  // expected message (regex)
};

std::string replace_first(std::string s, const std::string& from, const std::string& to) {
  auto pos = s.find(from);
  if (pos == std::string::npos) throw std::runtime_error("test text not found: " + from);
  return s.replace(pos, from.size(), to);
}

TEST(CsvImportErrors, EachMalformedInputNamesItsLineAndColumn) {
  const std::string good = export_csv(testing::every_field_matrix());
  // Lines of the valid export: 1 #property, 2 format, 3 name, 4 title, 5 cycle_ms,
  // 6 secure_write, 7-8 group_deactivation, 9 #sif_group, 10-12 groups, 13 #cause,
  // 14.. causes.
  const std::vector<BadCase> cases = {
      {"unterminated quote", "intersection,7,5,X", "intersection,7,5,\"X", "line [0-9]+, column 4", "never closed"},
      {"text after quote", "cause,2,PS_AND", "cause,2,\"PS\"AND", "line 15, column 3", "after the closing quote"},
      {"stray quote", "cause,2,PS_AND", "cause,2,PS\"AND", "line 15, column 3", "quote inside an unquoted field"},
      {"unknown record type", "cause,2,PS_AND", "kause,2,PS_AND", "line 15, column 1", "unknown record type 'kause'"},
      {"unknown header", "#sif_group,number,name", "#sif_groups,number,name", "line 9, column 1", "unknown header"},
      {"record before header", "#property,key,value\r\n", "", "line 1, column 1", "before its header row '#property'"},
      {"header lacks column", "#sif_group,number,name", "#sif_group,number", "line 9, column 1", "lacks column 'name'"},
      {"header unknown column", "#sif_group,number,name", "#sif_group,number,name,colour", "line 9, column 4", "unknown column 'colour'"},
      {"bad integer", "cause,2,PS_AND", "cause,two,PS_AND", "line 15, column 2", "id: 'two' is not an integer"},
      {"bad float", "0.1,0.3,0.05", "0.1,0.3,nan", "line 14, column 23", "analog_prewarning: 'nan' is not a finite number"},
      {"decimal comma", "0.1,0.3,0.05", "0.1,\"0,3\",0.05", "line 14, column 22", "'0,3' is not a finite number"},
      {"bad bool", "on_delay,2000,false", "on_delay,2000,no", "line 14, column 11", "auto_ack: 'no' is not true or false"},
      {"bad enum", "cause,2,PS_AND,\" leading and trailing blanks \",3,discrete,and",
       "cause,2,PS_AND,\" leading and trailing blanks \",3,discrete,nand", "line 15, column 7",
       "function: 'nand' is not one of normal, and, or, 2oo3, comment"},
      {"duplicate cause id", "cause,2,PS_AND", "cause,1,PS_AND", "line 15, column 2", "cause id 1 repeats line 14"},
      {"bad intersection type", "intersection,3,2,S", "intersection,3,2,Q", "line [0-9]+, column 4", "type: 'Q' is not one of"},
      {"duplicate intersection", "intersection,3,2,S", "intersection,3,1,S", "line [0-9]+, column 2", "repeats line"},
      {"tag position gap", "cause_tag,1,3,LT 100C", "cause_tag,1,4,LT 100C", "line [0-9]+, column 3", "tag position 4 where 3"},
      {"tag of missing cause", "cause_tag,4,1,LT_200", "cause_tag,9,1,LT_200", "line [0-9]+, column 2", "cause_tag of cause 9, which has no 'cause' row"},
      {"override prealarm alone", ",600,540,", ",,540,", "line [0-9]+, column 12", "override_prealarm_s given without override_max_s"},
      {"extra value", "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,0,false,,,,,,,,",
       "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,0,false,,,,,,,,,surprise",
       "line 18, column 27", "extra value 'surprise' beyond the 25 columns"},
      {"wrong format", "property,format,cemv-matrix/1", "property,format,cemv-matrix/2", "line 2, column 3", "is not 'cemv-matrix/1'"},
      {"repeated property", "property,cycle_ms,50", "property,name,X", "line 5, column 2", "property 'name' repeated"},
      {"unknown property", "property,cycle_ms,50", "property,cycle,50", "line 5, column 2", "unknown property 'cycle'"},
      // User text is quoted as in every other format (model::in_quotes): bytes
      // outside printable ASCII escaped, shortened after 48 characters.
      {"control byte in a value", "on_delay,2000,false", "on_delay,2000,fa\x1b[2Jlse", "line 14, column 11",
       "auto_ack: 'fa\\\\x1B\\[2Jlse' is not true or false"},
      {"long value", "property,cycle_ms,50", "property,cycle_ms," + std::string(60, '9'), "line 5, column 3",
       "value: '9{48}\\.\\.\\.' is not an integer"},
      {"analog value without limit type", "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,0,false,,,",
       "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,0,false,,,5", "line 18, column 21",
       "analog_limit given without analog_limit_type"},
      // Rules the JSON loader enforces come back with the CSV line of the element.
      {"loader: bad tag name", "cause_tag,4,1,LT_200", "cause_tag,4,1,LT%200", "line 17 \\(causes\\[3\\]\\.tags\\[0\\]\\.name\\)", "%"},
      {"loader: line break in a note", "effect note; with", "effect\nnote; with", "line [0-9]+ \\(effects\\[0\\]\\.note\\)", "control character"},
      {"loader: first-out group out of range", "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,0,",
       "cause,7,COMMENT_ONLY,Comment line,0,discrete,comment,trip,none,0,true,true,0,0,,,16,",
       "line 18 \\(causes\\[4\\]\\.first_out_group\\)", "15"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string text = replace_first(good, c.from, c.to);
    try {
      import_csv(text, "bad.csv");
      ADD_FAILURE() << c.name << ": accepted";
    } catch (const LoadError& e) {
      ASSERT_FALSE(e.issues().empty());
      bool found = false;
      std::string all;
      for (const auto& issue : e.issues()) {
        all += issue.str() + "\n";
        found = found || (std::regex_search(issue.where, std::regex("^bad\\.csv: " + c.where + "$")) &&
                          std::regex_search(issue.what, std::regex(c.what)));
      }
      EXPECT_TRUE(found) << c.name << ": got\n" << all;
    }
  }
}

TEST(CsvImportErrors, EveryProblemIsReportedNotOnlyTheFirst) {
  std::string text = export_csv(testing::every_field_matrix());
  text = replace_first(text, "cause,2,PS_AND", "cause,x,PS_AND");
  text = replace_first(text, "intersection,3,2,S", "intersection,3,2,Q");
  try {
    import_csv(text, "two.csv");
    FAIL();
  } catch (const LoadError& e) {
    EXPECT_EQ(e.issues().size(), 2u);
  }
}

}  // namespace
}  // namespace cemv::formats
