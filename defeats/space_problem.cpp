#include "defeats/space_problem.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "checker/engines/invariants.hpp"
#include "checker/engines/solving.hpp"
#include "encoder/encode.hpp"
#include "formats/diagnostics.hpp"
#include "properties/monitor.hpp"
#include "properties/parser.hpp"
#include "response/property.hpp"

namespace cemv::defeats {

namespace {


// The requirement with every action excluded, parsed once: its property's
// assumptions are the exclusions, one per action and in the actions' order
// (response::requirement_property_text states no other).
properties::PropertyFile requirement_file(const model::Matrix& m, const PathDefeats& pd) {
  std::vector<std::string> excluded;
  for (const auto& a : pd.actions) excluded.push_back(a.excluded_term());
  const std::string name = "defeat." + pd.path.key() + ".space";
  const std::string text = response::requirement_property_text(m, pd.path, *pd.requirement, name, excluded);
  properties::PropertyFile f;
  try {
    f = properties::parse_properties(text, m, "cemv-defeats:" + name);
  } catch (const formats::LoadError& e) {
    std::string what;
    for (const auto& i : e.issues()) what += "\n" + i.str();
    throw std::logic_error("cemv defeats wrote a property the parser refuses:" + what + "\n" + text);
  }
  if (f.properties.size() != 1 || !f.assumptions.empty() ||
      f.properties[0].assumptions.size() != pd.actions.size())
    throw std::logic_error("cemv defeats: the requirement's assumptions are not its actions' exclusions");
  return f;
}

z3::expr in_range(const encoder::Encoding& enc, const z3::expr& var) {
  z3::context& ctx = var.ctx();
  const float range = std::numeric_limits<float>::max();
  return z3::expr(ctx, Z3_mk_fpa_geq(ctx, var, enc.ts.float_const(-range))) &&
         z3::expr(ctx, Z3_mk_fpa_leq(ctx, var, enc.ts.float_const(range)));
}

}  // namespace

Builder::Builder(const model::Matrix& m, const PathDefeats& pd) : m_(m), file_(requirement_file(m, pd)) {
  const properties::Property& all = file_.properties[0];
  roots_ = properties::property_roots(all, {}, m);
  free_ = all;
  free_.assumptions.clear();
  for (std::size_t i = 0; i < all.assumptions.size(); ++i) {
    properties::Property x;
    x.name = all.name + ".x" + std::to_string(i + 1);
    x.kind = properties::PropertyKind::Invariant;
    x.body = all.assumptions[i].expr;
    exclusions_.push_back(std::move(x));
  }
}

Built Builder::build(z3::context& ctx, bool none) const {
  std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m_, roots_);
  const properties::Monitor mon = properties::compile_monitor(*enc, free_, {});
  std::vector<z3::expr> keep;
  for (const auto& x : exclusions_) keep.push_back(properties::compile_monitor(*enc, x, {}).good);
  z3::expr assumption = mon.assumption;
  for (const auto& in : enc->ts.inputvars())
    if (in.var.is_fpa()) assumption = assumption && in_range(*enc, in.var);
  if (none)
    for (const auto& k : keep) assumption = assumption && k;
  checker::OwnedProblem original{enc, checker::SafetyProblem{&enc->ts, mon.good, assumption}};
  if (none) return Built{checker::reduce(original), {}};
  checker::OwnedProblem reduced = checker::reduce_with(original, keep);
  return Built{std::move(reduced), std::move(keep)};
}

properties::Property Builder::property(const std::vector<int>& allowed) const {
  properties::Property p = file_.properties[0];
  p.assumptions.clear();
  for (std::size_t i = 0; i < file_.properties[0].assumptions.size(); ++i)
    if (!std::binary_search(allowed.begin(), allowed.end(), static_cast<int>(i)))
      p.assumptions.push_back(file_.properties[0].assumptions[i]);
  return p;
}

// The relations that hold while no action occurs (a monitor's counter and
// the on-delay it waits for): mined on the problem with every action
// excluded, which the checker reduces to a system whose commands are
// constants, and read back over this system's variables; a candidate over a
// variable that reduction removed, or gave another sort, is left out.
std::vector<z3::expr> mined_without_actions(const Builder& b, const encoder::TransitionSystem& ts) {
  std::vector<std::string> texts;
  {
    z3::context ctx;
    const Built none = b.build(ctx, true);
    checker::MiningOptions mining;
    mining.bool_implications = true;
    for (const auto& c : checker::mine_candidates(none.problem.problem, mining)) texts.push_back(checker::to_smtlib(c));
  }
  return checker::from_smtlib_readable(ts, texts);
}

}  // namespace cemv::defeats
