// Vendor C&E sheets as CSV (docs/csv.md "Vendor sheets"): attribute columns
// and stacked header rows read as attributes, never as elements; voting
// groups; setpoints and the side that trips; footnoted marks; deleted rows;
// the layout description given, found, and given again. Every rule is read
// right or refused with its cell named.
#include <gtest/gtest.h>

#include <algorithm>

#include "sheets/csv.hpp"
#include "sheets/csv_grid.hpp"
#include "sheets/csv_grid_values.hpp"
#include "formats/matrix_json.hpp"
#include "formats/params.hpp"

namespace cemv::formats {

using namespace cemv::model;
namespace {

// The matrix sheet of tests/sheets/vendor_cases/sis-matrix.fods as
// LibreOffice saves it as CSV (merged cells: the text in the first one).
const char* kSheet =
    "CAUSE AND EFFECT MATRIX - SAFETY INSTRUMENTED SYSTEM,,,,,,,,,\n"
    ",,,,,,,,,\n"
    "CAUSES,,,,,,,EFFECTS,,\n"
    "Effect description,,,,,,,Close feed drum inlet valve,Stop feed pump P-1001,Open blowdown valve\n"
    "Action,,,,,,,CLOSE,STOP,OPEN\n"
    "Final element tag,,,,,,,XV-1001,P-1001,BDV-1001\n"
    "SIL,,,,,,,2,2,1\n"
    "Item,Cause description,Tag,Setpoint,Unit,Voting,SIL,1,2,3\n"
    "1,Feed drum pressure high-high,PT-1001A,45,barg,2oo3,2,S,N,\n"
    ",,PT-1001B,,,,,,,\n"
    ",,PT-1001C,,,,,,,\n"
    "2,Feed drum level low-low,LT-1002,20,%,1oo1,2,S*,N*,\n"
    "3,Manual emergency shutdown,HS-1003,-,-,1oo1,2,S,S,S\n"
    "4,Feed pump suction pressure low (DELETED Rev. C),PT-1004,0.8,barg,1oo1,1,,N,\n"
    "5,Blowdown drum level high,LT-1005,75,%,1oo1,1,NP,,N\n"
    "6,Feed drum temperature,TT-1006,180,degC,1oo1,1,N,N,\n"
    "7,Fire detected in feed pump area,BS-1007A,-,-,1oo2,1,,N,N\n"
    ",,BS-1007B,,,,,,,\n"
    ",,,,,,,,,\n"
    "Notes: S* and N* see note * on sheet Remarks.,,,,,,,,,\n";

SheetLayout minimal_layout() {
  SheetLayout l;
  l.marks["NP"] = MarkMeaning{std::nullopt, ""};
  l.trip_sides["6"] = LimitType::High;
  l.footnotes["*"] = "Trip delayed 10 s during start-up";
  return l;
}

CsvImportResult import(const std::string& text, std::optional<SheetLayout> layout = minimal_layout(),
                       CsvOrientation orientation = CsvOrientation::Auto) {
  CsvImportOptions opt;
  opt.sheet_layout = std::move(layout);
  opt.orientation = orientation;
  return import_csv(text, "sis.csv", opt);
}

// Every message of the refusal ("" when the text imports).
std::string refusal(const std::string& text, std::optional<SheetLayout> layout = minimal_layout()) {
  try {
    import(text, std::move(layout));
  } catch (const LoadError& e) {
    std::string all;
    for (const auto& i : e.issues()) all += i.str() + "\n";
    return all;
  }
  return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error(from);
  return text.replace(at, from.size(), to);
}

TEST(VendorSheet, AttributesAreReadAsAttributesNeverAsElements) {
  const auto r = import(kSheet);
  const Matrix& m = r.matrix;
  ASSERT_EQ(m.effects.size(), 3u);  // not Tag, Setpoint, Unit, Voting and SIL as five more
  ASSERT_EQ(m.causes.size(), 6u);   // items 1-7 without the deleted 4; a group is one cause
  const Cause& c1 = *m.find_cause(1);
  EXPECT_EQ(c1.function, CauseFunction::TwoOoThree);
  ASSERT_EQ(c1.tags.size(), 3u);
  EXPECT_EQ(c1.tags[2].name, "PT-1001C");
  EXPECT_EQ(c1.sil, 2);
  ASSERT_TRUE(c1.analog.has_value());
  EXPECT_EQ(c1.analog->limit_type, LimitType::High);  // "high-high"
  EXPECT_EQ(c1.analog->limit, 45.0f);
  EXPECT_EQ(c1.analog->unit, "barg");
  EXPECT_EQ(m.find_cause(2)->analog->limit_type, LimitType::Low);
  EXPECT_EQ(m.find_cause(6)->analog->limit_type, LimitType::High);  // the layout's trip side
  EXPECT_EQ(m.find_cause(3)->input, InputKind::Discrete);            // setpoint '-'
  EXPECT_EQ(m.find_cause(7)->function, CauseFunction::Or);           // 1oo2
  EXPECT_EQ(m.find_cause(4), nullptr);
  const Effect& e1 = *m.find_effect(1);
  EXPECT_EQ(e1.tags.at(0).name, "XV-1001");
  EXPECT_EQ(e1.sil, 2);
  EXPECT_EQ(e1.note, "sheet id: 1; Action: CLOSE");
  EXPECT_EQ(m.intersections.size(), 12u);
  EXPECT_EQ(m.find_intersection(2, 1)->type, IntersectionType::S);
  EXPECT_EQ(m.find_intersection(2, 1)->note, "* Trip delayed 10 s during start-up");
  EXPECT_EQ(m.find_intersection(5, 1), nullptr);  // NP: no intersection
  for (const char* part : {"read 6 causes (rows 9-18, ids in column 1), 3 effects (columns 8-10, ids in row 8)",
                           "label column 4 'Setpoint' read as the cause setpoints",
                           "header row 6 'Final element tag' read as the effect tags",
                           "voting groups: rows 9-11 (2oo3), rows 17-18 (1oo2)", "4 setpoints read as analog limits",
                           "left out 1 deleted cause: row 14 (id '4': 'Feed pump suction pressure low (DELETED "})
    EXPECT_NE(r.summary.find(part), std::string::npos) << part << "\n" << r.summary;
}

TEST(VendorSheet, WhatTheSheetCannotSayIsRefusedAtItsCell) {
  const std::string all = refusal(kSheet, std::nullopt);
  EXPECT_NE(all.find("sis.csv: line 15, column 8: mark 'NP' at cause C_5 / effect E_1 has no meaning"), std::string::npos)
      << all;
  EXPECT_NE(all.find("sis.csv: line 16, column 4: setpoint '180' of cause '6': nothing says which side trips"),
            std::string::npos)
      << all;
  EXPECT_EQ(std::count(all.begin(), all.end(), '\n'), 2);
}

// The plant parameters can say which side a setpoint trips on (docs/csv.md
// "Setpoints"): read before the sheet, they are one more source that must
// agree with the others.
TEST(VendorSheet, TheParametersSayWhichSideTrips) {
  SheetLayout layout = minimal_layout();
  layout.trip_sides.clear();
  const std::string params =
      R"({"format": "cemv-params/1", "causes": {"6": {"analog": {"limit_type": "high", "limit": 180}}}})";
  CsvImportOptions opt;
  opt.sheet_layout = layout;
  opt.parameter_trip_sides = params_trip_sides(params, "plant.json");
  ASSERT_EQ(opt.parameter_trip_sides.size(), 1u);
  const auto r = import_csv(kSheet, "sis.csv", opt);
  EXPECT_EQ(r.matrix.find_cause(6)->analog->limit_type, LimitType::High);
  EXPECT_EQ(r.matrix.find_cause(6)->analog->limit, 180.0f);
  // A side the description contradicts is refused, naming both sources.
  opt.parameter_trip_sides = params_trip_sides(
      R"({"format": "cemv-params/1", "causes": {"2": {"analog": {"limit_type": "high"}}, "6": {"analog": {"limit_type": "low"}}}})",
      "plant.json");
  try {
    import_csv(kSheet, "sis.csv", opt);
    ADD_FAILURE() << "a contradicted trip side was imported";
  } catch (const LoadError& e) {
    std::string all;
    for (const auto& i : e.issues()) all += i.str() + "\n";
    EXPECT_NE(all.find("setpoint '20' of cause '2': the parameters' causes.2.analog.limit_type says high, the "
                       "description says low"),
              std::string::npos)
        << all;
  }
  EXPECT_THROW(params_trip_sides("{not json", "plant.json"), LoadError);
}

TEST(VendorSheet, TheLayoutUsedReadsTheSheetTheSameWhenGivenAgain) {
  const auto first = import(kSheet);
  const SheetLayout used = first.layout_used;
  EXPECT_EQ(used.orientation, CsvOrientation::CausesAsRows);
  EXPECT_EQ(used.causes.size(), 7u);
  EXPECT_EQ(used.effects.size(), 5u);
  EXPECT_EQ(used.footnotes.at("*"), "Trip delayed 10 s during start-up");
  const std::string saved = sheet_layout_json(used);
  const auto again = import(kSheet, parse_sheet_layout(saved, "saved.json"));
  EXPECT_EQ(signature(again.matrix), signature(first.matrix));
  EXPECT_NE(again.summary.find("as given by the layout's orientation"), std::string::npos);
  // The layout's places hold even where a header says nothing: 'Trip @' is no
  // known spelling, so without the layout it is a note.
  const std::string renamed = replaced(kSheet, "Item,Cause description,Tag,Setpoint", "Item,Cause description,Tag,Trip @");
  EXPECT_EQ(signature(import(renamed, parse_sheet_layout(saved, "saved.json")).matrix), signature(first.matrix));
  const auto unread = import(renamed);
  EXPECT_NE(unread.summary.find("label column 4 'Trip @' kept in the cause notes"), std::string::npos) << unread.summary;
  EXPECT_EQ(unread.matrix.find_cause(6)->note, "sheet id: 6; Trip @: 180; Unit: degC");
}

TEST(VendorSheet, VotingGroupsAreOneCauseOrRefused) {
  // Two rows where the voting says three.
  const std::string short_group = replaced(kSheet, ",,PT-1001C,,,,,,,\n", "");
  EXPECT_NE(refusal(short_group).find("line 9, column 6: voting '2oo3' of cause '1' over 2 tags (rows 9-10): it needs 3 tags"),
            std::string::npos)
      << refusal(short_group);
  // A member row with another unit, or another mark, than its group.
  EXPECT_NE(refusal(replaced(kSheet, ",,PT-1001B,,,,,,,", ",,PT-1001B,,psig,,,,,"))
                .find("line 10, column 5: 'psig' differs from the group's 'barg' in row 9"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kSheet, ",,PT-1001B,,,,,,,", ",,PT-1001B,,,,,N,,"))
                .find("line 10, column 8: mark 'N' differs from 'S' in line 9, column 8"),
            std::string::npos);
  // The group's tags in one cell, PT-1001A/B/C, is the same cause.
  std::string one_cell = replaced(kSheet, "PT-1001A,45", "PT-1001A/B/C,45");
  one_cell = replaced(replaced(one_cell, ",,PT-1001B,,,,,,,\n", ""), ",,PT-1001C,,,,,,,\n", "");
  const Cause& c = *import(one_cell).matrix.find_cause(1);
  ASSERT_EQ(c.tags.size(), 3u);
  EXPECT_EQ(c.tags[1].name, "PT-1001B");
  EXPECT_EQ(c.function, CauseFunction::TwoOoThree);
  // Tags without a voting, and a voting 6.3.1 cannot express.
  EXPECT_NE(refusal(replaced(kSheet, "TT-1006,180,degC,1oo1", "TT-1006/B,180,degC,")).find("has 2 tags (row 16) but no voting"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kSheet, "2oo3,2,S,N", "2oo4,2,S,N")).find("voting '2oo4' of cause '1' over 3 tags"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kSheet, "2oo3,2,S,N", "majority,2,S,N")).find("voting 'majority': not a voting"),
            std::string::npos);
}

TEST(VendorSheet, SetpointsBecomeAnalogLimitsWhenTheSideIsSaid) {
  // The side from the setpoint itself, or from a trip-side word after it.
  auto limit_of = [](const std::string& sheet, int cause) { return *import(sheet).matrix.find_cause(cause)->analog; };
  SheetLayout no_side = minimal_layout();
  no_side.trip_sides.clear();
  EXPECT_EQ(import(replaced(kSheet, "TT-1006,180,", "TT-1006,< 180,"), no_side).matrix.find_cause(6)->analog->limit_type,
            LimitType::Low);
  const auto hh = import(replaced(kSheet, "TT-1006,180,", "TT-1006,180 HH,"), no_side);
  EXPECT_EQ(hh.matrix.find_cause(6)->analog->limit_type, LimitType::High);
  // A unit written with the setpoint, when the unit column is empty; not another one.
  EXPECT_EQ(limit_of(replaced(kSheet, "TT-1006,180,degC", "TT-1006,180 degF,"), 6).unit, "degF");
  EXPECT_NE(refusal(replaced(kSheet, "TT-1006,180,degC", "TT-1006,180 degF,degC")).find("names the unit 'degF', the unit column 'degC'"),
            std::string::npos);
  // Two sources that disagree, and a description that names both sides.
  EXPECT_NE(refusal(replaced(kSheet, "Feed drum temperature,TT-1006,180", "Feed drum temperature low,TT-1006,180"))
                .find("the layout's trip_sides says high, the description says low"),
            std::string::npos);
  EXPECT_NE(refusal(replaced(kSheet, "Feed drum temperature,TT-1006,180", "Feed drum temperature high/low,TT-1006,180"),
                    no_side)
                .find("(the description names both)"),
            std::string::npos);
  // A switch's state is no number: a discrete cause, the state in its note.
  const auto pressed = import(replaced(kSheet, "HS-1003,-,-", "HS-1003,Pressed,-"));
  const Cause& sw = *pressed.matrix.find_cause(3);
  EXPECT_EQ(sw.input, InputKind::Discrete);
  EXPECT_EQ(sw.note, "sheet id: 3; Setpoint: Pressed");
  EXPECT_NE(refusal(replaced(kSheet, "1oo1,2,S*", "1oo1,SIL 5,S*")).find("line 12, column 7: SIL 'SIL 5' is not"),
            std::string::npos);
}

TEST(VendorSheet, DeletedRowsAreLeftOutAndListed) {
  // By the layout's words: here 'VOID' instead of the default 'DELETED'.
  SheetLayout words = minimal_layout();
  words.deleted.words = {"VOID"};
  const std::string voided = replaced(kSheet, "(DELETED Rev. C)", "VOID");
  const auto r = import(voided, words);
  EXPECT_EQ(r.matrix.find_cause(4), nullptr);
  EXPECT_NE(r.summary.find("row 14 (id '4': 'Feed pump suction pressure low VOID', 'VOID' in column 2)"),
            std::string::npos)
      << r.summary;
  // Without a rule that says so, the row is an active cause (a CSV has no strikethrough).
  words.deleted.words.clear();
  EXPECT_NE(import(voided, words).matrix.find_cause(4), nullptr);
  // A deleted voting group: all its rows are left out.
  const std::string deleted_group = replaced(kSheet, "Feed drum pressure high-high", "DELETED pressure trip");
  const auto g = import(deleted_group);
  EXPECT_EQ(g.matrix.find_cause(1), nullptr);
  EXPECT_EQ(g.matrix.causes.size(), 5u);
  EXPECT_EQ(g.matrix.find_intersection(1, 1), nullptr);
}

TEST(VendorSheet, EffectsAsRowsReadTheSame) {
  // The sheet transposed: the causes on the columns, the voting groups across them.
  std::vector<std::vector<std::string>> cells;
  std::size_t width = 0;
  for (std::size_t start = 0; start < std::string(kSheet).size();) {
    const std::string text(kSheet);
    const std::size_t end = text.find('\n', start);
    std::vector<std::string> row;
    std::string line = text.substr(start, end - start), cell;
    for (char ch : line + ",") {
      if (ch == ',') row.push_back(cell), cell.clear();
      else cell += ch;
    }
    width = std::max(width, row.size());
    cells.push_back(row);
    start = end + 1;
  }
  std::string transposed;
  for (std::size_t c = 0; c < width; ++c) {
    for (std::size_t r = 0; r < cells.size(); ++r) transposed += (r ? "," : "") + (c < cells[r].size() ? cells[r][c] : "");
    transposed += "\n";
  }
  const auto rows = import(kSheet);
  const auto columns = import(transposed);
  EXPECT_EQ(columns.orientation, CsvOrientation::EffectsAsRows);
  EXPECT_EQ(signature(columns.matrix), signature(rows.matrix)) << columns.summary;
  EXPECT_NE(columns.summary.find("voting groups: columns 9-11 (2oo3)"), std::string::npos) << columns.summary;
  EXPECT_NE(columns.summary.find("orientation effects-as-rows from the corner labels ('CAUSES' in line 1, column 3; "
                                 "'EFFECTS' in line 8, column 3) and the attribute headers"),
            std::string::npos)
      << columns.summary;
}

TEST(VendorSheet, FootnoteTextsAreGivenOnce) {
  const std::string legend = std::string(kSheet) + "*,Trip delayed 10 s during start-up\n";
  EXPECT_EQ(import(legend).matrix.find_intersection(2, 2)->note, "* Trip delayed 10 s during start-up");
  const std::string other = std::string(kSheet) + "*,Trip delayed 30 s\n";
  EXPECT_NE(refusal(other).find("footnote * reads 'Trip delayed 30 s' here and 'Trip delayed 10 s during start-up' in "
                                "the layout: give it one text"),
            std::string::npos)
      << refusal(other);
}

TEST(VendorValues, HeadersVotingSetpointsAndTags) {
  using grid::attribute_of_header;
  for (const auto& [header, attribute] : std::vector<std::pair<const char*, SheetAttribute>>{
           {"No.", SheetAttribute::Id},         {"#", SheetAttribute::Id},
           {"Item", SheetAttribute::Id},        {"Service", SheetAttribute::Description},
           {"Instrument tag", SheetAttribute::Tag}, {"Output tag", SheetAttribute::Tag},
           {"Set point", SheetAttribute::Setpoint}, {"Trip setting", SheetAttribute::Setpoint},
           {"Eng. units", SheetAttribute::Unit}, {"Vote", SheetAttribute::Voting},
           {"Voting logic", SheetAttribute::Voting}, {"SIL rating", SheetAttribute::Sil},
           {"Trip direction", SheetAttribute::TripSide}, {"Final action", SheetAttribute::Action},
           {"Remarks", SheetAttribute::Note}}) {
    const auto m = attribute_of_header(header);
    ASSERT_TRUE(m.has_value()) << header;
    EXPECT_EQ(m->attribute, attribute) << header;
  }
  EXPECT_EQ(attribute_of_header("Cause description")->kind, grid::ElementKind::Cause);
  EXPECT_FALSE(attribute_of_header("Causes/Detection").has_value());  // a corner label
  EXPECT_FALSE(attribute_of_header("Effects").has_value());
  EXPECT_FALSE(attribute_of_header("TMA-A-1").has_value());
  std::string problem;
  for (const char* v : {"2oo3", "2 oo 3", "2 out of 3", "2/3", "2OO3"}) {
    const auto voting = grid::parse_voting(v, problem);
    ASSERT_TRUE(voting.has_value()) << v;
    EXPECT_EQ(grid::function_of(*voting, 3), CauseFunction::TwoOoThree) << v;
  }
  EXPECT_EQ(grid::function_of(*grid::parse_voting("1oo2", problem), 2), CauseFunction::Or);
  EXPECT_EQ(grid::function_of(*grid::parse_voting("2oo2", problem), 2), CauseFunction::And);
  EXPECT_EQ(grid::function_of(*grid::parse_voting("3oo3", problem), 3), CauseFunction::And);
  EXPECT_EQ(grid::function_of(*grid::parse_voting("OR", problem), 3), CauseFunction::Or);
  EXPECT_FALSE(grid::function_of(*grid::parse_voting("1oo1", problem), 2).has_value());
  EXPECT_FALSE(grid::parse_voting("3oo2", problem).has_value());
  EXPECT_FALSE(grid::parse_voting("2 3", problem).has_value());
  EXPECT_EQ(grid::parse_setpoint("0,8")->value, 0.8);
  EXPECT_EQ(grid::parse_setpoint(">= -5")->side, LimitType::High);
  EXPECT_EQ(grid::parse_setpoint("45 barg")->rest, "barg");
  EXPECT_FALSE(grid::parse_setpoint("closed").has_value());
  EXPECT_EQ(grid::split_tags("PT-101A/B/C"), (std::vector<std::string>{"PT-101A", "PT-101B", "PT-101C"}));
  EXPECT_EQ(grid::split_tags("XV-1001 / XV-1002; XV-1003"), (std::vector<std::string>{"XV-1001", "XV-1002", "XV-1003"}));
  EXPECT_EQ(grid::parse_sil("SIL 3"), 3);
  EXPECT_EQ(grid::parse_sil("-"), 0);
  EXPECT_FALSE(grid::parse_sil("a").has_value());
}

}  // namespace
}  // namespace cemv::formats
