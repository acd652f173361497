#include "checker/equivalence.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "checker/check/recheck.hpp"
#include "checker/engines/bmc.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/engines/relational.hpp"
#include "checker/random_runs.hpp"
#include "checker/replay.hpp"
#include "checker/shrink.hpp"
#include "encoder/product.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"
#include "runtime/runtime.hpp"

namespace cemv::checker {

namespace {

using Clock = std::chrono::steady_clock;
using model::Node;

bool has_node(const model::Matrix& m, const Node& n) {
  return n.kind == Node::Kind::Cause ? m.find_cause(n.id) != nullptr : m.find_effect(n.id) != nullptr;
}

// The roots to encode in `m` for a group: its own nodes that `m` has, and
// every node with mutually locked maintenance in either matrix. A slice does
// not see a lock held outside its cone (docs/encoding.md, "Cone of
// influence"); a product of two slices would then miss a difference that
// lies only in who holds a lock. With every locked node inside, the slice of
// an effect is exact for the effect's observables (first out, the other
// over-approximation, is a cause observable).
std::vector<Node> roots_in(const model::Matrix& m, const model::Matrix& other, const std::vector<Node>& group) {
  if (group.empty()) return {};
  std::set<Node> out;
  for (const auto& n : group)
    if (has_node(m, n)) out.insert(n);
  for (const auto* mm : {&m, &other}) {
    for (const auto& c : mm->causes)
      if (c.mutually_locked_maintenance) out.insert({Node::Kind::Cause, c.id});
    for (const auto& e : mm->effects)
      if (e.mutually_locked_maintenance) out.insert({Node::Kind::Effect, e.id});
  }
  std::vector<Node> v;
  for (const auto& n : out)
    if (has_node(m, n) && (n.kind == Node::Kind::Cause ? m.find_cause(n.id)->function != model::CauseFunction::Comment
                                                       : m.find_effect(n.id)->function != model::EffectFunction::Comment))
      v.push_back(n);
  return v;
}

// The part of `m` an encoding of `roots` reads (every node of their cone,
// docs/encoding.md "Cone of influence", and the matrix-level settings); with
// `texts_aside`, every text that no semantics reads is set aside too (names,
// descriptions, notes, SIF, SIL, units): two matrices with equal such
// restrictions have equal encodings term for term. Without, the restriction
// is a matrix the reference runtime runs as the slice the product encodes.
model::Matrix cone_matrix(const model::Matrix& m, const std::vector<Node>& roots, bool texts_aside) {
  model::Matrix r;
  if (!texts_aside) r.name = m.name;
  r.cycle_ms = m.cycle_ms;
  r.secure_write = m.secure_write;
  r.group_deactivation = m.group_deactivation;
  std::set<Node> cone;
  for (const auto& n : model::DependencyGraph(m).feeders_of(roots)) cone.insert(n);
  for (auto c : m.causes) {
    if (!cone.count({Node::Kind::Cause, c.id})) continue;
    if (texts_aside) {
      c.name = "c" + std::to_string(c.id);
      c.description.clear();
      c.note.clear();
      c.sif.clear();
      c.sil = 0;
      if (c.analog) c.analog->unit.clear();
    }
    r.causes.push_back(c);
  }
  for (auto e : m.effects) {
    if (!cone.count({Node::Kind::Effect, e.id})) continue;
    if (texts_aside) {
      e.name = "e" + std::to_string(e.id);
      e.description.clear();
      e.note.clear();
      e.sif.clear();
      e.sil = 0;
    }
    r.effects.push_back(e);
  }
  for (auto is : m.intersections) {
    if (!cone.count({Node::Kind::Effect, is.effect}) || !cone.count({Node::Kind::Cause, is.cause})) continue;
    if (texts_aside) is.note.clear();
    r.intersections.push_back(is);
  }
  return r;
}

std::string cone_configuration(const model::Matrix& m, const std::vector<Node>& roots) {
  return formats::to_canonical_json(cone_matrix(m, roots, true));
}

struct KeyInfo {
  std::string key;
  model::FieldType type = model::FieldType::Bool;
  std::size_t index_a = 0, index_b = 0;  // in model::observables of each
};

// The product with `good` = every key of the group equal in both copies;
// inputs restricted to finite floats as in every checker problem (what a
// scenario can write, so every run found can be replayed).
ProblemFactory product_factory(const model::Matrix& a, const model::Matrix& b, const std::vector<Node>& ra,
                               const std::vector<Node>& rb, const std::vector<std::string>& keys) {
  return [a, b, ra, rb, keys](z3::context& ctx) {
    std::shared_ptr<encoder::Product> p = encoder::product(ctx, a, b, ra, rb);
    z3::expr_vector eqs(ctx);
    for (const auto& k : keys) {
      auto ta = p->term_a(k), tb = p->term_b(k);
      if (!ta || !tb) throw std::logic_error("the product does not encode observable " + k);
      eqs.push_back(*ta == *tb);
    }
    z3::expr good = eqs.empty() ? ctx.bool_val(true) : z3::mk_and(eqs);
    z3::expr assumption = ctx.bool_val(true);
    const z3::expr max = p->ts.float_const(std::numeric_limits<float>::max());
    const z3::expr min = p->ts.float_const(-std::numeric_limits<float>::max());
    for (const auto& in : p->ts.inputvars())
      if (in.var.is_fpa())
        assumption = assumption && z3::expr(ctx, Z3_mk_fpa_geq(ctx, in.var, min)) &&
                     z3::expr(ctx, Z3_mk_fpa_leq(ctx, in.var, max));
    return OwnedProblem{p, SafetyProblem{&p->ts, good, assumption}};
  };
}

// Inputs nothing requires otherwise keep the plant at rest of matrix a (the
// scenario defaults), good quality, no command: a readable run.
PreferredValue plant_at_rest(const encoder::Product& p, const model::Matrix& a, const model::Matrix& b) {
  auto preferred = std::make_shared<std::unordered_map<std::string, Value>>();
  auto name = [](const z3::expr& v) { return v.decl().name().str(); };
  auto add = [&](const encoder::Encoding& enc, const model::Matrix& m) {
    const model::CycleInput defaults = model::default_cycle_input(m);
    for (std::size_t i = 0; i < enc.tag_value.size() && i < defaults.tags.size(); ++i) {
      if (enc.tag_value[i] && !preferred->count(name(*enc.tag_value[i]))) {
        Value v;
        if (enc.tag_value[i]->is_fpa()) {
          v.is_float = true;
          v.f = defaults.tags[i].value;
        } else {
          v.i = defaults.tags[i].value != 0.0f ? 1 : 0;
        }
        (*preferred)[name(*enc.tag_value[i])] = v;
      }
      if (enc.tag_bad[i]) (*preferred)[name(*enc.tag_bad[i])] = Value{};
    }
    for (const auto& c : enc.commands) (*preferred)[name(c.var)] = Value{};
  };
  add(*p.a, a);
  add(*p.b, b);
  return [preferred](const std::string& input) -> std::optional<Value> {
    auto it = preferred->find(input);
    if (it == preferred->end()) return std::nullopt;
    return it->second;
  };
}

// The cycle inputs of a product run for one of the two matrices: every tag
// the matrix reads takes the run's value wherever either copy encodes it
// (a tag in one cone only must not fall back to a default on the other
// side: both runtimes see one plant), else the matrix's default; the
// commands of its own encoding in their processing order, then those of the
// other encoding whose target this matrix has.
std::vector<model::CycleInput> product_inputs(const Trace& t, const encoder::Encoding& self,
                                              const encoder::Encoding& other, const model::Matrix& m) {
  std::vector<model::CycleInput> out = cycle_inputs(t, self, m);
  const model::InputTable table(m);
  std::unordered_map<std::string, std::size_t> column;
  for (std::size_t i = 0; i < t.input_names.size(); ++i) column.emplace(t.input_names[i], i);
  auto number = [](const Value& v) { return v.is_float ? v.f : static_cast<float>(v.i); };
  std::vector<std::string> own;
  for (const auto& c : self.commands) own.push_back(c.var.decl().name().str());
  for (std::size_t k = 0; k < out.size(); ++k) {
    for (std::size_t i = 0; i < table.size(); ++i) {
      auto v = column.find("input." + table.tags()[i].name);
      if (v != column.end()) out[k].tags[i].value = number(t.cycles[k].inputs[v->second]);
      auto b = column.find("input." + table.tags()[i].name + ".bad");
      if (b != column.end()) out[k].tags[i].bad_quality = t.cycles[k].inputs[b->second].i != 0;
    }
    for (const auto& ci : other.commands) {
      const std::string name = ci.var.decl().name().str();
      if (std::find(own.begin(), own.end(), name) != own.end()) continue;
      auto c = column.find(name);
      if (c == column.end() || t.cycles[k].inputs[c->second].i == 0) continue;
      if ((ci.cause && !m.find_cause(ci.cause)) || (ci.effect && !m.find_effect(ci.effect))) continue;
      if (!ci.tag_name.empty() && !table.find(ci.tag_name)) continue;
      model::Command cmd;
      cmd.op = ci.op;
      cmd.cause = ci.cause;
      cmd.effect = ci.effect;
      cmd.tag = ci.tag;
      cmd.group = ci.group;
      cmd.on = ci.on;
      cmd.tag_name = ci.tag_name;
      if (ci.value) {
        auto v = column.find(ci.value->decl().name().str());
        if (v != column.end()) cmd.value = number(t.cycles[k].inputs[v->second]);
      }
      out[k].commands.push_back(cmd);
    }
  }
  return out;
}

// How many cycles deep BMC looks for a difference shorter than a random run's
// (Decider::shortest).
constexpr int kShortestCheckDepth = 4;

class Decider {
 public:
  Decider(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& g, const EquivalenceOptions& o)
      : a_(a), b_(b), g_(g), o_(o) {
    deadline_ = std::min(o.deadline, Clock::now() + o.timeout);
  }

  GroupEquivalence run() {
    const auto start = Clock::now();
    GroupEquivalence out;
    out.group = g_.name;
    decide(out);
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return out;
  }

 private:
  void decide(GroupEquivalence& out) {
    if (!interface(out)) return;
    std::vector<Node> group_roots = g_.roots;
    if (group_roots.empty() && o_.identical_cone_shortcut && !narrow_to_changed_nodes(group_roots)) {
      out.verdict = EquivalenceVerdict::Equivalent;
      out.method = "identical cone";
      return;
    }
    const std::vector<Node> ra = roots_in(a_, b_, group_roots), rb = roots_in(b_, a_, group_roots);
    if (o_.identical_cone_shortcut && !ra.empty() && ra == rb &&
        cone_configuration(a_, ra) == cone_configuration(b_, rb)) {
      out.verdict = EquivalenceVerdict::Equivalent;
      out.method = "identical cone";
      return;
    }
    std::vector<std::string> keys;
    for (const auto& k : keys_) keys.push_back(k.key);
    ProverResult r;
    try {
      const ProblemFactory make = product_factory(a_, b_, ra, rb, keys);
      // Random runs first: a difference a run of a few segments shows is
      // found on the runtimes long before a solver has unrolled the analog
      // arithmetic or a long timer. The run found is then held against BMC
      // below its length, at most kShortestCheckDepth cycles deep: BMC's
      // first answer is a shortest difference, so a shorter run is found
      // where there is one that short, and where the bound reaches the run's
      // length the random run is a shortest one too. Deeper than that, the
      // run stays as minimised (random_runs.hpp): unrolling the product
      // deeper costs many times what the runs did (tank-overfill's soft bypass
      // at 3 s: 1 s CPU with the run alone, 29 s with BMC to depth 30, still
      // some 20 s to depth 8 where the cone has analog causes).
      if (const std::optional<int> found = falsify(ra, rb, out)) {
        if (*found > 0) shortest(make, *found, ra, rb, out);
        return;
      }
      {
        // A few cycles of BMC next: a structural change mostly shows within
        // a cycle or two of the right inputs, which a solver finds where the
        // random runs needed several tags set together (the 128 x 128
        // benchmark: a 2oo3 cause whose effect three other causes latch).
        // Its first answer is a shortest difference.
        Limits probe;
        probe.deadline = std::min(deadline_, Clock::now() + o_.timeout / 6);
        probe.max_depth = kShortestCheckDepth - 1;
        {
          z3::context ctx;
          OwnedProblem op = make(ctx);
          r = Bmc().prove(op.problem, probe);
        }
      }
      if (r.verdict != Verdict::Falsified) {
        // The relational engine next: where the two copies are built alike,
        // a.x = b.x is inductive and proves the group in a few solver calls.
        // Its proof is re-checked with the real float semantics in a fresh
        // context (an InternalError if it fails), like every portfolio answer.
        // At most a third of the time: Houdini on a product whose copies do
        // differ weakens the claims one by one to no proof, and BMC in the
        // portfolio needs the rest.
        Limits limits;
        limits.deadline = std::min(deadline_, Clock::now() + o_.timeout / 3);
        {
          z3::context ctx;
          OwnedProblem op = make(ctx);
          r = make_relational_prover()->prove(op.problem, limits);
        }
        if (r.verdict == Verdict::Proved) {
          check::recheck(make, r);
          out.verdict = EquivalenceVerdict::Equivalent;
          out.method = r.method;
          return;
        }
        limits.deadline = deadline_;
        r = Portfolio(make).run(limits);
      }
    } catch (const std::invalid_argument& e) {
      out.verdict = EquivalenceVerdict::Differs;
      out.method = "interface";
      out.reason = e.what();
      out.distinction.reset();
      return;
    }
    out.method = r.method;
    out.k = r.k;
    if (r.verdict == Verdict::Proved) {
      out.verdict = EquivalenceVerdict::Equivalent;
      return;
    }
    if (r.verdict == Verdict::Unknown) {
      out.verdict = EquivalenceVerdict::Unknown;
      out.reason = r.reason;
      return;
    }
    std::string why;
    if (confirm(r.cex, ra, rb, out, why)) return;
    // A slice's run that the runtimes do not reproduce: the whole matrices
    // are exact (docs/encoding.md); their run must replay.
    if (!ra.empty() || !rb.empty()) {
      Limits limits;
      limits.deadline = deadline_;
      r = Portfolio(product_factory(a_, b_, {}, {}, keys)).run(limits);
      out.method = r.method;
      if (r.verdict == Verdict::Falsified && confirm(r.cex, {}, {}, out, why)) return;
      if (r.verdict != Verdict::Falsified)
        throw InternalError("equivalence of " + g_.name + ": a run of the sliced product distinguishes the two "
                            "matrices, the runtimes do not, and the whole product says " + to_string(r.verdict) +
                            "\n" + why);
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
    out.method = "interface";
    if (!only_a.empty()) out.reason = "only in the first matrix: " + only_a;
    if (!only_b.empty()) out.reason += std::string(out.reason.empty() ? "" : "; ") + "only in the second matrix: " + only_b;
    return false;
  }

  // BMC on the product below the random run's cycle `found` (0-based), at
  // most kShortestCheckDepth cycles: a shorter difference replaces the run;
  // an answer cut short by the time limit is said in `reason`.
  void shortest(const ProblemFactory& make, int found, const std::vector<Node>& ra, const std::vector<Node>& rb,
                GroupEquivalence& out) {
    Limits limits;
    limits.deadline = std::min(deadline_, Clock::now() + o_.timeout / 6);
    limits.max_depth = std::min(found - 1, kShortestCheckDepth - 1);
    ProverResult r;
    {
      z3::context ctx;
      OwnedProblem op = make(ctx);
      r = Bmc().prove(op.problem, limits);
    }
    std::string why;
    GroupEquivalence shorter = out;
    if (r.verdict == Verdict::Falsified && confirm(r.cex, ra, rb, shorter, why)) {
      shorter.method = "simulation, bmc";
      out = std::move(shorter);
    } else if (r.verdict != Verdict::Unknown || r.reason != "bound reached") {
      out.reason = "a shorter difference is not ruled out (BMC: " +
                   (r.verdict == Verdict::Unknown ? r.reason : std::string("a run the runtimes do not reproduce")) +
                   ")";
    }
  }

  // Seeded random runs of both reference runtimes side by side, on one plant
  // (every tag both read takes one value) and the same operator: a mutant
  // that differs mostly does so on a run of a few segments, found long before
  // a solver has unrolled the analog arithmetic or a long timer
  // (checker/random_runs.hpp). The inputs vary over both cones, held for the
  // durations of both matrices. The runs are searched on the slices the
  // product encodes (the cones of the group's roots, run by the runtime: a
  // 128 x 128 matrix costs the cycles of its cone only), and what is found
  // is replayed on both whole matrices. Returns the 0-based cycle of the
  // difference (`out` filled); only what the runs cannot separate goes to
  // the provers.
  std::optional<int> falsify(const std::vector<Node>& ra, const std::vector<Node>& rb, GroupEquivalence& out) {
    if (keys_.empty()) return std::nullopt;
    std::vector<std::string> tags;
    std::vector<model::Command> commands;
    {
      z3::context ctx;
      for (const auto& [m, roots] : {std::make_pair(&a_, &ra), std::make_pair(&b_, &rb)}) {
        std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, *m, *roots);
        for (std::size_t i = 0; i < enc->tag_value.size(); ++i)
          if (enc->tag_value[i] || enc->tag_bad[i]) tags.push_back(enc->inputs.tags()[i].name);
        for (const auto& c : enc->commands) commands.push_back(c.command());
      }
    }
    RunSpace space = run_space(a_, &b_, tags, commands);
    if (commands.empty()) space.commands.clear();  // no command reaches the cones
    RandomRuns gen(std::move(space), 0x5eedULL);
    const model::CycleInput start_a = model::default_cycle_input(a_);
    model::CycleInput start_b = model::default_cycle_input(b_);
    {
      const model::InputTable ta(a_), tb(b_);
      for (std::size_t i = 0; i < tb.size(); ++i)
        if (auto j = ta.find(tb.tags()[i].name)) start_b.tags[i] = start_a.tags[*j];
    }
    // The slices, started from the whole matrices' values (a tag's value at
    // rest depends on every cause that reads it, in the cone or not).
    const model::Matrix sa = ra.empty() ? a_ : cone_matrix(a_, ra, false);
    const model::Matrix sb = rb.empty() ? b_ : cone_matrix(b_, rb, false);
    auto start_of = [](const model::Matrix& slice, const model::Matrix& whole, const model::CycleInput& start) {
      model::CycleInput s = model::default_cycle_input(slice);
      const model::InputTable ts(slice), tw(whole);
      for (std::size_t i = 0; i < ts.size(); ++i)
        if (auto j = tw.find(ts.tags()[i].name)) s.tags[i] = start.tags[*j];
      return s;
    };
    const model::CycleInput slice_start_a = start_of(sa, a_, start_a), slice_start_b = start_of(sb, b_, start_b);
    std::vector<std::pair<std::size_t, std::size_t>> slice_index;  // per key, in observables(sa), (sb)
    {
      const auto oa = model::observables(sa), ob = model::observables(sb);
      auto at = [](const std::vector<model::Observable>& obs, const std::string& key) -> std::optional<std::size_t> {
        for (std::size_t i = 0; i < obs.size(); ++i)
          if (obs[i].key == key) return i;
        return std::nullopt;
      };
      for (const auto& k : keys_) {
        auto x = at(oa, k.key), y = at(ob, k.key);
        if (!x || !y) return std::nullopt;  // not in a slice: the provers decide
        slice_index.emplace_back(*x, *y);
      }
    }
    auto differs = [&](const Run& run) -> long {
      const auto in_a = expand(sa, run, slice_start_a), in_b = expand(sb, run, slice_start_b);
      runtime::Runtime x(sa), y(sb);
      std::vector<int> oa, ob;
      for (std::size_t c = 0; c < in_a.size(); ++c) {
        x.step(in_a[c]);
        y.step(in_b[c]);
        x.snapshot(oa);
        y.snapshot(ob);
        for (const auto& [i, j] : slice_index)
          if (oa[i] != ob[j]) return static_cast<long>(c);
      }
      return -1;
    };
    constexpr int kRuns = 300;
    constexpr std::size_t kSegments = 10;
    // At most a third of the group's time: a proof still gets the rest.
    const Clock::time_point stop = std::min(deadline_, Clock::now() + o_.timeout / 3);
    for (int r = 0; r < kRuns && Clock::now() < stop; ++r) {
      // Every sixteenth run may hold an input for hours of cycles (a soft
      // bypass timeout of 8 h moved by a second); the others stay short.
      Run run = gen.next(kSegments, r % 16 == 15 ? 400000 : 5000);
      if (differs(run) < 0) continue;
      run = minimise_run(std::move(run), differs);
      const long c = differs(run);
      if (c < 0) continue;
      // The run on the whole matrices: the difference must be there, in the
      // same cycle (the slice is exact for the group's observables,
      // docs/encoding.md); a run that is not is left to the provers.
      ConcreteTrace ta = run_on_runtime(a_, expand(a_, run, start_a));
      ConcreteTrace tb = run_on_runtime(b_, expand(b_, run, start_b));
      const std::size_t cycle = static_cast<std::size_t>(c);
      bool earlier = false;
      for (std::size_t k = 0; k < cycle && !earlier; ++k)
        for (const auto& key : keys_) earlier |= ta.observables[k][key.index_a] != tb.observables[k][key.index_b];
      if (earlier) continue;
      for (const auto& k : keys_) {
        if (ta.observables[cycle][k.index_a] == tb.observables[cycle][k.index_b]) continue;
        out.verdict = EquivalenceVerdict::Differs;
        out.method = "simulation";
        out.distinction = distinction(k, cycle, std::move(ta), std::move(tb));
        return static_cast<int>(cycle);
      }
    }
    return std::nullopt;
  }

  // The distinction of two runtime runs that first differ on key `k` in
  // `cycle`: both cut after it.
  static Distinction distinction(const KeyInfo& k, std::size_t cycle, ConcreteTrace ta, ConcreteTrace tb) {
    Distinction d;
    d.key = k.key;
    d.type = k.type;
    d.cycle = static_cast<int>(cycle);
    d.value_a = ta.observables[cycle][k.index_a];
    d.value_b = tb.observables[cycle][k.index_b];
    ta.inputs.resize(cycle + 1);
    ta.observables.resize(cycle + 1);
    tb.inputs.resize(cycle + 1);
    tb.observables.resize(cycle + 1);
    d.run_a = std::move(ta);
    d.run_b = std::move(tb);
    return d;
  }

  // Replays a product run on both runtimes; true (and `out` filled) when they
  // differ on a key of the group.
  bool confirm(const Trace& cex, const std::vector<Node>& ra, const std::vector<Node>& rb, GroupEquivalence& out,
               std::string& why) {
    std::vector<std::string> keys;
    for (const auto& k : keys_) keys.push_back(k.key);
    z3::context ctx;
    OwnedProblem op = product_factory(a_, b_, ra, rb, keys)(ctx);
    const auto& p = *std::static_pointer_cast<encoder::Product>(op.owner);
    Limits limits;
    limits.deadline = std::min(deadline_, Clock::now() + std::chrono::seconds(10));
    Trace readable = shrink_trace(op.problem, cex, plant_at_rest(p, a_, b_), limits);
    std::vector<model::CycleInput> in_a = product_inputs(readable, *p.a, *p.b, a_);
    std::vector<model::CycleInput> in_b = product_inputs(readable, *p.b, *p.a, b_);
    ConcreteTrace ta = run_on_runtime(a_, in_a), tb = run_on_runtime(b_, in_b);
    for (std::size_t c = 0; c < ta.observables.size(); ++c)
      for (const auto& k : keys_) {
        if (ta.observables[c][k.index_a] == tb.observables[c][k.index_b]) continue;
        out.verdict = EquivalenceVerdict::Differs;
        out.distinction = distinction(k, c, std::move(ta), std::move(tb));
        return true;
      }
    why = "the run of " + std::to_string(readable.length()) + " cycles gives equal values of every observable of " +
          g_.name + " on both runtimes\nfirst matrix, runtime against its encoding:\n" +
          describe_disagreement(a_, ta, run_on_encoding(*p.a, a_, in_a)) +
          "second matrix, runtime against its encoding:\n" + describe_disagreement(b_, tb, run_on_encoding(*p.b, b_, in_b));
    return false;
  }

  const model::Matrix& a_;
  const model::Matrix& b_;
  const ObservableGroup& g_;
  const EquivalenceOptions& o_;
  Clock::time_point deadline_;
  std::vector<KeyInfo> keys_;
};

}  // namespace

GroupEquivalence decide_equivalence(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& group,
                                    const EquivalenceOptions& options) {
  return Decider(a, b, group, options).run();
}

}  // namespace cemv::checker
