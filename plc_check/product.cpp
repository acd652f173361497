// The matrix and the program in one transition system (docs/plc.md "Relations").
#include "plc_check/product.hpp"

#include <algorithm>
#include <stdexcept>

#include "plc_encoder/encode.hpp"

namespace cemv::plc_check {

namespace {

bool same(const std::string& a, const std::string& b) { return model::tag_key(a) == model::tag_key(b); }

bool covers(const formats::PlcCommandBinding& b, const encoder::CommandInput& c) {
  return b.op == c.op && (!b.cause || b.cause == c.cause) && (!b.effect || b.effect == c.effect) &&
         (!b.tag || b.tag == c.tag) && (b.tag_name.empty() || same(b.tag_name, c.tag_name)) && (!b.on || *b.on == c.on);
}

z3::expr constant(z3::context& ctx, plc::Type t, double v) {
  switch (t) {
    case plc::Type::Bool: return ctx.bool_val(v != 0.0);
    case plc::Type::Int:
    case plc::Type::Dint:
    case plc::Type::Time: return ctx.int_val(static_cast<std::int64_t>(v));
    case plc::Type::Real: return ctx.fpa_val(static_cast<float>(v));
  }
  return ctx.bool_val(false);
}

class Binder {
 public:
  Binder(z3::context& ctx, const model::Matrix& m, const ResolvedMap& map, ProductProblem& p)
      : ctx_(ctx), m_(m), map_(map), p_(p), assumption_(ctx.bool_val(true)) {}

  // What program input `in` reads in every scan.
  z3::expr bind(const plc_encoder::InputVar& in) {
    const auto& enc = *p_.matrix;
    for (const auto& b : map_.map.inputs) {
      const auto idx = enc.inputs.find(b.tag);
      if (!idx) continue;
      if (same(b.variable, in.variable)) return tag(*idx, false);
      if (same(b.bad_quality, in.variable)) return tag(*idx, true);
    }
    for (const auto& b : map_.map.commands) {
      if (b.variable.empty() || !same(b.variable, in.variable)) continue;
      model::Command c;
      c.op = b.op;
      c.cause = b.cause;
      c.effect = b.effect;
      c.tag = b.tag;
      c.tag_name = b.tag_name;
      c.on = b.on.value_or(true);
      if (const auto* ci = enc.find_command(c)) return ci->var;
      return extra("cmd.plc." + in.variable, ctx_.bool_sort(), {});
    }
    for (const auto& b : map_.map.program_inputs)
      if (same(b.variable, in.variable))
        return in.type == plc::Type::Real ? p_.matrix->ts.float_const(static_cast<float>(b.value))
                                          : constant(ctx_, in.type, b.value);
    throw std::logic_error("program input " + in.variable + " is not in the completed map");
  }

  // The map's assumptions over the matrix's inputs in every scan.
  z3::expr assumption() {
    const auto& enc = *p_.matrix;
    for (const auto& b : map_.map.inputs) {
      const auto idx = enc.inputs.find(b.tag);
      if (!idx) continue;
      if (b.variable.empty() && b.value) {
        const auto& tag_in = enc.inputs.tags()[*idx];
        const z3::expr v = tag(*idx, false);
        assumption_ = assumption_ && (tag_in.kind == model::TagKind::Analog
                                          ? v == p_.matrix->ts.float_const(static_cast<float>(*b.value))
                                          : v == ctx_.bool_val(*b.value != 0.0));
      }
      if (b.bad_quality.empty() && enc.tag_bad[*idx]) assumption_ = assumption_ && !*enc.tag_bad[*idx];
    }
    for (const auto& ci : enc.commands)
      for (const auto& b : map_.map.commands)
        if (b.variable.empty() && covers(b, ci)) assumption_ = assumption_ && !ci.var;
    return assumption_;
  }

 private:
  z3::expr tag(std::size_t idx, bool bad) {
    auto& enc = *p_.matrix;
    const auto& slot = bad ? enc.tag_bad[idx] : enc.tag_value[idx];
    if (slot) return *slot;
    const auto& t = enc.inputs.tags()[idx];
    const std::string name = "input." + t.name + (bad ? ".bad" : "");
    if (auto v = enc.ts.inputvar(name)) return *v;
    const bool analog = !bad && t.kind == model::TagKind::Analog;
    const z3::expr v = extra(name, analog ? ctx_.fpa_sort<32>() : ctx_.bool_sort(), ProductProblem::Extra{name, idx, bad});
    // As the matrix encoder states of its own analog inputs: a scan reads no NaN.
    if (analog) p_.matrix->ts.add_constraint(name + ".not_nan", !z3::expr(ctx_, Z3_mk_fpa_is_nan(ctx_, v)));
    return v;
  }

  z3::expr extra(const std::string& name, const z3::sort& s, ProductProblem::Extra e) {
    if (auto v = p_.matrix->ts.inputvar(name)) return *v;
    e.name = name;
    p_.extras.push_back(e);
    return p_.matrix->ts.make_inputvar(name, s);
  }

  z3::context& ctx_;
  const model::Matrix& m_;
  const ResolvedMap& map_;
  ProductProblem& p_;
  z3::expr assumption_;
};

}  // namespace

const char* to_string(Relation r) { return r == Relation::Equal ? "equal" : "safe-side"; }

std::shared_ptr<ProductProblem> build_product(z3::context& ctx, const model::Matrix& m, const plc::Program& program,
                                              const plc::Pou& pou, const ResolvedMap& map,
                                              const std::vector<OutputQuestion>& qs, Relation relation) {
  if (qs.empty()) throw std::logic_error("a product without a question");
  auto p = std::shared_ptr<ProductProblem>(
      new ProductProblem{nullptr, {}, {}, ctx.bool_val(false), ctx.bool_val(false), {}, {nullptr, ctx.bool_val(true), ctx.bool_val(true)}});
  std::vector<model::Node> roots;
  for (const auto& q : qs) {
    const model::Node n{model::Node::Kind::Effect, q.effect};
    if (std::none_of(roots.begin(), roots.end(), [&](const model::Node& r) { return r.id == n.id; })) roots.push_back(n);
  }
  p->matrix = encoder::encode(ctx, m, roots);
  auto& ts = p->matrix->ts;
  const plc_encoder::ProgramSystem sys = plc_encoder::encode(ctx, program, pou, map.scan_ms, kProgramPrefix);
  for (float v : sys.real_literals) ts.float_const(v);
  Binder binder(ctx, m, map, *p);
  z3::expr_vector from(ctx), to(ctx);
  for (const auto& in : sys.inputs) {
    from.push_back(in.var);
    to.push_back(binder.bind(in));
    std::optional<double> held;
    for (const auto& b : map.map.program_inputs)
      if (same(b.variable, in.variable)) held = b.value;
    p->program_inputs.push_back({in.variable, in.type, to.back(), held});
  }
  for (const auto& s : sys.states) {
    const z3::expr v = ts.make_statevar(s.name, s.var.get_sort());
    ts.set_init(v, s.init);
    ts.assign_next(v, z3::expr(s.next).substitute(from, to));
  }
  z3::expr_vector goods(ctx);
  for (const auto& q : qs) {
    const std::string key = "effect[" + std::to_string(q.effect) + "].tag[" + std::to_string(q.position) + "]";
    const auto matrix_out = ts.term(key);
    if (!matrix_out) throw std::logic_error("the encoding has no " + key);
    std::optional<z3::expr> program_out;
    for (const auto& o : sys.outputs)
      if (same(o.variable, q.variable)) program_out = z3::expr(o.term).substitute(from, to);
    if (!program_out) throw std::logic_error("the program has no output " + q.variable);
    const std::string name = std::string(kProgramPrefix) + "out." + q.variable;
    if (!ts.term(name)) ts.name_term(name, *program_out);
    if (&q == &qs.front()) {
      p->matrix_output = *matrix_out;
      p->program_output = *program_out;
    }
    const z3::expr safe = ctx.bool_val(q.ett);
    p->goods.push_back(relation == Relation::Equal ? *program_out == *matrix_out
                                                   : z3::implies(*matrix_out == safe, *program_out == safe));
    goods.push_back(p->goods.back());
  }
  p->problem = checker::SafetyProblem{&ts, z3::mk_and(goods), binder.assumption()};
  ts.check_complete();
  return p;
}

checker::ProblemFactory product_factory(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                                        const ResolvedMap& map, std::vector<OutputQuestion> qs, Relation relation) {
  return [&m, &program, &pou, &map, qs = std::move(qs), relation](z3::context& ctx) {
    auto p = build_product(ctx, m, program, pou, map, qs, relation);
    checker::OwnedProblem owned{p, p->problem};
    return owned;
  };
}

}  // namespace cemv::plc_check
