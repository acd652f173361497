// The one encoding of a path that every defeat question of the path is asked
// on (docs/defeats.md, "One encoding per path"): the cone of the path's
// effect with response/'s requirement monitor compiled in once, each action's
// exclusion behind an assumption literal. A set of allowed actions is tested
// by solving under assumptions, in solvers that live as long as the path:
// the demand runs on the runtime first, then Houdini invariants and
// k-induction (a proof, whose unsat cores name the exclusions it needed),
// then BMC (a counterexample, whose model names the actions it used).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "checker/prover.hpp"
#include "defeats/analysis.hpp"
#include "defeats/runs.hpp"

namespace cemv::defeats {

struct Test {
  enum class Answer { Holds, Defeats, Unknown };
  Answer answer = Answer::Unknown;
  // Holds: the allowed actions the proof covers, the tested set grown by
  // every action whose exclusion the proof did not use (ascending).
  std::vector<int> covered;
  // Defeats: the actions the counterexample takes, a subset of the tested set.
  std::vector<int> used;
  checker::ProverResult proof;  // Holds: the proof (invariant, k) that check/ re-checks
  std::string method;
  std::string reason;  // Unknown: why
  checker::Work work = 0;
};

// A demand run on the runtime that violates the requirement.
struct RunDefeat {
  std::vector<int> used;  // the actions the run takes before its violation
  int violation_cycle = 0;
};

class ActionSpace {
 public:
  ActionSpace(const model::Matrix& m, const PathDefeats& pd, const std::vector<Run>& demand_runs);
  ~ActionSpace();
  ActionSpace(const ActionSpace&) = delete;
  ActionSpace& operator=(const ActionSpace&) = delete;

  // Whether exactly the actions of `allowed` (ascending) may occur defeats the
  // path, within `limits` (its work is the test's budget). With a
  // `proof_depth`: a proof only (the demand runs of the set, Houdini,
  // k-induction up to that k and its base cases), no demand run of the
  // subsets and no BMC over T: a set the proof leaves open is Unknown, for
  // the checker's question to decide.
  Test test(const std::vector<int>& allowed, const checker::Limits& limits,
            std::optional<int> proof_depth = std::nullopt);

  // The first of the demand runs with the actions of `allowed` taken that
  // violates the requirement on the runtime (judged by the concrete
  // evaluator with exactly `allowed` allowed), as the checker tries them.
  std::optional<RunDefeat> run(const std::vector<int>& allowed) const;

  // Re-proves a Holds test's proof for its covered set in a fresh Z3 context
  // (checker/check/); throws checker::InternalError when it fails.
  void recheck(const Test& t, const checker::Limits& limits) const;

  // The path's solvers (defeats/space_solvers.hpp, internal to defeats/).
  struct Solvers;

 private:
  const model::Matrix& m_;
  const PathDefeats& pd_;
  const std::vector<Run>& demand_runs_;
  std::unique_ptr<Solvers> s_;
};

}  // namespace cemv::defeats
