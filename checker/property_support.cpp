// The support of a proof (docs/checker.md, "Support"), PropertyChecker's
// third step. `core`: the proof's obligations asked again on the property's
// encoding with each removable cell guarded by an activation literal
// (encoder::EncodeOptions::guard_cells), every literal assumed; the cells of
// the unsat cores, with every candidate no literal guards, are the support.
// It is re-checked before it is reported: the same proof re-proved in a
// fresh context on the matrix without the other cells, else the property
// proved there by the engines and re-checked; when neither holds, the
// support is the whole set of candidates (nothing removed: the proof itself).
// `full`: that core minimised by deletion, one re-proof per cell of the core.
#include <set>

#include "checker/check/recheck.hpp"
#include "checker/context_pool.hpp"
#include "checker/engines/portfolio.hpp"
#include "checker/engines/solving.hpp"
#include "checker/property_checker.hpp"
#include "checker/reduce.hpp"
#include "encoder/encode.hpp"
#include "model/validate.hpp"

namespace cemv::checker {

namespace {

using properties::Expr;

// The input tags a property reads are resolved to positions in the matrix's
// input table (properties/ast.hpp). A support trial deletes elements, and a
// deleted bypass, inhibit or reset tag leaves the table, moving the positions
// after it: rewrite them for the trial matrix. False when a tag the property
// reads is gone (the element cannot be deleted without changing the property).
bool remap_inputs(Expr& e, const model::InputTable& from, const model::InputTable& to) {
  if (e.kind == Expr::Kind::InputValue || e.kind == Expr::Kind::InputBad) {
    auto index = to.find(from.tags()[e.input].name);
    if (!index) return false;
    e.input = *index;
  }
  for (auto& a : e.args)
    if (!remap_inputs(a, from, to)) return false;
  return true;
}

bool remap_inputs(properties::PropertyFile& f, properties::Property& p, const model::InputTable& from,
                  const model::InputTable& to) {
  bool ok = remap_inputs(p.body, from, to) && remap_inputs(p.trigger, from, to) && remap_inputs(p.response, from, to);
  for (auto& a : p.assumptions) ok = ok && remap_inputs(a.expr, from, to);
  for (auto& a : f.assumptions) ok = ok && remap_inputs(a.expr, from, to);
  return ok;
}


// Every candidate, as the support that claims nothing smaller than the cone.
std::vector<SupportElement> all_of(const std::vector<Deletion>& candidates) {
  std::vector<SupportElement> out;
  for (const auto& d : candidates) out.push_back(d.element);
  return out;
}

}  // namespace

std::optional<ProverResult> PropertyChecker::prove_on(const model::Matrix& trial, bool checked,
                                                      const Limits& limits) const {
  struct Trial {
    properties::PropertyFile file;
    properties::Property property;
  };
  auto t = std::make_shared<Trial>(Trial{file_, p_});
  if (!remap_inputs(t->file, t->property, model::InputTable(m_), model::InputTable(trial))) return std::nullopt;
  ProblemOptions o;
  o.modify_encoding = options_.modify_encoding;
  PortfolioOptions po;
  po.preferred = preferred_;
  po.quick_work = options_.budgets.quick;
  po.engine_work = options_.budgets.support;
  // A trial only steers the search: its answer is not reported, so it skips
  // the re-check and the readable counterexample; the support found is
  // proved once more, checked.
  po.recheck = checked;
  po.shrink_work = 0;
  ProblemFactory make = property_problem(trial, t->file, t->property, o);
  return Portfolio([make, t](z3::context& ctx) { return make(ctx); }, po).run(limits);
}

std::optional<SupportCore> PropertyChecker::own_core(const std::vector<Deletion>& candidates,
                                                    const Limits& limits) const {
  SupportCore out;  // the core's terms die with their context: only its keys leave
  std::set<std::string>& guarded = out.guarded;
  {
    ProblemOptions o;
    o.guard_cells = true;
    o.modify_encoding = options_.modify_encoding;
    PooledContext ctx;
    OwnedProblem original = property_problem(m_, file_, p_, o)(ctx);
    const auto& enc = *std::static_pointer_cast<encoder::Encoding>(original.owner);
    std::set<std::string> keys;
    for (const auto& d : candidates) keys.insert(d.element.key);
    // The literals of the candidates are asked about; any other guard (a
    // cell of an element that only feeds the property's roots) stays TRUE.
    std::vector<z3::expr> literals, fixed;
    for (const auto& [key, literal] : enc.guards) {
      if (keys.count(key)) {
        literals.push_back(literal);
        guarded.insert(key);
      } else {
        fixed.push_back(literal);
      }
    }
    // The proof was found on a reduced problem: its invariant names that
    // problem's variables. A cone group's proof may name variables of the
    // other members' goods, which this member's reduction drops: then the
    // unreduced problem, which has them all.
    OwnedProblem problem = reduce(original);
    std::optional<std::vector<z3::expr>> core = check::proof_core(problem.problem, *proof_, literals, fixed, options_.budgets.support, limits);
    if (!core) core = check::proof_core(original.problem, *proof_, literals, fixed, options_.budgets.support, limits);
    if (!core) return std::nullopt;
    for (const auto& l : *core) out.used.insert(l.decl().name().str().substr(std::string("guard.").size()));
  }
  return out;
}

std::vector<SupportElement> PropertyChecker::core_support(const std::vector<Deletion>& candidates,
                                                          const std::optional<SupportCore>& given,
                                                          model::Matrix& reduced, const Limits& limits) const {
  reduced = m_;
  std::optional<SupportCore> core = given ? given : own_core(candidates, limits);
  if (!core) return all_of(candidates);
  std::vector<SupportElement> support;
  for (const auto& d : candidates) {
    if (!core->guarded.count(d.element.key) || core->used.count(d.element.key)) support.push_back(d.element);
    else d.apply(reduced);
  }
  if (support.size() == candidates.size()) return support;  // nothing removed: the proof itself
  if (!model::has_errors(model::validate(reduced))) {
    // The re-check: the proof itself on the matrix without the other cells,
    // in a fresh context; else the engines there, their answer re-checked.
    ProblemOptions o;
    o.modify_encoding = options_.modify_encoding;
    auto t = std::make_shared<std::pair<properties::PropertyFile, properties::Property>>(file_, p_);
    if (remap_inputs(t->first, t->second, model::InputTable(m_), model::InputTable(reduced))) {
      const ProblemFactory make = reducing(property_problem(reduced, t->first, t->second, o));
      try {
        check::recheck_proof([make, t](z3::context& ctx) { return make(ctx); }, *proof_, &limits);
        return support;
      } catch (const InternalError&) {
        // The proof's invariant names what the smaller matrix no longer has,
        // or does not carry over: the engines decide.
      }
      std::optional<ProverResult> r = prove_on(reduced, true, limits);
      stop_if_interrupted(limits);
      if (r && r->verdict == Verdict::Proved) return support;
    }
  }
  reduced = m_;
  return all_of(candidates);
}

std::vector<Deletion> PropertyChecker::support_candidates() const { return candidate_deletions(m_, roots_); }

void PropertyChecker::find_support(PropertyResult& out, const Limits& limits,
                                   const std::optional<SupportCore>& group_core) const {
  if (!needs_support(out)) return;
  const auto start = Clock::now();
  const std::vector<Deletion> candidates = support_candidates();
  model::Matrix reduced;
  out.support = core_support(candidates, group_core, reduced, limits);
  out.support_minimal = false;
  out.seconds += seconds_since(start);
  if (options_.support_mode != SupportMode::Full) return;
  // Deletion on the core only: each of its cells deleted in turn from the
  // matrix the core was checked on, kept when the proof then fails.
  std::vector<Deletion> core;
  for (const auto& d : candidates)
    for (const auto& s : out.support)
      if (s.key == d.element.key) core.push_back(d);
  auto reprove = [&](const model::Matrix& trial) {
    if (limits.interrupted()) return ReproveOutcome::Undecided;
    std::optional<ProverResult> r = prove_on(trial, false, limits);
    if (!r || r->verdict == Verdict::Falsified) return ReproveOutcome::NotProved;
    return r->verdict == Verdict::Proved ? ReproveOutcome::Proved : ReproveOutcome::Undecided;
  };
  bool minimal = true;
  model::Matrix smaller = reduced;
  std::vector<SupportElement> kept = minimal_support(reduced, core, reprove, minimal, &smaller);
  out.seconds += seconds_since(start);
  if (kept.size() == out.support.size()) {
    out.support_minimal = minimal;
    return;
  }
  std::optional<ProverResult> r = prove_on(smaller, true, limits);
  stop_if_interrupted(limits);
  if (r && r->verdict == Verdict::Falsified)
    throw InternalError("the support of property " + p_.name + " does not carry its proof: a trial was proved, " +
                        "its re-proof is falsified");
  if (!r || r->verdict != Verdict::Proved) return;  // undecided within the limits: the checked core stands
  out.support = std::move(kept);
  out.support_minimal = minimal;
}

}  // namespace cemv::checker
