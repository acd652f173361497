// Properties of validation and the dependency graph on many seeded random
// matrices (tests/support): the generator's matrices are valid, the order is a
// topological order except exactly at the edges marked reads_previous, every
// cycle contains such an edge, and everything is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "model/graph.hpp"
#include "reports/dot.hpp"
#include "model/validate.hpp"
#include "tests/support/random_matrix.hpp"

namespace cemv::model {
namespace {

std::string dump(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += d.rule + " " + d.element + ": " + d.message + "\n";
  return s;
}

void check_graph(const Matrix& m, const DependencyGraph& g) {
  // The order holds every processed element exactly once.
  std::set<Node> expected;
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) expected.insert({Node::Kind::Cause, c.id});
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) expected.insert({Node::Kind::Effect, e.id});
  const auto& order = g.evaluation_order();
  ASSERT_EQ(order.size(), expected.size());
  ASSERT_EQ(std::set<Node>(order.begin(), order.end()), expected);

  std::map<Node, std::size_t> pos;
  for (std::size_t i = 0; i < order.size(); ++i) pos[order[i]] = i;
  for (const auto& e : g.edges()) {
    if (e.reads_previous) {
      EXPECT_EQ(e.kind, Edge::Kind::Reference);
      EXPECT_GE(pos[e.from], pos[e.to]);
    } else {
      EXPECT_LT(pos[e.from], pos[e.to]);
    }
  }
  // Every cycle is broken by at least one of its edges.
  for (const auto& cycle : g.cycles()) {
    bool broken = false;
    for (std::size_t i = 0; i < cycle.size(); ++i)
      broken |= g.reads_previous(cycle[i], cycle[(i + 1) % cycle.size()]);
    EXPECT_TRUE(broken);
  }
  // A reads_previous edge closes a cycle: its reader reaches its source.
  for (const auto& e : g.cycle_closing_edges()) {
    auto reach = g.reach_of(e.to);
    EXPECT_TRUE(std::binary_search(reach.begin(), reach.end(), e.from));
  }
  // Feeders and reach are mirror images.
  for (const auto& n : order)
    for (const auto& f : g.feeders_of(n)) {
      auto reach = g.reach_of(f);
      EXPECT_TRUE(std::binary_search(reach.begin(), reach.end(), n));
    }
}

TEST(RandomMatrices, ValidWithConsistentOrder) {
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Matrix m = testsupport::random_matrix(seed);
    auto ds = validate(m);
    EXPECT_FALSE(has_errors(ds)) << dump(ds);
    EXPECT_EQ(dump(validate(m)), dump(ds));
    DependencyGraph g(m);
    check_graph(m, g);
    EXPECT_EQ(cemv::reports::to_dot(m, DependencyGraph(m)), cemv::reports::to_dot(m, g));
  }
}

TEST(RandomMatrices, ReferenceHeavyMatricesKeepTheirProperties) {
  testsupport::MatrixOptions opt;
  opt.min_causes = 8;
  opt.max_causes = 20;
  opt.min_effects = 4;
  opt.max_effects = 10;
  opt.p_internal_ref = 0.8;
  opt.p_cycle_ref = 0.7;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    Matrix m = testsupport::random_matrix(seed, opt);
    EXPECT_NO_THROW(validate(m));
    check_graph(m, DependencyGraph(m));
  }
}

// The 128 x 128 x 1024 benchmark matrix (its timing lives in bench/).
TEST(RandomMatrices, BigMatrixIsValid) {
  Matrix m = testsupport::big_matrix(1);
  auto ds = validate(m);
  EXPECT_FALSE(has_errors(ds)) << dump(ds);
  check_graph(m, DependencyGraph(m));
}

}  // namespace
}  // namespace cemv::model
