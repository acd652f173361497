// The re-checks themselves: a wrong answer must raise InternalError (never
// pass), and a right proof's obligations, exported as SMT-LIB, are unsat for
// a second solver (cvc5) too.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

#include "checker/check/recheck.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/invariants.hpp"
#include "checker/engines/kinduction.hpp"
#include "checker/translate.hpp"
#include "tests/checker/problems.hpp"

using namespace cemv;
using namespace cemv::checker;

namespace {

ProverResult solve(Prover& prover, const fixtures::NamedProblem& p) {
  z3::context ctx;
  OwnedProblem o = p.make(ctx);
  return prover.prove(o.problem, Limits{}.with_work(60 * kMega).with_depth(30));
}

TEST(Recheck, AcceptsTheHippsOverrideProof) {
  auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult r = solve(*make_invariant_prover(), p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  EXPECT_NO_THROW(check::recheck_proof(p.make, r));
}

// The user's time limit interrupts a re-check through its context: every
// later call on that context (push and add, not only check) may throw
// "canceled" (with the default solver), and that is an interruption, never
// an internal error.
TEST(Recheck, AnInterruptedContextIsAnInterruptionNotAFailure) {
  auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult r = solve(*make_invariant_prover(), p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  z3::context ctx;
  OwnedProblem o = p.make(ctx);
  CancelToken token;
  token.cancel();
  Limits limits;
  limits.cancel = &token;
  ctx.interrupt();
  // Either the re-check still ends (each obligation unsat) or it stops as
  // interrupted; a Z3 exception or an InternalError would be exit 4.
  bool ended = false;
  try {
    check::recheck_proof(o.problem, r, &limits);
    ended = true;
  } catch (const Interrupted&) {
    ended = true;
  }
  EXPECT_TRUE(ended);
}

TEST(Recheck, RejectsAProofWhoseInvariantIsWeakened) {
  auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult r = solve(*make_invariant_prover(), p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  // Drop the relation between the monitor and the override timer.
  std::vector<std::string> kept;
  for (const auto& c : r.invariant.clauses)
    if (c.find("override.elapsed") == std::string::npos || c.find("monitor") == std::string::npos) kept.push_back(c);
  ASSERT_LT(kept.size(), r.invariant.clauses.size());
  r.invariant.clauses = kept;
  EXPECT_THROW(check::recheck_proof(p.make, r), InternalError);
}

TEST(Recheck, RejectsAnInvariantThatIsNotInductive) {
  auto p = fixtures::guarded_counter(3);
  ProverResult r = solve(*make_invariant_prover(), p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  r.invariant.clauses.push_back("(<= x 1)");  // true initially, not preserved
  EXPECT_THROW(check::recheck_proof(p.make, r), InternalError);
}

TEST(Recheck, RejectsAProofOfAFalseProperty) {
  auto p = fixtures::guarded_counter(2);
  ProverResult forged;
  forged.verdict = Verdict::Proved;
  forged.method = Method::KInduction;
  forged.k = 2;
  EXPECT_THROW(check::recheck_proof(p.make, forged), InternalError);
}

// The re-checks of cone groups and of the portfolio state the obligations
// over a copy of the engines' problem in a fresh context
// (checker/translate.hpp): the copy must judge a proof as the problem built
// there by its factory does, accepting the right one and rejecting a wrong one.
TEST(Recheck, ATranslatedProblemJudgesProofsAsTheOriginal) {
  auto p = fixtures::override_instance_monitor(18000, Verdict::Proved);
  ProverResult r = solve(*make_invariant_prover(), p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  z3::context engines;
  OwnedProblem o = p.make(engines);
  std::vector<z3::expr> extra{!o.problem.good};
  z3::context fresh;
  OwnedProblem copy = translate(o.problem, fresh, &extra);
  ASSERT_EQ(&copy.problem.ts->ctx(), &fresh);
  EXPECT_EQ(copy.problem.ts->statevars().size(), o.problem.ts->statevars().size());
  EXPECT_EQ(copy.problem.ts->inputvars().size(), o.problem.ts->inputvars().size());
  for (std::size_t i = 0; i < copy.problem.ts->statevars().size(); ++i)
    EXPECT_EQ(copy.problem.ts->statevars()[i].name, o.problem.ts->statevars()[i].name);
  EXPECT_EQ(&extra.front().ctx(), &fresh);
  EXPECT_EQ(extra.front().to_string(), (!copy.problem.good).to_string());
  EXPECT_NO_THROW(check::recheck_proof(copy.problem, r));
  ProverResult weakened = r;
  weakened.invariant.clauses.clear();
  for (const auto& c : r.invariant.clauses)
    if (c.find("override.elapsed") == std::string::npos || c.find("monitor") == std::string::npos)
      weakened.invariant.clauses.push_back(c);
  ASSERT_LT(weakened.invariant.clauses.size(), r.invariant.clauses.size());
  EXPECT_THROW(check::recheck_proof(copy.problem, weakened), InternalError);
}

TEST(Recheck, ATranslatedProblemRejectsAProofOfAFalseProperty) {
  auto p = fixtures::guarded_counter(2);
  z3::context engines;
  OwnedProblem o = p.make(engines);
  z3::context fresh;
  OwnedProblem copy = translate(o.problem, fresh);
  ProverResult forged;
  forged.verdict = Verdict::Proved;
  forged.method = Method::KInduction;
  forged.k = 2;
  EXPECT_THROW(check::recheck_proof(copy.problem, forged), InternalError);
}

// k-induction needs its lazily added simple-path constraints here, and the
// re-check must use them too (without them the step is sat).
TEST(Recheck, SimplePathProofOfTheLasso) {
  auto p = fixtures::lasso();
  KInductionOptions plain;
  plain.mine_invariants = false;
  KInduction with_simple_path(plain);
  ProverResult r = solve(with_simple_path, p);
  ASSERT_EQ(r.verdict, Verdict::Proved) << r.reason_text();
  EXPECT_TRUE(r.simple_path);
  EXPECT_EQ(r.k, 2);
  EXPECT_NO_THROW(check::recheck_proof(p.make, r));
  r.simple_path = false;
  EXPECT_THROW(check::recheck_proof(p.make, r), InternalError);

  plain.simple_path = false;
  KInduction without(plain);
  ProverResult u = solve(without, p);
  EXPECT_EQ(u.verdict, Verdict::Unknown);
  EXPECT_EQ(u.reason, UnknownReason::BoundReached);
}

TEST(Replay, AcceptsABmcCounterexample) {
  auto p = fixtures::saturating_counter(10, 4);
  Bmc bmc;
  ProverResult r = solve(bmc, p);
  ASSERT_EQ(r.verdict, Verdict::Falsified);
  EXPECT_NO_THROW(check::replay_counterexample(p.make, r.cex));
}

TEST(Replay, RejectsACounterexampleWithAChangedInput) {
  auto p = fixtures::saturating_counter(10, 4);
  Bmc bmc;
  ProverResult r = solve(bmc, p);
  ASSERT_EQ(r.verdict, Verdict::Falsified);
  ASSERT_EQ(r.cex.length(), 6u);
  r.cex.cycles[2].inputs[0].i = 0;  // `go` false resets the counter
  EXPECT_THROW(check::replay_counterexample(p.make, r.cex), InternalError);
}

TEST(Replay, RejectsATruncatedCounterexample) {
  auto p = fixtures::guarded_counter(2);
  Bmc bmc;
  ProverResult r = solve(bmc, p);
  ASSERT_EQ(r.verdict, Verdict::Falsified);
  EXPECT_NO_THROW(check::replay_counterexample(p.make, r.cex));
  r.cex.cycles.pop_back();
  EXPECT_THROW(check::replay_counterexample(p.make, r.cex), InternalError);
}

TEST(Replay, RejectsATraceWhoseStatesDisagreeWithTheFormulas) {
  auto p = fixtures::example_term("tank-overfill", {model::Node{model::Node::Kind::Effect, 1}}, "effect[1].active",
                                  true, Verdict::Falsified, 1);
  Bmc bmc;
  ProverResult r = solve(bmc, p);
  ASSERT_EQ(r.verdict, Verdict::Falsified);
  EXPECT_NO_THROW(check::replay_counterexample(p.make, r.cex));
  r.cex.cycles[0].state[0].i ^= 1;  // first_cycle
  EXPECT_THROW(check::replay_counterexample(p.make, r.cex), InternalError);
}

// A property the Evaluator cannot compute (multiplication is no operator the
// encoder emits): its counterexample cannot be re-checked, so it is an
// internal error, not a verdict.
TEST(Replay, RefusesWhatItCannotResimulate) {
  auto p = fixtures::saturating_counter(10, 4);
  p.make = [inner = p.make](z3::context& ctx) {
    OwnedProblem o = inner(ctx);
    z3::expr x = *o.problem.ts->statevar("x");
    o.problem.good = x * x <= 16;
    return o;
  };
  Bmc bmc;
  ProverResult r = solve(bmc, p);
  ASSERT_EQ(r.verdict, Verdict::Falsified);
  EXPECT_THROW(check::replay_counterexample(p.make, r.cex), InternalError);
}

std::string run(const std::string& cmd) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  if (!pipe) return out;
  char buf[256];
  while (fgets(buf, sizeof buf, pipe.get())) out += buf;
  return out;
}

// The base case and inductive step of real proofs, confirmed by cvc5.
TEST(SmtlibExport, Cvc5ConfirmsTheProofObligations) {
  struct Item {
    fixtures::NamedProblem problem;
    std::unique_ptr<Prover> prover;
  };
  std::vector<Item> items;
  items.push_back({fixtures::override_instance_monitor(18000, Verdict::Proved), make_invariant_prover()});
  items.push_back({fixtures::guarded_counter(3), std::make_unique<KInduction>()});
  items.push_back({fixtures::saturating_counter(10, 10), std::make_unique<KInduction>()});
  auto dir = std::filesystem::temp_directory_path() / ("cemv_checker_smt_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  int confirmed = 0;
  for (auto& item : items) {
    z3::context ctx;
    OwnedProblem o = item.problem.make(ctx);
    ProverResult r = item.prover->prove(o.problem, Limits{}.with_work(60 * kMega).with_depth(10));
    ASSERT_EQ(r.verdict, Verdict::Proved) << item.problem.name << " " << r.reason_text();
    auto obligations = check::proof_obligations_smtlib(o.problem, r);
    ASSERT_GE(obligations.size(), 3u);
    for (const auto& ob : obligations) {
      auto file = dir / (item.problem.name + "." + ob.name + ".smt2");
      std::ofstream(file) << ob.script;
      std::string out = run("cvc5 --lang smt2 " + file.string() + " 2>&1");
      EXPECT_EQ(out.substr(0, out.find('\n')), "unsat") << item.problem.name << " " << ob.name << "\n" << out;
      ++confirmed;
    }
  }
  std::filesystem::remove_all(dir);
  EXPECT_GE(confirmed, 9);
}

// A large invariant (kChunkedClauses or more) is re-checked a chunk of
// clauses at a time, each first under the premise cut to what decides it.
// The system: a shift register x0 <- FALSE, xi <- x(i-1) of 1,100 stages,
// and a <- b, b <- b, d <- d; everything FALSE initially.
struct ShiftRegister {
  z3::context ctx;
  encoder::TransitionSystem ts{ctx};
  static constexpr int kStages = 1100;
  ShiftRegister() {
    z3::expr prev = ctx.bool_val(false);
    for (int i = 0; i < kStages; ++i) {
      const z3::expr x = ts.make_statevar(("x" + std::to_string(i)).c_str(), ctx.bool_sort());
      ts.set_init(x, ctx.bool_val(false));
      ts.assign_next(x, prev);
      prev = x;
    }
    const z3::expr a = ts.make_statevar("a", ctx.bool_sort());
    const z3::expr b = ts.make_statevar("b", ctx.bool_sort());
    const z3::expr d = ts.make_statevar("d", ctx.bool_sort());
    for (const auto& v : {a, b, d}) ts.set_init(v, ctx.bool_val(false));
    ts.assign_next(a, b);
    ts.assign_next(b, b);
    ts.assign_next(d, d);
    ts.check_complete();
  }
  SafetyProblem problem() { return SafetyProblem{&ts, ctx.bool_val(true), ctx.bool_val(true)}; }
  // Every stage FALSE, but `skip`; `not a` first, and last the clause it
  // needs, which also reads d: beyond a's next-state function, so a's
  // chunk is decided only under the whole premise.
  static ProverResult proof(int skip = -1) {
    ProverResult r;
    r.verdict = Verdict::Proved;
    r.method = Method::InvariantsInduction;
    r.k = 0;
    r.invariant.clauses.push_back("(not a)");
    for (int i = 0; i < kStages; ++i)
      if (i != skip) r.invariant.clauses.push_back("(not x" + std::to_string(i) + ")");
    r.invariant.clauses.push_back("(not (or b d))");
    return r;
  }
};

TEST(Recheck, AcceptsALargeInvariantChunkByChunk) {
  ShiftRegister s;
  EXPECT_NO_THROW(check::recheck_proof(s.problem(), ShiftRegister::proof()));
}

TEST(Recheck, RejectsALargeInvariantWithOneClauseNotInductive) {
  ShiftRegister s;
  // Without stage 500's clause, stage 501's is not inductive.
  try {
    check::recheck_proof(s.problem(), ShiftRegister::proof(500));
    ADD_FAILURE() << "the re-check passed";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("invariant-step (clauses 385 to 512)"), std::string::npos) << e.what();
  }
}

// At k = 0 a large invariant's outputs are re-checked one conjunct of the
// property at a time: `not b` reads b alone, and its clause also reads d,
// so it follows only under the whole premise; `x0` does not follow.
TEST(Recheck, AcceptsALargeInvariantsPropertyConjunctByConjunct) {
  ShiftRegister s;
  const z3::expr x3 = s.ts.statevars()[3].var, b = s.ts.statevars()[ShiftRegister::kStages + 1].var;
  const z3::expr a = s.ts.statevars()[ShiftRegister::kStages].var;
  const SafetyProblem p{&s.ts, (!a || x3) && !b && !x3, s.ctx.bool_val(true)};
  EXPECT_NO_THROW(check::recheck_proof(p, ShiftRegister::proof()));
}

TEST(Recheck, RejectsALargeInvariantsPropertyNamingTheConjunct) {
  ShiftRegister s;
  const z3::expr x0 = s.ts.statevars()[0].var, b = s.ts.statevars()[ShiftRegister::kStages + 1].var;
  const SafetyProblem p{&s.ts, !b && x0 && !x0.ctx().bool_val(false), s.ctx.bool_val(true)};
  try {
    check::recheck_proof(p, ShiftRegister::proof());
    ADD_FAILURE() << "the re-check passed";
  } catch (const InternalError& e) {
    EXPECT_NE(std::string(e.what()).find("step (conjunct 2 of 3 of the property)"), std::string::npos) << e.what();
  }
}

}  // namespace
