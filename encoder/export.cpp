#include "encoder/export.hpp"

#include <sstream>
#include <stdexcept>

#include "encoder/unroller.hpp"

namespace cemv::encoder {

namespace {

z3::expr goal_term(const Encoding& enc, const ExportGoal& goal) {
  z3::context& c = enc.ts.ctx();
  if (!goal.term) return c.bool_val(true);
  auto t = enc.ts.term(*goal.term);
  if (!t) throw std::invalid_argument("no term named '" + *goal.term + "' in this encoding");
  if (!t->is_bool()) throw std::invalid_argument("'" + *goal.term + "' is not Boolean");
  return *t;
}

std::string benchmark(z3::context& c, const z3::expr& f, const std::string& comment) {
  Z3_set_ast_print_mode(c, Z3_PRINT_SMTLIB2_COMPLIANT);
  std::string body = Z3_benchmark_to_smtlib_string(c, comment.c_str(), "ALL", "unknown", "", 0,
                                                   nullptr, f);
  // Z3 writes (set-logic ALL) first, which cvc5 needs for FP with integers.
  return body;
}

}  // namespace

z3::expr unrolled_query(const Encoding& enc, int depth, const ExportGoal& goal) {
  if (depth < 1) throw std::invalid_argument("depth must be at least 1");
  Unroller u(enc.ts);
  z3::context& c = enc.ts.ctx();
  z3::expr p = goal_term(enc, goal);
  z3::expr_vector hits(c);
  for (int k = 0; k < depth; ++k)
    hits.push_back(goal.kind == ExportGoal::Kind::Reach ? u.at(p, k) : !u.at(p, k));
  return u.path(depth) && z3::mk_or(hits);
}

std::string to_smt2(const Encoding& enc, int depth, const ExportGoal& goal) {
  z3::expr q = unrolled_query(enc, depth, goal);
  std::string what = goal.kind == ExportGoal::Kind::Reach ? "reach " : "violate ";
  std::string s = benchmark(enc.ts.ctx(), q,
                            "cemv unrolling of " + std::to_string(depth) + " cycles: " + what +
                                (goal.term ? *goal.term : std::string("true")));
  // Z3 ends with (check-sat); keep the file self-contained for any solver.
  return s;
}

std::string to_vmt(const Encoding& enc, const ExportGoal& goal) {
  const auto& ts = enc.ts;
  z3::context& c = ts.ctx();
  Z3_set_ast_print_mode(c, Z3_PRINT_SMTLIB2_COMPLIANT);
  // The property may read inputs; VMT properties range over states, so a
  // monitor state variable carries the property of the previous cycle.
  z3::expr p = goal_term(enc, goal);
  if (goal.kind == ExportGoal::Kind::Reach) p = !p;
  z3::expr monitor = c.bool_const("monitor.property");
  z3::expr monitor_next = c.bool_const("monitor.property.next");

  std::ostringstream o;
  o << "; cemv VMT-LIB transition system (docs/encoding.md)\n";
  o << "; property: " << (goal.kind == ExportGoal::Kind::Reach ? "never " : "always ")
    << (goal.term ? *goal.term : std::string("true")) << ", checked one cycle late by monitor.property\n";
  o << "(set-logic ALL)\n";
  auto quote = [](const std::string& n) { return "|" + n + "|"; };
  int idx = 0;
  auto declare_state = [&](const std::string& name, const z3::sort& sort) {
    o << "(declare-fun " << quote(name) << " () " << sort.to_string() << ")\n";
    o << "(declare-fun " << quote(name + ".next") << " () " << sort.to_string() << ")\n";
    o << "(define-fun .sv" << idx++ << " () " << sort.to_string() << " (! " << quote(name)
      << " :next " << quote(name + ".next") << "))\n";
  };
  for (const auto& s : ts.statevars()) declare_state(s.name, s.var.get_sort());
  declare_state("monitor.property", c.bool_sort());
  for (const auto& i : ts.inputvars())
    o << "(declare-fun " << quote(i.name) << " () " << i.var.get_sort().to_string() << ")\n";
  z3::expr init = ts.init_formula() && monitor;
  z3::expr trans = ts.trans_formula() && ts.constraint_formula() && monitor_next == p;
  o << "(define-fun .init () Bool (! " << init.to_string() << " :init true))\n";
  o << "(define-fun .trans () Bool (! " << trans.to_string() << " :trans true))\n";
  o << "(define-fun .prop () Bool (! " << monitor.to_string() << " :invar-property 0))\n";
  return o.str();
}

}  // namespace cemv::encoder
