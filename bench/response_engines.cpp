// Not a benchmark target of its own in make bench: each engine alone on one
// path's response property at T (proof) and T - 1 (counterexample), on the
// problem the checker's portfolio gives its engines (the property's problem,
// checker/property_problem.hpp, after the exact reductions of
// checker/reduce.hpp), to see which engine carries cemv response's probes.
// Usage:
//   response_engines MATRIX CAUSE EFFECT T [SECONDS] [ENGINE...]
#include <chrono>
#include <cstdlib>
#include <iostream>

#include "checker/engines/invariants.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "response/paths.hpp"
#include "response/property.hpp"

using namespace cemv;

int main(int argc, char** argv) {
  if (argc < 5) return 2;
  model::Matrix m = formats::load_matrix(argv[1]);
  const int cause = std::atoi(argv[2]), effect = std::atoi(argv[3]);
  const long long t = std::atoll(argv[4]);
  const int seconds = argc > 5 ? std::atoi(argv[5]) : 30;
  std::vector<std::string> engines;
  for (int i = 6; i < argc; ++i) engines.emplace_back(argv[i]);
  if (engines.empty())
    engines = {"invariants+induction", "k-induction", "pdr", "accelerated-bmc", "bmc"};
  response::Path path;
  for (const auto& p : response::response_paths(m, {}))
    if (p.effect == effect && p.causes == std::vector<int>{cause}) path = p;
  for (long long bound : {t, t - 1}) {
    auto file = properties::parse_properties(
        response::response_property_text(m, path, response::Mode::Normal, bound, "probe"), m, "probe");
    const auto& prop = file.properties.at(0);
    auto make = checker::property_problem(m, file, prop);
    for (const auto& engine : engines) {
      z3::context ctx;
      checker::Reduction red;
      auto problem = checker::reduce(make(ctx), &red);
      if (std::getenv("SHOW_STATE") && engine == engines.front()) {
        for (const auto& v : problem.problem.ts->statevars()) std::cout << "  state " << v.name << std::endl;
        for (const auto& l : problem.problem.ts->lemmas()) std::cout << "  lemma " << l.term << std::endl;
      }
      if (std::getenv("SHOW_HOUDINI") && engine == engines.front()) {
        auto cands = checker::mine_candidates(problem.problem);
        auto kept = checker::houdini(problem.problem, cands,
                                     checker::Limits::within(std::chrono::seconds(seconds)));
        std::cout << "  mined " << cands.size() << ", inductive " << kept.size() << std::endl;
        for (const auto& c : cands) {
          bool k = false;
          for (const auto& d : kept) k = k || z3::eq(c, d);
          std::cout << (k ? "  kept    " : "  dropped ") << c << std::endl;
        }
      }
      auto prover = checker::make_prover(engine);
      auto start = std::chrono::steady_clock::now();
      auto r = prover->prove(problem.problem,
                             checker::Limits::within(std::chrono::seconds(seconds), static_cast<int>(bound + 2)));
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << "T=" << bound << " " << engine << ": " << checker::to_string(r.verdict) << " " << r.reason
                << " k=" << r.k << " " << s << " s (state variables " << red.state_vars_before << " -> "
                << red.state_vars_after << ", inputs " << red.inputs_before << " -> " << red.inputs_after
                << (red.floats_as_integers ? ", floats as integers" : "") << ")" << std::endl;
      if (r.verdict == checker::Verdict::Proved && !r.invariant.clauses.empty() && std::getenv("SHOW_INVARIANT"))
        std::cout << r.invariant.text() << std::endl;
    }
  }
}
