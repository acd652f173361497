// The AST printed back as text reads back as the same AST: on every property
// of the examples' requirement files and of the standard sets of the examples
// and of random matrices (compared as printed text and by value on a trace).
#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/print.hpp"
#include "properties/standard.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

void round_trip(const model::Matrix& m, const PropertyFile& f, const std::string& what) {
  model::InputTable inputs(m);
  Trace t = testing::run_inputs(m, testsupport::random_inputs(m, 5, 300));
  Evaluator ev(m);
  for (const auto& p : f.properties) {
    std::string text = statement_text(p, inputs);
    PropertyFile again = parse_properties("property p {\n  " + text + "\n}\n", m, "again.props");
    Property q = again.properties.at(0);
    q.assumptions = p.assumptions;  // the statement text leaves them out
    EXPECT_EQ(statement_text(q, inputs), text) << what << ": " << p.name;
    EXPECT_EQ(q.kind, p.kind);
    EXPECT_EQ(q.within_cycles, p.within_cycles);
    auto a = ev.evaluate(p, f.assumptions, t), b = ev.evaluate(q, f.assumptions, t);
    EXPECT_EQ(a.holds, b.holds) << what << ": " << p.name;
    EXPECT_EQ(a.cycle, b.cycle) << what << ": " << p.name;
  }
}

TEST(PropertiesPrint, RequirementFilesAndStandardSetsReadBack) {
  for (const char* name : {"tank-overfill", "pipeline-hipps", "burner-management", "compressor"}) {
    std::string dir = std::string(CEMV_SOURCE_DIR) + "/examples/" + name;
    model::Matrix m = formats::load_matrix(dir + "/matrix.json");
    round_trip(m, load_properties(dir + "/requirements.props", m), name);
    round_trip(m, standard_properties(m), std::string(name) + " standard");
  }
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    model::Matrix m = testsupport::random_matrix(seed);
    round_trip(m, standard_properties(m), "random " + std::to_string(seed));
  }
}

TEST(PropertiesPrint, PrecedenceAndLiterals) {
  model::Matrix m = formats::load_matrix(CEMV_SOURCE_DIR "/examples/tank-overfill/matrix.json");
  model::InputTable inputs(m);
  auto show = [&](const std::string& body) {
    PropertyFile f = parse_properties("property p { always " + body + " }", m, "t.props");
    return to_text(f.properties[0].body, inputs);
  };
  EXPECT_EQ(show("not (HS_100_BYP and HS_101_RST) or HS_100_ESD"), "not (HS_100_BYP and HS_101_RST) or HS_100_ESD");
  EXPECT_EQ(show("(HS_100_BYP -> HS_101_RST) -> HS_100_ESD"), "(HS_100_BYP implies HS_101_RST) implies HS_100_ESD");
  EXPECT_EQ(show("HS_100_BYP -> HS_101_RST -> HS_100_ESD"), "HS_100_BYP implies HS_101_RST implies HS_100_ESD");
  EXPECT_EQ(show("(HS_100_BYP or HS_101_RST) and HS_100_ESD"), "(HS_100_BYP or HS_101_RST) and HS_100_ESD");
  EXPECT_EQ(show("lt_100a >= 90"), "LT_100A >= 90.0");
  EXPECT_EQ(show("LT_102 < -40.5"), "LT_102 < -40.5");
  EXPECT_EQ(show("cause[LT100_HH].voting == 2oo3"), "cause[1].voting == 2oo3");
  EXPECT_EQ(show("held(bad(LT_100A), 250 ms)"), "held(bad(LT_100A), 3 cycles)");
  EXPECT_EQ(show("issued(soft_bypass_tag, cause = LT100_HH, tag = 2, on = false)"),
            "issued(soft_bypass_tag, cause = 1, tag = 2, on = false)");
  EXPECT_EQ(show("count(c in effect[1].causes: c.active) >= 2"),
            "count(cause[1].active, cause[2].active, cause[3].active) >= 2");
  Signals s = signals_of(parse_properties("assume not HS_100_BYP\nproperty p { assume not issued(ack_cause)\n"
                                          "whenever bad(LT_100A) then effect[1].active within 1 s }",
                                          m, "t.props")
                             .properties[0],
                         {});
  EXPECT_EQ(s.inputs, std::vector<std::size_t>{*inputs.find("LT_100A")});
  EXPECT_EQ(s.observables, std::vector<std::string>{"effect[1].active"});
  EXPECT_TRUE(s.commands);
}

}  // namespace
}  // namespace cemv::properties
