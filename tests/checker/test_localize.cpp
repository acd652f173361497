// Localization (checker/localize.hpp): the state of elements outside the
// kept set made free. A proof on the localization holds on the whole problem
// (its evidence re-checks there); a counterexample that needs the freed state
// to do what it never does is spurious, is not concretized, and the engines
// go on with the whole problem.
#include <gtest/gtest.h>

#include "checker/check/recheck.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/pdr.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/localize.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

namespace {

using namespace cemv;
using namespace cemv::checker;

// Two causes of one effect: cause 1 trips at once, cause 2 after an on-delay
// of 1 s (10 cycles), whose counter is state of cause 2.
model::Matrix two_causes() {
  return formats::parse_matrix(R"({"format": "cemv-matrix/1", "name": "L", "cycle_ms": 100,
    "causes": [{"id": 1, "name": "C1", "tags": [{"name": "S1"}]},
               {"id": 2, "name": "C2", "tags": [{"name": "S2"}], "time": {"mode": "on_delay", "ms": 1000}}],
    "effects": [{"id": 1, "name": "E1", "tags": [{"name": "Y1"}]}],
    "intersections": [{"cause": 1, "effect": 1, "type": "N"}, {"cause": 2, "effect": 1, "type": "N"}]})",
                               "l.json");
}

const char* kProperties = R"(
assume not issued(simulate_tag)
assume not issued(soft_bypass_cause)
assume not issued(soft_bypass_tag)
assume not issued(soft_bypass_effect)
property cause1.answered "cause 1 active means effect 1 active: whatever cause 2 does" {
  never cause[1].active and not effect[1].active
}
property cause2.waits "cause 2 is active only after its input has been tripped for a while" {
  never cause[2].active and not held(not S2 or not good(S2), 500 ms)
}
)";

struct Fixture {
  model::Matrix m = two_causes();
  properties::PropertyFile file = properties::parse_properties(kProperties, m, "l.props");
  ProblemFactory make(std::size_t property) const { return reducing(property_problem(m, file, file.properties.at(property))); }
};

const std::vector<model::Node> kCause1AndEffect1{{model::Node::Kind::Cause, 1}, {model::Node::Kind::Effect, 1}};

// The portfolio on a fixture's property, localized to cause 1 and effect 1
// first; every problem counts as wide, so `engines` are its wide engines.
ProverResult localized_portfolio(const Fixture& f, std::size_t property, std::vector<Method> engines) {
  PortfolioOptions o;
  o.quick_k = -1;
  o.wide_states = 0;
  o.wide_engines = std::move(engines);
  o.localize_keep = keep_elements(kCause1AndEffect1);
  return Portfolio(property_problem(f.m, f.file, f.file.properties.at(property)), o).run(Limits{});
}

TEST(Localize, FreesTheStateOfOtherElementsOnly) {
  Fixture f;
  z3::context ctx;
  OwnedProblem whole = f.make(0)(ctx);
  Localization what;
  auto local = localize(whole, keep_elements(kCause1AndEffect1), &what);
  ASSERT_TRUE(local.has_value());
  EXPECT_GT(what.freed, 0u);
  EXPECT_LT(what.state_vars_after, what.state_vars_before);
  for (const auto& s : local->problem.ts->statevars()) EXPECT_EQ(s.name.find("cause[2]"), std::string::npos) << s.name;
  // Keeping everything frees nothing: no localization.
  EXPECT_FALSE(localize(whole, [](const std::string&) { return true; }).has_value());
}

TEST(Localize, ProofOnTheLocalizationReChecksOnTheWholeProblem) {
  Fixture f;
  z3::context ctx;
  OwnedProblem whole = f.make(0)(ctx);
  auto local = localize(whole, keep_elements(kCause1AndEffect1));
  ASSERT_TRUE(local.has_value());
  ProverResult r = Pdr{}.prove(local->problem, Limits{}.with_work(60 * kMega));
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  EXPECT_NO_THROW(check::recheck_proof(f.make(0), r));
  // Through the portfolio: the localized answer, re-checked there.
  ProverResult p = localized_portfolio(f, 0, {Method::Bmc});
  EXPECT_EQ(p.verdict, Verdict::Proved) << p.reason_text();
  EXPECT_TRUE(p.localized) << p.method_text();
  EXPECT_NE(p.method_text().find(", localized"), std::string::npos) << p.method_text();
}

TEST(Localize, SpuriousCounterexampleIsNotConcretizedAndTheWholeProblemDecides) {
  Fixture f;
  z3::context ctx;
  OwnedProblem whole = f.make(1)(ctx);
  // Cause 2's on-delay counter freed: cause 2 may be active as soon as S2 trips.
  auto local = localize(whole, keep_elements(kCause1AndEffect1));
  ASSERT_TRUE(local.has_value());
  ProverResult r = Bmc{}.prove(local->problem, Limits{}.with_depth(20));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  EXPECT_FALSE(concretize(whole.problem, r.cex).has_value());
  ProverResult p = localized_portfolio(f, 1, {Method::Pdr, Method::KInduction});
  EXPECT_EQ(p.verdict, Verdict::Proved) << p.reason_text();
  EXPECT_FALSE(p.localized) << p.method_text();
}

TEST(Localize, RealCounterexampleOfTheLocalizationIsConcretized) {
  // Cause 1 trips at once when S1 does, and cause 2 cannot be active in the
  // first cycle, whatever its freed counter says in the localization (cause
  // 1 kept, cause 2's state free): the shortest trace's inputs violate the
  // whole problem too.
  Fixture f;
  auto file = properties::parse_properties(std::string(kProperties) + "property cause1.alone { never cause[1].active and not cause[2].active }\n",
                                           f.m, "l.props");
  z3::context ctx;
  OwnedProblem whole = reducing(property_problem(f.m, file, file.properties.at(2)))(ctx);
  auto local = localize(whole, keep_elements({{model::Node::Kind::Cause, 1}}));
  ASSERT_TRUE(local.has_value());
  ProverResult r = Bmc{}.prove(local->problem, Limits{}.with_depth(20));
  ASSERT_EQ(r.verdict, Verdict::Falsified) << r.reason_text();
  auto t = concretize(whole.problem, r.cex);
  ASSERT_EQ(r.cex.length(), 1u);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->length(), 1u);
  EXPECT_NO_THROW(check::replay_counterexample(whole.problem, *t));
}

}  // namespace
