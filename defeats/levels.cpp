// The level-by-level enumeration of one path's minimal defeat sets
// (docs/defeats.md, "The level-by-level enumeration"): singletons by group
// testing, pairs by divide and conquer, larger sets from the covered
// subsets. On one encoding, each group and candidate is first tested on the
// path's ActionSpace (its demand runs and a proof under assumptions, whose
// unsat cores grow the set it covers); the checker is asked only for a
// candidate that proof leaves open or that defeats, whose counterexample is
// the one reported.
#include "defeats/enumerate.hpp"
#include "defeats/ask.hpp"

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>

#include "checker/check/recheck.hpp"
#include "defeats/runs.hpp"
#include "defeats/space.hpp"
#include "response/demand.hpp"

namespace cemv::defeats {

namespace {

using Set = std::vector<int>;

// The depth of the k-induction a test on the encoding tries: with the
// invariant candidates Houdini filters, every proof of the four examples'
// sets is at k <= 1, and a deeper step (with its base cases, a BMC) costs
// most where the set defeats, which the checker's question then decides
// anyway (docs/performance.md, "cemv defeats").
constexpr int kProofDepth = 1;

bool subset_of(const Set& a, const Set& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); }

std::string group_name(const PathDefeats& pd, int n) { return "defeat." + pd.path.key() + ".group" + std::to_string(n); }

class Enumerator {
 public:
  Enumerator(const model::Matrix& m, PathDefeats& pd, const AskOptions& o, bool on_encoding)
      : m_(m), pd_(pd), o_(o), runs_(response::demand_runs(m, pd.path, response::Mode::Normal, *pd.requirement)),
        space_(on_encoding ? std::make_unique<ActionSpace>(m, pd, runs_) : nullptr) {}

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
    recheck_proofs();
    finish();
  }

 private:
  bool cancelled() const { return o_.cancel && o_.cancel->cancelled(); }

  // Decides whether exactly the actions of `s` may occur defeats the path.
  // `write`: a candidate whose counterexample may be reported (written
  // under the out folder); group questions (named by the caller) are not.
  const Question& ask(const Set& s, bool write, const std::string& name_override) {
    const bool group = !name_override.empty();
    const std::string name = group ? name_override : set_name(pd_, s);
    checker::Work spent = 0;
    if (space_ && !cancelled()) {
      // A group gets a quarter of the budget, as the checker's group question.
      const Test t = space_->test(s, limits(group ? o_.work / 4 : o_.work), kProofDepth);
      spent = t.work;
      if (t.answer == Test::Answer::Holds || group) return record(s, name, t);
    }
    pd_.questions.push_back(ask_checker(m_, pd_, s, name, group, write, runs_, o_));
    pd_.questions.back().work += spent;
    return pd_.questions.back();
  }

  checker::Limits limits(checker::Work work) const {
    checker::Limits l;
    l.work = work;
    l.cancel = o_.cancel;
    if (o_.timeout_s > 0)
      l.deadline = checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                               std::chrono::duration<double>(o_.timeout_s));
    return l;
  }

  // A test on the path's encoding as a question: one that holds lists the
  // set its proof covers, and keeps its proof for the re-check.
  const Question& record(const Set& s, const std::string& name, const Test& t) {
    Question q;
    q.property = name;
    q.actions = t.answer == Test::Answer::Holds ? t.covered : s;
    q.method = t.method;
    q.work = t.work;
    q.reason = t.reason;
    q.verdict = t.answer == Test::Answer::Holds     ? checker::PropertyVerdict::Proved
                : t.answer == Test::Answer::Defeats ? checker::PropertyVerdict::Falsified
                                                    : checker::PropertyVerdict::Unknown;
    if (t.answer == Test::Answer::Holds) proofs_.emplace_back(pd_.questions.size(), t);
    pd_.questions.push_back(std::move(q));
    return pd_.questions.back();
  }

  // Every proof on the encoding re-proved in a fresh context, as the checker
  // re-proves its own: those a reported set's minimality cites, and those
  // the completeness of the path rests on (a group or candidate covered).
  void recheck_proofs() {
    for (const auto& [question, proof] : proofs_) {
      try {
        space_->recheck(proof, limits(o_.work));
      } catch (const checker::Interrupted&) {
        unchecked_ = question;
        return;
      }
    }
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
    if (unchecked_) {
      complete_ = false;
      if (reason_.empty()) reason_ = pd_.questions[*unchecked_].property + ": its re-check was interrupted";
    }
    finish_path(pd_, complete_, reason_, cancelled());
  }

  const model::Matrix& m_;
  PathDefeats& pd_;
  const AskOptions& o_;
  std::vector<Run> runs_;
  std::unique_ptr<ActionSpace> space_;               // on one encoding: the path's
  std::vector<std::pair<std::size_t, Test>> proofs_;  // its proofs, by question
  std::optional<std::size_t> unchecked_;              // a proof whose re-check was interrupted
  bool complete_ = true;
  std::string reason_;
  int groups_ = 0;
};

}  // namespace

void enumerate_level_by_level(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o,
                              bool on_encoding) {
  Enumerator(m, pd, o, on_encoding).run(max_size);
}

}  // namespace cemv::defeats
