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

void measure(Method engine, const fixtures::NamedProblem& p, int seconds, int max_depth) {
  z3::context ctx;
  OwnedProblem o = p.make(ctx);
  auto t0 = std::chrono::steady_clock::now();
  Limits l;
  l.deadline = Clock::now() + std::chrono::seconds(seconds);
  l.max_depth = max_depth;
  ProverResult r = make_prover(engine)->prove(o.problem, l);
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::string checked = "-";
  if (r.verdict != Verdict::Unknown) {
    auto c0 = std::chrono::steady_clock::now();
    check::recheck(p.make, r);
    checked = std::to_string(std::chrono::duration<double>(std::chrono::steady_clock::now() - c0).count());
  }
  std::printf("| %-44s | %-20s | %-9s | %-13s | k=%-6d | cex %6zu | %8.3f s | recheck %s s |\n", p.name.c_str(),
              to_string(engine), to_string(r.verdict).c_str(), r.reason_text().c_str(), r.k, r.cex.length(), s,
              checked.c_str());
  std::fflush(stdout);
}

void portfolio(const fixtures::NamedProblem& p, int seconds) {
  auto t0 = std::chrono::steady_clock::now();
  Limits l;
  l.deadline = Clock::now() + std::chrono::seconds(seconds);
  ProverResult r = Portfolio(p.make).run(l);
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("| %-44s | %-20s | %-9s | %-13s | k=%-6d | cex %6zu | %8.3f s | (in portfolio) |\n", p.name.c_str(),
              ("portfolio:" + r.method_text()).c_str(), to_string(r.verdict).c_str(), r.reason_text().c_str(), r.k,
              r.cex.length(), s);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int slow = argc > 1 ? std::stoi(argv[1]) : 60;
  auto holds = fixtures::override_instance_monitor(18000, Verdict::Proved);
  auto tight = fixtures::override_instance_monitor(17999, Verdict::Falsified);
  auto restart = fixtures::override_monitor(18000, Verdict::Falsified);
  measure(Method::InvariantsInduction, holds, 60, 1000);
  measure(Method::KInduction, holds, 60, 10);
  measure(Method::AcceleratedBmc, tight, 60, 1000);
  measure(Method::AcceleratedBmc, restart, 60, 1000);
  portfolio(holds, 60);
  portfolio(tight, 60);
  measure(Method::Bmc, tight, slow, 18001);
  measure(Method::Pdr, holds, slow, 1000);
  return 0;
}
