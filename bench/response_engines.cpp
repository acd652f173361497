// Not a benchmark target of its own in make bench: each engine alone on one
// path's response property at T (proof) and T - 1 (counterexample), on the
// problem the checker's portfolio gives its engines (the property's problem,
// checker/property_problem.hpp, after the exact reductions of
// checker/reduce.hpp), to see which engine carries cemv response's probes.
// Usage:
//   response_engines MATRIX CAUSE EFFECT T [WORK] [ENGINE...]   (WORK: millions of Z3 resource units per engine)
// Environment: SEARCH=1 the path's figure as cemv response searches it (each
// probe within SECONDS); SHOW_PROPERTY=1 the probe's property text (=2: its member
// lemmas, and on stderr the bound assuming them); PROPERTY=FILE that
// file's first property instead; LOCALIZE=1 the engines on the path's localization (KEEP="e22 c5": those
// elements kept too)
// (checker/localize.hpp; a proof re-checked on the whole problem, a trace
// concretized), SHOW_LOCAL=1 what it keeps and frees; SHOW_DEMAND=1 the
// demand run of T cycles on the runtime (the path's elements and the
// effect's signals, one digit a cycle; =2 the demand with the path alone,
// =3 the demand after a reset, =4 an XooN's pulses first, =5 the settled demand); SHOW_PATHS=1 the number of paths
// (=2: every path with its estimate); SHOW_STATE, SHOW_HOUDINI,
// SHOW_INVARIANT as before; MAX_DEPTH=N the engines' bound (default T + 2); SHOW_ALL=1 with SHOW_DEMAND every observable, JUDGE=1 the property's verdict on it;
// OUT=DIR with SHOW_CHECK writes the probe's scenario there (ENGINEs named: those, in order,
// on any cone); DEGRADED=1 the
// degraded figure's property and demand runs.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <iostream>

#include "checker/check.hpp"
#include "checker/engines/invariants.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/localize.hpp"
#include "checker/check/recheck.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "properties/build.hpp"
#include "properties/evaluator.hpp"
#include "properties/parser.hpp"
#include "response/paths.hpp"
#include "response/demand.hpp"
#include "response/property.hpp"
#include "response/search.hpp"
#include "checker/replay.hpp"
#include "model/vocabulary.hpp"

using namespace cemv;

int main(int argc, char** argv) {
  if (argc < 5) return 2;
  model::Matrix m = formats::load_matrix(argv[1]);
  // CAUSE: one id, or the ids of an XooN path joined by '_' (its key).
  std::vector<int> causes;
  for (const char* c = argv[2]; *c;) {
    causes.push_back(std::atoi(c));
    while (*c && *c != '_') ++c;
    if (*c == '_') ++c;
  }
  const int effect = std::atoi(argv[3]);
  const long long t = std::atoll(argv[4]);
  const checker::Work work = static_cast<checker::Work>((argc > 5 ? std::atof(argv[5]) : 30.0) * checker::kMega);
  std::vector<checker::Method> engines;
  for (int i = 6; i < argc; ++i) {
    auto e = checker::method_from_string(argv[i]);
    if (!e) {
      std::cerr << "unknown engine " << argv[i] << std::endl;
      return 2;
    }
    engines.push_back(*e);
  }
  if (engines.empty())
    engines = {checker::Method::InvariantsInduction, checker::Method::KInduction, checker::Method::Pdr,
               checker::Method::AcceleratedBmc, checker::Method::Bmc};
  if (std::getenv("SHOW_PATHS")) {
    auto paths = response::response_paths(m, {});
    std::size_t chains = 0;
    for (const auto& p : paths) {
      bool chain = p.elements.size() > p.causes.size() + 1;
      chains += chain;
      if (std::getenv("SHOW_PATHS")[0] == '2') std::cout << p.sif << " " << p.key() << " E=" << p.estimate << (chain ? " chain" : "") << std::endl;
    }
    std::cout << paths.size() << " paths, " << chains << " through references" << std::endl;
    return 0;
  }
  // DEGRADED=1: the degraded figure's property and runs.
  const response::Mode mode = std::getenv("DEGRADED") ? response::Mode::Degraded : response::Mode::Normal;
  response::Path path;
  for (const auto& p : response::response_paths(m, {}))
    if (p.effect == effect && p.causes == causes) path = p;
  if (std::getenv("SHOW_DEMAND")) {
    auto run = response::demand_run(m, path, mode, t);
    if (std::getenv("SHOW_DEMAND")[0] == '2')
      if (auto alone = response::demand_run_alone(m, path, mode, t)) run = *alone;
    if (std::getenv("SHOW_DEMAND")[0] == '4')
      if (auto pulses = response::demand_run_pulses_first(m, path, mode, t)) run = *pulses;
    if (std::getenv("SHOW_DEMAND")[0] == '5')
      run = response::demand_run_settled(m, path, mode, t).value_or(run);
    if (std::getenv("SHOW_DEMAND")[0] == '3')
      if (auto reset = response::demand_run_after_reset(m, path, mode, t)) run = *reset;
    auto trace = checker::run_on_runtime(m, run);
    if (std::getenv("JUDGE")) {  // the concrete evaluator's verdict on the run
      auto file = response::response_property(m, path, mode, t, "probe");
      properties::Trace pt;
      for (std::size_t k = 0; k < trace.inputs.size(); ++k) pt.push_back({trace.inputs[k], trace.observables[k]});
      auto e = properties::Evaluator(m).evaluate(file, pt).at(0);
      std::cout << "holds=" << e.holds << " judged=" << e.judged << "/" << pt.size()
                << " cycle=" << (e.cycle ? static_cast<long long>(*e.cycle) : -1) << std::endl;
    }
    const auto all = model::observables(m);
    for (std::size_t i = 0; i < all.size(); ++i) {
      const std::string& key = all[i].key;
      bool show = false;
      for (const auto& e : path.elements)
        show = show || key.rfind((e.kind == model::Node::Kind::Cause ? "cause[" : "effect[") + std::to_string(e.id) + "].active", 0) == 0;
      show = show || key.rfind("effect[2].", 0) == 0;
      for (const auto& x : m.intersections)
        show = show || (x.effect == effect && key == "cause[" + std::to_string(x.cause) + "].active");
      if (std::getenv("SHOW_ALL")) show = true;
      if (!show && key.find("output") == std::string::npos && key.find(".tag[") == std::string::npos) continue;
      if (!show && key.rfind("effect[" + std::to_string(effect) + "]", 0) != 0) continue;
      std::string line;
      for (const auto& o : trace.observables) line += std::to_string(o[i]);
      std::cout << key << " " << line << std::endl;
    }
    return 0;
  }
  if (std::getenv("SEARCH")) {  // the whole search of the path's figure, as cemv response runs it
    response::SearchOptions o;
    o.work = work;
    if (const char* out = std::getenv("OUT")) o.out_dir = out;
    const auto start = std::chrono::steady_clock::now();
    response::Figure f = response::least_response(m, path, mode, o);
    const char* kinds[] = {"exact", "unbounded", "unknown"};
    std::cout << kinds[static_cast<int>(f.kind)] << " T=" << f.cycles << " probes=" << f.probes << " method=" << f.method
              << " reason=" << f.reason << " "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s" << std::endl;
    return 0;
  }
  // PROPERTY=FILE: that property file's first property instead of the
  // path's (the same text at T and T - 1).
  auto property_file = [&](long long bound) {
    if (const char* f = std::getenv("PROPERTY")) {
      std::ifstream in(f);
      return properties::parse_properties(
          std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()), m, f);
    }
    return response::response_property(m, path, mode, bound, "probe");
  };
  const model::InputTable inputs(m);
  if (std::getenv("SHOW_PROPERTY")) {
    if (std::getenv("SHOW_PROPERTY")[0] == '2') {  // the member lemmas, and the bound assuming them
      auto lemmas = response::member_lemmas(m, path, mode, t, "probe.members");
      if (!lemmas) return 1;
      std::cout << properties::build::file_text(lemmas->file, inputs);
      std::cerr << properties::build::file_text(response::response_property(m, path, mode, t, "probe", lemmas->terms),
                                                inputs);
      return 0;
    }
    std::cout << properties::build::file_text(response::response_property(m, path, mode, t, "probe"), inputs);
    return 0;
  }
  if (std::getenv("SHOW_CHECK")) {
    auto file = response::response_property(m, path, mode, t, "probe");
    checker::CheckOptions o;
    o.budgets.engine = work;
    o.support = false;
    o.engines = {checker::Method::InvariantsInduction, checker::Method::KInduction, checker::Method::Bmc};
    o.engines_when_wide = {checker::Method::Pdr};
    // Engines named on the command line: those, in order, on any cone.
    if (argc > 6) o.engines = o.engines_when_wide = engines;
    o.localize_to = path.elements;
    if (const char* out = std::getenv("OUT")) o.out_dir = out;
    o.directed_runs = response::demand_runs(m, path, mode, t);
    auto r = checker::check_properties(m, {file}, o);
    const auto& pr = r.properties.at(0);
    std::cout << checker::to_string(pr.verdict) << " " << pr.method << " " << pr.reason << std::endl;
    for (const auto& n : pr.notes) std::cout << "  note: " << n << std::endl;
    return 0;
  }
  for (long long bound : {t, t - 1}) {
    auto file = property_file(bound);
    const auto& prop = file.properties.at(0);
    auto make = checker::property_problem(m, file, prop);
    for (const auto& engine : engines) {
      z3::context ctx;
      checker::Reduction red;
      auto problem = checker::reduce(make(ctx), &red);
      auto concrete = problem;
      if (std::getenv("LOCALIZE")) {
        // The path's elements, and those KEEP names ("e22 c5").
        std::vector<model::Node> kept = path.elements;
        if (const char* extra = std::getenv("KEEP"))
          for (const char* c = extra; *c;) {
            if (*c == 'c' || *c == 'e')
              kept.push_back({*c == 'c' ? model::Node::Kind::Cause : model::Node::Kind::Effect, std::atoi(c + 1)});
            ++c;
            while (*c && *c != ' ') ++c;
            while (*c == ' ') ++c;
          }
        auto keep = checker::keep_elements(kept);
        checker::Localization loc;
        auto l = checker::localize(problem, keep, &loc);
        std::cout << "localized: " << loc.state_vars_before << " -> " << loc.state_vars_after << " (freed "
                  << loc.freed << ")" << std::endl;
        if (l) problem = *l;
        if (std::getenv("SHOW_LOCAL")) {
          for (const auto& e : path.elements) std::cout << (e.kind == model::Node::Kind::Cause ? " c" : " e") << e.id;
          std::cout << std::endl;
          for (const auto& v : problem.problem.ts->statevars()) std::cout << "  kept " << v.name << std::endl;
          for (const auto& v : problem.problem.ts->inputvars())
            if (!concrete.problem.ts->inputvar(v.name)) std::cout << "  freed " << v.name << std::endl;
        }
      }
      if (std::getenv("SHOW_STATE") && engine == engines.front()) {
        for (const auto& v : problem.problem.ts->statevars()) std::cout << "  state " << v.name << std::endl;
        for (const auto& l : problem.problem.ts->lemmas()) std::cout << "  lemma " << l.term << std::endl;
      }
      if (std::getenv("SHOW_HOUDINI") && engine == engines.front()) {
        auto cands = checker::mine_candidates(problem.problem);
        checker::WorkMeter meter(problem.problem.ts->ctx(), work);
        auto kept = checker::houdini(problem.problem, cands, checker::Limits{}, meter);
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
                             checker::Limits{}.with_work(work).with_depth(std::getenv("MAX_DEPTH")
                                                                             ? std::atoi(std::getenv("MAX_DEPTH"))
                                                                             : static_cast<int>(bound + 2)));
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cout << "T=" << bound << " " << checker::to_string(engine) << ": " << checker::to_string(r.verdict) << " "
                << r.reason_text()
                << " k=" << r.k << " " << s << " s (state variables " << red.state_vars_before << " -> "
                << red.state_vars_after << ", inputs " << red.inputs_before << " -> " << red.inputs_after
                << (red.floats_as_integers ? ", floats as integers" : "") << ")" << std::endl;
      if (std::getenv("LOCALIZE") && r.verdict == checker::Verdict::Proved) {
        auto t0 = std::chrono::steady_clock::now();
        checker::check::recheck_proof(concrete.problem, r);
        std::cout << "  re-checked on the original in "
                  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s" << std::endl;
      }
      if (std::getenv("LOCALIZE") && r.verdict == checker::Verdict::Falsified) {
        auto c = checker::concretize(concrete.problem, r.cex);
        std::cout << "  concretized: " << (c ? "real" : "spurious") << std::endl;
      }
      if (r.verdict == checker::Verdict::Proved && !r.invariant.clauses.empty() && std::getenv("SHOW_INVARIANT"))
        std::cout << r.invariant.text() << std::endl;
    }
  }
}
