// Internal to testgen/: many objectives of one SIF group on one incremental
// BMC (docs/testgen.md, "Synthesis and minimisation"). The group's cone is
// encoded once per question with every objective's monitor compiled into it;
// each objective's target is a term of the one unrolling, and each depth asks
// whether any open target holds there, so the first answer is a shortest
// extension. At that depth the other targets are tried in catalogue order
// under assumption literals, and every one that the same run can reach as
// well is kept: one witness covers several compatible objectives. With
// `held`, each step is a macro step (checker/engines/macro_unrolling.hpp):
// one cycle or a stretch of held inputs, so that objectives behind timers are
// asked together too; every answer is re-simulated cycle by cycle, and one
// that the stretches only approximated is excluded and asked again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "model/vocabulary.hpp"
#include "properties/ast.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen::detail {

struct SweepQuestion {
  const properties::PropertyFile* file = nullptr;
  std::vector<const properties::Property*> targets;  // catalogue order; all with the same assumptions
  std::vector<model::Node> roots;                     // the union of their cones
  const std::vector<model::CycleInput>* prefix = nullptr;  // the test extended (none: from start-up)
  int max_depth = 0;                                  // cycles (held: macro steps) added at most
  bool held = false;                                  // macro steps of held inputs (timers), else cycles
  std::int64_t max_cycles = 0;                        // held: cycles added at most
  checker::Work budget = 0;                           // for the whole question
};

struct SweepAnswer {
  std::vector<model::CycleInput> cycles;  // after the prefix; empty: nothing reached
  std::vector<std::size_t> reached;       // indices into `targets` reached in the last cycle
  std::string reason;                     // why nothing was reached
};

// Analog inputs take only the values an engineer sets (as Searcher::find's
// first attempt), so a witness reads like a test sheet.
SweepAnswer sweep(const model::Matrix& m, const TestgenOptions& options, const SweepQuestion& q);

}  // namespace cemv::testgen::detail
