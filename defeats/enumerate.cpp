#include "defeats/enumerate.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "checker/check.hpp"
#include "defeats/runs.hpp"
#include "formats/diagnostics.hpp"
#include "properties/parser.hpp"
#include "response/demand.hpp"
#include "response/property.hpp"

namespace cemv::defeats {

namespace {

using Set = std::vector<int>;

bool subset_of(const Set& a, const Set& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); }

// The property's name for a set: the path's key and the set's action
// numbers (1-based), "defeat.c1.e2.a3_7"; the empty set "defeat.c1.e2.none";
// a group question (never reported as a defeat) "defeat.c1.e2.group<n>".
std::string set_name(const PathDefeats& pd, const Set& s) {
  std::string n = "defeat." + pd.path.key() + ".";
  if (s.empty()) return n + "none";
  n += "a";
  for (std::size_t i = 0; i < s.size(); ++i) n += (i ? "_" : "") + std::to_string(s[i] + 1);
  return n;
}

std::string group_name(const PathDefeats& pd, int n) { return "defeat." + pd.path.key() + ".group" + std::to_string(n); }

class Enumerator {
 public:
  Enumerator(const model::Matrix& m, PathDefeats& pd, const AskOptions& o)
      : m_(m), pd_(pd), o_(o), runs_(response::demand_runs(m, pd.path, response::Mode::Normal, *pd.requirement)) {}

  void run(int max_size) {
    const Question& none = ask({}, true, "");
    if (!none.holds()) {
      if (none.defeats()) record_defeat(pd_.questions.size() - 1);
      finish();
      return;
    }
    Set all(pd_.actions.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    if (max_size >= 1) singles(all);
    if (max_size >= 2 && !cancelled()) pairs(proved_singles());
    for (int k = 3; k <= max_size && !cancelled(); ++k) level(k);
    finish();
  }

 private:
  bool cancelled() const { return o_.cancel && o_.cancel->cancelled(); }

  // Decides whether exactly the actions of `s` may occur defeats the path.
  // `write`: a candidate whose counterexample may be reported (written
  // under the out folder); group questions are not.
  const Question& ask(const Set& s, bool write, const std::string& name_override) {
    // A group question (named by the caller) only needs a proof: a group
    // that is not proved is split, whether it defeats or is undecided.
    const bool group = !name_override.empty();
    Question q;
    q.actions = s;
    q.property = name_override.empty() ? set_name(pd_, s) : name_override;
    std::vector<std::string> excluded;
    for (std::size_t i = 0; i < pd_.actions.size(); ++i)
      if (!std::binary_search(s.begin(), s.end(), static_cast<int>(i)))
        excluded.push_back(pd_.actions[i].excluded_term());
    const std::string text =
        response::requirement_property_text(m_, pd_.path, *pd_.requirement, q.property, excluded);
    properties::PropertyFile file;
    try {
      file = properties::parse_properties(text, m_, "cemv-defeats:" + q.property);
    } catch (const formats::LoadError& e) {
      std::string what;
      for (const auto& i : e.issues()) what += "\n" + i.str();
      throw std::logic_error("cemv defeats wrote a property the parser refuses:" + what + "\n" + text);
    }
    checker::CheckOptions options;
    options.property_timeout_s = o_.timeout_s;
    options.cancel = o_.cancel;
    options.jobs = 1;
    options.out_dir = write ? o_.out_dir : "";
    options.support = false;
    options.budgets.engine = o_.work;
    // The demand with the set's actions taken: most defeats shown by one run
    // of the runtime; the runs also witness that a demand can occur (vacuity).
    options.directed_runs = defeat_runs(m_, pd_.path, pd_.actions, s, runs_);
    options.localize_to = pd_.path.elements;
    // A question no directed run falsifies usually holds: the engines of a
    // proof first, as cemv response asks for a bound it expects to hold
    // (invariants+induction, k-induction, BMC; PDR and BMC on a wide cone);
    // left open, the whole portfolio.
    // A group gets the proof engines alone, within a quarter of the budget:
    // searching a group's counterexample past the directed runs (the
    // accelerated unrolling over a long T) is work the split does anyway.
    options.engines = {checker::Method::InvariantsInduction, checker::Method::KInduction, checker::Method::Bmc};
    options.engines_when_wide = {checker::Method::Pdr, checker::Method::Bmc};
    if (group) {
      options.engines.pop_back();
      options.engines_when_wide.pop_back();
      options.budgets.engine = o_.work / 4;
    }
    checker::CheckResult r = checker::check_properties(m_, {file}, options);
    if (r.properties.at(0).verdict == checker::PropertyVerdict::Unknown && !group && !cancelled()) {
      options.engines.clear();
      options.engines_when_wide.clear();
      options.localize_to.clear();
      r = checker::check_properties(m_, {file}, options);
    }
    const checker::PropertyResult& pr = r.properties.at(0);
    q.verdict = pr.verdict;
    q.method = pr.method;
    q.reason = pr.reason;
    q.work = pr.work;
    q.violation_cycle = pr.violation_cycle;
    if (!pr.scenario_file.empty()) q.scenario = std::filesystem::path(pr.scenario_file).filename().string();
    if (!write) q.scenario.clear();
    pd_.questions.push_back(std::move(q));
    return pd_.questions.back();
  }

  void incomplete(const Question& q) {
    complete_ = false;
    if (reason_.empty()) reason_ = q.property + ": " + (q.reason.empty() ? "unknown" : q.reason);
  }

  // The question whose proof covers `s` (a holding superset), or none.
  std::optional<std::size_t> cover(const Set& s) const {
    for (std::size_t i = 0; i < pd_.questions.size(); ++i)
      if (pd_.questions[i].holds() && subset_of(s, pd_.questions[i].actions)) return i;
    return std::nullopt;
  }

  bool contains_defeat(const Set& s) const {
    return std::any_of(pd_.sets.begin(), pd_.sets.end(),
                       [&](const DefeatSet& d) { return subset_of(d.actions, s); });
  }

  void record_defeat(std::size_t question) {
    DefeatSet d;
    d.actions = pd_.questions[question].actions;
    d.question = question;
    const bool declared = !d.actions.empty() && std::all_of(d.actions.begin(), d.actions.end(), [&](int a) {
      return declared_for(m_, pd_.path, pd_.actions[a]);
    });
    d.set_class = declared ? SetClass::Declared : SetClass::Indirect;
    for (std::size_t drop = 0; drop < d.actions.size(); ++drop) {
      Set sub = d.actions;
      sub.erase(sub.begin() + static_cast<std::ptrdiff_t>(drop));
      const std::optional<std::size_t> c = cover(sub);
      if (!c) throw std::logic_error("cemv defeats: a defeat set without proofs of its subsets");
      d.subsets.emplace_back(sub, *c);
    }
    pd_.sets.push_back(std::move(d));
  }

  // Level 1 by group testing: a group of actions proved not to defeat covers
  // each of its singletons at once; a group that defeats (or is undecided)
  // is halved. Each singleton left is asked on its own, and its
  // counterexample is the one reported.
  void singles(const Set& group) {
    if (group.empty() || cancelled()) return;
    if (group.size() == 1) {
      const Question& q = ask(group, true, "");
      if (q.defeats()) record_defeat(pd_.questions.size() - 1);
      return;
    }
    // Proved: its proof covers every singleton of the group. Otherwise
    // (it defeats, or is undecided, which the halves then decide) halved.
    if (ask(group, false, group_name(pd_, ++groups_)).holds()) return;
    const auto mid = group.begin() + static_cast<std::ptrdiff_t>(group.size() / 2);
    singles(Set(group.begin(), mid));
    singles(Set(mid, group.end()));
  }

  // The actions whose singleton is proved not to defeat.
  Set proved_singles() const {
    Set live;
    for (std::size_t i = 0; i < pd_.actions.size(); ++i)
      if (cover({static_cast<int>(i)})) live.push_back(static_cast<int>(i));
    return live;
  }

  // One pair asked on its own (its counterexample is the one reported).
  void pair(const Set& s) {
    if (cancelled() || contains_defeat(s) || cover(s)) return;
    if (ask(s, true, "").defeats()) record_defeat(pd_.questions.size() - 1);
  }

  // A group of actions proved not to defeat covers all its pairs; none is
  // asked when it holds a known defeat set (it would defeat) or is covered.
  // True when covered.
  bool group_holds(const Set& s) {
    if (cover(s)) return true;
    if (contains_defeat(s)) return false;
    return ask(s, false, group_name(pd_, ++groups_)).holds();
  }

  static std::pair<Set, Set> halves(const Set& s) {
    const auto mid = s.begin() + static_cast<std::ptrdiff_t>(s.size() / 2);
    return {Set(s.begin(), mid), Set(mid, s.end())};
  }

  // Level 2 by divide and conquer over actions none of which defeats
  // alone: the pairs within each half, then the pairs across the halves.
  void pairs(const Set& s) {
    if (s.size() < 2 || cancelled()) return;
    if (s.size() == 2) return pair(s);
    if (group_holds(s)) return;
    const auto [a, b] = halves(s);
    pairs(a);
    pairs(b);
    cross(a, b);
  }

  // The pairs with one action in `a` and one in `b`: their union asked as
  // one group, halving the larger side while it defeats.
  void cross(const Set& a, const Set& b) {
    if (a.empty() || b.empty() || cancelled()) return;
    if (a.size() == 1 && b.size() == 1) {
      Set s{a[0], b[0]};
      std::sort(s.begin(), s.end());
      return pair(s);
    }
    Set u = a;
    u.insert(u.end(), b.begin(), b.end());
    std::sort(u.begin(), u.end());
    if (group_holds(u)) return;
    const bool split_a = a.size() >= b.size();
    const auto [x, y] = halves(split_a ? a : b);
    cross(split_a ? x : a, split_a ? b : x);
    cross(split_a ? y : a, split_a ? b : y);
  }

  // Level k >= 3: the sets of k actions none of whose subsets defeats,
  // all of whose (k-1)-subsets are proved not to, and not covered already.
  void level(int k) {
    std::vector<Set> candidates;
    Set live;
    for (std::size_t i = 0; i < pd_.actions.size(); ++i)
      if (!contains_defeat({static_cast<int>(i)})) live.push_back(static_cast<int>(i));
    if (static_cast<int>(live.size()) < k) return;
    std::vector<bool> pick(live.size(), false);
    std::fill(pick.begin(), pick.begin() + k, true);
    do {
      Set s;
      for (std::size_t i = 0; i < live.size(); ++i)
        if (pick[i]) s.push_back(live[i]);
      if (contains_defeat(s) || cover(s)) continue;
      bool subsets_hold = true;
      for (std::size_t drop = 0; drop < s.size() && subsets_hold; ++drop) {
        Set sub = s;
        sub.erase(sub.begin() + static_cast<std::ptrdiff_t>(drop));
        subsets_hold = cover(sub).has_value();
      }
      if (subsets_hold) candidates.push_back(std::move(s));  // else a subset undecided: not minimal for sure
    } while (std::prev_permutation(pick.begin(), pick.end()));
    if (candidates.empty()) return;
    if (candidates.size() > 1) {
      // One question for the whole level first: the union of the candidates
      // proved not to defeat covers every one of them.
      Set all;
      for (const auto& c : candidates) all.insert(all.end(), c.begin(), c.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      if (ask(all, false, group_name(pd_, ++groups_)).holds()) return;
    }
    for (const auto& s : candidates) {
      if (cancelled()) return;
      if (contains_defeat(s) || cover(s)) continue;
      if (ask(s, true, "").defeats()) record_defeat(pd_.questions.size() - 1);
    }
  }

  void finish() {
    // A group question left undecided was split: only a candidate's own
    // undecided answer leaves the path incomplete.
    complete_ = true;
    reason_.clear();
    for (const auto& q : pd_.questions)
      if (q.verdict == checker::PropertyVerdict::Unknown && q.property.find(".group") == std::string::npos)
        incomplete(q);
    if (cancelled()) {
      complete_ = false;
      if (reason_.empty()) reason_ = checker::to_string(checker::UnknownReason::TimeLimit);
    }
    pd_.status = complete_ ? PathStatus::Complete : PathStatus::Unknown;
    pd_.reason = reason_;
    std::stable_sort(pd_.sets.begin(), pd_.sets.end(), [](const DefeatSet& a, const DefeatSet& b) {
      return a.actions.size() != b.actions.size() ? a.actions.size() < b.actions.size() : a.actions < b.actions;
    });
    for (const auto& d : pd_.sets)
      if (d.set_class == SetClass::Indirect) {
        pd_.distance = static_cast<int>(d.actions.size());
        break;
      }
  }

  const model::Matrix& m_;
  PathDefeats& pd_;
  const AskOptions& o_;
  std::vector<std::vector<model::CycleInput>> runs_;
  bool complete_ = true;
  std::string reason_;
  int groups_ = 0;
};

}  // namespace

void enumerate_minimal_sets(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o) {
  Enumerator(m, pd, o).run(max_size);
}

}  // namespace cemv::defeats
