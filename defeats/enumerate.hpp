// The minimal defeat sets of one path, level by level (docs/defeats.md,
// "Enumeration"): every question decided by the checker, so every
// counterexample is replayed on the runtime and every proof re-checked.
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
void enumerate_minimal_sets(const model::Matrix& m, PathDefeats& pd, int max_size, const AskOptions& o);

}  // namespace cemv::defeats
