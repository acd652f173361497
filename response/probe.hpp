// One probe of the search (response/search.hpp): "the path responds within
// T cycles" decided by the checker, with the engines and runs that the
// answer the search expects calls for (docs/response-time.md, "Method",
// "Compositional proof").
#pragma once

#include <string>
#include <vector>

#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "response/paths.hpp"
#include "response/property.hpp"
#include "response/search.hpp"

namespace cemv::response {

// What a probe answers: the checker's verdict on the property, and for a
// counterexample its scenario file (relative to the out folder) and inputs.
struct Probe {
  checker::PropertyVerdict verdict = checker::PropertyVerdict::Unknown;
  std::string reason;
  std::string method;
  std::string scenario;
  std::vector<model::CycleInput> run;  // Falsified: the counterexample's inputs, as replayed
};

// Runs the checker tries before its engines (checker::CheckOptions::
// directed_runs): the demand run, and the counterexample of a smaller bound
// continued with its last inputs held.
using Runs = std::vector<std::vector<model::CycleInput>>;

// What a probe expects, from the search's state: the estimate and the bounds
// above a falsified one are expected to be proved, the bound below a proved
// one to be falsified; a bisection step may go either way.
enum class Expect { Proof, Counterexample, Either };

// One probe: for an XooN bound that may hold, first its demand runs alone,
// then its member lemmas (within half of the probe's time); then the engines
// for the expected answer; when they give none, the whole portfolio, within
// what is left of the probe's time limit (--timeout is a hard limit per
// probe: none left, the probe is unknown).
Probe decide_probe(const model::Matrix& m, const Path& p, Mode mode, long long cycles, const SearchOptions& o,
                   Expect e, const Runs& runs);

}  // namespace cemv::response
