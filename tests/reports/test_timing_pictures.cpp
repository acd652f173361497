// The timing diagram (SVG) and value change dump (VCD) writers on a real run:
// an example scenario replayed on the reference runtime. Golden files under
// golden/ pin the exact bytes (CEMV_UPDATE_GOLDEN=1 rewrites them; review the
// diff); the VCD is also read back by a small reader here and must give every
// value of the run at every cycle.
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "model/vocabulary.hpp"
#include "reports/timing_svg.hpp"
#include "reports/vcd.hpp"
#include "runtime/runtime.hpp"

namespace {

using cemv::checker::ConcreteTrace;
namespace model = cemv::model;
namespace reports = cemv::reports;

const std::string kExample = std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/";

ConcreteTrace run(const model::Matrix& m, const std::vector<model::CycleInput>& cycles) {
  cemv::runtime::Runtime rt(m);
  ConcreteTrace t;
  std::vector<int> snap;
  for (const auto& in : cycles) {
    rt.step(in);
    rt.snapshot(snap);
    t.inputs.push_back(in);
    t.observables.push_back(snap);
  }
  return t;
}

ConcreteTrace scenario_run(const model::Matrix& m, const std::string& file) {
  auto sc = cemv::formats::load_scenario(kExample + file, m);
  return run(m, cemv::formats::expand_scenario(sc, m).cycles);
}

void golden(const std::string& name, const std::string& actual) {
  std::string path = std::string(CEMV_GOLDEN_DIR) + "/" + name;
  if (std::getenv("CEMV_UPDATE_GOLDEN")) {
    std::ofstream(path, std::ios::binary) << actual;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  ASSERT_TRUE(in) << path << " missing (CEMV_UPDATE_GOLDEN=1 writes it)";
  std::stringstream expected;
  expected << in.rdbuf();
  EXPECT_EQ(expected.str(), actual) << "differs from " << path;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(TimingSvg, ScenarioRunMatchesGolden) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "drawn");
  ConcreteTrace t = scenario_run(m, "scenario-1-overfill-trip.json");
  reports::TimingDiagram d;
  d.title = "scenario-1-overfill-trip";
  d.all_changing = true;
  d.marks.push_back({t.inputs.size() - 1, "expectation failed: example mark"});
  std::string svg = reports::timing_svg(m, t, d);
  EXPECT_EQ(svg, reports::timing_svg(m, t, d));  // deterministic
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);  // self-contained
  // The analog level transmitters with the cause's limit, prewarning and release lines.
  EXPECT_NE(svg.find(">LT_100A<"), std::string::npos);
  EXPECT_NE(svg.find("high limit 90"), std::string::npos);
  EXPECT_NE(svg.find("prewarning 85"), std::string::npos);
  EXPECT_GE(count(svg, "class=\"bad\""), 1u);    // LT_100B's bad quality
  EXPECT_GE(count(svg, "class=\"timer\""), 1u);  // the 2 s on-delay running
  EXPECT_EQ(count(svg, "class=\"mark\""), 1u);
  golden("timing_scenario1.svg", svg);
}

// 3,000 cycles of which only a handful change: the quiet stretches fold and
// the picture keeps a sensible width, and says what it folded.
TEST(TimingSvg, LongRunFoldsConstantStretches) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "drawn");
  model::InputTable table(m);
  std::vector<model::CycleInput> cycles(3000, model::default_cycle_input(m));
  for (std::size_t k = 1500; k < 1600; ++k)
    for (const char* tag : {"LT_100A", "LT_100B", "LT_100C"}) cycles[k].tags[*table.find(tag)].value = 95.0f;
  ConcreteTrace t = run(m, cycles);
  reports::TimingDiagram d;
  d.title = "long";
  d.shown = {"cause[1].active", "cause[1].timer_running"};
  d.marks.push_back({1520, "violated: example"});
  std::string svg = reports::timing_svg(m, t, d);
  auto w = svg.find("width=\"");
  double width = std::stod(svg.substr(w + 7));
  EXPECT_LT(width, 2500.0);
  EXPECT_NE(svg.find("3000 cycles of 100 ms"), std::string::npos);
  EXPECT_NE(svg.find("Folded: cycles 4-1499 (1496 cycles"), std::string::npos);
  EXPECT_NE(svg.find("unchanged cycles folded"), std::string::npos);
  golden("timing_long.svg", svg);
}

// Drawn as it runs: the recorder, fed one cycle at a time and holding no
// trace, writes the bytes timing_svg writes for the whole trace; so on the
// scenario with bad quality, timers and commands.
TEST(TimingSvg, RecorderCycleByCycleGivesTheSameBytes) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "drawn");
  for (const char* file : {"scenario-1-overfill-trip.json", "scenario-2-bypass-timer.json",
                           "scenario-3-low-level-esd.json"}) {
    auto sc = cemv::formats::load_scenario(kExample + file, m);
    auto cycles = cemv::formats::expand_scenario(sc, m).cycles;
    ConcreteTrace t = run(m, cycles);
    reports::TimingDiagram d;
    d.title = file;
    d.all_changing = true;
    d.checks = {0, cycles.size() / 2};
    d.marks.push_back({cycles.size() / 3, "expectation failed: x"});
    reports::TimingRecorder rec(m, d);
    for (std::size_t k = 0; k < cycles.size(); ++k) rec.add(t.inputs[k], t.observables[k]);
    EXPECT_EQ(rec.svg(), reports::timing_svg(m, t, d)) << file;
  }
}

// A short run gives a narrow picture: the title, the mark and the legend wrap
// onto more lines instead of running past its right edge, and no word is lost.
TEST(TimingSvg, NarrowDiagramWrapsHeaderAndLegendInsideItsWidth) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "drawn");
  std::vector<model::CycleInput> cycles(3, model::default_cycle_input(m));
  ConcreteTrace t = run(m, cycles);
  reports::TimingDiagram d;
  d.title = "Counterexample to req5.stored_holds: effect 1 stays active while any cause of SIF 1 is active, "
            "also after a reset command from the operator panel";
  d.shown = {"effect[1].active"};
  d.marks.push_back({2, "violated: req5.stored_holds_with_a_very_long_property_name_that_has_no_spaces_at_all_x"});
  const std::string svg = reports::timing_svg(m, t, d);
  const double width = std::stod(svg.substr(svg.find("width=\"") + 7));
  EXPECT_LE(width, 700.0);  // narrow: 3 cycles
  std::string title_text;
  std::size_t texts = 0;
  for (auto p = svg.find("<text"); p != std::string::npos; p = svg.find("<text", p + 1)) {
    const std::string tag = svg.substr(p, svg.find('>', p) - p);
    if (tag.find("text-anchor") != std::string::npos || tag.find("x=\"10\"") == std::string::npos) continue;
    const std::size_t from = svg.find('>', p) + 1;
    std::string content = svg.substr(from, svg.find("</text>", from) - from);
    double size = tag.find("title") != std::string::npos ? 15 : tag.find("small") != std::string::npos ? 10 : 12;
    double factor = tag.find("title") != std::string::npos || tag.find("marktext") != std::string::npos ? 0.66 : 0.6;
    EXPECT_LE(10 + content.size() * size * factor, width) << content;
    if (tag.find("class=\"title\"") != std::string::npos) title_text += (title_text.empty() ? "" : " ") + content;
    ++texts;
  }
  EXPECT_GT(texts, 6u);
  EXPECT_EQ(title_text, d.title);
  EXPECT_GE(count(svg, "class=\"title\""), 2u);  // the title took more than one line
  EXPECT_NE(svg.find(">Cycle n starts at t = (n-1) x 100 ms;"), std::string::npos);  // the legend is still there
}

// ---- VCD ------------------------------------------------------------------

// A small reader of what the writer emits: variables with their scope path,
// and the value of each code at each time.
struct VcdFile {
  std::map<std::string, std::string> code_of;  // "TANK.inputs.LT_100A" -> code
  std::map<std::string, std::string> type_of;  // code -> "wire"/"real"/"integer"
  std::map<std::uint64_t, std::map<std::string, std::string>> changes;  // time -> code -> value
  std::string timescale;

  explicit VcdFile(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> scope;
    std::string tok;
    bool defs = true;
    std::uint64_t now = 0;
    while (in >> tok) {
      if (defs) {
        if (tok == "$scope") {
          std::string kind, name;
          in >> kind >> name >> tok;
          scope.push_back(name);
        } else if (tok == "$upscope") {
          in >> tok;
          scope.pop_back();
        } else if (tok == "$var") {
          std::string type, size, code, name, end;
          in >> type >> size >> code >> name >> end;
          EXPECT_EQ(end, "$end");
          std::string path;
          for (const auto& s : scope) path += s + ".";
          code_of[path + name] = code;
          type_of[code] = type;
        } else if (tok == "$timescale") {
          std::string a;
          while (in >> a && a != "$end") timescale += (timescale.empty() ? "" : " ") + a;
        } else if (tok == "$enddefinitions") {
          in >> tok;
          defs = false;
        } else if (tok[0] == '$') {
          while (tok != "$end" && in >> tok) {}
        }
        continue;
      }
      if (tok == "$dumpvars" || tok == "$end") continue;
      if (tok[0] == '#') {
        now = std::stoull(tok.substr(1));
      } else if (tok[0] == 'b' || tok[0] == 'r') {
        std::string code;
        in >> code;
        changes[now][code] = tok;
      } else {
        changes[now][tok.substr(1)] = tok.substr(0, 1);
      }
    }
  }

  // The value of `code` at time `t` (the last change at or before t).
  std::string at(const std::string& code, std::uint64_t t) const {
    std::string v = "?";
    for (const auto& [time, vals] : changes) {
      if (time > t) break;
      if (auto it = vals.find(code); it != vals.end()) v = it->second;
    }
    return v;
  }
};

TEST(Vcd, ReadsBackEveryValueOfTheRun) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "dumped");
  ConcreteTrace t = scenario_run(m, "scenario-1-overfill-trip.json");
  std::string text = reports::vcd(m, t, {"", "test", "scenario 1"});
  EXPECT_EQ(text, reports::vcd(m, t, {"", "test", "scenario 1"}));
  VcdFile f(text);
  EXPECT_EQ(f.timescale, "1 ms");
  model::InputTable table(m);
  const std::string top = m.name + ".";
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& tag = table.tags()[i];
    ASSERT_TRUE(f.code_of.count(top + "inputs." + tag.name)) << tag.name;
    std::string code = f.code_of[top + "inputs." + tag.name];
    for (std::size_t k = 0; k < t.inputs.size(); ++k) {
      std::string v = f.at(code, k * m.cycle_ms);
      if (tag.kind == model::TagKind::Analog) {
        ASSERT_EQ(v[0], 'r');
        EXPECT_EQ(std::stof(v.substr(1)), t.inputs[k].tags[i].value) << tag.name << " cycle " << k + 1;
      } else {
        EXPECT_EQ(v, t.inputs[k].tags[i].value != 0 ? "1" : "0") << tag.name << " cycle " << k + 1;
      }
    }
  }
  // Every status field, in its element's scope.
  const auto obs = model::observables(m);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    const auto& o = obs[i];
    std::string scope_prefix = o.kind == model::Node::Kind::Cause ? "cause_" : "effect_";
    std::string found;
    for (const auto& [path, code] : f.code_of) {
      std::string want_scope = top + scope_prefix + std::to_string(o.id) + "_";
      if (path.rfind(want_scope, 0) != 0) continue;
      std::string leaf = path.substr(path.rfind('.') + 1);
      if (o.field != "tag" ? leaf == o.field
                           : leaf == "out_" + m.find_effect(o.id)->tags[std::size_t(o.tag - 1)].name)
        found = code;
    }
    ASSERT_FALSE(found.empty()) << o.key;
    for (std::size_t k = 0; k < t.inputs.size(); ++k) {
      std::string v = f.at(found, k * m.cycle_ms);
      int expected = t.observables[k][i];
      int actual = v[0] == 'b' ? std::stoi(v.substr(1), nullptr, 2) : std::stoi(v);
      EXPECT_EQ(actual, o.type == model::FieldType::Bool ? (expected != 0) : expected) << o.key << " cycle " << k + 1;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
  // A cause's scope also shows its input tags, under the same code.
  EXPECT_EQ(f.code_of[top + "cause_1_LT100_HH.in_LT_100A"], f.code_of[top + "inputs.LT_100A"]);
  golden("scenario1.vcd", text);
}

// `cemv check --vcd FILE`: several runs in one dump, a scope each, every run
// from time 0; the shorter one keeps its last values.
TEST(Vcd, SeveralRunsEachInItsScopeFromTimeZero) {
  model::Matrix m = cemv::formats::load_valid_matrix(kExample + "matrix.json", "dumped");
  ConcreteTrace a = scenario_run(m, "scenario-1-overfill-trip.json");
  std::vector<model::CycleInput> quiet(3, model::default_cycle_input(m));
  ConcreteTrace b = run(m, quiet);
  std::string text = reports::vcd_runs(m, {{"req5.stored_holds", &a}, {"req7.reach", &b}}, {"", "test", "two runs"});
  VcdFile f(text);
  const std::string top = m.name + ".";
  model::InputTable table(m);
  const std::size_t lt = *table.find("LT_100A");
  const std::string ca = f.code_of[top + "req5_stored_holds.inputs.LT_100A"];
  const std::string cb = f.code_of[top + "req7_reach.inputs.LT_100A"];
  ASSERT_FALSE(ca.empty());
  ASSERT_FALSE(cb.empty());
  EXPECT_NE(ca, cb);
  for (std::size_t k = 0; k < a.inputs.size(); ++k) {
    EXPECT_EQ(std::stof(f.at(ca, k * m.cycle_ms).substr(1)), a.inputs[k].tags[lt].value) << k;
    const auto& last = b.inputs[std::min(k, b.inputs.size() - 1)].tags[lt];
    EXPECT_EQ(std::stof(f.at(cb, k * m.cycle_ms).substr(1)), last.value) << k;
  }
  EXPECT_NE(text.find("2 runs, each from time 0: req5_stored_holds (" + std::to_string(a.inputs.size()) +
                      " cycles) req7_reach (3 cycles)"),
            std::string::npos);
  // One run alone is the dump of `vcd`, inside its own scope.
  EXPECT_EQ(count(text, "$enddefinitions"), 1u);
}

}  // namespace
