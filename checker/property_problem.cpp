#include "checker/property_problem.hpp"

#include <limits>
#include <memory>

#include "encoder/evaluate.hpp"
#include "properties/monitor.hpp"

namespace cemv::checker {

namespace {

z3::expr in_range(const encoder::Encoding& enc, const z3::expr& var, float range) {
  z3::context& ctx = var.ctx();
  const z3::expr max = enc.ts.float_const(range);
  const z3::expr min = enc.ts.float_const(-range);
  return z3::expr(ctx, Z3_mk_fpa_geq(ctx, var, min)) && z3::expr(ctx, Z3_mk_fpa_leq(ctx, var, max));
}

// One of `values` (an empty list: no restriction).
z3::expr one_of(const encoder::Encoding& enc, const z3::expr& var, const std::vector<float>& values) {
  z3::context& ctx = var.ctx();
  z3::expr any = ctx.bool_val(values.empty());
  for (float v : values) any = any || z3::expr(ctx, Z3_mk_fpa_eq(ctx, var, enc.ts.float_const(v)));
  return any;
}

}  // namespace

void start_after(encoder::Encoding& enc, const std::vector<model::CycleInput>& prefix) {
  encoder::Evaluator ev(enc);
  for (const auto& in : prefix) ev.step(in);
  const auto state = ev.state();
  const auto& vars = enc.ts.statevars();
  z3::context& ctx = enc.ts.ctx();
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const z3::expr& v = vars[i].var;
    z3::expr value = v.is_bool()  ? ctx.bool_val(state[i].i != 0)
                     : v.is_int() ? ctx.int_val(static_cast<int64_t>(state[i].i))
                                  : enc.ts.float_const(state[i].f);
    enc.ts.set_init(v, value);
  }
}


ProblemFactory property_problem(const model::Matrix& m, const properties::PropertyFile& file,
                                const properties::Property& p, const ProblemOptions& options) {
  std::vector<model::Node> roots;
  if (options.sliced) roots = options.roots.empty() ? properties::property_roots(p, file.assumptions, m) : options.roots;
  const properties::Property* property = &p;
  const properties::PropertyFile* f = &file;
  return [m, roots, property, f, options](z3::context& ctx) {
    encoder::EncodeOptions eo;
    eo.guard_cells = options.guard_cells;
    std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m, roots, eo);
    if (options.modify_encoding) options.modify_encoding(*enc);
    properties::Monitor mon = properties::compile_monitor(*enc, *property, f->assumptions);
    // The encoder already excludes NaN; the range goes here, as comparisons
    // with a float constant, which every consumer of the encoding's terms
    // already interprets.
    z3::expr assumption = mon.assumption;
    for (const auto& in : enc->ts.inputvars())
      if (in.var.is_fpa()) assumption = assumption && in_range(*enc, in.var, options.analog_range);
    for (std::size_t i = 0; i < options.analog_values.size() && i < enc->tag_value.size(); ++i)
      if (enc->tag_value[i] && enc->tag_value[i]->is_fpa())
        assumption = assumption && one_of(*enc, *enc->tag_value[i], options.analog_values[i]);
    if (options.prefix && !options.prefix->empty()) start_after(*enc, *options.prefix);
    z3::expr good = mon.good;
    if (options.goal == Goal::Antecedent) good = mon.antecedent ? !*mon.antecedent : ctx.bool_val(true);
    if (options.goal == Goal::Assumptions) good = ctx.bool_val(false);
    return OwnedProblem{enc, SafetyProblem{&enc->ts, good, assumption}};
  };
}

}  // namespace cemv::checker
