// Statements of one scan: assignment, IF, CASE, FOR with constant bounds
// (unrolled), calls of block instances (docs/plc.md "The program as a
// transition system").
#include <cctype>

#include "plc_encoder/symbolic.hpp"

namespace cemv::plc_encoder {

namespace {

constexpr std::int64_t kMaxIterations = 100000;  // of one FOR statement, unrolled

std::string upper(std::string s) {
  for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

}  // namespace

Env merge(const std::vector<z3::expr>& conditions, const std::vector<Env>& values, const Env& otherwise) {
  Env out = otherwise;
  for (auto& [k, v] : out) {
    for (std::size_t i = conditions.size(); i-- > 0;) {
      const z3::expr& branch_value = values[i].at(k);
      if (!z3::eq(branch_value, v)) v = z3::ite(conditions[i], branch_value, v);
    }
  }
  return out;
}

void Scan::exec(const std::vector<plc::Statement>& body, const Scope& scope, Env& env) {
  for (const auto& s : body) exec(s, scope, env);
}

void Scan::exec(const plc::Statement& s, const Scope& scope, Env& env) {
  using K = plc::Statement::Kind;
  switch (s.kind) {
    case K::Assign: {
      z3::expr v = eval(s.value, scope, env);
      at(env, key(scope, s.target), s.position) = v;
      return;
    }
    case K::If: return branch(s, scope, env);
    case K::Case: return case_of(s, scope, env);
    case K::For: return for_loop(s, scope, env);
    case K::Call: return block_call(s, scope, env);
  }
}

void Scan::branch(const plc::Statement& s, const Scope& scope, Env& env) {
  ++conditional_;
  std::vector<z3::expr> conditions;
  std::vector<Env> values;
  for (const auto& b : s.branches) {
    conditions.push_back(eval(b.condition, scope, env));
    Env copy = env;
    exec(b.body, scope, copy);
    values.push_back(std::move(copy));
  }
  Env otherwise = env;
  exec(s.else_body, scope, otherwise);
  --conditional_;
  env = merge(conditions, values, otherwise);
}

void Scan::case_of(const plc::Statement& s, const Scope& scope, Env& env) {
  ++conditional_;
  const z3::expr selector = eval(s.value, scope, env);
  const unsigned width = selector.get_sort().bv_size();
  std::vector<z3::expr> conditions;
  std::vector<Env> values;
  for (const auto& arm : s.arms) {
    z3::expr c = ctx_.bool_val(false);
    for (const auto& r : arm.labels) {
      const z3::expr lo = ctx_.bv_val(static_cast<std::int64_t>(r.low), width);
      const z3::expr hi = ctx_.bv_val(static_cast<std::int64_t>(r.high), width);
      c = c || (r.low == r.high ? selector == lo : z3::sle(lo, selector) && z3::sle(selector, hi));
    }
    conditions.push_back(c.simplify());
    Env copy = env;
    exec(arm.body, scope, copy);
    values.push_back(std::move(copy));
  }
  Env otherwise = env;
  exec(s.else_body, scope, otherwise);
  --conditional_;
  env = merge(conditions, values, otherwise);
}

// The loop is unrolled; the variable holds each value of the range in turn
// and, after the loop, the first value beyond it.
void Scan::for_loop(const plc::Statement& s, const Scope& scope, Env& env) {
  const std::string k = key(scope, s.target);
  const unsigned width = at(env, k, s.position).get_sort().bv_size();
  if (s.by == 0) throw Unsupported(s.position, "FOR with a step of 0 never ends");
  const std::int64_t count = s.by > 0 ? (s.to >= s.from ? (s.to - s.from) / s.by + 1 : 0)
                                      : (s.from >= s.to ? (s.from - s.to) / -s.by + 1 : 0);
  if (count > kMaxIterations)
    throw Unsupported(s.position, "FOR of " + std::to_string(count) + " iterations: the encoding unrolls at most " +
                                      std::to_string(kMaxIterations));
  ++conditional_;
  std::int64_t i = s.from;
  for (std::int64_t n = 0; n < count; ++n, i += s.by) {
    env.at(k) = ctx_.bv_val(i, width);
    exec(s.body, scope, env);
  }
  --conditional_;
  env.at(k) = ctx_.bv_val(i, width);
}

void Scan::block_call(const plc::Statement& s, const Scope& scope, Env& env) {
  const std::string k = key(scope, s.target);
  const plc::Variable* inst = plc::find_variable(*scope.pou, s.target);
  if (!inst || inst->type.kind == plc::VarType::Kind::Elementary)
    throw Unsupported(s.position, s.target + " is no block instance");
  // Inputs are evaluated before the block runs, all in the caller's environment.
  std::vector<std::pair<std::string, z3::expr>> inputs;
  Scope inner;
  inner.path = k + ".";
  for (const auto& a : s.args) {
    if (a.output) continue;
    if (inst->type.kind == plc::VarType::Kind::User) {
      const plc::Pou* pou = plc::find_pou(program_, inst->type.user);
      const plc::Variable* param = pou ? plc::find_variable(*pou, a.name) : nullptr;
      if (param && param->section == plc::Section::InOut) {
        inner.alias[upper(a.name)] = key(scope, a.value.name);
        continue;
      }
    }
    inputs.emplace_back(k + "." + upper(a.name), eval(a.value, scope, env));
  }
  for (auto& [pin, v] : inputs) at(env, pin, s.position) = v;
  if (inst->type.kind == plc::VarType::Kind::Standard) {
    standard_block(inst->type.block, k, s.position, env);
  } else {
    inner.pou = plc::find_pou(program_, inst->type.user);
    if (!inner.pou) throw Unsupported(s.position, "no FUNCTION_BLOCK " + inst->type.user);
    exec(inner.pou->body, inner, env);
  }
  for (const auto& a : s.args)
    if (a.output) at(env, key(scope, a.value.name), a.position) = at(env, k + "." + upper(a.name), a.position);
}

}  // namespace cemv::plc_encoder
