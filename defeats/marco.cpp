// MARCO-style enumeration of one path's minimal defeat sets up to K actions
// on its one encoding (docs/defeats.md, "Enumeration"): a map solver over one
// Boolean per action proposes a set of at most K actions that is neither a
// superset of a known defeat set nor a subset of a set known to hold; a set
// that holds grows through the unsat cores of its proof, one that defeats
// shrinks through the models of its counterexamples, and each answer blocks
// what it covers. The map's exhaustion is the completeness of the answer.
#include <algorithm>
#include <optional>
#include <stdexcept>

#include <z3++.h>

#include "checker/check/recheck.hpp"
#include "defeats/ask.hpp"
#include "defeats/enumerate.hpp"
#include "defeats/space.hpp"
#include "response/demand.hpp"

namespace cemv::defeats {

namespace {

using Set = std::vector<int>;

bool subset_of(const Set& a, const Set& b) { return std::includes(b.begin(), b.end(), a.begin(), a.end()); }

Set without(const Set& s, std::size_t at) {
  Set r = s;
  r.erase(r.begin() + static_cast<std::ptrdiff_t>(at));
  return r;
}

// The sets explored so far, as constraints over one Boolean per action.
class Map {
 public:
  Map(std::size_t actions, int max_size) : solver_(ctx_) {
    z3::expr_vector all(ctx_);
    for (std::size_t i = 0; i < actions; ++i) {
      x_.push_back(ctx_.bool_const(("a" + std::to_string(i + 1)).c_str()));
      all.push_back(x_.back());
    }
    if (!x_.empty()) solver_.add(z3::atmost(all, static_cast<unsigned>(max_size)));
    max_size_ = static_cast<std::size_t>(max_size);
  }

  // A set of at most K actions not yet covered, as large as the map allows
  // (a larger set that holds covers more), or none: every set is decided.
  std::optional<Set> seed() {
    if (solver_.check() != z3::sat) return std::nullopt;
    const z3::model m = solver_.get_model();
    Set s;
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (m.eval(x_[i], true).is_true()) s.push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < x_.size() && s.size() < max_size_; ++i) {
      if (std::binary_search(s.begin(), s.end(), static_cast<int>(i))) continue;
      Set t = s;
      t.insert(std::upper_bound(t.begin(), t.end(), static_cast<int>(i)), static_cast<int>(i));
      if (std::none_of(defeats_.begin(), defeats_.end(), [&](const Set& d) { return subset_of(d, t); }))
        s = std::move(t);
    }
    return s;
  }
  // Every subset of `s` is decided (it holds).
  void block_down(const Set& s) {
    z3::expr_vector out(ctx_);
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (!std::binary_search(s.begin(), s.end(), static_cast<int>(i))) out.push_back(x_[i]);
    solver_.add(z3::mk_or(out));
  }
  // Every superset of `s` is decided (it defeats, and none is minimal).
  void block_up(const Set& s) {
    z3::expr_vector not_in(ctx_);
    for (int i : s) not_in.push_back(!x_[static_cast<std::size_t>(i)]);
    solver_.add(z3::mk_or(not_in));
    defeats_.push_back(s);
  }
  // `s` alone is decided (left undecided: not asked again).
  void block_exactly(const Set& s) {
    z3::expr_vector differ(ctx_);
    for (std::size_t i = 0; i < x_.size(); ++i)
      differ.push_back(std::binary_search(s.begin(), s.end(), static_cast<int>(i)) ? !x_[i] : x_[i]);
    solver_.add(z3::mk_or(differ));
  }

 private:
  z3::context ctx_;
  z3::solver solver_;
  std::vector<z3::expr> x_;
  std::vector<Set> defeats_;
  std::size_t max_size_ = 0;
};

class Marco {
 public:
  Marco(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o)
      : m_(m), pd_(pd), o_(o), runs_(response::demand_runs(m, pd.path, response::Mode::Normal, *pd.requirement)),
        space_(m, pd, runs_), map_(pd.actions.size(), max_size) {}

  void run(int max_size) {
    const Test none = decide({});
    if (none.answer == Test::Answer::Defeats) report({});
    if (none.answer != Test::Answer::Holds || max_size == 0) return finish();
    map_.block_down(none.covered);
    while (!cancelled()) {
      const std::optional<Set> s = map_.seed();
      if (!s) break;
      const Test t = decide(*s);
      if (t.answer == Test::Answer::Holds) {
        map_.block_down(t.covered);
      } else if (t.answer == Test::Answer::Unknown) {
        map_.block_exactly(*s);
      } else if (const std::optional<Set> d = shrink(t.used)) {
        report(*d);
      } else {
        map_.block_exactly(*s);
      }
    }
    recheck_minimality();
    finish();
  }

 private:
  bool cancelled() const { return o_.cancel && o_.cancel->cancelled(); }

  checker::Limits limits() const {
    checker::Limits l;
    l.work = o_.work;
    l.cancel = o_.cancel;
    if (o_.timeout_s > 0)
      l.deadline = checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                               std::chrono::duration<double>(o_.timeout_s));
    return l;
  }

  // One set decided on the path's encoding; left open there, by the
  // checker's portfolio. Recorded as a question: one that holds lists the
  // set its proof covers.
  Test decide(const Set& s) {
    const std::string name = s.empty() ? set_name(pd_, s) : "defeat." + pd_.path.key() + ".t" + std::to_string(++tests_);
    Test t = space_.test(s, limits());
    Question q;
    q.property = name;
    q.actions = s;
    q.method = t.method;
    q.work = t.work;
    if (t.answer == Test::Answer::Unknown && !cancelled()) {
      q = ask_checker(m_, pd_, s, name, false, false, runs_, o_);
      q.work += t.work;
      t = Test{};
      t.answer = q.holds() ? Test::Answer::Holds : q.defeats() ? Test::Answer::Defeats : Test::Answer::Unknown;
      if (q.holds()) t.covered = s;
      if (q.defeats()) t.used = s;
      t.reason = q.reason;
    } else {
      q.verdict = t.answer == Test::Answer::Holds     ? checker::PropertyVerdict::Proved
                  : t.answer == Test::Answer::Defeats ? checker::PropertyVerdict::Falsified
                                                      : checker::PropertyVerdict::Unknown;
      q.reason = t.reason;
    }
    if (t.answer == Test::Answer::Holds) {
      q.actions = t.covered;
      holds_.push_back(pd_.questions.size());
      proofs_.push_back(t.proof.verdict == checker::Verdict::Proved ? std::optional<Test>(t) : std::nullopt);
    }
    if (t.answer == Test::Answer::Unknown) incomplete(q);
    pd_.questions.push_back(std::move(q));
    return t;
  }

  void incomplete(const Question& q) {
    complete_ = false;
    if (reason_.empty()) reason_ = q.property + ": " + (q.reason.empty() ? "unknown" : q.reason);
  }

  // The position in holds_ of a set that holds and covers `s`, or none.
  std::optional<std::size_t> cover(const Set& s) const {
    for (std::size_t i = 0; i < holds_.size(); ++i)
      if (subset_of(s, pd_.questions[holds_[i]].actions)) return i;
    return std::nullopt;
  }

  // A defeat set shrunk to a minimal one: each action dropped in turn, the
  // rest decided (a counterexample of the rest names the fewer actions it
  // takes); nullopt when a rest stays undecided.
  std::optional<Set> shrink(Set d) {
    for (std::size_t i = 0; i < d.size();) {
      const Set rest = without(d, i);
      if (cover(rest)) {
        ++i;
        continue;
      }
      const Test t = decide(rest);
      if (t.answer == Test::Answer::Holds) {
        map_.block_down(t.covered);
        ++i;
      } else if (t.answer == Test::Answer::Defeats) {
        d = t.used;
        i = 0;
      } else {
        return std::nullopt;
      }
    }
    return d;
  }

  // A minimal set's own question to the checker: its counterexample, replayed
  // on the runtime and on the question's encoding, is the one reported (and
  // written under --out), as the level-by-level enumeration reports it.
  Question confirm(const Set& d) const {
    return ask_checker(m_, pd_, d, set_name(pd_, d), false, true, runs_, o_);
  }

  void report(const Set& d) {
    map_.block_up(d);
    if (cancelled()) return;
    pd_.questions.push_back(confirm(d));
    const Question& q = pd_.questions.back();
    if (q.holds())
      throw checker::InternalError("cemv defeats: " + q.property +
                                   " defeats the path on its encoding, and the checker proves it does not");
    if (!q.defeats()) return incomplete(q);
    DefeatSet s;
    s.actions = d;
    s.question = pd_.questions.size() - 1;
    const bool declared = !d.empty() && std::all_of(d.begin(), d.end(), [&](int a) {
      return declared_for(m_, pd_.path, pd_.actions[static_cast<std::size_t>(a)]);
    });
    s.set_class = declared ? SetClass::Declared : SetClass::Indirect;
    for (std::size_t drop = 0; drop < d.size(); ++drop) {
      const Set sub = without(d, drop);
      const std::optional<std::size_t> c = cover(sub);
      if (!c) throw std::logic_error("cemv defeats: a defeat set without proofs of its subsets");
      s.subsets.emplace_back(sub, holds_[*c]);
    }
    pd_.sets.push_back(std::move(s));
  }

  // Every proof a reported set's minimality rests on, re-proved in a fresh
  // context (the checker's own answers were re-checked when given).
  void recheck_minimality() {
    std::vector<bool> done(holds_.size(), false);
    for (const auto& s : pd_.sets)
      for (const auto& [sub, question] : s.subsets) {
        const std::size_t i = static_cast<std::size_t>(
            std::find(holds_.begin(), holds_.end(), question) - holds_.begin());
        if (done[i] || !proofs_[i]) continue;
        done[i] = true;
        try {
          space_.recheck(*proofs_[i], limits());
        } catch (const checker::Interrupted&) {
          incomplete(pd_.questions[question]);
          return;
        }
      }
  }

  void finish() {
    finish_path(pd_, complete_, reason_, cancelled());
  }

  const model::Matrix& m_;
  PathDefeats& pd_;
  const AskOptions& o_;
  std::vector<Run> runs_;
  ActionSpace space_;
  Map map_;
  std::vector<std::size_t> holds_;            // questions that hold, by position
  std::vector<std::optional<Test>> proofs_;   // their proofs on the encoding (none: the checker's)
  bool complete_ = true;
  std::string reason_;
  int tests_ = 0;
};

}  // namespace

void enumerate_one_encoding(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o) {
  Marco(m, pd, max_size, o).run(max_size);
}

void enumerate_minimal_sets(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o,
                            Enumeration how) {
  if (how == Enumeration::OneEncoding) return enumerate_one_encoding(m, pd, max_size, o);
  enumerate_level_by_level(m, pd, max_size, o, how == Enumeration::LevelsOnEncoding);
}

}  // namespace cemv::defeats
