// The reductions the engines work on (checker/reduce.hpp) are exact: the
// integer order of floats is the float order, and a reduced problem judges
// every run as the original does.
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <unordered_map>

#include <gtest/gtest.h>

#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "encoder/evaluate.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

namespace {

using namespace cemv;
using namespace cemv::checker;

std::vector<float> interesting_floats() {
  std::vector<float> v{0.0f, -0.0f, 1.0f, -1.0f, 90.0f, 88.0f, 87.99999f, 90.00001f,
                       std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                       std::numeric_limits<float>::min(), std::numeric_limits<float>::denorm_min(),
                       -std::numeric_limits<float>::denorm_min(), 1e-38f, -3.5e12f};
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> bits;
  while (v.size() < 400) {
    float f = std::bit_cast<float>(bits(rng));
    if (std::isfinite(f)) v.push_back(f);
  }
  return v;
}

TEST(FloatKey, OrdersLikeTheFloats) {
  const auto v = interesting_floats();
  for (float a : v)
    for (float b : v) {
      ASSERT_EQ(a <= b, float_key(a) <= float_key(b)) << a << " " << b;
      ASSERT_EQ(a < b, float_key(a) < float_key(b)) << a << " " << b;
      ASSERT_EQ(a == b, float_key(a) == float_key(b)) << a << " " << b;
    }
}

TEST(FloatKey, RoundTripsAndMergesTheZeros) {
  for (float a : interesting_floats()) {
    if (a == 0.0f) continue;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(key_float(float_key(a))), std::bit_cast<std::uint32_t>(a)) << a;
  }
  EXPECT_EQ(float_key(-0.0f), 0);
  EXPECT_FALSE(std::signbit(key_float(0)));
}

struct Example {
  model::Matrix matrix;
  properties::PropertyFile file;
};

Example load(const std::string& name, const std::string& props_text) {
  auto dir = std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / name;
  Example e{formats::load_matrix(dir / "matrix.json"), {}};
  e.file = properties::parse_properties(props_text, e.matrix, "test.props");
  return e;
}

const char* kTwoOfThree = R"(
property two_of_three {
  assume not issued(simulate_tag)
  assume not issued(soft_bypass_tag, cause = 1)
  whenever held(count(t in cause[1].tags: good(t) and t >= 90.0) >= 2, 2 s) and not cause[1].bypassed
  then not XV_101 within 500 ms
}
property deviation { never cause[1].delta_alarm and effect[1].active }
)";

TEST(Reduce, FreezesWhatTheAssumptionsFixAndTurnsComparedFloatsIntoIntegers) {
  Example e = load("tank-overfill", kTwoOfThree);
  z3::context ctx;
  Reduction what;
  OwnedProblem reduced = reduce(property_problem(e.matrix, e.file, e.file.properties[0])(ctx), &what);
  EXPECT_TRUE(what.floats_as_integers);
  EXPECT_LT(what.state_vars_after, what.state_vars_before);
  EXPECT_LT(what.inputs_after, what.inputs_before);
  // The simulation states the assumption freezes are gone.
  for (const auto& sv : reduced.problem.ts->statevars()) EXPECT_EQ(sv.name.find("sim["), std::string::npos) << sv.name;
  for (const auto& in : reduced.problem.ts->inputvars()) EXPECT_FALSE(in.var.is_fpa()) << in.name;
}

TEST(Reduce, KeepsFloatsWhereTheDeviationAlarmSubtractsThem) {
  Example e = load("tank-overfill", kTwoOfThree);
  z3::context ctx;
  Reduction what;
  reduce(property_problem(e.matrix, e.file, e.file.properties[1])(ctx), &what);
  EXPECT_FALSE(what.floats_as_integers);  // |a - b| > delta needs Float32 arithmetic
}

// Random runs of the original and the reduced problem, inputs translated by
// name: while the original's facts hold, the reduced facts hold too and both
// give `good` the same value in every cycle.
void expect_same_judgement(const Example& e, const properties::Property& p) {
  z3::context ctx;
  OwnedProblem original = property_problem(e.matrix, e.file, p)(ctx);
  OwnedProblem reduced = reduce(original);
  auto evaluator_of = [&](const SafetyProblem& sp, encoder::Encoding& enc) {
    enc.ts = *sp.ts;
    enc.ts.name_term("t.good", sp.good);
    enc.ts.name_term("t.facts", sp.ts->constraint_formula() && sp.assumption);
  };
  encoder::Encoding eo(ctx), er(ctx);
  evaluator_of(original.problem, eo);
  evaluator_of(reduced.problem, er);
  std::unordered_map<std::string, bool> forced;
  for (auto& [name, value] : forced_inputs(original.problem)) forced[name] = value;
  const std::vector<float> pool{0.0f, 87.0f, 87.99999f, 88.0f, 89.99999f, 90.0f, 95.0f, -1.0f, 1.0f};
  std::mt19937 rng(11);
  int judged = 0;
  for (int run = 0; run < 40; ++run) {
    encoder::Evaluator o(eo), r(er);
    for (int cycle = 0; cycle < 60; ++cycle) {
      std::unordered_map<std::string, encoder::Evaluator::Value> by_name;
      std::vector<encoder::Evaluator::Value> in_o;
      for (const auto& in : eo.ts.inputvars()) {
        encoder::Evaluator::Value v;
        if (in.var.is_fpa()) v.f = pool[rng() % pool.size()];
        else if (auto f = forced.find(in.name); f != forced.end()) v.i = f->second;
        else v.i = rng() % 8 == 0;  // commands and bad quality now and then
        by_name[in.name] = v;
        in_o.push_back(v);
      }
      std::vector<encoder::Evaluator::Value> in_r;
      for (const auto& in : er.ts.inputvars()) {
        encoder::Evaluator::Value v = by_name.at(in.name);
        if (in.var.is_int()) v.i = float_key(v.f);
        in_r.push_back(v);
      }
      o.step_raw(in_o);
      r.step_raw(in_r);
      if (!o.value("t.facts")) break;
      ASSERT_TRUE(r.value("t.facts")) << p.name << " run " << run << " cycle " << cycle;
      ASSERT_EQ(o.value("t.good"), r.value("t.good")) << p.name << " run " << run << " cycle " << cycle;
      ++judged;
    }
  }
  EXPECT_GT(judged, 200) << "the runs must get past the assumptions";
}

TEST(Reduce, JudgesEveryRunAsTheOriginalDoes) {
  Example e = load("tank-overfill", kTwoOfThree);
  for (const auto& p : e.file.properties) expect_same_judgement(e, p);
}

TEST(Reduce, LiftedTracesKeepEveryInputOfTheOriginal) {
  Example e = load("tank-overfill", kTwoOfThree);
  z3::context ctx;
  OwnedProblem original = property_problem(e.matrix, e.file, e.file.properties[0])(ctx);
  OwnedProblem reduced = reduce(original);
  Trace t;
  for (const auto& in : reduced.problem.ts->inputvars()) t.input_names.push_back(in.name);
  Trace::Cycle c;
  for (const auto& in : reduced.problem.ts->inputvars())
    c.inputs.push_back(Value{false, in.var.is_int() ? float_key(90.0f) : 0, 0.0f});
  t.cycles = {c, c};
  Trace lifted = lift_trace(original.problem, t);
  ASSERT_EQ(lifted.input_names.size(), original.problem.ts->inputvars().size());
  ASSERT_EQ(lifted.length(), 2u);
  EXPECT_EQ(lifted.input(1, "input.LT_100A").f, 90.0f);
  EXPECT_TRUE(lifted.input(1, "input.LT_100A").is_float);
  ASSERT_EQ(lifted.state_names.size(), original.problem.ts->statevars().size());
}

}  // namespace
