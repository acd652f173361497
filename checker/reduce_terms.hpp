// The term rewriting behind checker/reduce.hpp (internal to checker/):
// variables and conjuncts of a term, the Boolean folding a substitution
// needs, Float32 terms as ordered integers, and Float32 constants stated the
// way the encoder's Evaluator knows them.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <z3++.h>

#include "checker/reduce.hpp"
#include "encoder/term_memo.hpp"
#include "encoder/transition_system.hpp"

namespace cemv::checker::reduce_terms {

using z3::expr;

inline bool is_variable(const expr& e) {
  return e.is_app() && e.num_args() == 0 && e.decl().decl_kind() == Z3_OP_UNINTERPRETED;
}

// The variables of a term, by Z3 AST id.
inline void collect_variables(const expr& e, std::unordered_set<unsigned>& out, std::unordered_set<unsigned>& seen) {
  if (!seen.insert(e.id()).second || !e.is_app()) return;
  if (is_variable(e)) {
    out.insert(e.id());
    return;
  }
  for (unsigned i = 0; i < e.num_args(); ++i) collect_variables(e.arg(i), out, seen);
}
inline std::unordered_set<unsigned> variables_of(const expr& e) {
  std::unordered_set<unsigned> out, seen;
  collect_variables(e, out, seen);
  return out;
}

inline void conjuncts(const expr& e, std::vector<expr>& out) {
  if (e.is_app() && e.decl().decl_kind() == Z3_OP_AND) {
    for (unsigned i = 0; i < e.num_args(); ++i) conjuncts(e.arg(i), out);
  } else if (!(e.is_true())) {
    out.push_back(e);
  }
}

struct Unsupported {};

// Reduction 2: Float32 terms as integers of the same order. Throws
// Unsupported at the first operation that is not a comparison, a choice or a
// constant (arithmetic needs the real thing).
class FloatsAsIntegers {
 public:
  explicit FloatsAsIntegers(z3::context& c) : c_(c) {}

  void map_variable(const expr& fp_var, const expr& int_var) {
    memo_.emplace(fp_var, int_var);
  }

  expr operator()(const expr& e) {
    if (const expr* known = memo_.find(e)) return *known;
    return memo_.emplace(e, rewrite(e));
  }

 private:
  expr rewrite(const expr& e) {
    if (!e.is_app()) throw Unsupported{};
    const Z3_decl_kind k = e.decl().decl_kind();
    if (e.is_fpa()) {
      if (e.num_args() == 0 && k != Z3_OP_UNINTERPRETED) return c_.int_val(constant_key(e));
      if (k == Z3_OP_ITE) return z3::ite((*this)(e.arg(0)), (*this)(e.arg(1)), (*this)(e.arg(2)));
      throw Unsupported{};  // arithmetic, conversions, or an unmapped variable
    }
    if (e.num_args() > 0 && e.arg(0).is_fpa()) {
      auto a = [&](unsigned i) { return (*this)(e.arg(i)); };
      switch (k) {
        case Z3_OP_FPA_LE: return a(0) <= a(1);
        case Z3_OP_FPA_LT: return a(0) < a(1);
        case Z3_OP_FPA_GE: return a(0) >= a(1);
        case Z3_OP_FPA_GT: return a(0) > a(1);
        case Z3_OP_FPA_EQ:
        case Z3_OP_EQ: return a(0) == a(1);
        case Z3_OP_DISTINCT:
          if (e.num_args() == 2) return a(0) != a(1);
          throw Unsupported{};
        case Z3_OP_FPA_IS_NAN:
        case Z3_OP_FPA_IS_INF: return c_.bool_val(false);  // only finite values remain
        default: throw Unsupported{};
      }
    }
    if (e.num_args() == 0) return e;
    z3::expr_vector args(c_);
    bool changed = false;
    for (unsigned i = 0; i < e.num_args(); ++i) {
      expr r = (*this)(e.arg(i));
      changed = changed || r.id() != e.arg(i).id();
      args.push_back(r);
    }
    return changed ? e.decl()(args) : e;
  }

  std::int64_t constant_key(const expr& e) {
    expr bits = expr(c_, Z3_mk_fpa_to_ieee_bv(c_, e)).simplify();
    if (!bits.is_numeral()) throw Unsupported{};
    const float f = std::bit_cast<float>(static_cast<std::uint32_t>(bits.get_numeral_uint64()));
    if (!std::isfinite(f)) throw Unsupported{};
    return float_key(f);
  }

  z3::context& c_;
  encoder::TermMemo<expr> memo_;
};

// Folds the Boolean constants a substitution leaves behind (`and` with
// FALSE, `ite` on TRUE, ...), and nothing else: Z3's simplify() would also
// rewrite Float32 terms into operators the encoder's Evaluator, which
// re-simulates traces, does not interpret.
class FoldBooleans {
 public:
  expr operator()(const expr& e) {
    if (const expr* known = memo_.find(e)) return *known;
    return memo_.emplace(e, fold(e));
  }

 private:
  expr fold(const expr& e) {
    if (!e.is_app() || e.num_args() == 0) return e;
    z3::context& c = e.ctx();
    std::vector<expr> a;
    for (unsigned i = 0; i < e.num_args(); ++i) a.push_back((*this)(e.arg(i)));
    switch (e.decl().decl_kind()) {
      case Z3_OP_NOT:
        if (a[0].is_true()) return c.bool_val(false);
        if (a[0].is_false()) return c.bool_val(true);
        return !a[0];
      case Z3_OP_AND: {
        z3::expr_vector kept(c);
        for (auto& x : a) {
          if (x.is_false()) return c.bool_val(false);
          if (!x.is_true()) kept.push_back(x);
        }
        return kept.empty() ? c.bool_val(true) : kept.size() == 1 ? kept[0] : z3::mk_and(kept);
      }
      case Z3_OP_OR: {
        z3::expr_vector kept(c);
        for (auto& x : a) {
          if (x.is_true()) return c.bool_val(true);
          if (!x.is_false()) kept.push_back(x);
        }
        return kept.empty() ? c.bool_val(false) : kept.size() == 1 ? kept[0] : z3::mk_or(kept);
      }
      case Z3_OP_ITE:
        if (a[0].is_true()) return a[1];
        if (a[0].is_false()) return a[2];
        break;
      case Z3_OP_IMPLIES:
        if (a[0].is_false() || a[1].is_true()) return c.bool_val(true);
        if (a[0].is_true()) return a[1];
        break;
      default: break;
    }
    z3::expr_vector args(c);
    bool changed = false;
    for (unsigned i = 0; i < a.size(); ++i) {
      changed = changed || a[i].id() != e.arg(i).id();
      args.push_back(a[i]);
    }
    return changed ? e.decl()(args) : e;
  }
  encoder::TermMemo<expr> memo_;
};

inline void collect_float_constants(const expr& e, std::vector<expr>& out, std::unordered_set<unsigned>& seen) {
  if (!seen.insert(e.id()).second || !e.is_app()) return;
  if (e.num_args() == 0) {
    if (e.is_fpa() && e.decl().decl_kind() != Z3_OP_UNINTERPRETED) out.push_back(e);
    return;
  }
  for (unsigned i = 0; i < e.num_args(); ++i) collect_float_constants(e.arg(i), out, seen);
}

// Simplification folds Float32 constants into new terms (+zero, say). The
// encoder's Evaluator, which shrinks and re-checks traces, knows a constant
// by the system's float_const: state each one that way.
class FloatConstants {
 public:
  explicit FloatConstants(encoder::TransitionSystem& ts) : ts_(ts), from_(ts.ctx()), to_(ts.ctx()) {}
  expr operator()(const expr& e) {
    std::vector<expr> found;
    collect_float_constants(e, found, seen_);
    for (const auto& f : found) {
      expr bits = expr(ts_.ctx(), Z3_mk_fpa_to_ieee_bv(ts_.ctx(), f)).simplify();
      if (!bits.is_numeral()) throw Unsupported{};
      from_.push_back(f);
      to_.push_back(ts_.float_const(std::bit_cast<float>(static_cast<std::uint32_t>(bits.get_numeral_uint64()))));
    }
    expr copy = e;
    return from_.empty() ? copy : copy.substitute(from_, to_);
  }

 private:
  encoder::TransitionSystem& ts_;
  z3::expr_vector from_, to_;
  std::unordered_set<unsigned> seen_;
};

}  // namespace cemv::checker::reduce_terms
