// cemv-sheet-layout/1 (docs/csv.md "The layout description"): read, written
// back the same, and every malformed part refused at its line and column.
#include <gtest/gtest.h>

#include "formats/diagnostics.hpp"
#include "sheets/sheet_layout.hpp"

namespace cemv::formats {
namespace {

const char* kFull = R"({
  "format": "cemv-sheet-layout/1",
  "sheet": "SIS Matrix",
  "orientation": "causes-as-rows",
  "causes": {
    "id": "A",
    "description": "B",
    "tag": "C",
    "setpoint": "D",
    "unit": "E",
    "voting": "F",
    "sil": "G",
    "note": [
      "H"
    ]
  },
  "effects": {
    "id": 9,
    "description": 5,
    "tag": 7,
    "sil": 8,
    "action": 6
  },
  "marks": {
    "NP": {
      "type": "none"
    },
    "S*": {
      "type": "S",
      "footnote": "*"
    }
  },
  "footnotes": {
    "*": "Inhibited during start-up"
  },
  "remarks_sheet": "Remarks",
  "trip_sides": {
    "6": "high"
  },
  "deleted": {
    "strikethrough": true,
    "words": [
      "DELETED",
      "VOID"
    ]
  }
}
)";

std::string refusal(const std::string& text) {
  try {
    parse_sheet_layout(text, "l.json");
  } catch (const LoadError& e) {
    std::string all;
    for (const auto& i : e.issues()) all += i.message() + "\n";
    return all;
  }
  return "";
}

TEST(SheetLayout, ReadsEveryPartAndWritesItBackTheSame) {
  const SheetLayout l = parse_sheet_layout(kFull, "l.json");
  EXPECT_EQ(l.sheet, "SIS Matrix");
  EXPECT_EQ(l.orientation, CsvOrientation::CausesAsRows);
  ASSERT_EQ(l.causes.size(), 8u);
  EXPECT_EQ(l.causes[3].attribute, SheetAttribute::Setpoint);
  EXPECT_EQ(l.causes[3].position, 4);
  ASSERT_EQ(l.effects.size(), 5u);
  EXPECT_EQ(l.effects[0].position, 9);
  EXPECT_FALSE(l.marks.at("NP").type.has_value());
  EXPECT_EQ(l.marks.at("S*").type, model::IntersectionType::S);
  EXPECT_EQ(l.marks.at("S*").footnote, "*");
  EXPECT_EQ(l.trip_sides.at("6"), model::LimitType::High);
  EXPECT_EQ(l.deleted.words.size(), 2u);
  // The writer's key order is the reader's: the text comes back byte for byte.
  EXPECT_EQ(sheet_layout_json(l), kFull);
  EXPECT_EQ(sheet_layout_json(parse_sheet_layout(sheet_layout_json(l, true), "one.json")), kFull);
  // Columns also as numbers; nothing else is needed.
  const SheetLayout minimal = parse_sheet_layout(
      R"({"format": "cemv-sheet-layout/1", "orientation": "effects-as-rows", "causes": {"id": 3}, "effects": {"id": 2}})",
      "m.json");
  EXPECT_EQ(minimal.causes.at(0).position, 3);  // a row: the causes are the columns
  EXPECT_EQ(minimal.effects.at(0).position, 2);
  EXPECT_TRUE(minimal.deleted.strikethrough);
  EXPECT_EQ(minimal.deleted.words, std::vector<std::string>{"DELETED"});
}

TEST(SheetLayout, RefusesEachMalformedPartAtItsPlace) {
  EXPECT_NE(refusal("").find("l.json: error: file is empty"), std::string::npos);
  EXPECT_NE(refusal("[]").find("a layout description is a JSON object"), std::string::npos);
  EXPECT_NE(refusal(R"({"format": "cemv-layout/1"})").find("l.json:1:2: error: format: expected \"cemv-sheet-layout/1\""),
            std::string::npos);
  const std::string many = refusal(R"({
  "format": "cemv-sheet-layout/1",
  "orientation": "sideways",
  "causes": {"setpoint": "D", "action": "E"},
  "effects": {"id": "B", "tag": 3, "sil": 3},
  "marks": {"NP": {"type": "nothing"}, "S*": {"type": "S", "footnote": "#"}},
  "trip_sides": {"4": "up"},
  "deleted": {"strikethrough": "yes"},
  "colour": 1
})");
  for (const char* expected : {
           "l.json:3:3: error: orientation: must be \"auto\", \"causes-as-rows\" or \"effects-as-rows\", not \"sideways\"",
           "l.json:4:3: error: causes: the places of the attributes need the orientation",
           "l.json:4:31: error: causes.action: not an attribute of a cause",
           "l.json:5:36: error: effects.sil: the same place as another attribute",
           "l.json:6:20: error: marks.NP.type: must be N, S, V, R, X, * or none, not \"nothing\"",
           "error: marks['S*'].footnote: must be a footnote key",
           "l.json:7:18: error: trip_sides['4']: must be \"high\" or \"low\", not \"up\"",
           "l.json:8:15: error: deleted.strikethrough: must be true or false",
           "l.json:9:3: error: colour: unknown key"})
    EXPECT_NE(many.find(expected), std::string::npos) << expected << "\n" << many;
  // With causes as rows, the effects' places are rows: a letter is refused.
  EXPECT_NE(refusal(R"({"format": "cemv-sheet-layout/1", "orientation": "causes-as-rows", "effects": {"id": "B"}})")
                .find("effects.id: must be a row number 1-16384, not \"B\""),
            std::string::npos);
}

TEST(SheetLayout, NamesAndColumns) {
  EXPECT_EQ(column_letters(1), "A");
  EXPECT_EQ(column_letters(26), "Z");
  EXPECT_EQ(column_letters(28), "AB");
  EXPECT_EQ(column_letters(16384), "XFD");
  EXPECT_STREQ(to_string(SheetAttribute::TripSide), "trip_side");
  EXPECT_STREQ(to_string(CsvOrientation::EffectsAsRows), "effects-as-rows");
}

}  // namespace
}  // namespace cemv::formats
