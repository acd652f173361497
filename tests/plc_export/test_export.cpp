// `cemv export-st` (docs/plc.md "Generated programs"): the program of every
// example and of 40 seeded random matrices is inside the subset (read back
// and checked by plc/'s own reader, as ST and as PLCopen XML), its map is
// complete for plc-check, and the program's interpreter gives the matrix
// runtime's output tags in every scan of seeded random input sequences.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "plc/interpreter.hpp"
#include "plc/parser.hpp"
#include "plc/plcopen.hpp"
#include "plc/print.hpp"
#include "plc_check/check.hpp"
#include "plc_check/map.hpp"
#include "plc_export/export.hpp"
#include "runtime/runtime.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv::plc_export {
namespace {

const char* const kExamples[] = {"burner-management", "compressor", "pipeline-hipps", "tank-overfill"};

model::Matrix example(const std::string& name) {
  return formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json", "exported");
}

// The 40 random matrices of the translation validation.
model::Matrix random(int i) { return testsupport::random_matrix(static_cast<std::uint64_t>(1000 + i)); }

plc_check::VarType var_type(const plc::VarType& t) {
  if (t.kind != plc::VarType::Kind::Elementary) return plc_check::VarType::Other;
  switch (t.type) {
    case plc::Type::Bool: return plc_check::VarType::Bool;
    case plc::Type::Real: return plc_check::VarType::Real;
    case plc::Type::Time: return plc_check::VarType::Time;
    default: return plc_check::VarType::Int;
  }
}

// The generated program's interface, as plc-check reads it.
plc_check::ProgramInterface interface_of(const plc::Program& p) {
  plc_check::ProgramInterface iface;
  iface.file = "generated.st";
  iface.pou = p.pous.front().name;
  for (const auto& v : p.pous.front().variables) {
    const auto kind = v.section == plc::Section::Input    ? plc_check::VarKind::Input
                      : v.section == plc::Section::Output ? plc_check::VarKind::Output
                                                          : plc_check::VarKind::Local;
    iface.variables.push_back({v.name, kind, var_type(v.type)});
  }
  return iface;
}

// Reads the program back both ways and completes its map against it.
plc::Program read_back(const model::Matrix& m, const Export& e) {
  const std::string st = plc::print_program(e.program);
  plc::Program p = plc::parse_st(st, "generated.st");
  // Printing what was read gives the same statements: the text is the tree.
  EXPECT_EQ(plc::print_program(p), plc::print_program(plc::without_positions(e.program)));
  const plc::Program x = plc::parse_plcopen(plc::write_plcopen(e.program), "generated.xml");
  EXPECT_EQ(plc::print_program(x), plc::print_program(p));
  EXPECT_EQ(x.scan_time_ms, std::optional<std::int64_t>(m.cycle_ms));
  const auto resolved = plc_check::resolve_map(m, interface_of(p), &e.map, "generated.map.json");
  EXPECT_EQ(formats::plc_map_json(resolved.map), formats::plc_map_json(e.map))
      << "the map the generator writes is complete: plc-check finds nothing to add";
  // the map survives its own format
  EXPECT_EQ(formats::plc_map_json(formats::parse_plc_map(formats::plc_map_json(e.map), "map")),
            formats::plc_map_json(e.map));
  return p;
}

bool program_command(model::CommandOp op) {
  return op == model::CommandOp::AckCause || op == model::CommandOp::ResetEffect ||
         op == model::CommandOp::OverrideEffect || op == model::CommandOp::StopOverride;
}

// The frames with the commands the map declares unused (soft bypasses,
// simulation) left out: what the program's proof assumes.
std::vector<model::CycleInput> allowed_inputs(const model::Matrix& m, std::uint64_t seed, int cycles) {
  auto frames = testsupport::random_inputs(m, seed, cycles);
  for (auto& f : frames) {
    std::vector<model::Command> kept;
    for (const auto& c : f.commands)
      if (program_command(c.op) || c.op == model::CommandOp::ClearAlarms || c.op == model::CommandOp::ClearFirstOut)
        kept.push_back(c);
    f.commands = kept;
  }
  return frames;
}

// One frame as the program's inputs, through the map.
std::map<std::string, plc::Value> program_frame(const model::InputTable& table, const formats::PlcMap& map,
                                                const plc::Pou& pou, const model::CycleInput& in) {
  std::map<std::string, plc::Value> out;
  for (const auto& b : map.inputs) {
    const auto i = table.find(b.tag);
    const model::TagValue v = in.tags[*i];
    const plc::Variable* var = plc::find_variable(pou, b.variable);
    if (var->type.type == plc::Type::Real) out[b.variable] = plc::Value{plc::Type::Real, 0, v.value};
    else out[b.variable] = plc::Value{plc::Type::Bool, v.value != 0.0f ? 1 : 0, 0.0f};
    if (!b.bad_quality.empty()) out[b.bad_quality] = plc::Value{plc::Type::Bool, v.bad_quality ? 1 : 0, 0.0f};
  }
  for (const auto& b : map.commands) {
    if (b.variable.empty()) continue;
    bool issued = false;
    for (const auto& c : in.commands)
      issued = issued || (c.op == b.op && c.cause == b.cause && c.effect == b.effect);
    out[b.variable] = plc::Value{plc::Type::Bool, issued ? 1 : 0, 0.0f};
  }
  return out;
}

// Runs the program and the matrix side by side; the first scan where an
// output tag differs, described, or "".
std::string differential(const model::Matrix& m, const Export& e, const plc::Program& p, std::uint64_t seed,
                         int cycles) {
  runtime::Runtime rt(m);
  plc::Interpreter run(p);
  const model::InputTable table(m);
  std::map<std::string, model::Observable> observable;
  for (const auto& o : model::observables(m)) observable.emplace(o.key, o);
  const auto frames = allowed_inputs(m, seed, cycles);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    rt.step(frames[k]);
    run.step(program_frame(table, e.map, run.pou(), frames[k]), m.cycle_ms);
    for (const auto& b : e.map.outputs) {
      int effect = b.effect, position = 0;
      for (const auto& ef : m.effects)
        for (std::size_t j = 0; j < ef.tags.size(); ++j)
          if ((b.effect == 0 || b.effect == ef.id) && position == 0 && ef.function != model::EffectFunction::Comment &&
              model::tag_key(ef.tags[j].name) == model::tag_key(b.tag)) {
            effect = ef.id;
            position = static_cast<int>(j + 1);
          }
      const std::string key =
          model::observable_key({model::Node::Kind::Effect, effect}, "tag", position);
      const int want = rt.value(observable.at(key));
      const int got = static_cast<int>(run.value(b.variable).integer);
      if (want != got) {
        std::ostringstream s;
        s << "seed " << seed << ", scan " << (k + 1) << ": " << key << " (" << b.variable << ") matrix " << want
          << ", program " << got;
        return s.str();
      }
    }
  }
  return "";
}

TEST(ExportSt, EveryExampleReadsBackAndRunsAsItsMatrix) {
  for (const char* name : kExamples) {
    SCOPED_TRACE(name);
    const model::Matrix m = example(name);
    const Export e = export_program(m);
    const plc::Program p = read_back(m, e);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::string diff = differential(m, e, p, seed, 300);
      ASSERT_EQ(diff, "") << name;
    }
  }
}

TEST(ExportSt, FortyRandomMatricesReadBackAndRunAsTheirMatrices) {
  for (int i = 0; i < 40; ++i) {
    const model::Matrix m = random(i);
    SCOPED_TRACE("random matrix " + std::to_string(1000 + i));
    const Export e = export_program(m);
    const plc::Program p = read_back(m, e);
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const std::string diff = differential(m, e, p, seed, 200);
      ASSERT_EQ(diff, "") << plc::print_program(e.program);
    }
  }
}

// The options the generator implements, each on many random matrices: the
// matrices of these seeds between them use every option of the format.
TEST(ExportSt, ManyRandomMatricesRunAsTheirMatrices) {
  for (int i = 0; i < 300; ++i) {
    const model::Matrix m = testsupport::random_matrix(static_cast<std::uint64_t>(5000 + i));
    SCOPED_TRACE("random matrix " + std::to_string(5000 + i));
    const Export e = export_program(m);
    const plc::Program p = plc::parse_st(plc::print_program(e.program), "generated.st");
    const std::string diff = differential(m, e, p, static_cast<std::uint64_t>(i), 150);
    ASSERT_EQ(diff, "") << plc::print_program(e.program);
  }
}

// Translation validation of the 40 random matrices' programs (issue 39): every
// output tag of every program proved equal by plc-check's decision, with its
// default budgets. One case per matrix, so that ctest spreads them over the
// cores. Budgets are work, so the answers are the same on every machine.
class FortyRandomPrograms : public ::testing::TestWithParam<int> {};

// Every output of the matrix's generated program proved equal, by the
// correspondence of the two states, not by the engines that decide an output
// alone when it is missing (random matrix 1037's outputs went to BMC and the
// portfolio, 200 s, before the seeded runs drew each input near its own
// limits).
void expect_proved_by_correspondence(const model::Matrix& m, const std::string& what) {
  const Export e = export_program(m);
  const plc::Program p = plc::parse_st(plc::print_program(e.program), "generated.st");
  const auto map = plc_check::resolve_map(m, interface_of(p), &e.map, "generated.map.json");
  const auto questions = plc_check::questions(m, map);
  ASSERT_FALSE(questions.empty());
  for (const auto& q : questions) {
    const auto r = plc_check::check_output(m, p, p.pous.front(), map, q, {});
    EXPECT_EQ(r.verdict, plc_check::OutputVerdict::Related)
        << what << " " << q.tag << ": " << plc_check::to_string(r.verdict) << " " << r.reason;
    EXPECT_EQ(r.method, "correspondence invariants") << what << " " << q.tag;
  }
}

TEST_P(FortyRandomPrograms, ProvedEqual) {
  const int i = GetParam();
  expect_proved_by_correspondence(random(i), "random matrix " + std::to_string(1000 + i));
}

// The proof by cone groups decides as each output alone does: on small
// seeded random matrices (several outputs, cones shared or apart) every
// output's verdict is the same with and without the groups.
TEST(ExportSt, GroupsDecideAsEachOutputAlone) {
  testsupport::MatrixOptions o;
  o.min_causes = 2;
  o.max_causes = 4;
  o.min_effects = 2;
  o.max_effects = 3;
  for (std::uint64_t seed = 7000; seed < 7004; ++seed) {
    const model::Matrix m = testsupport::random_matrix(seed, o);
    const Export e = export_program(m);
    const plc::Program p = read_back(m, e);
    const auto map = plc_check::resolve_map(m, interface_of(p), &e.map, "generated.map.json");
    plc_check::CheckOptions alone;
    alone.by_groups = false;
    for (const auto& q : plc_check::questions(m, map)) {
      const auto grouped = plc_check::check_output(m, p, p.pous.front(), map, q, {});
      const auto single = plc_check::check_output(m, p, p.pous.front(), map, q, alone);
      EXPECT_EQ(plc_check::to_string(grouped.verdict), plc_check::to_string(single.verdict))
          << "random matrix " << seed << " " << q.tag << ": " << grouped.reason << " / " << single.reason;
      EXPECT_EQ(grouped.verdict, plc_check::OutputVerdict::Related) << "random matrix " << seed << " " << q.tag;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ExportSt, FortyRandomPrograms, ::testing::Range(0, 40),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return "matrix_" + std::to_string(1000 + info.param);
                         });

// Expected: every output proved by correspondence invariants. Effect 114 is
// reset by effect 101's second output tag, energised to trip, with
// pass-through of BDV_601_BPCS (E.8, E.9): at rest that process value is
// FALSE, so the tag is TRUE and never rises, and an acceptance run that
// left it there never started effect 114's override; its program flag and
// scan count were paired with nothing and its outputs were unknown (as in
// big_matrix's generated program, where this pair comes from).
TEST(ExportSt, AResetByAPassThroughTagOfAnotherEffectIsProved) {
  const model::Matrix m = formats::load_valid_matrix(
      std::string(CEMV_SOURCE_DIR) + "/tests/plc_export/regress/reset_by_pass_through_ett_tag.json", "regress");
  expect_proved_by_correspondence(m, "reset_by_pass_through_ett_tag");
}

TEST(ExportSt, EachOutputTagIsAssignedInOneStatement) {
  const model::Matrix m = example("tank-overfill");
  const Export e = export_program(m);
  const std::string st = plc::print_program(e.program);
  for (const auto& b : e.map.outputs) {
    std::size_t count = 0;
    for (std::size_t at = st.find("\n  " + b.variable + " := "); at != std::string::npos;
         at = st.find("\n  " + b.variable + " := ", at + 1))
      ++count;
    EXPECT_EQ(count, 1u) << b.variable;
  }
  // named after the elements, commented with the rules
  EXPECT_NE(st.find("PROGRAM TANK_T100"), std::string::npos);
  EXPECT_NE(st.find("LT100_HH_ON_DELAY(IN := LT100_HH_REQ, PT := T#2s);"), std::string::npos) << st;
  EXPECT_NE(st.find("C.6 on-delay"), std::string::npos);
  EXPECT_NE(st.find("E.9 output tag 1 XV_101"), std::string::npos);
}

TEST(ExportSt, ADelayBeyondTimeIsRefusedNamingItsCause) {
  model::Matrix m = example("tank-overfill");
  m.causes.front().time.ms = 3'000'000'000u;
  try {
    (void)export_program(m);
    FAIL() << "exported";
  } catch (const Unsupported& u) {
    EXPECT_NE(std::string(u.what()).find("cause 1 LT100_HH"), std::string::npos) << u.what();
  }
}

TEST(ExportSt, SameMatrixSameBytes) {
  const model::Matrix m = random(7);
  EXPECT_EQ(plc::print_program(export_program(m).program), plc::print_program(export_program(m).program));
  EXPECT_EQ(plc::write_plcopen(export_program(m).program), plc::write_plcopen(export_program(m).program));
}

}  // namespace
}  // namespace cemv::plc_export
