// Plant parameters beside a sheet (cemv-params/1, docs/params.md), what an
// import records (docs/format.md "Provenance"), the text encodings of inputs,
// and the new fields of cemv-matrix/1 through every lossless layout.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "sheets/csv.hpp"
#include "sheets/import_record.hpp"
#include "formats/matrix_json.hpp"
#include "formats/params.hpp"
#include "formats/text_encoding.hpp"
#include "sheets/workbook.hpp"

namespace cemv::formats {
namespace {

// A grid of two causes and two effects, one R(1) cell, as a sheet states it.
model::Matrix grid() {
  const std::string csv =
      ";Effects;Stop drives;Lock platform;\n"
      "Causes;;A-1;A-2;\n"
      "Travel limit;D-1;R(1);;\n"
      "Emergency button;D-2;S;N;\n";
  return import_csv(csv, "sheet.csv").matrix;
}

std::string error_of(const model::Matrix& m, const std::string& params) {
  try {
    apply_params(m, params, "p.json");
  } catch (const LoadError& e) {
    return e.issues().front().message();
  }
  return "";
}

TEST(Params, SetsValuesAndRecordsEachWithItsOrigin) {
  const model::Matrix m = grid();
  const std::string params = R"j({
    "format": "cemv-params/1",
    "origin": "assumed for the test",
    "matrix": {"name": "PLANT", "cycle_ms": 50},
    "effects": {"A-1": {"override": {"max_s": 600, "prealarm_s": 540}, "origin": "the plant's manual"}},
    "tags": {"D_1": {"description": "Travel limit switch"}}
  })j";
  ParamsApplication a = apply_params(m, params, "dir/p.json");
  EXPECT_EQ(a.matrix.name, "PLANT");
  EXPECT_EQ(a.matrix.cycle_ms, 50u);
  ASSERT_TRUE(a.matrix.find_effect(1)->override_time);
  EXPECT_EQ(a.matrix.find_effect(1)->override_time->max_s, 600u);
  EXPECT_EQ(a.matrix.tag_descriptions.at("D_1"), "Travel limit switch");
  ASSERT_EQ(a.matrix.provenance.parameters.size(), 1u);
  const auto& rec = a.matrix.provenance.parameters[0];
  EXPECT_EQ(rec.file, "p.json");  // the base name: the signature does not depend on where the file was
  EXPECT_EQ(rec.sha256, sha256_hex(params));
  EXPECT_EQ(rec.origin, "assumed for the test");
  bool override_recorded = false;
  for (const auto& v : rec.values)
    if (v.element == "effect[1] A_1" && v.field == "override") {
      override_recorded = true;
      EXPECT_EQ(v.value, R"j({"max_s":600,"prealarm_s":540})j");
      EXPECT_EQ(v.previous, "null");
      EXPECT_EQ(v.origin, "the plant's manual");
    }
  EXPECT_TRUE(override_recorded);
  // The record is part of the matrix: its canonical form, and so its signature.
  EXPECT_NE(to_canonical_json(a.matrix).find("\"provenance\""), std::string::npos);
  EXPECT_EQ(parse_matrix(to_canonical_json(a.matrix)).provenance.parameters[0].values.size(), rec.values.size());
}

TEST(Params, PoliciesCoverEveryElementWithoutItsOwnEntry) {
  const model::Matrix m = grid();
  ParamsApplication a = apply_params(m, R"j({
    "format": "cemv-params/1",
    "soft_bypass": {"allowed": true, "max_s": 3600, "tags": false},
    "simulation": {"allowed": false},
    "causes": {"D-2": {"soft_bypass": {"allowed": false}}},
    "tags": {"A_2": {"simulation_allowed": true}}
  })j", "p.json");
  const auto* c1 = a.matrix.find_cause(1);
  const auto* c2 = a.matrix.find_cause(2);
  EXPECT_TRUE(c1->soft_bypass.allowed);
  EXPECT_EQ(c1->soft_bypass.max_s, 3600u);
  EXPECT_FALSE(c1->tags[0].soft_bypass_allowed);
  EXPECT_FALSE(c2->soft_bypass.allowed);  // its own entry wins
  EXPECT_FALSE(c1->tags[0].simulation_allowed);
  EXPECT_FALSE(a.matrix.find_effect(1)->tags[0].simulation_allowed);
  EXPECT_TRUE(a.matrix.find_effect(2)->tags[0].simulation_allowed);
  // The defaults the import adopted no longer name what the policies set.
  for (const auto& d : adopted_defaults(a.matrix)) {
    EXPECT_EQ(d.find("simulate"), std::string::npos) << d;
    EXPECT_EQ(d.find("soft-bypass it without time limit"), std::string::npos) << d;
  }
}

TEST(Params, FootnotesGiveTheirTextToTheCellsAndTheirMeaningToTheRecord) {
  const model::Matrix m = grid();
  ASSERT_EQ(m.find_intersection(1, 1)->note, "(1)");
  ParamsApplication a = apply_params(m, R"j({
    "format": "cemv-params/1",
    "footnotes": {"(1)": {"text": "Override with cabinet switch", "modelled": "the switch is the reset tag",
                          "effects": {"A-1": {"reset_tag": "OVR_SW", "override": {"max_s": 60}}}}}
  })j", "p.json");
  EXPECT_EQ(a.matrix.find_intersection(1, 1)->note, "(1) Override with cabinet switch");
  EXPECT_EQ(a.matrix.find_effect(1)->reset_tag.value_or(""), "OVR_SW");
  const auto& rec = a.matrix.provenance.parameters[0];
  ASSERT_EQ(rec.footnotes.size(), 1u);
  EXPECT_EQ(rec.footnotes[0].modelled, "the switch is the reset tag");
  bool reset_tag = false;
  for (const auto& v : rec.values)
    if (v.field == "reset_tag") reset_tag = v.origin.rfind("footnote (1) \"Override with cabinet switch\"", 0) == 0;
  EXPECT_TRUE(reset_tag);
}

TEST(Params, AFootnoteTheFileDoesNotExplainIsAWarning) {
  ParamsApplication a = apply_params(grid(), R"j({"format": "cemv-params/1"})j", "p.json");
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].what.find("footnote (1) (1 intersection) is not explained"), std::string::npos)
      << a.warnings[0].what;
}

TEST(Params, ErrorsAreAtTheirPlaceInTheParametersFile) {
  const model::Matrix m = grid();
  EXPECT_EQ(error_of(m, "{\"format\": \"cemv-params/2\"}"),
            "p.json:1:2: error: format: is \"cemv-params/2\", expected 'cemv-params/1'");
  EXPECT_EQ(error_of(m, "{\"format\": \"cemv-params/1\",\n \"efects\": {}}"),
            "p.json:2:2: error: efects: unknown key (did you mean 'effects'?)");
  EXPECT_EQ(error_of(m, "{\"format\": \"cemv-params/1\",\n \"effects\": {\"A-9\": {}}}"),
            "p.json:2:14: error: effects['A-9']: the matrix has no effect named 'A-9' (by name or sheet id) "
            "(did you mean 'A-1'?)");
  EXPECT_EQ(error_of(m, "{\"format\": \"cemv-params/1\",\n \"effects\": {\"A-1\": {\"id\": 7}}}"),
            "p.json:2:22: error: effects['A-1'].id: 'id' identifies the element; the parameters cannot change it");
  // A value the matrix format refuses, at the place that set it.
  EXPECT_EQ(error_of(m, "{\"format\": \"cemv-params/1\",\n \"effects\": {\"A-1\": {\"override\": {\"max_s\": \"600\"}}}}"),
            "p.json:2:22: error: effects['A-1'].override: sets effects[0].override.max_s: expected an integer, got "
            "the string '600'");
  // The same field twice.
  EXPECT_NE(error_of(m, R"j({"format": "cemv-params/1", "effects": {"A-1": {"sil": 2}},
                         "footnotes": {"(1)": {"text": "x", "effects": {"A_1": {"sil": 3}}}}})j")
                .find("effect[1] A_1 sil is already set by effects['A-1'].sil"),
            std::string::npos);
  // A tag the matrix does not have.
  EXPECT_NE(error_of(m, R"j({"format": "cemv-params/1", "tags": {"NO_SUCH_TAG": {"description": "x"}}})j")
                .find("the matrix reads or writes no tag 'NO_SUCH_TAG'"),
            std::string::npos);
}

TEST(Params, ASheetIdOfTwoElementsIsAmbiguous) {
  const std::string csv =
      ";Effects;Stop;\n"
      "Causes;;A-1;\n"
      "One;D-1;N;\n"
      "Two;D-1;S;\n";
  const model::Matrix m = import_csv(csv, "dup.csv").matrix;
  EXPECT_NE(error_of(m, R"j({"format": "cemv-params/1", "causes": {"D-1": {"sil": 1}}})j")
                .find("sheet id 'D-1' names 2 causes (D_1, D_1_2); use the name of the one meant"),
            std::string::npos);
  EXPECT_EQ(error_of(m, R"j({"format": "cemv-params/1", "causes": {"D_1_2": {"sil": 1}}})j"), "");
}

TEST(Params, AFileAppliesOnce) {
  const std::string params = R"j({"format": "cemv-params/1", "matrix": {"cycle_ms": 50}})j";
  ParamsApplication a = apply_params(grid(), params, "p.json");
  EXPECT_NE(error_of(a.matrix, params).find("is already applied to the matrix"), std::string::npos);
}

TEST(ImportRecord, StatesTheSourceItsWarningsAndEveryDefault) {
  model::Matrix m = grid();
  record_import(m, "/some/dir/sheet.csv", "bytes", "import-csv grid", "UTF-8", "read 2 causes", {"w1"});
  ASSERT_EQ(m.provenance.imports.size(), 1u);
  const auto& r = m.provenance.imports[0];
  EXPECT_EQ(r.file, "sheet.csv");
  EXPECT_EQ(r.sha256, sha256_hex("bytes"));
  EXPECT_EQ(r.warnings, std::vector<std::string>{"w1"});
  auto has = [&](const std::string& text) {
    for (const auto& d : r.defaults)
      if (d.find(text) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(has("matrix: scan cycle 100 ms"));
  EXPECT_TRUE(has("2 of 2 causes: the operator may soft-bypass it without time limit"));
  EXPECT_TRUE(has("2 of 2 causes: the operator may simulate its input tags"));
  EXPECT_TRUE(has("2 of 2 effects: no maximum override time"));
}

TEST(MatrixFields, NewFieldsAreWrittenOnlyWhenUsedAndSurviveEveryLosslessLayout) {
  model::Matrix m = grid();
  const std::string before = to_canonical_json(m);
  EXPECT_EQ(before.find("simulation_allowed"), std::string::npos);  // old matrices keep their signature
  EXPECT_EQ(before.find("tag_descriptions"), std::string::npos);
  EXPECT_EQ(before.find("provenance"), std::string::npos);
  m.causes[0].tags[0].simulation_allowed = false;
  m.effects[1].tags[0].simulation_allowed = false;
  m.tag_descriptions["d_2"] = "Emergency button, \"red\"";
  record_import(m, "sheet.csv", "x", "import-csv grid", "UTF-8", "summary", {"warning, with a comma"});
  m = apply_params(m, R"j({"format": "cemv-params/1", "footnotes": {"(1)": {"text": "t", "not_modelled": "why"}},
                         "limitations": ["one"]})j", "p.json").matrix;
  const std::string sig = signature(m);
  EXPECT_EQ(signature(parse_matrix(to_canonical_json(m))), sig);
  EXPECT_EQ(signature(import_csv(export_csv(m), "m.csv").matrix), sig);
  EXPECT_EQ(signature(import_workbook(export_workbook(m, WorkbookFormat::Xlsx), "m.xlsx").matrix), sig);
  EXPECT_EQ(signature(import_workbook(export_workbook(m, WorkbookFormat::Ods), "m.ods").matrix), sig);
}

TEST(MatrixFields, TagDescriptionsOfOneTagInTwoSpellingsAreRefused) {
  try {
    parse_matrix(R"j({"format": "cemv-matrix/1", "name": "M",
                     "tag_descriptions": [{"tag": "XV_1", "description": "a"}, {"tag": "xv_1", "description": "b"}]})j",
                 "m.json");
    FAIL() << "accepted";
  } catch (const LoadError& e) {
    EXPECT_NE(e.issues().front().what.find("is described twice"), std::string::npos) << e.issues().front().what;
  }
}

TEST(TextEncoding, Utf8IsCheckedAndWindows1252IsReadWhenAsked) {
  const std::string latin1 = "a;b\nAzimut \xDC" "berdrehzahl;c\n";
  try {
    decode_text(latin1, TextEncoding::Utf8, "x.csv");
    FAIL() << "Latin-1 read as UTF-8";
  } catch (const LoadError& e) {
    const LoadIssue& i = e.issues().front();
    EXPECT_EQ(i.line, 2u);
    EXPECT_EQ(i.column, 8u);
    EXPECT_NE(i.what.find("byte 0xDC is not UTF-8"), std::string::npos) << i.what;
    EXPECT_NE(i.what.find("--encoding windows-1252"), std::string::npos);
  }
  EXPECT_EQ(decode_text(latin1, TextEncoding::Windows1252, "x.csv"), "a;b\nAzimut \xC3\x9C" "berdrehzahl;c\n");
  EXPECT_EQ(decode_text("\x80", TextEncoding::Windows1252, "x"), "\xE2\x82\xAC");  // the euro sign
  EXPECT_THROW(decode_text("\x81", TextEncoding::Windows1252, "x"), LoadError);  // undefined in 1252
  EXPECT_EQ(decode_text("Gr\xC3\xBC\xC3\x9F" "e", TextEncoding::Utf8, "x"), "Gr\xC3\xBC\xC3\x9F" "e");
  EXPECT_TRUE(first_invalid_utf8("\xED\xA0\x80").has_value());  // a surrogate
  EXPECT_TRUE(first_invalid_utf8("\xC0\xAF").has_value());      // overlong
}

}  // namespace
}  // namespace cemv::formats
