// `cemv defeats`: the minimal sets of maintenance operations and input
// faults under which a path of a SIF group no longer meets its trip
// requirement, each shown by a replayed counterexample and proved minimal by
// proofs of its subsets (docs/defeats.md). The public header of defeats/.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "checker/result.hpp"
#include "defeats/actions.hpp"
#include "model/matrix.hpp"
#include "response/paths.hpp"
#include "response/search.hpp"

namespace cemv::defeats {

// How one path's sets are enumerated (docs/defeats.md, "Enumeration"):
// level by level, each candidate first tested on one encoding per path and
// asked of the checker only where that proof leaves it open or to show a
// defeat (the command line's); level by level with every candidate a
// question to the checker (the differential test's oracle); or MARCO-style
// on one encoding per path (internal: slower on long requirements,
// docs/performance.md "cemv defeats").
enum class Enumeration { LevelsOnEncoding, LevelByLevel, OneEncoding };

struct DefeatsOptions {
  std::vector<int> sifs;         // empty = every declared group
  int max_size = 2;              // --max-size K
  double timeout_s = 0.0;        // --timeout: wall clock per decided question (0 = none)
  double total_timeout_s = 0.0;  // --total-timeout: the whole run (0 = none)
  checker::Work work = 20 * checker::kMega;  // each engine's budget of work per question
  int jobs = 1;                  // paths decided in parallel
  std::string out_dir;           // counterexample scenarios ("" = none written)
  Enumeration enumeration = Enumeration::LevelsOnEncoding;
  // The logic figures of an earlier `cemv response` of the same matrix
  // (--response FILE), by path key: each path's requirement T is taken from
  // them instead of being proved again (response::ResponseOptions::known).
  std::map<std::string, response::Figure> known_figures;
  // Progress (serialised): the number of paths, then each path's key as it
  // starts and ends.
  std::function<void(std::size_t paths)> on_plan;
  std::function<void(const std::string& key)> on_start;
  std::function<void(const std::string& key)> on_done;
};

// One question decided by the checker: "do the actions of `actions` (indices
// into PathDefeats::actions, ascending), and no other, defeat the path?"
struct Question {
  std::vector<int> actions;
  std::string property;      // the property's name
  checker::PropertyVerdict verdict = checker::PropertyVerdict::Unknown;
  std::string method;        // the engine (proof or counterexample)
  std::string reason;        // unknown: why
  std::uint64_t work = 0;    // Z3 resource units spent
  std::string scenario;      // falsified: the counterexample's file, relative to the out folder ("" = none)
  int violation_cycle = -1;  // falsified: 0-based cycle the requirement fails
  bool defeats() const { return verdict == checker::PropertyVerdict::Falsified; }
  // Proved, or vacuous (no demand can occur): the actions do not defeat.
  bool holds() const {
    return verdict == checker::PropertyVerdict::Proved || verdict == checker::PropertyVerdict::Vacuous;
  }
};

enum class SetClass { Declared, Indirect };
const char* to_string(SetClass c);

struct DefeatSet {
  std::vector<int> actions;  // indices into PathDefeats::actions, ascending
  SetClass set_class = SetClass::Indirect;
  std::size_t question = 0;  // the question that falsified it (its counterexample)
  // Minimality: for each subset of one action fewer, the question whose
  // proof covers it (a proved superset of it that contains no defeat set).
  std::vector<std::pair<std::vector<int>, std::size_t>> subsets;
};

// Complete: every set up to max_size decided. Unbounded: the requirement
// fails with no action (cemv response finds the path unbounded), so the
// empty set defeats. Unknown: the requirement's T is unknown, or some
// question was left undecided (the sets reported are still minimal).
enum class PathStatus { Complete, Unbounded, Unknown };
const char* to_string(PathStatus s);

struct PathDefeats {
  response::Path path;
  std::string sif_name;
  int sil = 0;                          // the group's: the highest SIL of its members
  std::optional<long long> requirement; // T in cycles (the exact logic response)
  std::vector<Action> actions;
  std::vector<Question> questions;      // in the order asked
  std::vector<DefeatSet> sets;          // smallest first
  PathStatus status = PathStatus::Unknown;
  std::string reason;                   // Unknown: why
  // The smallest indirect set's size; nullopt: none up to max_size (when complete).
  std::optional<int> distance;
};

struct DefeatsResult {
  std::string matrix_name;
  std::string matrix_signature;
  int max_size = 2;
  std::vector<PathDefeats> paths;  // by group, as response_paths orders them
  bool interrupted = false;
};

// Throws std::invalid_argument for a SIF group the matrix does not declare or
// a max_size below 0.
DefeatsResult analyse(const model::Matrix& m, const DefeatsOptions& options);

// The SIL of a group: the highest `sil` of its member causes and effects.
int group_sil(const model::Matrix& m, int sif);

// The exit status: 1 some path unbounded, or (require_distance > 0) some path
// of a group of SIL 2 or more with an indirect set smaller than
// require_distance; 3 some path unknown; else 0.
int exit_code(const DefeatsResult& r, int require_distance);

// The paths the gate fails (those exit_code counts for require_distance).
std::vector<const PathDefeats*> gate_failures(const DefeatsResult& r, int require_distance);

}  // namespace cemv::defeats
