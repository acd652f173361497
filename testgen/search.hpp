// Internal to testgen/: one objective searched with the checker's engines.
// The objective is a `reachable` property, so its monitor's `good` is "not
// the objective" and a counterexample of the safety problem is a witness:
// BMC (checker/engines/bmc.hpp) on the cone of influence finds a shortest one,
// accelerated BMC a long one (timers of minutes), and the proving engines
// (checker/engines/portfolio.hpp) show that none exists. A search may start
// from start-up or continue an existing test: then the transition system's
// initial state is the state the test leaves (computed by the encoder's
// Evaluator over the test's cycles), which is how a test is extended.
#pragma once

#include <string>
#include <vector>

#include "checker/shrink.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "model/vocabulary.hpp"
#include "properties/ast.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen::detail {

struct Goal {
  const properties::PropertyFile* file = nullptr;
  const properties::Property* property = nullptr;
  std::vector<model::Node> roots;  // empty: the whole matrix
  int horizon = 0;
};

struct SearchResult {
  enum class Kind { Found, Infeasible, Undecided } kind = Kind::Undecided;
  std::vector<model::CycleInput> cycles;  // Found: the cycles after the prefix
  std::string method;
  std::string reason;
};

// Inputs keep their value unless the objective needs otherwise: `hold` (the
// end of the prefix, or the plant at rest), no operator command.
checker::PreferredValue held_inputs(const encoder::Encoding& enc, const model::CycleInput& hold);
// An engine's witness as cycle inputs; tags outside the encoding keep `hold`.
std::vector<model::CycleInput> witness_inputs(const checker::Trace& t, const encoder::Encoding& enc,
                                             const model::Matrix& m, const model::CycleInput& hold);

class Searcher {
 public:
  Searcher(const model::Matrix& m, const TestgenOptions& options) : m_(m), options_(options) {}
  // A run reaching the goal after `prefix` (empty: from start-up). Never
  // Infeasible: only a proof says that.
  SearchResult find(const Goal& g, const std::vector<model::CycleInput>& prefix, checker::Work budget) const;
  // Infeasible with the proof, or Undecided with the reason.
  SearchResult prove_unreachable(const Goal& g) const;

 private:
  SearchResult find_once(const Goal& g, const std::vector<model::CycleInput>& prefix, checker::Work budget,
                         bool engineer) const;
  const model::Matrix& m_;
  const TestgenOptions& options_;
};

}  // namespace cemv::testgen::detail
