// The slices, the product problem and the replay of a product run
// (checker/equivalence_product.hpp).
#include "checker/equivalence_product.hpp"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>
#include <unordered_map>

#include "checker/context_pool.hpp"
#include "checker/replay.hpp"
#include "checker/shrink.hpp"
#include "encoder/product.hpp"
#include "formats/matrix_json.hpp"
#include "model/graph.hpp"

namespace cemv::checker {

using model::Node;

std::vector<std::string> EquivalenceQuestion::key_names() const {
  std::vector<std::string> out;
  for (const auto& k : keys) out.push_back(k.key);
  return out;
}

namespace {

bool has_node(const model::Matrix& m, const Node& n) {
  return n.kind == Node::Kind::Cause ? m.find_cause(n.id) != nullptr : m.find_effect(n.id) != nullptr;
}

}  // namespace

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

ProblemFactory product_factory(const EquivalenceQuestion& q) {
  return product_factory(q.a, q.b, q.ra, q.rb, q.key_names());
}

namespace {

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
      model::Command cmd = ci.command();
      if (ci.value) {
        auto v = column.find(ci.value->decl().name().str());
        if (v != column.end()) cmd.value = number(t.cycles[k].inputs[v->second]);
      }
      out[k].commands.push_back(cmd);
    }
  }
  return out;
}

}  // namespace

// The distinction of two runtime runs that first differ on key `k` in
// `cycle`: both cut after it.
Distinction make_distinction(const KeyInfo& k, std::size_t cycle, ConcreteTrace ta, ConcreteTrace tb) {
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

bool replay_product_run(const EquivalenceQuestion& q, const OwnedProblem& op, const Trace& cex,
                        GroupEquivalence& out, std::string& why) {
  const auto& p = *std::static_pointer_cast<encoder::Product>(op.owner);
  const Trace readable =
      shrink_trace(op.problem, cex, plant_at_rest({{p.a.get(), &q.a}, {p.b.get(), &q.b}}), q.limits.with_work(q.work / 2));
  std::vector<model::CycleInput> in_a = product_inputs(readable, *p.a, *p.b, q.a);
  std::vector<model::CycleInput> in_b = product_inputs(readable, *p.b, *p.a, q.b);
  ConcreteTrace ta = run_on_runtime(q.a, in_a), tb = run_on_runtime(q.b, in_b);
  for (std::size_t c = 0; c < ta.observables.size(); ++c)
    for (const auto& k : q.keys) {
      if (ta.observables[c][k.index_a] == tb.observables[c][k.index_b]) continue;
      out.verdict = EquivalenceVerdict::Differs;
      out.distinction = make_distinction(k, c, std::move(ta), std::move(tb));
      return true;
    }
  why = "the run of " + std::to_string(readable.length()) + " cycles gives equal values of every observable of " +
        q.group + " on both runtimes\nfirst matrix, runtime against its encoding:\n" +
        describe_disagreement(q.a, ta, run_on_encoding(*p.a, q.a, in_a)) +
        "second matrix, runtime against its encoding:\n" +
        describe_disagreement(q.b, tb, run_on_encoding(*p.b, q.b, in_b));
  return false;
}

bool replay_product_run(const EquivalenceQuestion& q, const Trace& cex, GroupEquivalence& out, std::string& why) {
  PooledContext ctx;
  const OwnedProblem op = product_factory(q)(ctx);
  return replay_product_run(q, op, cex, out, why);
}

}  // namespace cemv::checker
