// Correspondence invariants of a product of matrix and program, and the
// proof of an output's relation from them (correspondence.hpp).
#include "plc_check/correspondence.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <unordered_set>

#include "checker/engines/invariants.hpp"
#include "checker/engines/solving.hpp"
#include "checker/limits.hpp"
#include "encoder/unroller.hpp"
#include "plc_check/cones.hpp"
#include "plc_check/houdini.hpp"
#include "plc_check/product.hpp"

namespace cemv::plc_check {

namespace {

using Sample = std::vector<encoder::Evaluator::Value>;
using checker::ProverResult;
using checker::UnknownReason;
using checker::Verdict;

// The templates of the header comment, tested on the samples.
class Templates {
 public:
  // Over the state variables of `cone` (ascending indices).
  // With `supports`, only the pairs and guards they accept. `samples`: states
  // of the product, or (with `weights`) of the cone's variables alone, each
  // standing for as many distinct states of the product as its weight.
  Templates(const encoder::TransitionSystem& ts, const std::vector<Sample>& samples, const std::vector<std::size_t>& cone,
            const Supports* supports, bool with_clauses, const std::vector<std::size_t>* weights = nullptr)
      : ts_(ts), count_(samples.size()), supports_(supports), with_clauses_(with_clauses), weights_(weights) {
    // Each variable's values over the samples in one array: every template
    // below reads a few variables across all the samples.
    slot_.assign(ts.statevars().size(), SIZE_MAX);
    columns_.resize(cone.size());
    for (std::size_t k = 0; k < cone.size(); ++k) {
      slot_[cone[k]] = k;
      const std::size_t col = weights ? k : cone[k];
      columns_[k].reserve(samples.size());
      for (const auto& sample : samples) columns_[k].push_back(sample[col].i);
    }
    for (std::size_t i : cone) {
      const auto& v = ts.statevars()[i];
      const bool program = v.name.rfind(kProgramPrefix, 0) == 0;
      if (v.var.is_int()) (program ? program_ints_ : matrix_ints_).push_back(i);
      else if (v.var.is_bool()) bools_.push_back(i);
    }
    // The pairs worth a relation, found once, not once per guard: a big
    // cone's flags are hundreds (a 128 x 128 matrix's widest cone, 709 state
    // variables), its related pairs a few per flag.
    for (std::size_t x : program_ints_)
      for (std::size_t y : matrix_ints_)
        if (!supports_ || supports_->related(x, y, true)) int_pairs_.push_back({x, y});
    for (std::size_t p : bools_)
      for (std::size_t q : bools_)
        if (program(p) && !program(q) && (!supports_ || supports_->related(p, q, true))) bool_pairs_.push_back({p, q});
    equal_everywhere_.assign(2 * bool_pairs_.size(), 0);
    // Where each pair is equal, and later each guard holds, as bits over the
    // samples: an equality under a guard is then a few words compared, not a
    // pass over up to 4,096 sampled states per pair and guard.
    words_ = (count_ + 63) / 64;
    equal_at_.assign(bool_pairs_.size() * words_, 0);
    for (std::size_t i = 0; i < bool_pairs_.size(); ++i) {
      const std::int64_t* p = column(bool_pairs_[i].first);
      const std::int64_t* q = column(bool_pairs_[i].second);
      for (std::size_t k = 0; k < count_; ++k)
        if (p[k] == q[k]) equal_at_[i * words_ + k / 64] |= std::uint64_t{1} << (k % 64);
    }
    guards_.push_back({SIZE_MAX, 1});
    for (std::size_t b : bools_)
      for (int pol = 1; pol >= 0; --pol)
        if (std::find(column(b), column(b) + count_, pol) != column(b) + count_)
          guards_.push_back({b, pol});
    for (const auto* side : {&program_ints_, &matrix_ints_})
      for (std::size_t v : *side) {
        const std::int64_t* c = column(v);
        if (std::all_of(c, c + count_, [&](std::int64_t x) { return x == c[0]; })) global_.push_back(v);
      }
    std::sort(global_.begin(), global_.end());
    total_weight_ = weights ? std::accumulate(weights->begin(), weights->end(), std::size_t{0}) : count_;
  }

  std::vector<z3::expr> make() {
    std::vector<std::uint32_t> rows;  // the samples where the guard holds
    for (const auto& g : guards_) {
      rows.clear();
      for (std::size_t k = 0; k < count_; ++k)
        if (holds(g, k)) rows.push_back(static_cast<std::uint32_t>(k));
      linear(g, rows);
      constants(g, rows);
      equalities(g, rows);
    }
    block_clauses();
    return std::move(out_);
  }

 private:
  struct Guard {
    std::size_t var;  // SIZE_MAX: none
    int pol;
  };
  bool worth(const Guard& g, std::size_t x, std::size_t y) const {
    if (!supports_) return true;
    if (y != SIZE_MAX && !supports_->related(x, y, true)) return false;
    return g.var == SIZE_MAX || supports_->may_guard(g.var, x, y);
  }
  const std::int64_t* column(std::size_t v) const { return columns_[slot_[v]].data(); }
  bool constant_on(std::size_t v, const std::vector<std::uint32_t>& rows) const {
    const std::int64_t* c = column(v);
    return std::all_of(rows.begin(), rows.end(), [&](std::uint32_t k) { return c[k] == c[rows.front()]; });
  }
  bool program(std::size_t v) const { return ts_.statevars()[v].name.rfind(kProgramPrefix, 0) == 0; }
  bool holds(const Guard& g, std::size_t k) const { return g.var == SIZE_MAX || column(g.var)[k] == g.pol; }
  z3::expr var(std::size_t v) const { return ts_.statevars()[v].var; }
  z3::expr num(std::int64_t c) const { return ts_.ctx().int_val(c); }
  void add(const Guard& g, const z3::expr& e) {
    if (g.var == SIZE_MAX) out_.push_back(e);
    else out_.push_back(z3::implies(g.pol ? var(g.var) : !var(g.var), e));
  }

  // x = a * y + b, x the program's, y the matrix's: a timer's elapsed time
  // and the matrix's delay counter (a = the scan time), a count and a count.
  // The line through the first sample and the first whose y differs from
  // it, if it passes through every sample under the guard.
  void linear(const Guard& g, const std::vector<std::uint32_t>& rows) {
    if (rows.empty()) return;
    for (const auto& [x, y] : int_pairs_) {
      if (g.var != SIZE_MAX && unguarded_.count({x, y})) continue;  // holds without the guard
      if (!worth(g, x, y)) continue;
      const std::int64_t* X = column(x);
      const std::int64_t* Y = column(y);
      const std::uint32_t first = rows.front();
      std::optional<std::int64_t> a, b;
      bool fits = true;
      for (std::uint32_t k : rows)
        if (Y[k] != Y[first]) {
          const std::int64_t dx = X[k] - X[first], dy = Y[k] - Y[first];
          if (dx == 0 || dx % dy != 0) fits = false;
          a = dx / dy;
          b = X[first] - *a * Y[first];
          break;
        }
      if (!fits || !a) continue;
      for (std::uint32_t k : rows)
        if (X[k] != *a * Y[k] + *b) {
          fits = false;
          break;
        }
      if (!fits) continue;
      add(g, var(x) == num(*a) * var(y) + num(*b));
      if (g.var == SIZE_MAX) unguarded_.insert({x, y});
    }
  }

  // p = q or p = not q, p the program's flag, q the matrix's, everywhere
  // (a latch and the effect's latch: stated here, not left to the checker's
  // clauses over pairs, which the first round of Houdini goes without) or
  // under a guard: an edge memory that starts TRUE ("no edge in the first
  // scan") is the matrix's previous value after the first scan. Only guards
  // that hold in a quarter of the sampled states at least: under a rarer one
  // many flags agree by chance, and each such candidate costs Houdini (on a
  // generated 4 x 4 program's widest output, 3,400 candidates and 7 s
  // against 700 and 2.6 s). Nor where both flags are constant under the
  // guard when the checker's clauses over pairs of Booleans come with the
  // templates: the samples show two constants there, which those clauses
  // state, not two flags that move together. An override's flags of the
  // causes active at its start are all FALSE while it has not started, so
  // every program flag would be "equal" to every matrix flag under every
  // other flag: n^3 candidates per effect, nearly all dropped (the
  // generated 128 x 128 x 1024 program: 103,710 candidates asked instead of
  // 121,989, the same proof in 9% less time). Without those clauses (an
  // output's first, cheaper round) the equality is all that says it: the
  // tank example's hand-written program needs it there.
  void equalities(const Guard& g, const std::vector<std::uint32_t>& rows) {
    std::size_t n = 0;
    for (std::uint32_t k : rows) n += weights_ ? (*weights_)[k] : 1;
    if (4 * n < total_weight_) return;
    std::vector<std::uint64_t> where(words_, 0);
    for (std::uint32_t k : rows) where[k / 64] |= std::uint64_t{1} << (k % 64);
    for (std::size_t i = 0; i < bool_pairs_.size(); ++i) {
      const std::size_t p = bool_pairs_[i].first, q = bool_pairs_[i].second;
      if (p == g.var || q == g.var || !worth(g, p, q)) continue;
      for (int same = 1; same >= 0; --same) {
        // Not where it holds without the guard: one candidate, not one per
        // guard (the guard-free pass comes first and records where it holds).
        char& everywhere = equal_everywhere_[2 * i + static_cast<std::size_t>(same)];
        if (g.var != SIZE_MAX && everywhere) continue;
        const std::uint64_t* eq = equal_at_.data() + i * words_;
        bool equal = true;
        for (std::size_t w = 0; w < words_ && equal; ++w) equal = (where[w] & (same ? ~eq[w] : eq[w])) == 0;
        if (!equal) continue;
        if (with_clauses_ && g.var != SIZE_MAX && constant_on(p, rows) && constant_on(q, rows)) continue;
        if (g.var == SIZE_MAX) everywhere = 1;
        add(g, same ? var(p) == var(q) : var(p) == !var(q));
      }
    }
  }

  // v = c wherever the guard holds (and not everywhere: the checker's
  // miner states those).
  void constants(const Guard& g, const std::vector<std::uint32_t>& rows) {
    if (g.var == SIZE_MAX || rows.empty()) return;
    for (const auto* side : {&program_ints_, &matrix_ints_})
      for (std::size_t v : *side) {
        if (!worth(g, v, SIZE_MAX) || std::binary_search(global_.begin(), global_.end(), v)) continue;
        if (constant_on(v, rows)) add(g, var(v) == num(column(v)[rows.front()]));
      }
  }

  // Clauses of three literals over the flags of one block instance of the
  // program ("plc.DLY.#RUN", "plc.DLY.#DONE", "plc.DLY.#PREV", "plc.DLY.Q"):
  // a timer's reachable states are a few of the eight its flags allow.
  void block_clauses() {
    std::map<std::string, std::vector<std::size_t>> blocks;
    for (std::size_t b : bools_) {
      const std::string& n = ts_.statevars()[b].name;
      const auto dot = n.rfind('.');
      if (n.rfind(kProgramPrefix, 0) == 0 && dot != std::string::npos && dot > std::string(kProgramPrefix).size())
        blocks[n.substr(0, dot)].push_back(b);
    }
    for (const auto& [name, flags] : blocks) {
      if (flags.size() < 3 || flags.size() > 8) continue;
      for (std::size_t i = 0; i < flags.size(); ++i)
        for (std::size_t j = i + 1; j < flags.size(); ++j)
          for (std::size_t l = j + 1; l < flags.size(); ++l)
            for (int pols = 0; pols < 8; ++pols) {
              const std::size_t v[3] = {flags[i], flags[j], flags[l]};
              const int pol[3] = {pols & 1, (pols >> 1) & 1, (pols >> 2) & 1};
              const std::int64_t* c[3] = {column(v[0]), column(v[1]), column(v[2])};
              bool always = true;
              for (std::size_t k = 0; k < count_ && always; ++k)
                always = c[0][k] == pol[0] || c[1][k] == pol[1] || c[2][k] == pol[2];
              if (!always) continue;
              z3::expr_vector lits(ts_.ctx());
              for (int t = 0; t < 3; ++t) lits.push_back(pol[t] ? var(v[t]) : !var(v[t]));
              out_.push_back(z3::mk_or(lits));
            }
    }
  }

  const encoder::TransitionSystem& ts_;
  std::size_t count_;         // of the samples
  std::size_t total_weight_;  // the distinct states of the product they stand for
  const Supports* supports_;
  bool with_clauses_;  // the checker's clauses over pairs of Booleans are asked beside these
  const std::vector<std::size_t>* weights_;
  std::vector<std::size_t> slot_;                   // by state variable: its column (SIZE_MAX: not in the cone)
  std::vector<std::vector<std::int64_t>> columns_;  // by cone variable: its value in each sample
  std::vector<std::size_t> global_;                 // the integers of one value in every sample, ascending
  std::vector<std::size_t> program_ints_, matrix_ints_, bools_;
  std::vector<std::pair<std::size_t, std::size_t>> int_pairs_;   // (program's, matrix's), worth a relation
  std::vector<std::pair<std::size_t, std::size_t>> bool_pairs_;  // (program's, matrix's), worth a relation
  std::vector<char> equal_everywhere_;  // by bool pair and polarity: equal without a guard
  std::size_t words_ = 0;               // of a set of samples
  std::vector<std::uint64_t> equal_at_;  // by bool pair: the samples where its flags are equal
  std::vector<Guard> guards_;
  std::set<std::pair<std::size_t, std::size_t>> unguarded_;  // (x, y) related without a guard
  std::vector<z3::expr> out_;
};

ProverResult unknown(ProverResult r, UnknownReason why) {
  r.verdict = Verdict::Unknown;
  r.reason = why;
  r.invariant = {};
  return r;
}

// From this many clauses an invariant's outputs are asked one by one
// (each_follows): the generated 128 x 128 x 1024 program's 120,000 kept
// clauses and 234 outputs took 322 s as one query.
constexpr std::size_t kOutputByOutput = 1024;

// Whether each conjunct of `good` follows in the same scan from the clauses
// of `S` and the facts over the state variables it reads (a premise cut
// only weakens what is assumed, so unsat there is unsat under the whole of
// S). False when one does not: the whole query decides then.
bool each_follows(const checker::SafetyProblem& p, const std::vector<z3::expr>& S, const checker::Limits& limits,
                  checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  encoder::Unroller u(ts);
  TermReads reads(ts);
  std::vector<std::pair<z3::expr, std::vector<std::size_t>>> premises;
  for (const auto& c : S) premises.push_back({c, reads.of(c)});
  for (const auto& f : conjuncts_of(ts.constraint_formula() && p.assumption)) premises.push_back({f, reads.of(f)});
  const std::vector<z3::expr> goods = conjuncts_of(p.good);
  std::vector<char> in(ts.statevars().size());
  z3::solver s = checker::linear_integer_solver(ts.ctx());
  for (const auto& g : goods) {
    std::fill(in.begin(), in.end(), 0);
    for (std::size_t v : reads.of(g)) in[v] = 1;
    z3::expr_vector cut(ts.ctx());
    for (const auto& [f, vars] : premises)
      if (std::all_of(vars.begin(), vars.end(), [&](std::size_t v) { return in[v] != 0; })) cut.push_back(f);
    s.push();
    s.add(u.at(z3::mk_and(cut) && !g, 0));
    const z3::check_result r = checker::check_within(s, meter);
    if (r == z3::unknown) throw checker::Stopped{checker::unknown_reason(s.reason_unknown(), limits, meter)};
    s.pop();
    if (r != z3::unsat) return false;
  }
  return true;
}

// `good` from the invariant S: in the same scan (k = 0), or in the first scan
// and after any scan that kept it (k = 1). nullopt when neither.
std::optional<int> good_from(const checker::SafetyProblem& p, const std::vector<z3::expr>& invariant,
                             const checker::Limits& limits, checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  if (invariant.size() >= kOutputByOutput && each_follows(p, invariant, limits, meter)) return 0;
  encoder::Unroller u(ts);
  z3::expr_vector all(ts.ctx());
  for (const auto& c : invariant) all.push_back(c);
  const z3::expr S = z3::mk_and(all);
  const z3::expr facts = ts.constraint_formula() && p.assumption;
  auto unsat = [&](const z3::expr& f) {
    z3::solver s(ts.ctx());
    s.add(f);
    const z3::check_result r = checker::check_within(s, meter);
    if (r == z3::unknown) throw checker::Stopped{checker::unknown_reason(s.reason_unknown(), limits, meter)};
    return r == z3::unsat;
  };
  if (unsat(u.at(S && facts && !p.good, 0))) return 0;
  if (!unsat(u.at(ts.init_formula() && facts && !p.good, 0))) return std::nullopt;
  if (unsat(u.at(S && facts && p.good && ts.trans_formula(), 0) && u.at(S && facts && !p.good, 1))) return 1;
  return std::nullopt;
}

// The sampled states of the cone of `vars`, if the runs kept them.
const ConeStates* states_of(const Samples& s, const std::vector<std::size_t>& vars) {
  for (const auto& c : s.cones)
    if (c.vars == vars) return c.states.empty() ? nullptr : &c;
  return nullptr;
}

}  // namespace

std::vector<z3::expr> correspondence_candidates(const checker::SafetyProblem& p, const Samples& samples,
                                                const std::vector<std::size_t>& cone, const Supports* supports,
                                                bool with_clauses) {
  if (const ConeStates* c = states_of(samples, cone))
    return Templates(*p.ts, c->states, cone, supports, with_clauses, &c->weights).make();
  if (samples.states.empty()) return {};
  return Templates(*p.ts, samples.states, cone, supports, with_clauses).make();
}

std::vector<std::size_t> every_state_variable(const checker::SafetyProblem& p) {
  std::vector<std::size_t> all(p.ts->statevars().size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  return all;
}

namespace {

checker::MiningOptions mining_options(const SamplingOptions& o, const checker::Limits& limits, bool clauses) {
  checker::MiningOptions mo;
  mo.runs = o.runs;
  mo.cycles_per_run = o.cycles_per_run;
  mo.seed = o.seed;
  mo.limits = &limits;
  mo.bool_implications = clauses;
  return mo;
}

// A group's candidates by layers (cones.hpp, Layer): each layer's templates
// and mined relations over its variables, sampled on them alone, those that
// read its top and nothing beyond its `near` variables (a candidate over
// earlier layers' variables alone is theirs; one that relates an effect's
// state to its causes' several layers below was most of the generated 32 x
// 32 program's candidates and Houdini rounds, and no proof of the smaller
// programs needs it); the encoder's lemmas in the first layer that holds
// what they read. `samples`: which variables change (the layers' states
// are sampled here). nullopt when these runs break an output's relation.
std::optional<std::vector<std::vector<z3::expr>>> layered_candidates(const checker::SafetyProblem& p,
                                                                     const Samples& samples,
                                                                     const std::vector<std::vector<std::size_t>>& cones,
                                                                     const SamplingOptions& o,
                                                                     const checker::Limits& limits,
                                                                     checker::WorkMeter& meter) {
  const auto& ts = *p.ts;
  const std::vector<std::size_t> constants = constant_states(p, samples, limits, meter);
  const Supports supports(ts, constants);
  const std::vector<Layer> layers = layers_of(ts, cones, supports);
  SamplingOptions lo = o;
  for (const auto& l : layers) lo.cones.push_back(l.vars);
  const Samples states = sample(p, lo);
  if (states.violation) return std::nullopt;
  checker::MiningOptions mo = mining_options(o, limits, true);
  // Two integers only when they depend on the same inputs (a program's
  // timer and the matrix's delay counter of one element): a bound or a
  // difference between two elements' counts (an override's scans against
  // a cause's delay, both mostly zero in the runs) holds in the samples by
  // chance, no correspondence needs one, and Houdini spent most of the
  // largest layers' rounds dropping them. Booleans when the inputs of one
  // include the other's: an effect's latch and the causes it reads.
  mo.related = [&](std::size_t x, std::size_t y) {
    const bool ints = ts.statevars()[x].var.is_int() && ts.statevars()[y].var.is_int();
    return supports.related(x, y, ints);
  };
  mo.may_guard = [&](std::size_t g, std::size_t x, std::size_t y) { return supports.may_guard(g, x, y); };
  // Mined from the layers' own samples, the acceptance tests' runs among
  // them: the miner's own runs never trip an effect's causes together nor
  // start its override, so a clause over a flag they leave at rest held in
  // all of them, and Houdini dropped such clauses by the thousand.
  std::vector<const std::vector<Sample>*> layer_states;
  for (const auto& l : layers) {
    const ConeStates* c = states_of(states, l.vars);
    layer_states.push_back(c ? &c->states : nullptr);
  }
  const auto mined = checker::mine_candidates_from(p, mo, lo.cones, layer_states);
  TermReads reads(ts);
  std::vector<std::vector<z3::expr>> out(layers.size());
  for (const auto& l : ts.lemmas()) {
    const auto vars = reads.of(l.term);
    for (std::size_t i = 0; i < layers.size(); ++i)
      if (std::all_of(vars.begin(), vars.end(), [&](std::size_t v) {
            return std::binary_search(layers[i].vars.begin(), layers[i].vars.end(), v);
          })) {
        out[i].push_back(l.term);
        break;
      }
  }
  for (std::size_t i = 0; i < layers.size(); ++i) {
    auto own = [&](const z3::expr& c) {
      const auto vars = reads.of(c);
      return std::any_of(vars.begin(), vars.end(), [&](std::size_t v) {
        return std::binary_search(layers[i].top.begin(), layers[i].top.end(), v);
      }) && std::all_of(vars.begin(), vars.end(), [&](std::size_t v) {
        return std::binary_search(layers[i].near.begin(), layers[i].near.end(), v);
      });
    };
    for (const auto& c : mined[i])
      if (own(c)) out[i].push_back(c);
    for (const auto& c : correspondence_candidates(p, states, layers[i].vars, &supports, true))
      if (own(c)) out[i].push_back(c);
  }
  return out;
}

}  // namespace

Correspondence prove_by_correspondence(const checker::SafetyProblem& p, const Samples& samples,
                                       const checker::Limits& limits, const SamplingOptions& o,
                                       std::vector<std::vector<std::size_t>> cones) {
  // Cones given: a group's, whose candidates must grow with its cones' sizes.
  const bool group = !cones.empty();
  if (cones.empty()) cones.push_back(every_state_variable(p));
  const auto start = checker::Clock::now();
  Correspondence out;
  ProverResult& r = out.result;
  r.method = checker::Method::InvariantsInduction;
  z3::context& ctx = p.ts->ctx();
  // The work read through a solver of the `skip` tactic (the SMT kernel's
  // set-up's meter), which spends none: a reading through a fresh default
  // solver costs about 7 ms, and Houdini arms the meter for each of its
  // thousands of checks (7% of the generated 32 x 32 program's run). The
  // queries here make their own solvers; the set-up changes only what a
  // budget of work buys.
  checker::WorkMeter meter(ctx, limits.work, checker::SolverSetup::SmtKernel);
  try {
    std::optional<int> k;
    if (group) {
      // A group: Houdini one layer at a time over the layers' candidates,
      // with the checker's clauses over pairs of Booleans from the start
      // (they strengthen what is kept; a group rarely proves without them).
      // No candidates: an output differs in a run, and each is decided alone.
      if (const auto candidates = layered_candidates(p, samples, cones, o, limits, meter)) {
        out.invariant = product_houdini_by_layers(p, *candidates, limits, meter);
        checker::Watchdog watchdog(ctx, limits);
        k = good_from(p, out.invariant, limits, meter);
      }
    }
    // One output: two rounds, cheaper first: without the checker's clauses
    // over pairs of Booleans (most of the candidates and of Houdini's
    // rounds), then with them when the output does not follow.
    for (int round = 0; !group && round < 2 && !k; ++round) {
      std::vector<z3::expr> cands;
      std::unordered_set<unsigned> ids;
      auto add = [&](const z3::expr& e) {
        if (ids.insert(e.id()).second) cands.push_back(e);
      };
      for (const auto& l : p.ts->lemmas()) add(l.term);
      const auto mined = checker::mine_candidates_within(p, mining_options(o, limits, round == 1), cones);
      for (const auto& c : mined.front()) add(c);
      for (const auto& c : correspondence_candidates(p, samples, cones.front(), nullptr, round == 1)) add(c);
      std::vector<z3::expr> kept = product_houdini(p, std::move(cands), limits, meter);
      checker::Watchdog watchdog(ctx, limits);
      k = good_from(p, kept, limits, meter);
      out.invariant = std::move(kept);
    }
    r.work = meter.spent();
    r.seconds = checker::seconds_since(start);
    if (!k) {
      r = unknown(r, UnknownReason::BoundReached);
      return out;
    }
    r.verdict = Verdict::Proved;
    r.k = *k;
    for (const auto& c : out.invariant) r.invariant.clauses.push_back(checker::to_smtlib(c));
  } catch (const checker::Stopped& e) {
    r.work = meter.spent();
    r.seconds = checker::seconds_since(start);
    r = unknown(r, e.reason);
  } catch (const z3::exception& e) {
    r.work = meter.spent();
    r.seconds = checker::seconds_since(start);
    r = unknown(r, checker::unknown_reason(e.msg(), limits, meter, &r.detail));
  }
  return out;
}

}  // namespace cemv::plc_check
