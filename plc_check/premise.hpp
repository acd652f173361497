// A Houdini query's premise without the clauses its own equalities repeat
// (docs/plc.md "A cone group's Houdini"). A correspondence keeps, for each
// program flag equal to a matrix flag, the same clause over either side: of a
// generated 32 x 32 program's layers' premises, half the clauses are another
// clause with a variable replaced by one the premise says is equal to it (or
// opposite). Such a clause follows from the premise without it; the solver
// need not hold it.
#pragma once

#include <cstddef>
#include <vector>

#include <z3++.h>

namespace cemv::plc_check {

// What the reduction reads of a fact: a clause of Boolean literals (a
// disjunction or an implication), an equality of two literals, or neither.
struct FactShape {
  struct Literal {
    unsigned var = 0;  // the Boolean constant's Z3 id
    bool negated = false;
  };
  enum class Kind { Other, Clause, Equality };
  Kind kind = Kind::Other;
  std::vector<Literal> literals;  // Clause: its literals; Equality: the two sides
};

FactShape shape_of(const z3::expr& fact);

// The positions in `premise` (indices into `shapes`) of the facts to assert:
// every fact but a clause that, each literal replaced by its class's under
// the premise's equalities, is a clause an earlier fact of the premise
// already is. What is left implies every fact left out.
std::vector<std::size_t> without_repeats(const std::vector<FactShape>& shapes, const std::vector<std::size_t>& premise);

}  // namespace cemv::plc_check
