// Writing an encoding for other tools (docs/encoding.md "Export"):
// SMT-LIB 2 (an unrolling of `depth` cycles with a goal) and VMT-LIB (the
// transition system with :next, :init, :trans and :invar-property
// annotations, read by nuXmv, ic3ia and Pono).
#pragma once

#include <optional>
#include <string>

#include "encoder/encode.hpp"

namespace cemv::encoder {

struct ExportGoal {
  // A named Boolean term (an observable such as "effect[1].active").
  // Invariant: the query asks for a path on which it is FALSE in some cycle
  // (sat = counterexample). Reach: for a path on which it is TRUE in some
  // cycle (sat = witness). Without a term the invariant is TRUE (unsat).
  enum class Kind { Invariant, Reach } kind = Kind::Invariant;
  std::optional<std::string> term;
};

// Throws std::invalid_argument when the goal names no Boolean named term.
std::string to_smt2(const Encoding& enc, int depth, const ExportGoal& goal);
std::string to_vmt(const Encoding& enc, const ExportGoal& goal);

// The goal formula of an unrolling of `depth` cycles (what to_smt2 asserts).
z3::expr unrolled_query(const Encoding& enc, int depth, const ExportGoal& goal);

}  // namespace cemv::encoder
