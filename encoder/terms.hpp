// Inside encode(): the terms every part of the encoding is made of (counters,
// state variables, single-precision comparisons, cell guards), over one
// transition system. Not a public header: nothing outside encoder/ includes it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <z3++.h>

#include "encoder/encode.hpp"

namespace cemv::encoder::detail {

using model::Node;
using z3::expr;

// Term names start with the element as observable keys spell it
// (model::observable_key), so each observable is the term named by its key.
inline std::string cause_prefix(int id) { return model::to_string(Node{Node::Kind::Cause, id}); }
inline std::string effect_prefix(int id) { return model::to_string(Node{Node::Kind::Effect, id}); }

// T.2: whole cycles of a duration, rounded up, 64-bit.
inline int cycles_of(std::uint64_t ms, std::uint32_t cycle_ms) {
  if (ms == 0 || cycle_ms == 0) return 0;
  return static_cast<int>((ms + cycle_ms - 1) / cycle_ms);
}

class Terms {
 public:
  Terms(z3::context& ctx, Encoding& enc, bool guard_cells)
      : c_(ctx), enc_(enc), ts_(enc.ts), fp32_(ctx.fpa_sort(8, 24)), guard_cells_(guard_cells) {}

 protected:
  expr B(bool b) { return c_.bool_val(b); }
  expr I(int v) { return c_.int_val(v); }
  // EncodeOptions::guard_cells: `term` under the activation literal of the
  // cell with support key `key` (made once); unguarded, `term` itself, so
  // that the plain encoding's terms (and its SMT-LIB text) stay as they are.
  expr guarded(const std::string& key, const expr& term) {
    if (!guard_cells_) return term;
    return guard(key) && term;
  }
  expr guard(const std::string& key) {
    for (const auto& [k, g] : enc_.guards)
      if (k == key) return g;
    expr g = c_.bool_const(("guard." + key).c_str());
    enc_.guards.emplace_back(key, g);
    return g;
  }
  expr count(const std::vector<expr>& bs) {
    if (bs.empty()) return I(0);
    expr sum = z3::ite(bs[0], I(1), I(0));
    for (std::size_t i = 1; i < bs.size(); ++i) sum = sum + z3::ite(bs[i], I(1), I(0));
    return sum;
  }
  expr any(const std::vector<expr>& bs) {
    if (bs.empty()) return B(false);  // a nullary (or) prints as a bare symbol
    if (bs.size() == 1) return bs[0];
    z3::expr_vector v(c_);
    for (const auto& b : bs) v.push_back(b);
    return z3::mk_or(v);
  }
  expr bool_state(const std::string& name, bool init) {
    expr v = ts_.make_statevar(name, c_.bool_sort());
    ts_.set_init(v, B(init));
    return v;
  }
  // An elapsed-cycles counter (T.2) saturating at d, with its range lemma.
  expr counter(const std::string& name, int d) {
    expr v = ts_.make_statevar(name, c_.int_sort());
    ts_.set_init(v, I(0));
    ts_.add_lemma(name + ".range", v >= 0 && v <= d);
    return v;
  }
  expr sat_inc(const expr& e, int d) { return z3::ite(e >= d, I(d), e + 1); }
  expr fconst(float v) { return ts_.float_const(v); }
  expr fge(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_geq(c_, a, b)); }
  expr fle(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_leq(c_, a, b)); }
  expr flt(const expr& a, const expr& b) { return expr(c_, Z3_mk_fpa_lt(c_, a, b)); }
  expr fabs_diff(const expr& a, const expr& b) {
    expr d(c_, Z3_mk_fpa_sub(c_, ts_.rne(), a, b));
    return expr(c_, Z3_mk_fpa_abs(c_, d));
  }
  expr not_nan(const expr& v) { return !expr(c_, Z3_mk_fpa_is_nan(c_, v)); }

  z3::context& c_;
  Encoding& enc_;
  TransitionSystem& ts_;
  z3::sort fp32_;
  bool guard_cells_ = false;
};

}  // namespace cemv::encoder::detail
