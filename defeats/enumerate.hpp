// The minimal defeat sets of one path (docs/defeats.md, "Enumeration"):
// level by level, every set a question of its own to the checker
// (levels.cpp), or MARCO-style on one encoding of the path with every action
// behind an assumption literal (marco.cpp); the differential test holds the
// second to the first.
#pragma once

#include <string>

#include "checker/limits.hpp"
#include "defeats/analysis.hpp"

namespace cemv::defeats {

struct AskOptions {
  checker::Work work = 20 * checker::kMega;
  double timeout_s = 0.0;
  checker::CancelToken* cancel = nullptr;
  std::string out_dir;
};

// Fills `pd.questions`, `pd.sets`, `pd.status` and `pd.distance` for sets of
// up to `max_size` actions; `pd.actions` and `pd.requirement` are given.
void enumerate_minimal_sets(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o,
                            Enumeration how = Enumeration::LevelByLevel);

// The two enumerations (enumerate_minimal_sets dispatches).
void enumerate_one_encoding(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o);
void enumerate_level_by_level(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o);

}  // namespace cemv::defeats
