// cemv_checker_probe MATRIX PROPS SECONDS [NAME...]: every engine alone on
// every property (or the named ones), each with SECONDS of wall clock, on the
// property's cone of influence; then the portfolio. The table tells which
// engine decides which property, and how fast: what the portfolio's schedule
// and docs/performance.md are based on. Built with the tests, not run by ctest.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>

#include "checker/engines/portfolio.hpp"
#include "checker/property_problem.hpp"
#include "checker/reduce.hpp"
#include "formats/matrix_json.hpp"
#include "properties/parser.hpp"

using namespace cemv;
using namespace cemv::checker;

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s MATRIX PROPS SECONDS [NAME...]\n", argv[0]);
    return 2;
  }
  model::Matrix m = formats::load_valid_matrix(argv[1], "probe");
  properties::PropertyFile f = properties::load_properties(argv[2], m);
  const int seconds = std::atoi(argv[3]);
  std::set<std::string> only(argv + 4, argv + argc);
  const std::vector<std::string> engines{"bmc", "k-induction", "invariants+induction", "pdr", "accelerated-bmc"};
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
      ProverResult r = make_prover(e, 10)->prove(o.problem, Limits::within(std::chrono::seconds(seconds), 1000));
      double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("| %-34s | %-20s | %-9s | k=%-4d | %-14s | %7.3f s |\n", p.name.c_str(), e.c_str(),
                  to_string(r.verdict).c_str(), r.k, r.reason.c_str(), s);
      std::fflush(stdout);
    }
    auto t0 = std::chrono::steady_clock::now();
    ProverResult r;
    try {
      r = Portfolio(make).run(Limits::within(std::chrono::seconds(seconds), 1000));
    } catch (const std::exception& e) {
      std::printf("| %-34s | portfolio failed: %s |\n", p.name.c_str(), e.what());
      continue;
    }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("| %-34s | %-20s | %-9s | k=%-4d | %-14s | %7.3f s |\n", p.name.c_str(),
                ("portfolio:" + r.method).c_str(), to_string(r.verdict).c_str(), r.k, r.reason.c_str(), s);
    std::fflush(stdout);
  }
}
