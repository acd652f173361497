// The standard property set: stable names, the XooN / output-delay / feedback
// forms, and (the real check) every standard invariant holds on runtime traces
// of random inputs on random matrices with every option, and on the examples.
#include <gtest/gtest.h>

#include <set>

#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"
#include "trace_support.hpp"

namespace cemv::properties {
namespace {

model::Matrix example(const std::string& name) {
  return formats::load_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json");
}

std::vector<std::string> names(const PropertyFile& f) {
  std::vector<std::string> out;
  for (const auto& p : f.properties) out.push_back(p.name);
  return out;
}

TEST(StandardProperties, TankNamesAndForms) {
  auto m = example("tank-overfill");
  PropertyFile f = standard_properties(m);
  std::vector<std::string> expected = {
      "std.intersection.c1.e1", "std.intersection.c1.e2", "std.intersection.c2.e1", "std.intersection.c2.e2",
      "std.intersection.c3.e1", "std.intersection.c3.e2", "std.intersection.c3.e3", "std.intersection.c4.e3",
      "std.reachable.e1",       "std.reachable.e2",       "std.reachable.e3",       "std.resettable.e1",
      "std.failsafe.c1",        "std.failsafe.c2",        "std.failsafe.c3",        "std.failsafe.c4"};  // c3: default "trip"
  EXPECT_EQ(names(f), expected);
  EXPECT_EQ(f.properties[0].kind, PropertyKind::Invariant);
  EXPECT_EQ(f.properties[0].loc.line, 0);
  EXPECT_EQ(f.properties[0].description, "cause 1 active, effect 1 not bypassed: effect 1 active");
  std::string text = standard_properties_text(m);
  EXPECT_NE(text.find("property std.intersection.c1.e1 \"cause 1 active, effect 1 not bypassed: effect 1 active\" {\n"
                      "  always cause[1].active and not effect[1].bypassed implies effect[1].active\n}\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("  assume not issued(simulate_tag, tag = LT_100A)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  always bad(LT_100A) and bad(LT_100B) and bad(LT_100C) and cause[1].voting != "
                      "bypass implies cause[1].trip_requested\n"),
            std::string::npos);
  EXPECT_NE(text.find("reachable prev(effect[1].latched) and not effect[1].latched"), std::string::npos);
}

TEST(StandardProperties, XooNOverrideAndOutputDelayForms) {
  // The pipeline example has XooN assignments, V/R intersections with overrides
  // and output delays (its README); find each form at least once.
  std::string all;
  for (const char* name : {"pipeline-hipps", "burner-management", "compressor", "tank-overfill"}) {
    auto m = example(name);
    all += standard_properties_text(m);
    EXPECT_NO_THROW(standard_properties(m)) << name;
  }
  EXPECT_NE(all.find(") >= 2 and not effect["), std::string::npos) << "no XooN form";
  EXPECT_NE(all.find(".override_active implies"), std::string::npos) << "no V/R form";
  EXPECT_NE(all.find("property std.output_delay.e"), std::string::npos) << "no output delay";
}

// The standard set is built as trees; its text is printed for people. Read
// back, the text must mean exactly the trees (the printer and the builder
// agree with the parser), for the examples and for random matrices.
bool same_expr(const Expr& a, const Expr& b) {
  if (a.kind != b.kind || a.type != b.type || a.args.size() != b.args.size()) return false;
  switch (a.kind) {
    case Expr::Kind::BoolConst: if (a.bool_value != b.bool_value) return false; break;
    case Expr::Kind::IntConst: if (a.int_value != b.int_value) return false; break;
    case Expr::Kind::FloatConst: if (a.float_value != b.float_value) return false; break;
    case Expr::Kind::Observable: if (a.observable.key != b.observable.key) return false; break;
    case Expr::Kind::InputValue:
    case Expr::Kind::InputBad: if (a.input != b.input) return false; break;
    case Expr::Kind::CommandIssued:
      if (a.command.op != b.command.op || a.command.cause != b.command.cause || a.command.effect != b.command.effect ||
          a.command.tag != b.command.tag || a.command.group != b.command.group || a.command.on != b.command.on ||
          a.command.tag_name != b.command.tag_name)
        return false;
      break;
    case Expr::Kind::Compare: if (a.cmp != b.cmp) return false; break;
    default: if (a.cycles != b.cycles) return false; break;
  }
  for (std::size_t i = 0; i < a.args.size(); ++i)
    if (!same_expr(a.args[i], b.args[i])) return false;
  return true;
}

void expect_text_means_the_trees(const model::Matrix& m, const std::string& what) {
  const PropertyFile built = standard_properties(m);
  const PropertyFile read = parse_properties(standard_properties_text(m), m, "<standard>");
  ASSERT_EQ(read.properties.size(), built.properties.size()) << what;
  for (std::size_t i = 0; i < built.properties.size(); ++i) {
    const Property &b = built.properties[i], &r = read.properties[i];
    EXPECT_EQ(r.name, b.name) << what;
    EXPECT_EQ(r.description, b.description) << what;
    EXPECT_EQ(r.kind, b.kind) << what << " " << b.name;
    EXPECT_TRUE(same_expr(r.body, b.body)) << what << " " << b.name;
    ASSERT_EQ(r.assumptions.size(), b.assumptions.size()) << what << " " << b.name;
    for (std::size_t k = 0; k < b.assumptions.size(); ++k)
      EXPECT_TRUE(same_expr(r.assumptions[k].expr, b.assumptions[k].expr)) << what << " " << b.name;
  }
}

TEST(StandardProperties, TheTextPrintedMeansTheTreesBuilt) {
  for (const char* name : {"pipeline-hipps", "burner-management", "compressor", "tank-overfill"})
    expect_text_means_the_trees(example(name), name);
  for (std::uint64_t seed = 1; seed <= 40; ++seed)
    expect_text_means_the_trees(testsupport::random_matrix(seed), "seed " + std::to_string(seed));
}

// Counts, per kind of standard property, how often each held / was witnessed.
struct Tally {
  int invariants = 0, antecedents_met = 0, reachable = 0, witnessed = 0;
};

void check_trace(const model::Matrix& m, const PropertyFile& f, const Trace& t, const std::string& what, Tally& tally) {
  Evaluator ev(m);
  for (const auto& r : ev.evaluate(f, t)) {
    if (r.kind == PropertyKind::Reachable) {
      ++tally.reachable;
      tally.witnessed += r.holds;
      continue;
    }
    ++tally.invariants;
    tally.antecedents_met += r.antecedent_met;
    EXPECT_TRUE(r.holds) << what << ": " << r.name << " violated in cycle " << *r.cycle;
  }
}

TEST(StandardProperties, InvariantsHoldOnRandomRuntimeTraces) {
  Tally tally;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    model::Matrix m = testsupport::random_matrix(seed);
    PropertyFile f = standard_properties(m);
    Trace t = testing::run_inputs(m, testsupport::random_inputs(m, seed * 7919, 400));
    check_trace(m, f, t, "seed " + std::to_string(seed), tally);
    if (HasFailure()) {
      ADD_FAILURE() << standard_properties_text(m);
      break;
    }
  }
  // The traces must exercise the properties, or holding them says little.
  EXPECT_GT(tally.invariants, 200);
  EXPECT_GT(tally.antecedents_met, tally.invariants / 3);
  EXPECT_GT(tally.witnessed, tally.reachable / 3);
}

TEST(StandardProperties, InvariantsHoldOnTheExamplesScenariosAndRandomInputs) {
  Tally tally;
  for (const char* name : {"tank-overfill", "pipeline-hipps", "burner-management", "compressor"}) {
    auto m = example(name);
    PropertyFile f = standard_properties(m);
    for (const auto& entry : std::filesystem::directory_iterator(std::string(CEMV_SOURCE_DIR) + "/examples/" + name)) {
      if (entry.path().filename().string().rfind("scenario-", 0) != 0) continue;
      check_trace(m, f, testing::run_scenario(m, entry.path()), entry.path().string(), tally);
    }
    for (std::uint64_t seed = 1; seed <= 5; ++seed)
      check_trace(m, f, testing::run_inputs(m, testsupport::random_inputs(m, seed, 2000)),
                  std::string(name) + " random seed " + std::to_string(seed), tally);
  }
  EXPECT_GT(tally.antecedents_met, tally.invariants / 3);
}

}  // namespace
}  // namespace cemv::properties

namespace cemv::properties {
namespace {

// The 128 x 128 matrix with 1024 intersections of the checker's benchmark: one
// intersection property per processed intersection, one reachability per
// processed effect, names unique.
TEST(StandardProperties, BigMatrix) {
  model::Matrix m = testsupport::big_matrix();
  PropertyFile f = standard_properties(m);
  std::size_t intersections = 0, effects = 0;
  for (const auto& i : m.intersections) {
    const auto* c = m.find_cause(i.cause);
    const auto* e = m.find_effect(i.effect);
    intersections += model::is_processed(i.type) && c && c->function != model::CauseFunction::Comment && e &&
                     e->function != model::EffectFunction::Comment;
  }
  for (const auto& e : m.effects) effects += e.function != model::EffectFunction::Comment;
  std::set<std::string> unique;
  std::size_t intersection_props = 0, reach_props = 0;
  for (const auto& p : f.properties) {
    unique.insert(p.name);
    intersection_props += p.name.rfind("std.intersection.", 0) == 0;
    reach_props += p.name.rfind("std.reachable.", 0) == 0;
  }
  EXPECT_EQ(unique.size(), f.properties.size());
  EXPECT_EQ(intersection_props, intersections);
  EXPECT_EQ(reach_props, effects);
  EXPECT_GT(intersections, 500u);
}

}  // namespace
}  // namespace cemv::properties
