// Single-point mutants of a matrix: every configuration error an engineer can
// make with one edit of one field (docs/mutation.md lists the operators). A
// mutant is a plain model::Matrix; whether it behaves differently from the
// original is the checker's to decide (checker/equivalence.hpp), whether a
// test suite notices is testgen's mutation report.
//
// Data in, data out: this folder uses model/ only, so the test generator, the
// diff tests and the command line can all draw on the same operator set.
#pragma once

#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::mutate {

struct Mutant {
  // Stable, file-name safe: "<operator>[.<variant>].<element>", e.g.
  // "intersection-type.S.c3e1", "time-ms-plus.c2", "tag-ett.c1t2".
  std::string id;
  std::string op;           // the operator, e.g. "intersection-removed"
  std::string element;      // e.g. "intersection cause[3]/effect[1]", "cause[2].tag[1]"
  std::string description;  // one sentence: what the edit is, old -> new
  model::Matrix matrix;
};

// A candidate edit that does not give a valid matrix (e.g. a 2oo3 cause
// turned into `normal` keeps three tags): the first validation error says why.
struct Refused {
  std::string id;
  std::string op;
  std::string element;
  std::string description;
  std::string reason;  // "RULE ELEMENT: message"
};

struct MutantSet {
  std::vector<Mutant> mutants;    // valid ones, in generation order (ids unique)
  std::vector<Refused> refused;
};

// Every single-point edit of `m` by the operators of docs/mutation.md, valid
// or not, in a fixed order: matrix-level intersections by (cause, effect),
// then causes by id, then effects by id.
std::vector<Mutant> all_edits(const model::Matrix& m);

// all_edits(m) split by model::validate: mutants with validation errors are
// refused, warnings do not refuse.
MutantSet mutants(const model::Matrix& m);

// The operator names, in generation order, with a sentence each (docs and
// `cemv mutate --list-operators`).
struct OperatorInfo {
  const char* name;
  const char* meaning;
};
const std::vector<OperatorInfo>& operators();

}  // namespace cemv::mutate
