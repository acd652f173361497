// The encoder on its own: fixed examples of docs/semantics.md, the concrete
// evaluator against Z3's simplifier, the cone of influence, the lemmas, and the
// SMT-LIB export through a second solver (cvc5).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include <cstdio>
#include <fstream>
#include <memory>

#include "encoder/encode.hpp"
#include "encoder/evaluate.hpp"
#include "encoder/export.hpp"
#include "encoder/unroller.hpp"
#include "model/vocabulary.hpp"
#include "tests/support/random_inputs.hpp"
#include "tests/support/random_matrix.hpp"

using namespace cemv;

namespace {

model::Matrix one_cause(model::CauseFunction f, int tags, bool analog) {
  model::Matrix m;
  m.name = "T";
  m.cycle_ms = 100;
  model::Cause c;
  c.id = 1;
  c.name = "C1";
  c.function = f;
  c.input = analog ? model::InputKind::Analog : model::InputKind::Discrete;
  for (int i = 0; i < tags; ++i) c.tags.push_back({"T" + std::to_string(i + 1), false, true});
  if (analog) c.analog = model::AnalogParams{model::LimitType::High, 90.0f, 5.0f, std::nullopt, 0.0f, ""};
  m.causes.push_back(c);
  model::Effect e;
  e.id = 1;
  e.name = "E1";
  e.tags.push_back({"OUT1", false});
  m.effects.push_back(e);
  m.intersections.push_back({1, 1, model::IntersectionType::N, std::nullopt, ""});
  return m;
}

model::CycleInput frame(const model::Matrix& m, std::vector<float> values) {
  model::InputTable t(m);
  model::CycleInput in;
  in.tags.resize(t.size());
  for (std::size_t i = 0; i < values.size() && i < in.tags.size(); ++i) in.tags[i].value = values[i];
  return in;
}

// C.4 fixed example: 2oo3 high, limit 90, hysteresis 5.
// A state variable without an initial value or a next-state function is an
// error the system reports by name, not a variable silently kept free or constant.
TEST(TransitionSystem, ReportsStateVariablesWithoutInitOrNext) {
  z3::context ctx;
  encoder::TransitionSystem ts(ctx);
  z3::expr a = ts.make_statevar("a", ctx.bool_sort());
  z3::expr b = ts.make_statevar("b", ctx.int_sort());
  z3::expr c = ts.make_statevar("c", ctx.bool_sort());
  ts.set_init(a, ctx.bool_val(false));
  ts.assign_next(a, !a);
  ts.assign_next(b, b + 1);
  ts.set_init(c, ctx.bool_val(true));
  try {
    ts.check_complete();
    ADD_FAILURE() << "an incomplete system passes";
  } catch (const std::logic_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "incomplete transition system: state variables without an initial value: b; "
              "state variables without a next-state function: c");
  }
  ts.set_init(b, ctx.int_val(0));
  ts.assign_next(c, c);
  EXPECT_NO_THROW(ts.check_complete());
}

// Every state variable the encoder makes has both (encode() checks it too).
TEST(TransitionSystem, EncodingsAreComplete) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    model::Matrix m = testsupport::random_matrix(seed);
    z3::context ctx;
    auto enc = encoder::encode(ctx, m);
    for (const auto& s : enc->ts.statevars()) {
      EXPECT_TRUE(s.has_init) << s.name;
      EXPECT_TRUE(s.has_next) << s.name;
    }
  }
}

TEST(Semantics, HysteresisExampleOfC4) {
  auto m = one_cause(model::CauseFunction::TwoOoThree, 3, true);
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  ev.step(frame(m, {95, 95, 87}));
  EXPECT_EQ(ev.value("cause[1].trip_requested"), 1);
  EXPECT_EQ(ev.value("cause[1].active"), 1);
  ev.step(frame(m, {95, 84, 87}));
  EXPECT_EQ(ev.value("cause[1].active"), 1);
  EXPECT_EQ(ev.value("cause[1].hysteresis_active"), 1);
  ev.step(frame(m, {95, 84, 80}));
  EXPECT_EQ(ev.value("cause[1].active"), 0);
  EXPECT_EQ(ev.value("effect[1].tag[1]"), 1);  // DTT output back to 1
}

// T.2 / C.6 fixed example: ON delay 2000 ms at 100 ms: active in k + 20.
TEST(Semantics, OnDelayExpiresAtCyclePlusTwenty) {
  auto m = one_cause(model::CauseFunction::Normal, 1, false);
  m.causes[0].time = {model::TimeMode::OnDelay, 2000};
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  ev.step(frame(m, {1}));  // not tripped (DTT TRUE)
  for (int n = 0; n <= 20; ++n) {
    ev.step(frame(m, {0}));
    EXPECT_EQ(ev.value("cause[1].active"), n == 20 ? 1 : 0) << n;
    EXPECT_EQ(ev.value("cause[1].timer_running"), n == 20 ? 0 : 1) << n;
  }
}

TEST(Semantics, OffDelayHoldsThroughCyclePlusNineteen) {
  auto m = one_cause(model::CauseFunction::Normal, 1, false);
  m.causes[0].time = {model::TimeMode::OffDelay, 2000};
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  ev.step(frame(m, {0}));
  EXPECT_EQ(ev.value("cause[1].active"), 1);
  for (int n = 0; n <= 20; ++n) {
    ev.step(frame(m, {1}));
    EXPECT_EQ(ev.value("cause[1].active"), n < 20 ? 1 : 0) << n;
  }
}

TEST(Semantics, TimedCauseIsNotRetriggerable) {
  auto m = one_cause(model::CauseFunction::Normal, 1, false);
  m.causes[0].time = {model::TimeMode::Timed, 500};  // D = 5
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  encoder::Evaluator ev(*enc);
  std::vector<float> in = {0, 1, 0, 1, 0, 0, 0, 0, 1, 0};
  std::vector<int> expect = {1, 1, 1, 1, 1, 0, 0, 0, 0, 1};
  for (std::size_t k = 0; k < in.size(); ++k) {
    ev.step(frame(m, {in[k]}));
    EXPECT_EQ(ev.value("cause[1].active"), expect[k]) << k;
  }
}

// The evaluator gives the same values as Z3's own simplifier on the formulas.
// The differential test runs the encoder's formulas through the Evaluator, so
// every agreement it reports rests on the Evaluator meaning what Z3 means: here
// Z3 itself evaluates every observable and next-state function (substitute the
// concrete state and inputs, simplify) on random matrices, cycle by cycle.
class EvaluatorVsZ3 : public ::testing::TestWithParam<int> {};

TEST_P(EvaluatorVsZ3, AgreesWithZ3Simplify) {
  const auto first = static_cast<std::uint64_t>(4 * GetParam() + 1);
  for (std::uint64_t seed = first; seed < first + 4; ++seed) {
    auto m = testsupport::random_matrix(seed);
    auto inputs = testsupport::random_inputs(m, seed, 50);
    z3::context ctx;
    auto enc = encoder::encode(ctx, m);
    encoder::Evaluator ev(*enc);
    const auto& ts = enc->ts;
    auto to_expr = [&](const z3::expr& var, const encoder::Evaluator::Value& v) {
      if (var.is_bool()) return ctx.bool_val(v.i != 0);
      if (var.is_int()) return ctx.int_val(static_cast<int64_t>(v.i));
      return ctx.fpa_val(v.f);
    };
    for (auto in : inputs) {
      in.commands = enc->canonical_commands(in.commands);
      auto state = ev.state();
      auto iv = ev.input_values(in);
      z3::expr_vector from(ctx), to(ctx);
      for (std::size_t i = 0; i < ts.statevars().size(); ++i) {
        from.push_back(ts.statevars()[i].var);
        to.push_back(to_expr(ts.statevars()[i].var, state[i]));
      }
      for (std::size_t i = 0; i < ts.inputvars().size(); ++i) {
        from.push_back(ts.inputvars()[i].var);
        to.push_back(to_expr(ts.inputvars()[i].var, iv[i]));
      }
      ev.step_raw(iv);
      for (const auto& o : enc->observables) {
        z3::expr t = *ts.term(o.key);
        t = t.substitute(from, to).simplify();
        int z = t.is_bool() ? (t.is_true() ? 1 : 0) : static_cast<int>(t.get_numeral_int64());
        ASSERT_TRUE(t.is_bool() ? (t.is_true() || t.is_false()) : t.is_numeral()) << o.key;
        ASSERT_EQ(z, ev.value(o.key)) << "seed " << seed << " " << o.key;
      }
      for (std::size_t i = 0; i < ts.statevars().size(); ++i) {
        z3::expr t = ts.statevars()[i].next;
        t = t.substitute(from, to).simplify();
        const auto& v = ev.state()[i];
        if (t.is_bool()) ASSERT_EQ(t.is_true() ? 1 : 0, v.i) << ts.statevars()[i].name;
        else if (t.is_int()) ASSERT_EQ(t.get_numeral_int64(), v.i) << ts.statevars()[i].name;
        else ASSERT_TRUE(z3::expr(t == ctx.fpa_val(v.f)).simplify().is_true()) << ts.statevars()[i].name;
      }
    }
  }
}

// Six shards of four seeds each (24 random matrices x 50 cycles), so ctest runs
// them in parallel.
INSTANTIATE_TEST_SUITE_P(Seeds, EvaluatorVsZ3, ::testing::Range(0, 6));

// Cone of influence: a slice for one effect carries none of the others.
TEST(Cone, SliceOfOneEffectIsSmallerAndAgrees) {
  auto m = testsupport::random_matrix(77, {.min_causes = 6, .max_causes = 6, .min_effects = 4, .max_effects = 4});
  z3::context ctx;
  auto full = encoder::encode(ctx, m);
  int target = 0;
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment) target = e.id;
  ASSERT_NE(target, 0);
  auto slice = encoder::encode(ctx, m, {model::Node{model::Node::Kind::Effect, target}});
  EXPECT_LT(slice->ts.statevars().size(), full->ts.statevars().size());
  for (const auto& n : slice->nodes)
    EXPECT_FALSE(n.kind == model::Node::Kind::Effect && n.id != target &&
                 !model::DependencyGraph(m).feeders_of(model::Node{model::Node::Kind::Effect, target}).empty() &&
                 std::find(slice->nodes.begin(), slice->nodes.end(), n) == slice->nodes.end());
  // Observables of the target agree between slice and full encoding.
  encoder::Evaluator a(*full), b(*slice);
  std::string key = model::observable_key({model::Node::Kind::Effect, target}, "active");
  for (auto in : testsupport::random_inputs(m, 77, 200)) {
    in.commands = full->canonical_commands(in.commands);
    a.step(in);
    b.step(in);
    ASSERT_EQ(a.value(key), b.value(key));
  }
}

// Every replay orders a cycle's commands by the model (model::CommandOrder),
// so the encoding, whole or sliced, must create its command inputs in that
// order: then the runtime meets conflicting commands (on and off, simulate and
// stop, two locked maintenance operations) in the order the encoding does.
// A slice keeps the matrix's order of simulatable tags: it cannot see a tag as
// an output where the whole matrix sees it as an input, since a tag both
// written by an effect and read by the matrix is E-TAG-IN-AND-OUT.
TEST(Cone, SlicesCreateTheirCommandsInTheMatrixOrder) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    auto m = testsupport::random_matrix(seed);
    const model::CommandOrder order(m);
    std::vector<std::vector<model::Node>> roots = {{}};
    for (const auto& e : m.effects)
      if (e.function != model::EffectFunction::Comment) roots.push_back({{model::Node::Kind::Effect, e.id}});
    for (const auto& r : roots) {
      z3::context ctx;
      auto enc = encoder::encode(ctx, m, r);
      std::optional<std::size_t> last;
      for (const auto& ci : enc->commands) {
        auto rank = order.rank(ci.command());
        ASSERT_TRUE(rank) << "seed " << seed << ": " << ci.var;
        if (last) {
          ASSERT_LT(*last, *rank) << "seed " << seed << ": " << ci.var;
        }
        last = rank;
      }
    }
  }
}

// The counter range lemmas are inductive: init implies them, and they are
// preserved by one transition (checked by Z3 per lemma).
TEST(Lemmas, CounterRangesAreInductive) {
  auto m = testsupport::random_matrix(5);
  m.causes[0].time = {model::TimeMode::OnDelay, 1000};
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  const auto& ts = enc->ts;
  ASSERT_FALSE(ts.lemmas().empty());
  z3::expr_vector cur(ctx), nxt(ctx);
  for (const auto& s : ts.statevars()) {
    cur.push_back(s.var);
    nxt.push_back(s.next_var);
  }
  for (const auto& l : ts.lemmas()) {
    z3::solver s(ctx);
    s.add(ts.init_formula());
    s.add(!l.term);
    EXPECT_EQ(s.check(), z3::unsat) << "init " << l.name;
    z3::solver t(ctx);
    z3::expr l_next = l.term;
    l_next = l_next.substitute(cur, nxt);
    t.add(l.term && ts.trans_formula() && ts.constraint_formula() && !l_next);
    EXPECT_EQ(t.check(), z3::unsat) << "step " << l.name;
  }
}

std::string run(const std::string& cmd) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> p(popen(cmd.c_str(), "r"), pclose);
  if (!p) return out;
  char buf[256];
  while (fgets(buf, sizeof buf, p.get())) out += buf;
  return out;
}

// The exported SMT-LIB gives cvc5 the same verdict as Z3 on small queries.
TEST(Export, Cvc5AgreesWithZ3OnSmallQueries) {
  int sat = 0, unsat = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    auto m = testsupport::random_matrix(seed, {.min_causes = 2, .max_causes = 3, .min_effects = 1, .max_effects = 2});
    z3::context ctx;
    auto enc = encoder::encode(ctx, m);
    int queries = 0;
    for (const auto& o : enc->observables) {
      if (o.type != model::FieldType::Bool || (o.field != "active" && o.field != "tag")) continue;
      if (++queries > 2) break;
      for (auto kind : {encoder::ExportGoal::Kind::Reach, encoder::ExportGoal::Kind::Invariant}) {
        encoder::ExportGoal goal{kind, o.key};
        z3::solver s(ctx);
        s.add(encoder::unrolled_query(*enc, 3, goal));
        z3::check_result z = s.check();
        std::string file = ::testing::TempDir() + "cemv_q.smt2";
        std::ofstream(file) << encoder::to_smt2(*enc, 3, goal);
        std::string out = run("cvc5 --lang smt2 " + file + " 2>&1");
        std::string verdict = out.substr(0, out.find('\n'));
        ASSERT_EQ(verdict, z == z3::sat ? "sat" : "unsat") << o.key << "\n" << out;
        (z == z3::sat ? sat : unsat)++;
      }
    }
  }
  EXPECT_GT(sat, 0);
}

TEST(Export, VmtHasTheAnnotations) {
  auto m = one_cause(model::CauseFunction::Normal, 1, false);
  z3::context ctx;
  auto enc = encoder::encode(ctx, m);
  std::string v = encoder::to_vmt(*enc, {encoder::ExportGoal::Kind::Invariant, "effect[1].active"});
  EXPECT_NE(v.find(":next"), std::string::npos);
  EXPECT_NE(v.find(":init true"), std::string::npos);
  EXPECT_NE(v.find(":trans true"), std::string::npos);
  EXPECT_NE(v.find(":invar-property 0"), std::string::npos);
  EXPECT_THROW(encoder::to_vmt(*enc, {encoder::ExportGoal::Kind::Invariant, "nope"}), std::invalid_argument);
}

}  // namespace

// Z3 4.8.12's z3++.h did not release the term a move assignment overwrote
// (the build fixes it: top-level CMakeLists.txt, docs/checker.md "Z3 notes").
// A released term's id is recycled for the next new term.
TEST(Z3CppApi, MoveAssignmentReleasesTheTermItOverwrites) {
  z3::context c;
  const z3::expr kept = c.int_const("cemv_test_b") * 2;
  z3::expr e = c.int_const("cemv_test_a") + 1;
  const unsigned overwritten = e.id();
  e = z3::expr(kept);  // a temporary: the move assignment
  bool recycled = false;
  std::vector<z3::expr> fresh;
  for (int i = 0; i < 8 && !recycled; ++i) {
    fresh.push_back(c.int_const(("cemv_test_c" + std::to_string(i)).c_str()) - 7);
    recycled = fresh.back().id() == overwritten || fresh.back().arg(0).id() == overwritten;
  }
  EXPECT_TRUE(recycled);
}

// Unroller::at substitutes only the variables a term contains: the result is
// the term with each state variable at k, each input at k and each primed
// state variable at k + 1, the others untouched, inside a quantifier too.
TEST(Unroller, AtPutsEachVariableInItsCycle) {
  z3::context c;
  encoder::TransitionSystem ts(c);
  const z3::expr a = ts.make_statevar("a", c.int_sort());
  const z3::expr b = ts.make_statevar("b", c.bool_sort());
  const z3::expr unused = ts.make_statevar("unused", c.int_sort());
  const z3::expr i = ts.make_inputvar("i", c.int_sort());
  for (const auto& s : ts.statevars()) {
    ts.set_init(s.var, s.var.is_bool() ? c.bool_val(false) : c.int_val(0));
    ts.assign_next(s.var, s.var);
  }
  const z3::expr a_next = ts.statevars()[0].next_var;
  encoder::Unroller u(ts);
  const z3::expr a2 = c.int_const("a@2"), a3 = c.int_const("a@3"), i2 = c.int_const("i@2");
  const z3::expr b2 = c.bool_const("b@2");
  EXPECT_TRUE(z3::eq(u.at(a + i > a_next || b, 2), a2 + i2 > a3 || b2));
  EXPECT_TRUE(z3::eq(u.at(a_next == a_next + a, 2), a3 == a3 + a2));  // a shared subterm
  EXPECT_TRUE(z3::eq(u.at(c.int_val(3) > 2, 5), c.int_val(3) > 2));
  const z3::expr y = c.int_const("y");  // not a variable of the system: kept
  EXPECT_TRUE(z3::eq(u.at(y + a > unused, 0), y + c.int_const("a@0") > c.int_const("unused@0")));
  EXPECT_TRUE(z3::eq(u.at(z3::forall(y, y > a || y + i > a_next), 2), z3::forall(y, y > a2 || y + i2 > a3)));
  EXPECT_TRUE(z3::eq(u.var_at(a_next, 2), a3));
}
