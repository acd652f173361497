// A memo of term rewrites keyed by Z3 AST id, for the passes that walk a
// shared term DAG once (the product's renaming, the reductions, the
// engines' abstractions). It keeps every key term alive with its result:
// Z3 reuses the id of a freed term, and a memo keyed by a freed term's id
// would answer for whatever term gets that id next (docs/checker.md,
// "Z3 notes").
#pragma once

#include <cstddef>
#include <unordered_map>
#include <utility>

#include <z3++.h>

namespace cemv::encoder {

template <class Result>
class TermMemo {
 public:
  // The result stored for `e`, or nullptr.
  const Result* find(const z3::expr& e) const {
    auto it = map_.find(e.id());
    return it == map_.end() ? nullptr : &it->second.second;
  }
  // Stores `r` for `e` unless `e` has a result already; returns the stored one.
  const Result& emplace(const z3::expr& e, Result r) {
    return map_.emplace(e.id(), std::make_pair(e, std::move(r))).first->second.second;
  }
  std::size_t size() const { return map_.size(); }

 private:
  std::unordered_map<unsigned, std::pair<z3::expr, Result>> map_;
};

}  // namespace cemv::encoder
