// The outputs proved by groups (docs/plc.md "How an equality is proved"):
// the outputs whose cones overlap (plc_check/cones.hpp) in one product, the
// matrix's cones of their effects and the whole program, sampled once, its
// correspondence invariant found once by Houdini over the union of each
// output's own cone's candidates, every output's relation following from it,
// the proof re-checked once in a fresh context. A program that computes the
// matrix's outputs is proved this way at about the cost of its cones'
// proofs, each shared cone once. When a group's conjunction does not follow
// (some output differs, or its proof needs more), the whole product is
// tried with every candidate of its variables (found once), and then each
// output is decided alone.
#pragma once

#include "model/matrix.hpp"
#include "plc/ast.hpp"
#include "plc_check/check.hpp"
#include "plc_check/map.hpp"
#include "plc_check/sampling.hpp"

namespace cemv::plc_check {

struct SharedProof {
  bool proved = false;  // every output's relation, with the invariant and k
  int k = 0;
};

// The proof of the questions of `q`'s group at once, within `options.work`
// per output tag of the group (not for a group of one: its own decision is
// the same product), else of every question at once with every candidate. The groups, and each group's proof, are
// found once per process for the same matrix, program, POU, map, relation
// and budgets, by whichever output asks first (the others wait for it): the
// answer depends on none of them. Throws checker::Interrupted when the
// asker's limits end it (nothing is kept then), checker::InternalError when
// its re-check fails.
SharedProof shared_proof(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                         const ResolvedMap& map, const CheckOptions& options, const OutputQuestion& q);

// The plant at rest for a product's inputs: each tag (named "input.TAG" on
// both sides) at its scenario default, good quality, no command; and, for
// each effect, an acceptance test's run (SamplingOptions::trips): its causes
// tripped together and its reset pulsed, held by the matrix's cycle time.
SamplingOptions at_rest(const model::Matrix& m);

}  // namespace cemv::plc_check
