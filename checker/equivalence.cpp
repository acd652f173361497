// Observable equivalence of two matrices (checker/equivalence.hpp): the
// order in which a group is decided. The parts are apart: the slices, the
// product and the replay of its runs (checker/equivalence_product.hpp), the
// random runs (checker/equivalence_falsifier.hpp).
#include "checker/equivalence.hpp"

#include <set>
#include <stdexcept>
#include <unordered_map>

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/engines/relational.hpp"
#include "checker/equivalence_falsifier.hpp"
#include "checker/equivalence_product.hpp"

namespace cemv::checker {

const char* to_string(EquivalenceBasis b) {
  switch (b) {
    case EquivalenceBasis::None:
    case EquivalenceBasis::Engine: return "";
    case EquivalenceBasis::Simulation: return "simulation";
    case EquivalenceBasis::IdenticalCone: return "identical cone";
    case EquivalenceBasis::Interface: return "interface";
    case EquivalenceBasis::InterfaceOnly: return "interface-only";
    case EquivalenceBasis::Suite: return "suite";
  }
  return "";
}

namespace {

using model::Node;

// How many cycles deep BMC looks for a difference before the random runs:
// its first answer is a shortest difference.
constexpr int kShortestCheckDepth = 4;

class Decider {
 public:
  Decider(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& g, const EquivalenceOptions& o)
      : a_(a), b_(b), g_(g), o_(o) {
    limits_.cancel = o.cancel;
    if (o.timeout_s > 0)
      limits_.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.timeout_s));
  }

  GroupEquivalence run() {
    const auto start = Clock::now();
    GroupEquivalence out;
    out.group = g_.name;
    try {
      decide(out);
    } catch (const Interrupted&) {
      out = GroupEquivalence{};
      out.group = g_.name;
    }
    if (limits_.interrupted() && out.verdict != EquivalenceVerdict::Equivalent &&
        out.verdict != EquivalenceVerdict::Differs)
      out.unknown = UnknownReason::TimeLimit;
    if (out.verdict == EquivalenceVerdict::Unknown && out.unknown == UnknownReason::TimeLimit) {
      out.basis = EquivalenceBasis::None;
      out.method.clear();
      out.reason = to_string(UnknownReason::TimeLimit);
      out.distinction.reset();
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  }

 private:
  void decide(GroupEquivalence& out) {
    if (!interface(out)) return;
    std::vector<Node> group_roots = g_.roots;
    if (group_roots.empty() && o_.identical_cone_shortcut && !narrow_to_changed_nodes(group_roots)) {
      out.verdict = EquivalenceVerdict::Equivalent;
      out.rest_on(EquivalenceBasis::IdenticalCone);
      return;
    }
    const EquivalenceQuestion q{a_,      b_,       g_.name, keys_, roots_in(a_, b_, group_roots), roots_in(b_, a_, group_roots),
                                limits_, o_.work, o_.random_cycles};
    if (o_.identical_cone_shortcut && !q.ra.empty() && q.ra == q.rb &&
        cone_configuration(a_, q.ra) == cone_configuration(b_, q.rb)) {
      out.verdict = EquivalenceVerdict::Equivalent;
      out.rest_on(EquivalenceBasis::IdenticalCone);
      return;
    }
    try {
      if (prove_or_falsify(q, out)) return;
    } catch (const std::invalid_argument& e) {
      out.verdict = EquivalenceVerdict::Differs;
      out.rest_on(EquivalenceBasis::Interface);
      out.reason = e.what();
      out.distinction.reset();
    }
  }

  // The engines in order, the answer in `out` (true; an InternalError when a
  // distinguishing run does not replay).
  bool prove_or_falsify(const EquivalenceQuestion& q, GroupEquivalence& out) {
    const ProblemFactory make = product_factory(q);
    std::string why;
    ProverResult r;
    {
      // BMC a few cycles deep first: a structural change mostly shows
      // within a cycle or two of the right inputs, which a solver finds
      // where random runs need several tags set together (the 128 x 128
      // benchmark: a 2oo3 cause whose effect three other causes latch). Its
      // first answer is a shortest difference, read and replayed in the same
      // context (building the product of two wide cones again costs as much
      // as the search). Contexts are borrowed from the pool: tearing down a
      // context that held the product of two wide cones cost more than
      // building and solving it (the benchmark's changed effect: 1.7 s of 4).
      const Limits probe = limits_.with_work(o_.work / 3).with_depth(kShortestCheckDepth - 1);
      PooledContext ctx;
      const OwnedProblem op = make(ctx);
      r = Bmc().prove(op.problem, probe);
      stop_if_interrupted(limits_);
      if (r.verdict == Verdict::Falsified) {
        out.rest_on_engine(r.method_text());
        out.k = r.k;
        if (replay_product_run(q, op, r.cex, out, why)) return true;
        return whole_product(q, out, why);
      }
    }
    // Random runs next, for differences deeper than that: one that takes a
    // timer or analog values past a threshold is found on the runtimes long
    // before a solver has unrolled the analog arithmetic or a long timer. A
    // run found is minimised (random_runs.hpp), not proved shortest beyond
    // the BMC bound (unrolling the product deeper costs many times what the
    // runs do: tank-overfill's soft bypass at 3 s, 1 s CPU with the runs
    // alone, 29 s with BMC to depth 30).
    if (RandomFalsifier(q).find(out)) {
      if (r.verdict == Verdict::Unknown && r.reason != UnknownReason::BoundReached)
        out.reason = "a shorter difference is not ruled out (BMC: " + r.reason_text() + ")";
      return true;
    }
    // The relational engine next: where the two copies are built alike,
    // a.x = b.x is inductive and proves the group in a few solver calls.
    // Its proof is re-checked with the real float semantics in a fresh
    // context (an InternalError if it fails), like every portfolio answer.
    // A third of an engine's budget: Houdini on a product whose copies do
    // differ weakens the claims one by one to no proof, and the portfolio
    // after it needs the rest.
    {
      PooledContext ctx;
      const OwnedProblem op = make(ctx);
      r = make_relational_prover()->prove(op.problem, limits_.with_work(o_.work / 3));
    }
    stop_if_interrupted(limits_);
    if (r.verdict == Verdict::Proved) {
      check::recheck(make, r, &limits_);
      out.verdict = EquivalenceVerdict::Equivalent;
      out.rest_on_engine(r.method_text());
      return true;
    }
    r = Portfolio(make, portfolio_options()).run(limits_);
    out.rest_on_engine(r.method_text());
    out.k = r.k;
    if (r.verdict == Verdict::Proved) {
      out.verdict = EquivalenceVerdict::Equivalent;
      return true;
    }
    if (r.verdict == Verdict::Unknown) {
      out.verdict = EquivalenceVerdict::Unknown;
      out.unknown = r.reason;
      out.reason = r.reason_text();
      return true;
    }
    if (replay_product_run(q, r.cex, out, why)) return true;
    return whole_product(q, out, why);
  }

  // A slice's run that the runtimes do not reproduce: the whole matrices
  // are exact (docs/encoding.md); their run must replay (true, `out`
  // filled), else an InternalError.
  bool whole_product(const EquivalenceQuestion& sliced, GroupEquivalence& out, const std::string& why) {
    if (!sliced.ra.empty() || !sliced.rb.empty()) {
      const EquivalenceQuestion q{a_, b_, g_.name, keys_, {}, {}, limits_, o_.work, o_.random_cycles};
      const ProverResult r = Portfolio(product_factory(q), portfolio_options()).run(limits_);
      stop_if_interrupted(limits_);
      out.rest_on_engine(r.method_text());
      out.k = r.k;
      std::string whole_why;
      if (r.verdict == Verdict::Falsified && replay_product_run(q, r.cex, out, whole_why)) return true;
      if (r.verdict != Verdict::Falsified)
        throw InternalError("equivalence of " + g_.name + ": a run of the sliced product distinguishes the two "
                            "matrices, the runtimes do not, and the whole product says " + to_string(r.verdict) +
                            "\n" + why);
      throw InternalError("equivalence of " + g_.name + ": the runtimes do not reproduce the distinguishing run\n" +
                          whole_why);
    }
    throw InternalError("equivalence of " + g_.name + ": the runtimes do not reproduce the distinguishing run\n" + why);
  }

  // A whole-matrix group: the nodes whose cone differs between the two
  // matrices (the observables of every other node are equal by the
  // identical-cone argument) become the roots, and only their observables
  // the keys. A cause's cone here takes in its first-out group, whose
  // members decide its first_out (docs/encoding.md, "Cone of influence").
  // False when no node's cone differs.
  bool narrow_to_changed_nodes(std::vector<Node>& roots) {
    std::set<Node> nodes;
    for (const auto* m : {&a_, &b_}) {
      for (const auto& c : m->causes)
        if (c.function != model::CauseFunction::Comment) nodes.insert({Node::Kind::Cause, c.id});
      for (const auto& e : m->effects)
        if (e.function != model::EffectFunction::Comment) nodes.insert({Node::Kind::Effect, e.id});
    }
    auto peers = [&](const Node& n) {
      std::set<Node> r{n};
      if (n.kind != Node::Kind::Cause) return r;
      for (const auto* m : {&a_, &b_}) {
        const model::Cause* c = m->find_cause(n.id);
        if (!c || c->first_out_group == 0) continue;
        for (const auto& o : m->causes)
          if (o.first_out_group == c->first_out_group && o.function != model::CauseFunction::Comment)
            r.insert({Node::Kind::Cause, o.id});
      }
      return r;
    };
    std::set<Node> changed, extended;
    for (const auto& n : nodes) {
      std::set<Node> p = peers(n);
      std::vector<Node> pv(p.begin(), p.end());
      const std::vector<Node> ra = roots_in(a_, b_, pv), rb = roots_in(b_, a_, pv);
      if (ra == rb && cone_configuration(a_, ra) == cone_configuration(b_, rb)) continue;
      changed.insert(n);
      extended.insert(p.begin(), p.end());
    }
    if (changed.empty()) return false;
    roots.assign(extended.begin(), extended.end());
    std::vector<KeyInfo> kept;
    const auto oa = model::observables(a_);
    for (const auto& k : keys_) {
      const auto& o = oa[k.index_a];
      if (changed.count(Node{o.kind, o.id})) kept.push_back(k);
    }
    keys_ = std::move(kept);
    return true;
  }

  // The group's keys as both matrices know them; false (Differs) when the
  // observable interface itself changed.
  bool interface(GroupEquivalence& out) {
    const auto oa = model::observables(a_), ob = model::observables(b_);
    std::unordered_map<std::string, std::size_t> ia, ib;
    for (std::size_t i = 0; i < oa.size(); ++i) ia.emplace(oa[i].key, i);
    for (std::size_t i = 0; i < ob.size(); ++i) ib.emplace(ob[i].key, i);
    std::string only_a, only_b;
    for (const auto& k : g_.keys) {
      auto x = ia.find(k), y = ib.find(k);
      if (x == ia.end() && y == ib.end()) continue;
      if (y == ib.end()) only_a += (only_a.empty() ? "" : ", ") + k;
      else if (x == ia.end()) only_b += (only_b.empty() ? "" : ", ") + k;
      else keys_.push_back(KeyInfo{k, oa[x->second].type, x->second, y->second});
    }
    if (only_a.empty() && only_b.empty()) return true;
    out.verdict = EquivalenceVerdict::Differs;
    out.rest_on(EquivalenceBasis::Interface);
    if (!only_a.empty()) out.reason = "only in the first matrix: " + only_a;
    if (!only_b.empty()) out.reason += std::string(out.reason.empty() ? "" : "; ") + "only in the second matrix: " + only_b;
    return false;
  }

  const model::Matrix& a_;
  const model::Matrix& b_;
  const ObservableGroup& g_;
  PortfolioOptions portfolio_options() const {
    PortfolioOptions p;
    p.engine_work = o_.work;
    return p;
  }

  const EquivalenceOptions& o_;
  Limits limits_;
  std::vector<KeyInfo> keys_;
};

}  // namespace

GroupEquivalence decide_equivalence(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& group,
                                    const EquivalenceOptions& options) {
  return Decider(a, b, group, options).run();
}

}  // namespace cemv::checker
