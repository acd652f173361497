// cemv_checker_measure [SECONDS]: the requirement-4 style figures (the
// pipeline-hipps 18,000-cycle override timer) engine by engine, with plain BMC
// and PDR given SECONDS each (default 60) for the same questions, so the
// closing note and docs/performance.md can quote a ratio. Built with the
// tests, not run by ctest (it takes minutes).
#include <chrono>
#include <cstdio>
#include <string>

#include "checker/check/recheck.hpp"
#include "checker/engines/portfolio.hpp"
#include "tests/checker/problems.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

void measure(const std::string& engine, const fixtures::NamedProblem& p, int seconds, int max_depth) {
  z3::context ctx;
  OwnedProblem o = p.make(ctx);
  auto t0 = std::chrono::steady_clock::now();
  ProverResult r = make_prover(engine)->prove(o.problem, Limits::within(std::chrono::seconds(seconds), max_depth));
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string checked = "-";
  if (r.verdict != Verdict::Unknown) {
    auto c0 = std::chrono::steady_clock::now();
    check::recheck(p.make, r);
    checked = std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count());
  }
  std::printf("| %-44s | %-20s | %-9s | %-13s | k=%-6d | cex %6zu | %8.3f s | recheck %s s |\n", p.name.c_str(),
              engine.c_str(), to_string(r.verdict).c_str(), r.reason.c_str(), r.k, r.cex.length(), s,
              checked.c_str());
  std::fflush(stdout);
}

void portfolio(const fixtures::NamedProblem& p, int seconds) {
  auto t0 = std::chrono::steady_clock::now();
  ProverResult r = Portfolio(p.make).run(Limits::within(std::chrono::seconds(seconds), 1000));
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("| %-44s | %-20s | %-9s | %-13s | k=%-6d | cex %6zu | %8.3f s | (in portfolio) |\n", p.name.c_str(),
              ("portfolio:" + r.method).c_str(), to_string(r.verdict).c_str(), r.reason.c_str(), r.k,
              r.cex.length(), s);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int slow = argc > 1 ? std::stoi(argv[1]) : 60;
  auto holds = fixtures::override_instance_monitor(18000, Verdict::Proved);
  auto tight = fixtures::override_instance_monitor(17999, Verdict::Falsified);
  auto restart = fixtures::override_monitor(18000, Verdict::Falsified);
  measure("invariants+induction", holds, 60, 1000);
  measure("k-induction", holds, 60, 10);
  measure("accelerated-bmc", tight, 60, 1000);
  measure("accelerated-bmc", restart, 60, 1000);
  portfolio(holds, 60);
  portfolio(tight, 60);
  measure("bmc", tight, slow, 18001);
  measure("pdr", holds, slow, 1000);
  return 0;
}
