#include "checker/property_problem.hpp"

#include <limits>
#include <memory>

#include "properties/monitor.hpp"

namespace cemv::checker {

ProblemFactory property_problem(const model::Matrix& m, const properties::PropertyFile& file,
                                const properties::Property& p, const ProblemOptions& options) {
  std::vector<model::Node> roots = options.sliced ? properties::property_roots(p, file.assumptions, m)
                                                  : std::vector<model::Node>{};
  const properties::Property* property = &p;
  const properties::PropertyFile* f = &file;
  const Goal goal = options.goal;
  auto modify = options.modify_encoding;
  return [m, roots, property, f, goal, modify](z3::context& ctx) {
    std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m, roots);
    if (modify) modify(*enc);
    properties::Monitor mon = properties::compile_monitor(*enc, *property, f->assumptions);
    // Analog inputs range over the finite single-precision values: what a
    // scenario can write (docs/scenario.md), so every trace the checker finds
    // can be replayed and handed over as a file. The encoder already excludes
    // NaN; the infinities go here, as comparisons with the largest float,
    // which every consumer of the encoding's terms already interprets.
    z3::expr assumption = mon.assumption;
    const z3::expr max = enc->ts.float_const(std::numeric_limits<float>::max());
    const z3::expr min = enc->ts.float_const(-std::numeric_limits<float>::max());
    for (const auto& in : enc->ts.inputvars())
      if (in.var.is_fpa())
        assumption = assumption && z3::expr(ctx, Z3_mk_fpa_geq(ctx, in.var, min)) &&
                     z3::expr(ctx, Z3_mk_fpa_leq(ctx, in.var, max));
    z3::expr good = mon.good;
    if (goal == Goal::Antecedent) good = mon.antecedent ? !*mon.antecedent : ctx.bool_val(true);
    if (goal == Goal::Assumptions) good = ctx.bool_val(false);
    return OwnedProblem{enc, SafetyProblem{&enc->ts, good, assumption}};
  };
}

}  // namespace cemv::checker
