// What a counterexample of `cemv check` rests on, and whether a stored one
// still holds, both decided on the reference runtime and the concrete
// property evaluator (docs/checker.md, "Counterexample support"). For the
// SARIF related locations (a finding at the matrix lines a change touches)
// and for the result cache (a cached counterexample is replayed before it is
// reported). Built into the product only: the CLI tests' checker double has
// no property semantics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::cli {

// Runs `inputs` on a fresh runtime of `m` and judges `p` on that run: the
// 0-based cycle of its first violation (of its first witness for a reachable
// property), or nullopt. `observables`, when given, receives the run.
std::optional<int> judged_cycle(const model::Matrix& m, const properties::PropertyFile& f,
                                const properties::Property& p, const std::vector<model::CycleInput>& inputs,
                                std::vector<std::vector<int>>* observables = nullptr);

// Whether a falsified or reachable result's trace is reproduced exactly by the
// runtime (the same observables in every cycle) and judged so by the
// evaluator in the same cycle.
bool confirms(const model::Matrix& m, const properties::PropertyFile& f, const properties::Property& p,
              const checker::PropertyResult& r);

// The support of a counterexample: the cells (intersections) of the
// property's cone of influence without which its inputs no longer violate
// the property ("intersection[3,2]"), each found by deleting the cell and
// replaying the run. Empty when no single cell carries the violation (a
// missing cell, an inhibit) or when the replays would exceed a fixed budget
// of scan cycles (a count, never a time).
std::vector<std::string> counterexample_cells(const model::Matrix& m, const properties::PropertyFile& f,
                                              const properties::Property& p, const checker::ConcreteTrace& trace);

// counterexample_cells of every falsified property of `r` that has a trace.
void add_counterexample_cells(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                              checker::CheckResult& r);

}  // namespace cemv::cli
