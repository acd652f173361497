// `cemv plc-check` on the tank example (examples/tank-overfill/plc): the
// hand-written program proved equal to its matrix output by output, each of
// the three copies with a seeded hand-coding error refuted by a run that the
// matrix's runtime and the program's interpreter both replay.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "formats/plc_map.hpp"
#include "plc/parser.hpp"
#include "plc_check/check.hpp"

namespace {

using namespace cemv;
using plc_check::OutputVerdict;
using plc_check::Relation;

const std::string kDir = std::string(CEMV_SOURCE_DIR) + "/examples/tank-overfill/";

struct Tank {
  model::Matrix m = formats::load_valid_matrix(kDir + "matrix.json", "test");
  formats::PlcMap given = formats::parse_plc_map(formats::read_text_file(kDir + "plc/tank_t100.map.json"), "map");
  plc::Program program;
  plc_check::ResolvedMap map;

  explicit Tank(const std::string& file) : program(plc::read_program(kDir + "plc/" + file)) {
    plc_check::ProgramInterface iface;
    iface.file = file;
    iface.pou = program.pous.front().name;
    for (const auto& v : program.pous.front().variables) {
      plc_check::ProgramVariable pv;
      pv.name = v.name;
      pv.kind = v.section == plc::Section::Input    ? plc_check::VarKind::Input
                : v.section == plc::Section::Output ? plc_check::VarKind::Output
                                                    : plc_check::VarKind::Local;
      pv.type = v.type.kind != plc::VarType::Kind::Elementary ? plc_check::VarType::Other
                : v.type.type == plc::Type::Bool             ? plc_check::VarType::Bool
                : v.type.type == plc::Type::Real             ? plc_check::VarType::Real
                                                             : plc_check::VarType::Int;
      iface.variables.push_back(pv);
    }
    map = plc_check::resolve_map(m, iface, &given, "map");
  }

  plc_check::OutputResult check(const std::string& tag, Relation r = Relation::Equal) {
    for (const auto& q : plc_check::questions(m, map))
      if (q.tag == tag) {
        plc_check::CheckOptions o;
        o.relation = r;
        return plc_check::check_output(m, program, program.pous.front(), map, q, o);
      }
    ADD_FAILURE() << "no output " << tag;
    return {};
  }
};

// Every output proved equal by the correspondence of the program's state
// to the matrix's (the TONs' elapsed times to the delay counters, the SR to
// the effect's latch), in one scan from the invariant.
TEST(PlcCheckTank, HandWrittenProgramIsEqualOutputByOutput) {
  Tank t("tank_t100.st");
  for (const char* tag : {"XV_101", "P_101_RUN", "P_102_RUN"}) {
    const auto r = t.check(tag);
    EXPECT_EQ(r.verdict, OutputVerdict::Related) << tag << ": " << r.method << " " << r.reason;
    EXPECT_EQ(r.method, "correspondence invariants") << tag;
    EXPECT_FALSE(r.difference) << tag;
  }
}

// Checks a refutation: the run breaks the relation in its last scan on both
// sides, and not before.
void expect_difference(const plc_check::OutputResult& r, int matrix_value, int program_value) {
  ASSERT_EQ(r.verdict, OutputVerdict::Differs) << r.question.tag << ": " << r.reason;
  ASSERT_TRUE(r.difference);
  const auto& d = *r.difference;
  const std::size_t n = static_cast<std::size_t>(d.scan) + 1;
  ASSERT_EQ(d.matrix_values.size(), n);
  ASSERT_EQ(d.program_values.size(), n);
  EXPECT_EQ(d.matrix_values.back(), matrix_value);
  EXPECT_EQ(d.program_values.back(), program_value);
  for (std::size_t c = 0; c + 1 < n; ++c) EXPECT_EQ(d.matrix_values[c], d.program_values[c]) << "scan " << c + 1;
  EXPECT_EQ(d.matrix_inputs.size(), n);
  EXPECT_EQ(d.runtime.observables.size(), n);
  EXPECT_TRUE(d.assigned_at) << "the program sets every output in every scan";
  // Readable: analog inputs at round numbers, not at the floats next to a
  // limit that the reduced problem's ordered integers stand for.
  for (std::size_t c = 0; c < n; ++c)
    for (const auto& [name, v] : d.program_inputs[c])
      if (v.type == cemv::plc::Type::Real) {
        EXPECT_EQ(v.real, static_cast<float>(std::round(v.real * 1000.0) / 1000.0)) << name << " in scan " << c + 1;
      }
}

// The inputs a run changes after its first scan: what the difference needs.
std::size_t changes_after_first_scan(const plc_check::Difference& d) {
  std::size_t changes = 0;
  for (std::size_t c = 1; c < d.program_inputs.size(); ++c)
    for (const auto& [name, v] : d.program_inputs[c]) changes += !(v == d.program_inputs[c - 1].at(name));
  return changes;
}

TEST(PlcCheckTank, ResetDominantLatchIsRefuted) {
  Tank t("tank_t100_reset_dominant.st");
  const auto r = t.check("XV_101");
  // The valve stays closed on the matrix (0) and opens on the program (1):
  // the reset clears the latch while an overfill cause is still active.
  expect_difference(r, 0, 1);
  EXPECT_EQ(r.difference->assigned_at->line, 118u);
  // Unsafe as well: the program trips less.
  expect_difference(t.check("XV_101", Relation::SafeSide), 0, 1);
  EXPECT_EQ(r.method, "bmc");
  EXPECT_EQ(t.check("P_101_RUN").verdict, OutputVerdict::Related);
  EXPECT_EQ(t.check("P_102_RUN").verdict, OutputVerdict::Related);
}

TEST(PlcCheckTank, OffDelayForOnDelayIsRefuted) {
  Tank t("tank_t100_off_delay.st");
  const auto r = t.check("P_101_RUN");
  // The TOF passes the trip at once; the matrix waits 2 s.
  expect_difference(r, 1, 0);
  EXPECT_EQ(r.difference->scan, 0);
  EXPECT_EQ(r.method, "bmc");
  EXPECT_EQ(t.check("P_102_RUN").verdict, OutputVerdict::Related);
}

TEST(PlcCheckTank, TwoOutOfThreeCodedAsOneOutOfThreeIsRefuted) {
  Tank t("tank_t100_one_of_three.st");
  const auto r = t.check("P_101_RUN");
  expect_difference(r, 1, 0);
  // One transmitter alone for the 2 s on-delay: the shortest run trips in
  // scan 21 (0-based 20), found by the seeded runs from rest or by BMC.
  EXPECT_EQ(r.difference->scan, 20);
  EXPECT_TRUE(r.method == "simulation" || r.method == "bmc") << r.method;
  // From the plant at rest: one transmitter over its limit from the start, one
  // more input changed at the most (checker/shrink.hpp put the others back).
  EXPECT_LE(changes_after_first_scan(*r.difference), 1u);
  const auto xv = t.check("XV_101");
  expect_difference(xv, 1, 0);
  EXPECT_EQ(xv.difference->scan, 20);
  EXPECT_EQ(t.check("P_102_RUN").verdict, OutputVerdict::Related);
}

}  // namespace
