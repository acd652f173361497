// cemv-plc-map/1: reading, writing, and completing a map against a matrix and
// a program's interface (docs/plc.md "Map and relations").
#include <algorithm>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "formats/plc_map.hpp"
#include "plc_check/map.hpp"

namespace {

using namespace cemv;
using plc_check::ProgramInterface;
using plc_check::ProgramVariable;
using plc_check::VarKind;
using plc_check::VarType;

const std::string kTank = std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/";

model::Matrix tank() { return formats::load_valid_matrix(kTank + "matrix.json", "test"); }

// The interface of examples/tank-overfill/plc/tank_t100.st, as its VAR blocks declare it.
ProgramInterface tank_program() {
  ProgramInterface p;
  p.file = "tank_t100.st";
  p.pou = "TANK_T100";
  for (const char* real : {"LT_100A", "LT_100B", "LT_100C", "LT_102"}) p.variables.push_back({real, VarKind::Input, VarType::Real});
  for (const char* b : {"LT_100A_BQ", "LT_100B_BQ", "LT_100C_BQ", "LSHH_100", "LSHH_100_BQ", "HS_100_ESD",
                        "HS_100_ESD_BQ", "LT_102_BQ", "HS_100_BYP", "HS_101_RST", "XV_101_BPCS"})
    p.variables.push_back({b, VarKind::Input, VarType::Bool});
  for (const char* o : {"XV_101", "P_101_RUN", "P_102_RUN"}) p.variables.push_back({o, VarKind::Output, VarType::Bool});
  p.variables.push_back({"LT100_HH_REQ", VarKind::Local, VarType::Bool});
  p.variables.push_back({"LT100_HH_THR", VarKind::Local, VarType::Real});
  return p;
}

formats::PlcMap tank_map() {
  return formats::parse_plc_map(formats::read_text_file(kTank + "plc/tank_t100.map.json"), "tank_t100.map.json");
}

std::string messages(const formats::LoadError& e) {
  std::string s;
  for (const auto& i : e.issues()) s += i.message() + "\n";
  return s;
}

std::string resolve_error(const model::Matrix& m, const ProgramInterface& p, const formats::PlcMap* map) {
  try {
    plc_check::resolve_map(m, p, map, "given.map.json");
  } catch (const formats::LoadError& e) {
    return messages(e);
  }
  return "";
}

bool has(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

TEST(PlcMap, TankMapBindsEveryTagAndStatesItsAssumptions) {
  const auto map = tank_map();
  const auto r = plc_check::resolve_map(tank(), tank_program(), &map, "tank_t100.map.json");
  EXPECT_EQ(r.scan_ms, 100u);
  ASSERT_EQ(r.map.inputs.size(), 9u);
  EXPECT_EQ(r.map.inputs[0].variable, "LT_100A");
  EXPECT_EQ(r.map.inputs[0].bad_quality, "LT_100A_BQ");
  EXPECT_EQ(r.map.inputs[3].tag, "HS_100_BYP");
  EXPECT_TRUE(r.map.inputs[3].bad_quality.empty());  // a bypass tag has no quality (I.2)
  ASSERT_EQ(r.map.outputs.size(), 3u);
  EXPECT_EQ(r.map.outputs[0].variable, "XV_101");
  EXPECT_EQ(r.map.commands.size(), 3u);
  // Causes 1, 2 and 4 allow a soft bypass: 6 commands; 5 tags allow theirs: 10;
  // 6 cause inputs and 3 outputs can be simulated: 9.
  EXPECT_TRUE(has(r.assumptions, "soft_bypass_cause never issued (declared unused): 6 commands"));
  EXPECT_TRUE(has(r.assumptions, "soft_bypass_tag never issued (declared unused): 10 commands"));
  EXPECT_TRUE(has(r.assumptions, "simulate_tag never issued (declared unused): 9 commands"));
  EXPECT_EQ(r.assumptions.size(), 3u);
}

TEST(PlcMap, FoundByNameIgnoringCaseAndSeparators) {
  auto p = tank_program();
  for (auto& v : p.variables)
    if (v.name == "LT_100A") v.name = "lt100a";
    else if (v.name == "LT_100A_BQ") v.name = "Lt-100a-bad";
    else if (v.name == "XV_101") v.name = "xv101";
  formats::PlcMap map;  // only the commands: everything else by name
  map.commands = tank_map().commands;
  const auto r = plc_check::resolve_map(tank(), p, &map, "m.json");
  EXPECT_EQ(r.map.inputs[0].variable, "lt100a");
  EXPECT_EQ(r.map.inputs[0].bad_quality, "Lt-100a-bad");
  EXPECT_EQ(r.map.outputs[0].variable, "xv101");
  EXPECT_TRUE(has(r.assumptions, "scan time 100 ms, the matrix's cycle"));
}

TEST(PlcMap, WithoutAMapTheCommandsAreListed) {
  const std::string err = resolve_error(tank(), tank_program(), nullptr);
  EXPECT_NE(err.find("tank_t100.st: error: operator commands the matrix accepts without a program variable"),
            std::string::npos) << err;
  EXPECT_NE(err.find("soft_bypass_cause cause 1 LT100_HH on"), std::string::npos) << err;
  EXPECT_NE(err.find("simulate_tag tag LT_100A"), std::string::npos) << err;
}

TEST(PlcMap, CommandsFoundByTheirDefaultNames) {
  auto p = tank_program();
  for (const auto& s : plc_check::command_slots(tank()))
    if (s.command.op != model::CommandOp::SimulateTag) p.variables.push_back({s.default_name, VarKind::Input, VarType::Bool});
  formats::PlcMap map;
  formats::PlcCommandBinding sim;
  sim.op = model::CommandOp::SimulateTag;
  map.commands.push_back(sim);
  const auto r = plc_check::resolve_map(tank(), p, &map, "m.json");
  ASSERT_EQ(r.map.commands.size(), 17u);
  EXPECT_EQ(r.map.commands[1].variable, "LT100_HH_SOFT_BYPASS_ON");
  EXPECT_EQ(r.map.commands[5].variable, "LT100_HH_TAG2_SOFT_BYPASS_ON");
  EXPECT_EQ(r.map.commands[1].cause, 1);
  EXPECT_EQ(r.map.commands[1].on, std::optional<bool>(true));
}

TEST(PlcMap, UnmatchedTagsAndProgramInputsAreErrors) {
  auto p = tank_program();
  p.variables.erase(std::remove_if(p.variables.begin(), p.variables.end(),
                                   [](const ProgramVariable& v) { return v.name == "LT_102" || v.name == "P_102_RUN"; }),
                    p.variables.end());
  p.variables.push_back({"SPARE_DI", VarKind::Input, VarType::Bool});
  const auto map = tank_map();
  std::string err = resolve_error(tank(), p, &map);
  EXPECT_NE(err.find("input tag LT_102: the program has no variable 'LT_102'"), std::string::npos) << err;
  EXPECT_NE(err.find("output tag P_102_RUN of effect 3: the program has no variable 'P_102_RUN'"), std::string::npos) << err;
  EXPECT_NE(err.find("program inputs without a matrix counterpart (bind them or hold them at a value in the map's "
                     "program_inputs): LT_102_BQ, SPARE_DI"), std::string::npos) << err;
  // Held at a value, the spare input and a missing tag become assumptions.
  auto held = map;
  for (const char* v : {"SPARE_DI", "LT_102_BQ"}) {
    formats::PlcProgramInput x;
    x.variable = v;
    held.program_inputs.push_back(x);
  }
  for (auto& b : held.inputs)
    if (b.tag == "LT_102") {
      b = formats::PlcInputBinding{};
      b.tag = "LT_102";
      b.value = 50.0;
    }
  held.outputs.pop_back();
  p.variables.push_back({"P_102_RUN", VarKind::Output, VarType::Bool});
  const auto r = plc_check::resolve_map(tank(), p, &held, "m.json");
  EXPECT_TRUE(has(r.assumptions, "input tag LT_102 held at 50 with good quality"));
  EXPECT_TRUE(has(r.assumptions, "program input SPARE_DI held at 0"));
}

TEST(PlcMap, WrongTypesKindsAndScanTimeAreErrors) {
  auto p = tank_program();
  for (auto& v : p.variables)
    if (v.name == "LT_100B") v.type = VarType::Int;
    else if (v.name == "XV_101") v.kind = VarKind::Local;
  p.task_ms = 50;
  auto map = tank_map();
  map.scan_ms.reset();
  const std::string err = resolve_error(tank(), p, &map);
  EXPECT_NE(err.find("input tag LT_100B: LT_100B is an integer, not REAL"), std::string::npos) << err;
  EXPECT_NE(err.find("XV_101 is not a VAR_OUTPUT of TANK_T100"), std::string::npos) << err;
  EXPECT_NE(err.find("scan time 50 ms differs from the matrix's cycle 100 ms"), std::string::npos) << err;
}

TEST(PlcMap, OneVariableForTwoThingsIsAnError) {
  auto map = tank_map();
  map.outputs[1].variable = "XV_101";
  const std::string err = resolve_error(tank(), tank_program(), &map);
  EXPECT_NE(err.find("program variable XV_101 is bound to two things of the matrix"), std::string::npos) << err;
}

TEST(PlcMap, AmbiguousNamesAreErrors) {
  auto p = tank_program();
  p.variables.push_back({"LT100A", VarKind::Input, VarType::Real});
  formats::PlcMap map;
  map.commands = tank_map().commands;
  const std::string err = resolve_error(tank(), p, &map);
  EXPECT_NE(err.find("input tag LT_100A matches several program variables by name (LT_100A, LT100A)"),
            std::string::npos) << err;
}

TEST(PlcMap, ReaderPlacesProblems) {
  const std::string text =
      "{\n  \"format\": \"cemv-plc-map/1\",\n  \"inputs\": [\n    { \"tag\": \"A\", \"variable\": \"X\", \"value\": 1 },\n"
      "    { \"tag\": \"B\", \"colour\": 3 }\n  ],\n  \"commands\": [ { \"command\": \"reboot\", \"unused\": true } ],\n"
      "  \"scan_ms\": 0\n}\n";
  try {
    formats::parse_plc_map(text, "bad.json");
    FAIL() << "accepted";
  } catch (const formats::LoadError& e) {
    const std::string err = messages(e);
    EXPECT_NE(err.find("bad.json:4:5: error: inputs[0]: give the tag either a \"variable\" or the \"value\""),
              std::string::npos) << err;
    EXPECT_NE(err.find("bad.json:5:19: error: inputs[1].colour: unknown key"), std::string::npos) << err;
    EXPECT_NE(err.find("commands[0].command: unknown command 'reboot'"), std::string::npos) << err;
    EXPECT_NE(err.find("bad.json:8:3: error: scan_ms: must be a whole number"), std::string::npos) << err;
  }
  EXPECT_THROW(formats::parse_plc_map("{\"format\": \"cemv-plc-map/2\"}", "v2.json"), formats::LoadError);
  EXPECT_THROW(formats::parse_plc_map("  ", "empty.json"), formats::LoadError);
  EXPECT_THROW(formats::parse_plc_map("[1, 2", "broken.json"), formats::LoadError);
}

// Seeded random maps: written, read back, written again byte for byte.
TEST(PlcMap, RandomMapsRoundTrip) {
  std::mt19937 rng(39);
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  auto ident = [&] {
    std::string s = "V";
    for (int i = pick(12); i >= 0; --i) s += "ABCXYZ_019-"[pick(11)];
    return s;
  };
  for (int round = 0; round < 200; ++round) {
    formats::PlcMap m;
    if (pick(2)) m.pou = ident();
    if (pick(2)) m.scan_ms = 1 + pick(1000);
    for (int i = pick(6); i > 0; --i) {
      formats::PlcInputBinding b;
      b.tag = ident();
      if (pick(3)) b.variable = ident();
      else b.value = pick(2) ? pick(200) - 100 : (pick(1000) / 8.0);
      if (!b.variable.empty() && pick(2)) {
        if (pick(2)) b.bad_quality = ident();
        else b.good_quality = true;
      }
      m.inputs.push_back(b);
    }
    for (int i = pick(4); i > 0; --i) {
      formats::PlcOutputBinding o;
      o.tag = ident();
      o.effect = pick(3) ? 0 : 1 + pick(9);
      o.variable = ident();
      m.outputs.push_back(o);
    }
    for (int i = pick(5); i > 0; --i) {
      formats::PlcCommandBinding c;
      c.op = static_cast<model::CommandOp>(pick(9));
      if (pick(2)) c.cause = 1 + pick(5);
      if (pick(2)) c.effect = 1 + pick(5);
      if (pick(2)) c.tag = 1 + pick(3);
      if (pick(3) == 0) c.tag_name = ident();
      if (pick(2)) c.on = pick(2) == 1;
      if (pick(2)) c.variable = ident();
      m.commands.push_back(c);
    }
    for (int i = pick(3); i > 0; --i) {
      formats::PlcProgramInput x;
      x.variable = ident();
      x.value = pick(2);
      m.program_inputs.push_back(x);
    }
    const std::string once = formats::plc_map_json(m);
    const std::string twice = formats::plc_map_json(formats::parse_plc_map(once, "round.json"));
    ASSERT_EQ(once, twice) << "round " << round;
  }
}

}  // namespace
