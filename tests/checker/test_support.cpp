// The support of proofs (docs/checker.md, "Support"; issue 38, section 1):
// --support core takes the cells of the proof's unsat core over activation
// literals, full minimises that core by deletion, off reports none. Every
// reported support is held to what it claims through the public API: the
// property is proved again, by a separate check_properties run, on the
// matrix without the other candidate cells, and a minimal one loses its
// proof when any one more cell goes.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "checker/check.hpp"
#include "checker/cone_group.hpp"
#include "checker/group_support.hpp"
#include "checker/support.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"
#include "properties/parser.hpp"
#include "properties/monitor.hpp"
#include "properties/print.hpp"
#include "properties/standard.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

std::filesystem::path example(const std::string& name) {
  return std::filesystem::path(CEMV_SOURCE_DIR) / "examples" / name / "matrix.json";
}

CheckResult check(const model::Matrix& m, const std::vector<properties::PropertyFile>& files, SupportMode mode) {
  CheckOptions o;
  o.support_mode = mode;
  o.support = mode != SupportMode::Off;
  o.jobs = 2;
  return check_properties(m, files, o);
}

// The property (by name) decided on `m` without the candidates of its
// roots that `support` does not name; nullopt when that matrix is invalid.
std::optional<PropertyVerdict> verdict_without_the_rest(const model::Matrix& m, const properties::PropertyFile& file,
                                                        const properties::Property& p,
                                                        const std::vector<SupportElement>& support,
                                                        const std::string& also_removed = "") {
  std::set<std::string> keep;
  for (const auto& s : support) keep.insert(s.key);
  keep.erase(also_removed);
  model::Matrix reduced = m;
  for (const auto& d : candidate_deletions(m, properties::property_roots(p, file.assumptions, m)))
    if (!keep.count(d.element.key)) d.apply(reduced);
  if (model::has_errors(model::validate(reduced))) return std::nullopt;
  // The same property, as text parsed against the smaller matrix (its tag
  // positions are that matrix's).
  const model::InputTable inputs(m);
  std::string text = "property " + p.name + " {\n";
  for (const auto& a : file.assumptions) text += "  assume " + properties::to_text(a.expr, inputs) + "\n";
  for (const auto& a : p.assumptions) text += "  assume " + properties::to_text(a.expr, inputs) + "\n";
  text += "  " + properties::statement_text(p, inputs) + "\n}\n";
  properties::PropertyFile again = properties::parse_properties(text, reduced, "again.props");
  CheckResult r = check(reduced, {again}, SupportMode::Off);
  return r.properties.at(0).verdict;
}

class SupportOnTheTank : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    m_ = new model::Matrix(formats::load_matrix(example("tank-overfill")));
    file_ = new properties::PropertyFile(properties::standard_properties(*m_));
    core_ = new CheckResult(check(*m_, {*file_}, SupportMode::Core));
    full_ = new CheckResult(check(*m_, {*file_}, SupportMode::Full));
  }
  static const PropertyResult& result(const CheckResult& r, const std::string& name) {
    for (const auto& p : r.properties)
      if (p.name == name) return p;
    throw std::runtime_error("no property " + name);
  }
  static const properties::Property& property(const std::string& name) {
    for (const auto& p : file_->properties)
      if (p.name == name) return p;
    throw std::runtime_error("no property " + name);
  }
  static bool has(const PropertyResult& r, const std::string& key) {
    for (const auto& s : r.support)
      if (s.key == key) return true;
    return false;
  }
  static inline model::Matrix* m_ = nullptr;
  static inline properties::PropertyFile* file_ = nullptr;
  static inline CheckResult* core_ = nullptr;
  static inline CheckResult* full_ = nullptr;
};

TEST_F(SupportOnTheTank, TheResultSaysWhichModeMadeIt) {
  EXPECT_EQ(core_->support_mode, SupportMode::Core);
  EXPECT_EQ(full_->support_mode, SupportMode::Full);
  CheckResult off = check(*m_, {*file_}, SupportMode::Off);
  EXPECT_EQ(off.support_mode, SupportMode::Off);
  for (const auto& p : off.properties) EXPECT_TRUE(p.support.empty()) << p.name;
}

TEST_F(SupportOnTheTank, NoVerdictDependsOnTheMode) {
  ASSERT_EQ(core_->properties.size(), full_->properties.size());
  for (std::size_t i = 0; i < core_->properties.size(); ++i)
    EXPECT_EQ(core_->properties[i].verdict, full_->properties[i].verdict) << core_->properties[i].name;
}

// Cause 1 requests effect 2 by its own intersection; causes 2 and 3 request
// it too, and the proof about cause 1 needs neither of theirs.
TEST_F(SupportOnTheTank, TheCoreNamesTheCellTheProofUsesAndNotItsNeighbours) {
  const PropertyResult& r = result(*core_, "std.intersection.c1.e2");
  ASSERT_EQ(r.verdict, PropertyVerdict::Proved) << r.reason;
  EXPECT_TRUE(has(r, "intersection[1,2]"));
  EXPECT_FALSE(has(r, "intersection[2,2]"));
  EXPECT_FALSE(has(r, "intersection[3,2]"));
  EXPECT_FALSE(r.support_minimal);
}

TEST_F(SupportOnTheTank, EveryCoreCarriesItsProofAlone) {
  int proofs = 0;
  for (const auto& r : core_->properties) {
    if (r.verdict != PropertyVerdict::Proved) continue;
    ++proofs;
    const properties::Property& p = property(r.name);
    const auto v = verdict_without_the_rest(*m_, *file_, p, r.support);
    ASSERT_TRUE(v.has_value()) << r.name;
    EXPECT_EQ(*v, PropertyVerdict::Proved) << r.name;
  }
  EXPECT_GT(proofs, 5);
}

TEST_F(SupportOnTheTank, FullIsInsideTheCoreAndMinimal) {
  for (const auto& r : full_->properties) {
    if (r.verdict != PropertyVerdict::Proved) continue;
    const PropertyResult& c = result(*core_, r.name);
    for (const auto& s : r.support) EXPECT_TRUE(has(c, s.key)) << r.name << ": " << s.key << " not in the core";
    const properties::Property& p = property(r.name);
    EXPECT_EQ(verdict_without_the_rest(*m_, *file_, p, r.support), PropertyVerdict::Proved) << r.name;
    if (!r.support_minimal) continue;
    // Minimal: without any one more cell the proof is gone (or the matrix
    // is invalid, which keeps the cell).
    for (const auto& s : r.support) {
      const auto v = verdict_without_the_rest(*m_, *file_, p, r.support, s.key);
      if (v) {
        EXPECT_NE(*v, PropertyVerdict::Proved) << r.name << " holds without " << s.key;
      }
    }
  }
}

// The core query of a cone group (checker/group_support.hpp): one guarded
// encoding of the group's cone for all the proofs its members found. A core
// names only the question's own candidates, and the group's proofs find one
// there (the supports made from them carry their proofs alone:
// EveryCoreCarriesItsProofAlone, through check_properties).
TEST_F(SupportOnTheTank, AGroupsCoresNameOnlyEachProofsOwnCandidates) {
  std::vector<GroupMember> members;
  for (const auto& p : file_->properties) members.push_back({file_, &p});
  const CheckOptions o;
  Limits l;
  l.solvers = o.solvers;
  std::size_t asked = 0, found = 0;
  for (const auto& g : cone_groups(*m_, members)) {
    if (g.size() < 2) continue;
    std::vector<GroupMember> group;
    for (std::size_t i : g) group.push_back(members[i]);
    const std::vector<EarlyAnswer> early = ConeGroup(*m_, group, o).decide(l);
    std::vector<SupportQuestion> questions;
    for (std::size_t k = 0; k < group.size(); ++k) {
      if (!early[k].proof) continue;
      SupportQuestion q;
      q.member = k;
      q.proof = &*early[k].proof;
      for (const auto& d : candidate_deletions(*m_, properties::property_roots(*group[k].property, file_->assumptions, *m_)))
        q.keys.insert(d.element.key);
      questions.push_back(std::move(q));
    }
    const auto cores = group_support_cores(*m_, group, questions, o, l);
    ASSERT_EQ(cores.size(), questions.size());
    for (std::size_t q = 0; q < questions.size(); ++q) {
      ++asked;
      if (!cores[q]) continue;
      ++found;
      for (const auto& k : cores[q]->used) EXPECT_TRUE(cores[q]->guarded.count(k)) << k;
      for (const auto& k : cores[q]->guarded) EXPECT_TRUE(questions[q].keys.count(k)) << k;
    }
  }
  EXPECT_GT(asked, 1u);
  EXPECT_EQ(found, asked);
}

}  // namespace
