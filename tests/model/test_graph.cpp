// The dependency graph: nodes, edges, evaluation order with cycle breaking,
// elementary cycles, cone of influence and DOT output.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "model/graph.hpp"
#include "reports/dot.hpp"
#include "validate_cases/builder.hpp"

namespace cemv::model {
namespace {

using testcases::MatrixBuilder;

Node C(int id) { return {Node::Kind::Cause, id}; }
Node E(int id) { return {Node::Kind::Effect, id}; }

std::string str(const std::vector<Node>& ns) {
  std::string s;
  // Appending piecewise: GCC 12 -O2 reports a false -Wrestrict (GCC bug 105651)
  // on `const char* + std::string` temporaries.
  for (const auto& n : ns) {
    if (!s.empty()) s += ' ';
    s += to_string(n);
  }
  return s;
}

std::string str(const std::vector<Edge>& es) {
  std::string s;
  for (const auto& e : es) {
    s += (s.empty() ? "" : ", ") + to_string(e.from) +
         (e.kind == Edge::Kind::Intersection ? "->" : "~>") + to_string(e.to);
    if (e.reads_previous) s += "(prev)";
  }
  return s;
}

// Every edge that does not read the previous cycle goes forward in the order,
// every edge that does goes backward (or is a self loop).
void expect_order_consistent(const DependencyGraph& g) {
  std::map<Node, std::size_t> pos;
  const auto& order = g.evaluation_order();
  for (std::size_t i = 0; i < order.size(); ++i) pos[order[i]] = i;
  for (const auto& e : g.edges()) {
    ASSERT_TRUE(pos.count(e.from) && pos.count(e.to));
    if (e.reads_previous)
      EXPECT_GE(pos[e.from], pos[e.to]) << str(std::vector<Edge>{e});
    else
      EXPECT_LT(pos[e.from], pos[e.to]) << str(std::vector<Edge>{e});
  }
}

TEST(NodeOrder, CausesBeforeEffectsThenById) {
  EXPECT_LT(C(9), E(1));
  EXPECT_LT(C(1), C(2));
  EXPECT_LT(E(1), E(2));
  EXPECT_EQ(to_string(C(3)), "cause[3]");
  EXPECT_EQ(to_string(E(12)), "effect[12]");
}

TEST(EvaluationOrder, TiesAreCausesBeforeEffectsThenId) {
  MatrixBuilder b;
  b.cause(3, "C3", {"I3"}).cause(1, "C1", {"I1"}).cause(2, "C2", {"I2"});
  b.effect(2, "E2", {"O2"}).effect(1, "E1", {"O1"});
  b.link(3, 1).link(1, 2).link(2, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] cause[2] cause[3] effect[1] effect[2]");
  EXPECT_TRUE(g.cycle_closing_edges().empty());
  EXPECT_TRUE(g.cycles().empty());
}

TEST(EvaluationOrder, ChainThroughReferencesFollowsTheDataFlow) {
  // cause 1 -> effect 1; cause 2 reads Effect[1]; cause 2 -> effect 2;
  // effect 2's reset tag reads Cause[3]. Cause 2 must wait for effect 1.
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"}).cause(2, "C2", {"Effect[1]"}).cause(3, "C3", {"I3"});
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2"});
  b.last_effect().reset_tag = "Cause[3]";
  b.link(1, 1).link(2, 2, IntersectionType::S).link(3, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] cause[3] effect[1] cause[2] effect[2]");
  EXPECT_EQ(str(g.edges()),
            "cause[1]->effect[1], cause[2]->effect[2], cause[3]->effect[1], cause[3]~>effect[2], "
            "effect[1]~>cause[2]");
  expect_order_consistent(g);
}

TEST(EvaluationOrder, EffectTagReferenceIsAnEdgeFromTheEffect) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"}).cause(2, "C2", {"Effect[2][2]"});
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2", "O3"});
  b.link(1, 2).link(2, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] effect[2] cause[2] effect[1]");
  EXPECT_FALSE(g.reads_previous(E(2), C(2)));
}

TEST(EvaluationOrder, EveryReferenceFieldGivesAnEdge) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"}).cause(2, "C2", {"I2"}).cause(3, "C3", {"I3"});
  b.last_cause().bypass_tag = "Cause[1]";
  b.last_cause().inhibit_tag = "Cause[2]";
  b.effect(1, "E1", {"O1"});
  b.last_effect().bypass_tag = "Cause[1]";
  b.last_effect().reset_tag = "Cause[2]";
  b.last_effect().process_data = ProcessData{"Cause[3]", true, "Effect[2]"};
  b.effect(2, "E2", {"O2"});
  b.link(1, 2).link(2, 2).link(3, 2);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.edges()),
            "cause[1]~>cause[3], cause[1]~>effect[1], cause[1]->effect[2], "
            "cause[2]~>cause[3], cause[2]~>effect[1], cause[2]->effect[2], "
            "cause[3]~>effect[1], cause[3]->effect[2], effect[2]~>effect[1]");
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] cause[2] cause[3] effect[2] effect[1]");
  expect_order_consistent(g);
}

TEST(EvaluationOrder, CycleIsBrokenAtItsSmallestNode) {
  // cause 1 -> effect 1 (N) and cause 1's bypass tag reads Effect[1]: the
  // reference closes the cycle, cause 1 sees effect 1 of the previous cycle.
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"});
  b.last_cause().bypass_tag = "Effect[1]";
  b.cause(2, "C2", {"I2"});
  b.effect(1, "E1", {"O1"});
  b.link(1, 1).link(2, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[2] cause[1] effect[1]");
  EXPECT_TRUE(g.reads_previous(E(1), C(1)));
  EXPECT_FALSE(g.reads_previous(C(1), E(1)));
  EXPECT_EQ(str(g.cycle_closing_edges()), "effect[1]~>cause[1](prev)");
  ASSERT_EQ(g.cycles().size(), 1u);
  EXPECT_EQ(str(g.cycles()[0]), "cause[1] effect[1]");
  expect_order_consistent(g);
}

TEST(EvaluationOrder, NodeDownstreamOfACycleReadsTheCurrentValue) {
  // Cycle: cause 3 -> effect 2 -> (inhibit of) cause 3. Cause 1 reads Effect[2]
  // but is not on the cycle: it must come after effect 2 and read it fresh,
  // although cause 1 is the smallest node left when the order gets stuck.
  MatrixBuilder b;
  b.cause(1, "C1", {"Effect[2]"});
  b.cause(3, "C3", {"I3"});
  b.last_cause().inhibit_tag = "Effect[2]";
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2"});
  b.link(1, 1).link(3, 2);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[3] effect[2] cause[1] effect[1]");
  EXPECT_TRUE(g.reads_previous(E(2), C(3)));
  EXPECT_FALSE(g.reads_previous(E(2), C(1)));
  EXPECT_EQ(str(g.cycle_closing_edges()), "effect[2]~>cause[3](prev)");
  expect_order_consistent(g);
}

TEST(EvaluationOrder, CycleAmongEffectsOnly) {
  // Effect 1's bypass reads Effect[2], effect 2's reset reads Effect[1][1].
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"});
  b.effect(1, "E1", {"O1"});
  b.last_effect().bypass_tag = "Effect[2]";
  b.effect(2, "E2", {"O2"});
  b.last_effect().reset_tag = "Effect[1][1]";
  b.link(1, 1).link(1, 2, IntersectionType::S);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] effect[1] effect[2]");
  EXPECT_TRUE(g.reads_previous(E(2), E(1)));
  EXPECT_FALSE(g.reads_previous(E(1), E(2)));
  ASSERT_EQ(g.cycles().size(), 1u);
  EXPECT_EQ(str(g.cycles()[0]), "effect[1] effect[2]");
  expect_order_consistent(g);
}

TEST(EvaluationOrder, SelfReferenceReadsThePreviousCycle) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"});
  b.last_cause().inhibit_tag = "Cause[1]";
  b.effect(1, "E1", {"O1"});
  b.link(1, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] effect[1]");
  EXPECT_TRUE(g.reads_previous(C(1), C(1)));
  ASSERT_EQ(g.cycles().size(), 1u);
  EXPECT_EQ(str(g.cycles()[0]), "cause[1]");
}

TEST(EvaluationOrder, CommentElementsAndUnprocessedIntersectionsAreNotInTheGraph) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"});
  b.comment_cause(2, "NOTE");
  b.cause(3, "C3", {"Cause[2]"});   // reference to a comment cause: no edge
  b.cause(4, "C4", {"I4"});
  b.effect(1, "E1", {"O1"});
  b.comment_effect(2, "FEEDBACK");
  b.effect(3, "E3", {"O3"});
  b.last_effect().bypass_tag = "Effect[2]";  // reference to a comment effect: no edge
  b.link(1, 1).link(2, 1).link(1, 2).link(3, 3, IntersectionType::X).link(4, 3,
                                                                         IntersectionType::Note);
  b.link(4, 1, IntersectionType::V);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] cause[3] cause[4] effect[1] effect[3]");
  EXPECT_EQ(str(g.edges()), "cause[1]->effect[1], cause[4]->effect[1]");
}

TEST(EvaluationOrder, ReferencesInsideCommentElementsAreIgnored) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"});
  b.comment_cause(2, "NOTE");
  b.last_cause().bypass_tag = "Cause[1]";
  b.effect(1, "E1", {"O1"});
  b.link(1, 1);
  Matrix m = b.build();
  EXPECT_TRUE(internal_references(m).empty());
  EXPECT_EQ(str(DependencyGraph(m).edges()), "cause[1]->effect[1]");
}

TEST(InternalReferences, ListsReaderFieldAndSource) {
  MatrixBuilder b;
  b.cause(1, "C1", {"I1", "Effect[2][3]"});
  b.last_cause().inhibit_tag = "Cause[4]";
  b.effect(1, "E1", {"O1"});
  b.last_effect().process_data = ProcessData{"P1", true, "Effect[7]"};
  auto refs = internal_references(b.build());
  ASSERT_EQ(refs.size(), 3u);
  EXPECT_EQ(refs[0].reader, C(1));
  EXPECT_EQ(refs[0].field, "input tag 2");
  EXPECT_EQ(refs[0].tag, "Effect[2][3]");
  EXPECT_EQ(refs[0].source, E(2));
  EXPECT_EQ(refs[0].source_tag, 3);
  EXPECT_EQ(refs[1].field, "inhibit_tag");
  EXPECT_EQ(refs[1].source, C(4));
  EXPECT_EQ(refs[1].source_tag, 0);
  EXPECT_EQ(refs[2].reader, E(1));
  EXPECT_EQ(refs[2].field, "process_data.mask_tag");
  EXPECT_EQ(refs[2].source, E(7));
}

TEST(EvaluationOrder, ReferencesToMissingElementsGiveNoEdge) {
  MatrixBuilder b;
  b.cause(1, "C1", {"Effect[9]"});
  b.effect(1, "E1", {"O1"});
  b.link(1, 1).link(5, 1);  // dangling intersection
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.edges()), "cause[1]->effect[1]");
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] effect[1]");
}

TEST(Cycles, EveryElementaryCycleOnceSorted) {
  // Two causes trip effect 1 and both read it: two cycles sharing effect 1;
  // plus cause 3 <-> effect 2 through Effect[2][1].
  MatrixBuilder b;
  b.cause(1, "C1", {"Effect[1]"}).cause(2, "C2", {"I2"});
  b.last_cause().bypass_tag = "Effect[1]";
  b.cause(3, "C3", {"Effect[2][1]"});
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2"});
  b.link(1, 1).link(2, 1).link(3, 2);
  DependencyGraph g(b.build());
  auto cycles = g.cycles();
  ASSERT_EQ(cycles.size(), 3u);
  EXPECT_EQ(str(cycles[0]), "cause[1] effect[1]");
  EXPECT_EQ(str(cycles[1]), "cause[2] effect[1]");
  EXPECT_EQ(str(cycles[2]), "cause[3] effect[2]");
  // Breaking at cause 1 leaves cause 2 -> effect 1 -> cause 2: broken at cause 2.
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] cause[2] effect[1] cause[3] effect[2]");
  EXPECT_EQ(str(g.cycle_closing_edges()),
            "effect[1]~>cause[1](prev), effect[1]~>cause[2](prev), effect[2]~>cause[3](prev)");
  expect_order_consistent(g);
}

TEST(Cycles, LongerCycleListedFromItsSmallestNode) {
  // effect 1 -> cause 2 -> effect 2 -> cause 1 -> effect 1
  MatrixBuilder b;
  b.cause(1, "C1", {"Effect[2]"}).cause(2, "C2", {"Effect[1]"});
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2"});
  b.link(1, 1).link(2, 2);
  DependencyGraph g(b.build());
  ASSERT_EQ(g.cycles().size(), 1u);
  EXPECT_EQ(str(g.cycles()[0]), "cause[1] effect[1] cause[2] effect[2]");
  EXPECT_EQ(str(g.evaluation_order()), "cause[1] effect[1] cause[2] effect[2]");
  EXPECT_EQ(str(g.cycle_closing_edges()), "effect[2]~>cause[1](prev)");
}

TEST(Cycles, DenseKnotIsCappedAndFast) {
  MatrixBuilder b;
  for (int e = 1; e <= 5; ++e) b.effect(e, "E" + std::to_string(e), {"Y" + std::to_string(e)});
  for (int c = 1; c <= 128; ++c) {
    b.cause(c, "C" + std::to_string(c), {"Effect[1]", "Effect[2]", "Effect[3]"});
    b.last_cause().bypass_tag = "Effect[4]";
    b.last_cause().inhibit_tag = "Effect[5]";
    for (int e = 1; e <= 5; ++e) b.link(c, e);
  }
  auto start = std::chrono::steady_clock::now();
  DependencyGraph g(b.build());
  auto elapsed = std::chrono::steady_clock::now() - start;
  auto cycles = g.cycles();
  EXPECT_EQ(cycles.size(), kMaxReportedCycles);
  EXPECT_TRUE(std::is_sorted(cycles.begin(), cycles.end()));
  EXPECT_LT(std::chrono::duration_cast<std::chrono::milliseconds>(elapsed).count(), 2000);
  EXPECT_EQ(g.evaluation_order().size(), 133u);
  expect_order_consistent(g);
}

TEST(ConeOfInfluence, FeedersAndReach) {
  // c1 -> e1 ~> c2 -> e2 ; c3 -> e2 ; c4 -> e3
  MatrixBuilder b;
  b.cause(1, "C1", {"I1"}).cause(2, "C2", {"Effect[1]"}).cause(3, "C3", {"I3"}).cause(4, "C4",
                                                                                      {"I4"});
  b.effect(1, "E1", {"O1"}).effect(2, "E2", {"O2"}).effect(3, "E3", {"O3"});
  b.link(1, 1).link(2, 2).link(3, 2).link(4, 3);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.feeders_of(E(2))), "cause[1] cause[2] cause[3] effect[1] effect[2]");
  EXPECT_EQ(str(g.feeders_of(E(3))), "cause[4] effect[3]");
  EXPECT_EQ(str(g.feeders_of(C(1))), "cause[1]");
  EXPECT_EQ(str(g.reach_of(C(1))), "cause[1] cause[2] effect[1] effect[2]");
  EXPECT_EQ(str(g.reach_of(C(3))), "cause[3] effect[2]");
  EXPECT_EQ(str(g.reach_of(E(2))), "effect[2]");
  EXPECT_EQ(str(g.feeders_of(std::vector<Node>{E(1), E(3)})), "cause[1] cause[4] effect[1] effect[3]");
  EXPECT_TRUE(g.feeders_of(E(9)).empty());
  EXPECT_TRUE(g.reach_of(C(9)).empty());
}

TEST(ConeOfInfluence, CyclesAreFollowed) {
  MatrixBuilder b;
  b.cause(1, "C1", {"Effect[1]"});
  b.effect(1, "E1", {"O1"});
  b.link(1, 1);
  DependencyGraph g(b.build());
  EXPECT_EQ(str(g.feeders_of(C(1))), "cause[1] effect[1]");
  EXPECT_EQ(str(g.reach_of(E(1))), "cause[1] effect[1]");
}

Matrix dot_matrix() {
  MatrixBuilder b("PLANT \"A\"");
  b.cause(1, "LT_HH", {"LT1", "LT2", "LT3"});
  b.last_cause().function = CauseFunction::TwoOoThree;
  b.last_cause().bypass_tag = "Effect[2]";
  b.cause(2, "PT_H", {"PT1"});
  b.effect(1, "CLOSE", {"XV1"});
  b.effect(2, "ALARM", {"XA1"});
  b.last_effect().reset_tag = "Cause[2]";
  b.link(1, 1, IntersectionType::R, 2).link(2, 1, IntersectionType::R, 2).link(1, 2, IntersectionType::S);
  return b.build();
}

TEST(Dot, GoldenOutput) {
  Matrix m = dot_matrix();
  DependencyGraph g(m);
  std::string want =
      "digraph \"PLANT \\\"A\\\"\" {\n"
      "  graph [rankdir=LR, labelloc=t, label=\"PLANT \\\"A\\\": dependency graph (dashed: "
      "internal reference, red: reads the previous cycle)\"];\n"
      "  node [fontname=\"Helvetica\", fontsize=10];\n"
      "  edge [fontname=\"Helvetica\", fontsize=9];\n"
      "  \"cause[1]\" [shape=box, label=\"cause 1\\nLT_HH\\n2oo3\\n#2\"];\n"
      "  \"cause[2]\" [shape=box, label=\"cause 2\\nPT_H\\nnormal\\n#1\"];\n"
      "  \"effect[1]\" [shape=ellipse, label=\"effect 1\\nCLOSE\\n#3\"];\n"
      "  \"effect[2]\" [shape=ellipse, label=\"effect 2\\nALARM\\n#4\"];\n"
      "  \"cause[1]\" -> \"effect[1]\" [label=\"R 2oo2\"];\n"
      "  \"cause[1]\" -> \"effect[2]\" [label=\"S\"];\n"
      "  \"cause[2]\" -> \"effect[1]\" [label=\"R 2oo2\"];\n"
      "  \"cause[2]\" -> \"effect[2]\" [label=\"Cause[2] as reset_tag\", style=dashed];\n"
      "  \"effect[2]\" -> \"cause[1]\" [label=\"Effect[2] as bypass_tag\\n(previous cycle)\", "
      "style=dashed, color=red, fontcolor=red];\n"
      "}\n";
  EXPECT_EQ(cemv::reports::to_dot(m, g), want);
}

TEST(Dot, DeterministicAcrossBuilds) {
  Matrix m = testcases::clean_matrix();
  std::string first = cemv::reports::to_dot(m, DependencyGraph(m));
  for (int i = 0; i < 5; ++i) EXPECT_EQ(cemv::reports::to_dot(m, DependencyGraph(m)), first);
  // The graph of a moved-from object is still usable after move assignment.
  DependencyGraph a(m);
  DependencyGraph c(dot_matrix());
  c = std::move(a);
  EXPECT_EQ(cemv::reports::to_dot(m, c), first);
}

TEST(Graph, EmptyMatrix) {
  Matrix m;
  DependencyGraph g(m);
  EXPECT_TRUE(g.evaluation_order().empty());
  EXPECT_TRUE(g.edges().empty());
  EXPECT_TRUE(g.cycles().empty());
  EXPECT_EQ(cemv::reports::to_dot(m, g),
            "digraph \"matrix\" {\n"
            "  graph [rankdir=LR, labelloc=t, label=\"matrix: dependency graph (dashed: internal "
            "reference, red: reads the previous cycle)\"];\n"
            "  node [fontname=\"Helvetica\", fontsize=10];\n"
            "  edge [fontname=\"Helvetica\", fontsize=9];\n"
            "}\n");
}

}  // namespace
}  // namespace cemv::model
