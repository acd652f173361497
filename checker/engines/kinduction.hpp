// k-induction (Sheeran, Singh, Stalmarck 2000) strengthened by invariants:
// the encoder's range lemmas (first filtered to an inductive subset, since a
// lemma is only a claim) and, optionally, mined relational invariants. The
// inductive step gets simple-path constraints lazily: only when its model
// repeats a state is that pair of states required to differ.
#pragma once

#include <string>

#include "checker/prover.hpp"

namespace cemv::checker {

struct KInductionOptions {
  bool use_lemmas = true;       // strengthen by the encoder's range lemmas that Houdini keeps
  bool mine_invariants = true;  // strengthen by engines/invariants' Houdini invariants
  bool bool_implications = false;  // MiningOptions::bool_implications
  bool simple_path = true;
  int max_k = -1;               // -1: Limits::max_depth
  Method method = Method::KInduction;
};

class KInduction : public Prover {
 public:
  explicit KInduction(KInductionOptions options = {}) : options_(std::move(options)) {}
  Method method() const override { return options_.method; }
  ProverResult prove(const SafetyProblem& problem, const Limits& limits) override;

 private:
  // The strengthening invariant: lemmas (and mined candidates) that Houdini keeps.
  // Throws Stopped when the limits end the search.
  std::vector<z3::expr> strengthening(const SafetyProblem& problem, const Limits& limits, WorkMeter& meter) const;
  KInductionOptions options_;
};

}  // namespace cemv::checker
