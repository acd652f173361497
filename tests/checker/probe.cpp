// cemv_checker_probe MATRIX PROPS WORK [NAME...]: every engine alone on
// every property (or the named ones), each with WORK million Z3 resource units, on the
// property's cone of influence; then the portfolio. The table tells which
// engine decides which property, and how fast: what the portfolio's schedule
// and docs/performance.md are based on. Built with the tests, not run by ctest.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "checker/check.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"
#include "properties/standard.hpp"
#include "tests/support/random_matrix.hpp"

using namespace cemv;
using namespace cemv::checker;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s MATRIX PROPS SECONDS [NAME...]\n", argv[0]);
    return 2;
  }
  // MATRIX may be random:N (the n x n matrix of bench/bench_checker.cpp's
  // standard-set scaling) or big (tests/support big_matrix); PROPS may be
  // standard (the matrix's standard property set).
  const std::string matrix_arg = argv[1];
  model::Matrix m;
  if (matrix_arg == "big") {
    m = testsupport::big_matrix(1);
  } else if (matrix_arg.rfind("random:", 0) == 0) {
    const int n = std::atoi(matrix_arg.c_str() + 7);
    testsupport::MatrixOptions o;
    o.min_causes = o.max_causes = n;
    o.min_effects = o.max_effects = n;
    o.cycle_ms = 100;
    m = testsupport::random_matrix(static_cast<std::uint64_t>(n), o);
  } else {
    m = formats::load_valid_matrix(argv[1], "probe");
  }
  if (const char* save = std::getenv("PROBE_SAVE")) {  // the matrix as a file, for cemv check
    formats::save_matrix(m, save);
    return 0;
  }
  properties::PropertyFile f = std::string(argv[2]) == "standard" ? properties::standard_properties(m)
                                                                   : properties::load_properties(argv[2], m);
  const double mega = std::atof(argv[3]);
  const Work work = static_cast<Work>(mega * kMega);
  if (std::getenv("PROBE_CHECK")) {  // check_properties as the benchmark runs it, one line per property
    CheckOptions o;
    o.budgets.engine = work;
    o.support = false;
    o.standard = true;
    o.on_result = [](const PropertyResult& r) {
      std::printf("%-34s %-11s %-22s %3d %7.3f s\n", r.name.c_str(), to_string(r.verdict),
                  r.method.c_str(), r.depth, r.seconds);
      std::fflush(stdout);
    };
    std::set<std::string> names(argv + 4, argv + argc);
    if (!names.empty()) std::erase_if(f.properties, [&](const auto& p) { return !names.count(p.name); });
    check_properties(m, {f}, o);
    return 0;
  }
  std::set<std::string> only(argv + 4, argv + argc);
  const std::vector<Method> engines{Method::Bmc, Method::KInduction, Method::InvariantsInduction, Method::Pdr,
                                    Method::AcceleratedBmc};
  for (const auto& p : f.properties) {
    if (!only.empty() && !only.count(p.name)) continue;
    ProblemFactory make = property_problem(m, f, p);
    if (std::getenv("PROBE_REDUCE")) {
      if (!std::getenv("PROBE_PORTFOLIO_ONLY")) make = reducing(make);
      z3::context ctx;
      Reduction what;
      reduce(property_problem(m, f, p)(ctx), &what);
      if (std::getenv("PROBE_DUMP")) {
        z3::context c2;
        OwnedProblem o = make(c2);
        for (const auto& sv : o.problem.ts->statevars())
          std::printf("state %s := %s\n  next %s\n", sv.name.c_str(), sv.init.to_string().c_str(), sv.next.to_string().c_str());
        std::printf("good %s\nassumption %s\n", o.problem.good.to_string().c_str(), o.problem.assumption.to_string().c_str());
      }
      std::printf("| %-34s | reduced: %zu -> %zu state vars, %zu -> %zu inputs, floats as integers: %s |\n",
                  p.name.c_str(), what.state_vars_before, what.state_vars_after, what.inputs_before,
                  what.inputs_after, what.floats_as_integers ? "yes" : "no");
    }
    {
      auto b0 = std::chrono::steady_clock::now();
      z3::context c0;
      OwnedProblem o0 = property_problem(m, f, p)(c0);
      auto b1 = std::chrono::steady_clock::now();
      OwnedProblem o1 = reduce(o0);
      auto b2 = std::chrono::steady_clock::now();
      std::printf("| %-34s | build %.3f s, reduce %.3f s |\n", p.name.c_str(),
                  std::chrono::duration<double>(b1 - b0).count(), std::chrono::duration<double>(b2 - b1).count());
    }
    for (const auto& e : engines) {
      if (std::getenv("PROBE_PORTFOLIO_ONLY")) break;
      z3::context ctx;
      OwnedProblem o = make(ctx);
      auto t0 = std::chrono::steady_clock::now();
      ProverResult r = make_prover(e, 10)->prove(o.problem, Limits{}.with_work(work));
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("| %-34s | %-20s | %-9s | k=%-4d | %-14s | %7.3f s | %llu work |\n", p.name.c_str(), to_string(e),
                  to_string(r.verdict).c_str(), r.k, r.reason_text().c_str(), s,
                  static_cast<unsigned long long>(r.work));
      std::fflush(stdout);
    }
    auto t0 = std::chrono::steady_clock::now();
    ProverResult r;
    try {
      PortfolioOptions po;
      po.engine_work = work;
      r = Portfolio(make, po).run(Limits{});
    } catch (const std::exception& e) {
      std::printf("| %-34s | portfolio failed: %s |\n", p.name.c_str(), e.what());
      continue;
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %-34s | %-20s | %-9s | k=%-4d | %-14s | %7.3f s |\n", p.name.c_str(),
                ("portfolio:" + r.method_text()).c_str(), to_string(r.verdict).c_str(), r.k, r.reason_text().c_str(), s);
    std::fflush(stdout);
  }
}
