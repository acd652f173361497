#include <cctype>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "mutate/mutants.hpp"

namespace {

using namespace cemv;

const char* kExamples[] = {"tank-overfill", "burner-management", "compressor", "pipeline-hipps"};

model::Matrix example(const std::string& name) {
  return formats::load_valid_matrix(std::string(CEMV_SOURCE_DIR) + "/examples/" + name + "/matrix.json", "mutated");
}

const mutate::Mutant* find(const mutate::MutantSet& s, const std::string& id) {
  for (const auto& m : s.mutants)
    if (m.id == id) return &m;
  return nullptr;
}

class Examples : public ::testing::TestWithParam<const char*> {};

// Every mutant is valid, differs from the original, has a unique file-safe id
// and one of the documented operators; refused edits say why.
TEST_P(Examples, MutantsAreValidDistinctSinglePointEdits) {
  const model::Matrix m = example(GetParam());
  const std::string original = formats::to_canonical_json(m);
  const mutate::MutantSet set = mutate::mutants(m);
  ASSERT_GT(set.mutants.size(), 20u);
  std::set<std::string> ops, ids, texts;
  for (const auto& o : mutate::operators()) ops.insert(o.name);
  for (const auto& mu : set.mutants) {
    EXPECT_TRUE(ids.insert(mu.id).second) << mu.id;
    EXPECT_TRUE(ops.count(mu.op)) << mu.op;
    EXPECT_EQ(mu.id.rfind(mu.op + ".", 0), 0u) << mu.id;
    for (char c : mu.id) EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') << mu.id;
    EXPECT_FALSE(model::has_errors(model::validate(mu.matrix))) << mu.id;
    const std::string text = formats::to_canonical_json(mu.matrix);
    EXPECT_NE(text, original) << mu.id;
    EXPECT_TRUE(texts.insert(text).second) << "two mutants with one matrix: " << mu.id;
    EXPECT_FALSE(mu.description.empty());
  }
  for (const auto& r : set.refused) {
    EXPECT_FALSE(r.reason.empty()) << r.id;
    EXPECT_FALSE(ids.count(r.id)) << r.id;
  }
}

// The same matrix gives the same mutants in the same order.
TEST_P(Examples, Deterministic) {
  const model::Matrix m = example(GetParam());
  const auto a = mutate::mutants(m), b = mutate::mutants(m);
  ASSERT_EQ(a.mutants.size(), b.mutants.size());
  for (std::size_t i = 0; i < a.mutants.size(); ++i) EXPECT_EQ(a.mutants[i].id, b.mutants[i].id);
}

INSTANTIATE_TEST_SUITE_P(Mutate, Examples, ::testing::ValuesIn(kExamples));

// Each operator does exactly its edit (tank-overfill: cause 1 is an analog
// 2oo3 with an on-delay of 2000 ms and a bypass tag; effect 1 has a reset tag
// and pass-through).
TEST(Mutate, OperatorsEditOneField) {
  const model::Matrix m = example("tank-overfill");
  const mutate::MutantSet s = mutate::mutants(m);
  const auto* removed = find(s, "intersection-removed.c1e1");
  ASSERT_NE(removed, nullptr);
  EXPECT_EQ(removed->matrix.find_intersection(1, 1), nullptr);
  EXPECT_EQ(removed->matrix.intersections.size() + 1, m.intersections.size());
  const auto* plus = find(s, "time-ms-plus.c1");
  ASSERT_NE(plus, nullptr);
  EXPECT_EQ(plus->matrix.find_cause(1)->time.ms, m.find_cause(1)->time.ms + m.cycle_ms);
  const auto* minus = find(s, "time-ms-minus.c1");
  ASSERT_NE(minus, nullptr);
  EXPECT_EQ(minus->matrix.find_cause(1)->time.ms, m.find_cause(1)->time.ms - m.cycle_ms);
  const auto* bq = find(s, "bad-quality.trip.c1");
  ASSERT_NE(bq, nullptr);
  EXPECT_EQ(bq->matrix.find_cause(1)->bad_quality, model::BadQuality::Trip);
  const auto* byp = find(s, "cause-bypass-tag-removed.c1");
  ASSERT_NE(byp, nullptr);
  EXPECT_FALSE(byp->matrix.find_cause(1)->bypass_tag.has_value());
  const auto* ett = find(s, "tag-ett.c1t2");
  ASSERT_NE(ett, nullptr);
  EXPECT_NE(ett->matrix.find_cause(1)->tags[1].ett, m.find_cause(1)->tags[1].ett);
  EXPECT_EQ(ett->matrix.find_cause(1)->tags[0].ett, m.find_cause(1)->tags[0].ett);
  const auto* reset = find(s, "effect-reset-tag-removed.e1");
  ASSERT_NE(reset, nullptr);
  EXPECT_FALSE(reset->matrix.find_effect(1)->reset_tag.has_value());
  const auto* pt = find(s, "pass-through.e1");
  ASSERT_NE(pt, nullptr);
  EXPECT_NE(pt->matrix.find_effect(1)->process_data->pass_through, m.find_effect(1)->process_data->pass_through);
  // A 2oo3 cause cannot become `normal` with three tags: refused, with the rule.
  bool refused = false;
  for (const auto& r : s.refused)
    if (r.id == "cause-function.normal.c1") refused = r.reason.find("E-FUNCTION-TAG-COUNT") != std::string::npos;
  EXPECT_TRUE(refused);
}

// Every operator of the list fires on some example.
TEST(Mutate, EveryOperatorIsExercised) {
  std::set<std::string> seen;
  for (const char* e : kExamples)
    for (const auto& mu : mutate::all_edits(example(e))) seen.insert(mu.op);
  for (const auto& o : mutate::operators()) EXPECT_TRUE(seen.count(o.name)) << o.name;
}

}  // namespace
