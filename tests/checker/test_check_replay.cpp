// The checker never reports a counterexample that the reference runtime does
// not reproduce. A wrong rule planted in the encoding (the transition system
// the engines search) yields a trace that the runtime, judged by the concrete
// evaluator, does not violate: check_properties must stop with InternalError
// (exit 4 at the command line), showing where the two sides differ.
#include <filesystem>

#include <gtest/gtest.h>

#include "checker/check.hpp"
#include "checker/prover.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

namespace {

using namespace cemv;

model::Matrix tank() {
  return formats::load_matrix(std::filesystem::path(CEMV_SOURCE_DIR) / "examples/tank-overfill/matrix.json");
}

// With the hard bypass key off and no soft bypass, cause 1 is never bypassed.
constexpr const char* kNeverBypassed = R"(
property cause1.not_bypassed "cause 1 is not bypassed while its key is off" {
  assume not HS_100_BYP
  assume not issued(soft_bypass_cause)
  never cause[1].bypassed
}
)";

checker::CheckOptions quick() {
  checker::CheckOptions o;
  o.property_timeout_s = 60;
  o.support = false;
  return o;
}

TEST(CheckReplay, HonestEncodingProvesTheProperty) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kNeverBypassed, m, "never_bypassed.props");
  auto r = checker::check_properties(m, {file}, quick());
  ASSERT_EQ(r.properties.size(), 1u);
  EXPECT_EQ(r.properties[0].verdict, checker::PropertyVerdict::Proved) << r.properties[0].reason;
}

TEST(CheckReplay, PlantedWrongRuleIsCaughtByTheRuntimeReplay) {
  model::Matrix m = tank();
  auto file = properties::parse_properties(kNeverBypassed, m, "never_bypassed.props");
  checker::CheckOptions o = quick();
  // The planted rule: cause 1 reads as bypassed in every cycle.
  o.modify_encoding = [](encoder::Encoding& enc) {
    enc.ts.name_term("cause[1].bypassed", enc.ts.ctx().bool_val(true));
  };
  try {
    checker::check_properties(m, {file}, o);
    FAIL() << "a counterexample the runtime does not reproduce was reported";
  } catch (const checker::InternalError& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("does not reproduce"), std::string::npos) << what;
    EXPECT_NE(what.find("cause[1].bypassed"), std::string::npos) << what;
  }
}

}  // namespace
