#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "checker/equivalence.hpp"
#include "checker/random_runs.hpp"
#include "checker/replay.hpp"
#include "encoder/product.hpp"
#include "formats/matrix_json.hpp"
#include "mutate/mutants.hpp"

namespace {

using namespace cemv;
using checker::EquivalenceVerdict;

model::Matrix example(const std::string& name) {
  return formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json", "compared");
}

model::Matrix mutant(const model::Matrix& m, const std::string& id) {
  for (const auto& mu : mutate::mutants(m).mutants)
    if (mu.id == id) return mu.matrix;
  ADD_FAILURE() << "no mutant " << id;
  return m;
}

checker::EquivalenceOptions no_shortcut() {
  checker::EquivalenceOptions o;
  o.identical_cone_shortcut = false;
  return o;
}

// The product names both copies apart and shares the inputs.
TEST(Product, CopiesAndSharedInputs) {
  const model::Matrix m = example("tank-overfill");
  z3::context ctx;
  auto p = encoder::product(ctx, m, m);
  EXPECT_EQ(p->ts.statevars().size(), 2 * p->a->ts.statevars().size());
  EXPECT_EQ(p->ts.inputvars().size(), p->a->ts.inputvars().size());
  EXPECT_TRUE(p->term_a("effect[1].active").has_value());
  EXPECT_TRUE(p->term_b("effect[1].active").has_value());
  EXPECT_TRUE(p->ts.statevar("a." + p->a->ts.statevars()[0].name).has_value());
  std::size_t eq = 0;
  for (const auto& l : p->ts.lemmas()) eq += l.name.rfind("eq.", 0) == 0;
  EXPECT_EQ(eq, p->a->ts.statevars().size());
}

// A matrix is equivalent to itself, and to a copy whose texts changed:
// proved on the product, not assumed.
TEST(Equivalence, SelfAndTextEditsAreProved) {
  const model::Matrix m = example("tank-overfill");
  model::Matrix texts = m;
  texts.causes[0].description = "another description";
  texts.effects[0].name = "RENAMED_EFFECT";
  for (const model::Matrix* other : {&m, static_cast<const model::Matrix*>(&texts)}) {
    auto r = checker::decide_equivalence(m, *other, checker::whole_matrix(m, *other), no_shortcut());
    EXPECT_EQ(r.verdict, EquivalenceVerdict::Equivalent) << r.reason;
    EXPECT_NE(r.method, "identical cone");
  }
}

// A removed intersection differs, with a run that both runtimes replay and
// on which they really differ.
TEST(Equivalence, RemovedIntersectionDiffersWithReplayedRun) {
  const model::Matrix m = example("tank-overfill");
  const model::Matrix mu = mutant(m, "intersection-removed.c2e1");
  auto r = checker::decide_equivalence(m, mu, checker::whole_matrix(m, mu));
  ASSERT_EQ(r.verdict, EquivalenceVerdict::Differs) << r.reason;
  ASSERT_TRUE(r.distinction.has_value());
  const auto& d = *r.distinction;
  EXPECT_NE(d.value_a, d.value_b);
  auto ta = checker::run_on_runtime(m, d.run_a.inputs), tb = checker::run_on_runtime(mu, d.run_b.inputs);
  const auto obs = model::observables(m);
  std::size_t i = 0;
  while (obs[i].key != d.key) ++i;
  EXPECT_EQ(ta.observables.back()[i], d.value_a);
  EXPECT_EQ(tb.observables.back()[i], d.value_b);
  EXPECT_EQ(static_cast<int>(ta.observables.size()), d.cycle + 1);
}

// Per effect: the mutant changes effect 1 only; the other effects are
// proved equivalent on the product, and the identical-cone shortcut gives
// the same answers.
TEST(Equivalence, PerEffectAndShortcutAgree) {
  const model::Matrix m = example("tank-overfill");
  const model::Matrix mu = mutant(m, "intersection-removed.c2e1");
  for (const auto& g : checker::effect_groups(m, mu)) {
    auto slow = checker::decide_equivalence(m, mu, g, no_shortcut());
    auto fast = checker::decide_equivalence(m, mu, g);
    EXPECT_EQ(slow.verdict, fast.verdict) << g.name;
    bool changed = g.name == "effect[1]";
    EXPECT_EQ(slow.verdict, changed ? EquivalenceVerdict::Differs : EquivalenceVerdict::Equivalent) << g.name;
  }
}

// A change of the observable interface (an output tag fewer) differs by interface.
TEST(Equivalence, InterfaceChange) {
  const model::Matrix m = example("tank-overfill");
  model::Matrix n = m;
  n.causes.erase(n.causes.begin() + 1);
  std::erase_if(n.intersections, [](const model::Intersection& i) { return i.cause == 2; });
  auto r = checker::decide_equivalence(m, n, checker::whole_matrix(m, n));
  EXPECT_EQ(r.verdict, EquivalenceVerdict::Differs);
  EXPECT_EQ(r.basis, checker::EquivalenceBasis::Interface);
  EXPECT_EQ(r.method, "interface");
  EXPECT_NE(r.reason.find("cause[2]"), std::string::npos);
}

}  // namespace

// Seeded random runs (checker/random_runs.hpp) are fixed by their seed, hold
// the inputs they set, and a run cut down by minimise_run still does what
// the caller keeps.
TEST(RandomRuns, DeterministicHeldAndMinimised) {
  const model::Matrix m = example("tank-overfill");
  checker::RandomRuns a(checker::run_space(m), 7), b(checker::run_space(m), 7);
  for (int i = 0; i < 20; ++i) {
    const checker::Run x = a.next(6), y = b.next(6);
    ASSERT_EQ(x.size(), y.size());
    for (std::size_t s = 0; s < x.size(); ++s) {
      EXPECT_EQ(x[s].cycles, y[s].cycles);
      ASSERT_EQ(x[s].changes.size(), y[s].changes.size());
      for (std::size_t c = 0; c < x[s].changes.size(); ++c) EXPECT_EQ(x[s].changes[c].tag, y[s].changes[c].tag);
    }
    const auto cycles = checker::expand(m, x, model::default_cycle_input(m));
    EXPECT_EQ(cycles.size(), checker::run_cycles(x));
    for (std::size_t k = 1; k < cycles.size(); ++k)
      for (std::size_t t = 0; t < cycles[k].tags.size(); ++t)
        if (cycles[k].tags[t].value != cycles[k - 1].tags[t].value) {
          // A value changes only at a segment's first cycle.
          std::size_t at = 0;
          bool start = false;
          for (const auto& s : x) {
            start |= at == k;
            at += s.cycles;
          }
          EXPECT_TRUE(start) << "cycle " << k;
        }
  }
  // The holds include every configured duration and one cycle either side.
  const auto space = checker::run_space(m);
  for (const auto& c : m.causes)
    if (c.time.ms > 0) {
      const std::size_t n = c.time.ms / m.cycle_ms;
      for (std::size_t d : {n - 1, n, n + 1})
        EXPECT_TRUE(std::count(space.holds.begin(), space.holds.end(), d)) << c.name << " " << d;
    }
  // Minimising keeps what the caller keeps: here, a run of at least 5 cycles.
  checker::Run run = checker::RandomRuns(checker::run_space(m), 3).next(8);
  run.push_back({{}, {}, 10});
  const checker::Run small = checker::minimise_run(run, [](const checker::Run& r) {
    return checker::run_cycles(r) >= 5 ? 4L : -1L;
  });
  EXPECT_EQ(checker::run_cycles(small), 5u);
}

// A mutant whose difference needs a timer and analog values is told apart
// by the simulation falsifier, with a run both runtimes replay, without the
// provers (a time function moved by one cycle on the analog high-level cause).
TEST(Equivalence, SimulationSeparatesTimerMutant) {
  const model::Matrix m = example("tank-overfill");
  const model::Matrix mu = mutant(m, "time-ms-plus.c1");
  auto r = checker::decide_equivalence(m, mu, checker::whole_matrix(m, mu));
  ASSERT_EQ(r.verdict, EquivalenceVerdict::Differs) << r.reason;
  EXPECT_EQ(r.method, "simulation");
  ASSERT_TRUE(r.distinction.has_value());
  const auto& d = *r.distinction;
  auto ta = checker::run_on_runtime(m, d.run_a.inputs), tb = checker::run_on_runtime(mu, d.run_b.inputs);
  const auto obs = model::observables(m);
  std::size_t i = 0;
  while (obs[i].key != d.key) ++i;
  EXPECT_EQ(ta.observables.back()[i], d.value_a);
  EXPECT_EQ(tb.observables.back()[i], d.value_b);
  EXPECT_NE(d.value_a, d.value_b);
}
