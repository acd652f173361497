// The minimal defeat sets of one path (docs/defeats.md, "Enumeration"):
// level by level (levels.cpp), each set tested on one encoding of the path
// with every action behind an assumption literal before it is asked of the
// checker, or every set a question of its own to the checker; or
// MARCO-style on that one encoding (marco.cpp). The differential test holds
// the first and the third to the second.
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
                            Enumeration how = Enumeration::LevelsOnEncoding);

// The enumerations (enumerate_minimal_sets dispatches). `on_encoding`: each
// candidate tested on the path's one encoding first.
void enumerate_one_encoding(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o);
void enumerate_level_by_level(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o,
                              bool on_encoding);

}  // namespace cemv::defeats
