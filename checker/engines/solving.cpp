#include "checker/engines/solving.hpp"

#include "checker/context_pool.hpp"

#include <bit>
#include <cstring>
#include <limits>

namespace cemv::checker {

Watchdog::Watchdog(z3::context& ctx, const Limits& limits)
    : ctx_(ctx), limits_(limits), thread_([this] { watch(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
  // Z3_interrupt leaves the context's resource limit cancelled until the next
  // solver check starts: until then every simplification throws "canceled",
  // and destroying a fixedpoint (Spacer) throws out of a Z3 destructor, which
  // is std::terminate (seen with Z3 4.8.12). A check of an empty solver
  // clears it.
  if (fired_) {
    try {
      z3::solver(ctx_).check();
    } catch (const z3::exception&) {
    }
  }
}

void Watchdog::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!done_) {
    wake_.wait_for(lock, std::chrono::milliseconds(10));
    if (!done_ && limits_.interrupted()) {
      discard_when_released(ctx_);
      ctx_.interrupt();
      fired_ = true;
    }
  }
}

z3::check_result check_within(z3::solver& s, WorkMeter& meter) {
  if (!meter.arm()) return z3::unknown;
  return s.check();
}

z3::check_result check_within(z3::solver& s, WorkMeter& meter, const z3::expr_vector& assumptions) {
  if (!meter.arm()) return z3::unknown;
  return s.check(assumptions);
}

UnknownReason unknown_reason(const std::string& z3_reason, const Limits& limits, std::string* detail) {
  if (limits.interrupted()) return UnknownReason::TimeLimit;
  if (z3_reason.find("memory") != std::string::npos) return UnknownReason::MemoryLimit;
  if (z3_reason.find("resource") != std::string::npos) return UnknownReason::WorkLimit;
  if (detail) *detail = z3_reason;
  return UnknownReason::SolverGaveUp;
}

UnknownReason unknown_reason(const std::string& z3_reason, const Limits& limits, const WorkMeter& meter,
                             std::string* detail) {
  if (limits.interrupted()) return UnknownReason::TimeLimit;
  if (meter.exhausted()) return UnknownReason::WorkLimit;
  return unknown_reason(z3_reason, limits, detail);
}

Value value_in(const z3::model& m, const z3::expr& e) {
  z3::expr v = m.eval(e, true);
  Value out;
  if (e.is_bool()) {
    out.i = v.is_true() ? 1 : 0;
  } else if (e.is_int()) {
    out.i = v.get_numeral_int64();
  } else if (e.is_fpa()) {
    out.is_float = true;
    // A NaN has no one bit pattern in SMT-LIB (only unconstrained states of an
    // inductive step hold one; inputs exclude NaN).
    if (Z3_fpa_is_numeral_nan(e.ctx(), v)) {
      out.f = std::numeric_limits<float>::quiet_NaN();
      return out;
    }
    // The IEEE bit pattern of the numeral, as the runtime's float holds it.
    z3::expr bits(e.ctx(), Z3_mk_fpa_to_ieee_bv(e.ctx(), v));
    std::uint64_t u = bits.simplify().get_numeral_uint64();
    out.f = std::bit_cast<float>(static_cast<std::uint32_t>(u));
  } else {
    throw std::logic_error("value_in: unsupported sort of " + e.to_string());
  }
  return out;
}

Trace trace_from_model(const encoder::TransitionSystem& ts, encoder::Unroller& u,
                       const z3::model& m, int last) {
  Trace t;
  for (const auto& i : ts.inputvars()) t.input_names.push_back(i.name);
  for (const auto& s : ts.statevars()) t.state_names.push_back(s.name);
  for (int k = 0; k <= last; ++k) {
    Trace::Cycle c;
    for (const auto& i : ts.inputvars()) c.inputs.push_back(value_in(m, u.var_at(i.var, k)));
    for (const auto& s : ts.statevars()) c.state.push_back(value_in(m, u.var_at(s.var, k)));
    t.cycles.push_back(std::move(c));
  }
  return t;
}

std::string to_smtlib(const z3::expr& e) {
  // Z3 prints terms in SMT-LIB syntax and quotes symbols such as
  // |cause[1].active|; let-bindings are avoided for short terms.
  return e.to_string();
}

namespace {

z3::expr_vector parse_terms(const encoder::TransitionSystem& ts, const std::vector<std::string>& terms,
                            std::size_t from, std::size_t to) {
  z3::context& ctx = ts.ctx();
  z3::sort_vector sorts(ctx);
  z3::func_decl_vector decls(ctx);
  for (const auto& s : ts.statevars()) decls.push_back(s.var.decl());
  for (const auto& i : ts.inputvars()) decls.push_back(i.var.decl());
  std::string text;
  for (std::size_t i = from; i < to; ++i) text.append("(assert ").append(terms[i]).append(")\n");
  return ctx.parse_string(text.c_str(), sorts, decls);
}

// [from, to) in one parse, or halved until the terms that do not read are alone.
void read_readable(const encoder::TransitionSystem& ts, const std::vector<std::string>& terms, std::size_t from,
                   std::size_t to, std::vector<z3::expr>& out) {
  if (from >= to) return;
  try {
    const z3::expr_vector parsed = parse_terms(ts, terms, from, to);
    if (parsed.size() == to - from) {
      for (unsigned i = 0; i < parsed.size(); ++i) out.push_back(parsed[i]);
      return;
    }
  } catch (const z3::exception&) {
  }
  if (to - from == 1) return;
  const std::size_t mid = from + (to - from) / 2;
  read_readable(ts, terms, from, mid, out);
  read_readable(ts, terms, mid, to, out);
}

}  // namespace

z3::expr from_smtlib(const encoder::TransitionSystem& ts, const std::string& term) {
  z3::expr_vector parsed = parse_terms(ts, {term}, 0, 1);
  if (parsed.size() != 1) throw InternalError("cannot read invariant clause: " + term);
  return parsed[0];
}

std::vector<z3::expr> from_smtlib_readable(const encoder::TransitionSystem& ts, const std::vector<std::string>& terms) {
  std::vector<z3::expr> out;
  read_readable(ts, terms, 0, terms.size(), out);
  return out;
}

z3::expr invariant_term(const encoder::TransitionSystem& ts, const Invariant& inv) {
  if (inv.clauses.empty()) return ts.ctx().bool_val(true);
  // One parse for every clause: a parse declares every variable of the
  // system again, which for thousands of clauses over hundreds of
  // variables cost more than the re-check's solver.
  const z3::expr_vector parts = parse_terms(ts, inv.clauses, 0, inv.clauses.size());
  if (parts.size() != inv.clauses.size()) throw InternalError("cannot read the invariant's clauses");
  return z3::mk_and(parts);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace cemv::checker
