// The least T for which a path's response property is proved, with T - 1
// falsified: each probe is one property decided by the checker
// (checker/check.hpp), so every proof is re-checked and every counterexample
// replayed on the runtime before it counts (docs/response-time.md, "Method").
#pragma once

#include <string>

#include "checker/limits.hpp"

#include "model/matrix.hpp"
#include "response/paths.hpp"
#include "response/property.hpp"

namespace cemv::response {

struct Figure {
  enum class Kind { Exact, Unbounded, Unknown };
  Kind kind = Kind::Unknown;
  long long cycles = -1;       // Exact: T; Unbounded: the largest bound tried (falsified)
  std::string counterexample;  // scenario of T - 1 (or of the bound), relative to the out folder; "" = none
  std::string reason;          // Unknown: why; Unbounded: why no demand lasts longer ("" = it can)
  std::string method;          // Exact: the engine that proved T
  int probes = 0;              // properties decided
};

struct SearchOptions {
  // Each engine's budget of work in a probe (checker::CheckBudgets::engine):
  // the same budgets give the same figures on every machine.
  checker::Work work = 20 * checker::kMega;
  double timeout_s = 0.0;      // --timeout: the user's wall clock per probe; 0 = none
  checker::CancelToken* cancel = nullptr;  // the run's (--total-timeout, a failure elsewhere)
  std::string out_dir;         // "" = no scenario files
};

// The bounds tried: up to twice the path's configured delays plus 64 cycles.
long long search_cap(const Path& p);

Figure least_response(const model::Matrix& m, const Path& p, Mode mode, const SearchOptions& options);

// The name of the property (and stem of its scenario file) of a path.
std::string property_name(const Path& p, Mode mode);

}  // namespace cemv::response
