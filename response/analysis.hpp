// `cemv response`: the worst-case response time of every path of every SIF
// group, proved exactly, and held against the group's process safety time
// (docs/response-time.md). The public header of response/.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "response/paths.hpp"
#include "response/search.hpp"

namespace cemv::response {

struct ResponseOptions {
  std::vector<int> sifs;      // empty = every declared group
  bool conservative = false;  // the controller's share from watchdog_ms instead of cycle_ms
  double timeout_s = 0.0;     // --timeout: the user's wall clock per decided property (0 = none)
  double total_timeout_s = 0.0;  // the whole run (0 = none): paths not decided by then are unknown
  checker::Work work = 20 * checker::kMega;  // each engine's budget of work in a probe
  int jobs = 1;               // paths decided in parallel
  // The degraded figure of a voted path (one input in bad quality). false:
  // the normal figure alone, for a caller that needs only the logic response
  // T (cemv defeats); PathResult::degraded is then empty.
  bool degraded = true;
  std::string out_dir;        // counterexample scenarios ("" = none written)
  // Normal figures the caller already has, by path key (Path::key): the
  // exact or unbounded figures of an earlier `cemv response` of the same
  // matrix (cemv defeats --response). Those paths' normal figures are taken
  // as given, not decided again; every other figure is decided.
  std::map<std::string, Figure> known;
  // The command line's progress line (serialised, from any worker thread):
  // once with the number of paths to decide (a path in several groups is
  // decided once), then when each path's figures start and are done, with
  // the path's key ("c1.e2").
  std::function<void(std::size_t paths)> on_plan;
  std::function<void(const std::string& key)> on_start;
  std::function<void(const std::string& key)> on_done;
};

enum class Verdict { Ok, Over, NoPst, Unbounded, Unknown };
const char* to_string(Verdict v);

struct PathResult {
  Path path;
  std::string sif_name;
  Figure logic;                              // the normal figure
  std::optional<Figure> degraded;            // voted paths only
  std::optional<long long> logic_ms;         // T x cycle_ms
  std::optional<long long> total_ms;
  std::optional<long long> degraded_total_ms;
  std::optional<std::uint32_t> process_safety_time_ms;
  std::optional<long long> margin_ms;        // PST - total
  std::optional<double> margin_percent;      // of the PST
  std::uint32_t sensor_ms = 0;               // the slowest trigger cause's
  std::uint32_t actuator_ms = 0;
  long long controller_ms = 0;               // 2 x cycle_ms, or 2 x watchdog_ms
  Verdict verdict = Verdict::Unknown;
};

struct ResponseResult {
  std::string matrix_name;
  std::string matrix_signature;
  std::uint32_t cycle_ms = 0;
  std::optional<std::uint32_t> watchdog_ms;
  bool conservative = false;
  std::vector<PathResult> paths;
  bool interrupted = false;  // the run's bound (total_timeout_s) ended it: undecided paths are unknown
};

// Throws std::invalid_argument for options the matrix cannot satisfy (a SIF
// group it does not declare, --conservative without watchdog_ms).
ResponseResult analyse(const model::Matrix& m, const ResponseOptions& options);

// The exit status of `cemv check`'s rules: 1 some path over or unbounded, 3
// some unknown and nothing over, else 0.
int exit_code(const ResponseResult& r);

}  // namespace cemv::response
