// Internal: the symbolic execution of one scan (encode.cpp, expressions.cpp,
// statements.cpp, blocks.cpp). Values live in an environment keyed by path:
// "LT100_HH_THR" for a variable of the program, "INST.X" for variable X of
// the user block instance INST, "DLY.Q" and "DLY.#e" for a pin and the
// internal state of the standard block instance DLY.
#pragma once

#include <map>
#include <set>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <z3++.h>

#include "plc/ast.hpp"
#include "plc_encoder/encode.hpp"

namespace cemv::plc_encoder {

using Env = std::map<std::string, z3::expr>;

// Where the names of a POU's body resolve: the instance path and, for
// VAR_IN_OUT parameters, the key of the variable bound to them.
struct Scope {
  const plc::Pou* pou = nullptr;
  std::string path;                          // "" for the program, "INST." inside an instance
  std::map<std::string, std::string> alias;  // upper-case parameter name -> key
};

class Scan {
 public:
  Scan(z3::context& ctx, const plc::Program& program, std::uint32_t scan_ms);

  z3::context& ctx() { return ctx_; }
  z3::expr literal(const plc::Literal& l);
  const std::set<float>& real_literals() const { return real_literals_; }
  z3::expr zero(plc::Type t);
  // An integer result reduced to the range of `t` (two's complement wrapping).
  z3::expr wrap(plc::Type t, const z3::expr& x);
  z3::expr rne() { return z3::expr(ctx_, Z3_mk_fpa_rne(ctx_)); }

  // The key of variable `name` as seen from `scope`.
  std::string key(const Scope& scope, const std::string& name) const;
  z3::expr& at(Env& env, const std::string& key, plc::Position where);

  z3::expr eval(const plc::Expr& e, const Scope& scope, Env& env);
  void exec(const std::vector<plc::Statement>& body, const Scope& scope, Env& env);

  const plc::Program& program() const { return program_; }

 private:
  z3::expr binary(const plc::Expr& e, const Scope& scope, Env& env);
  z3::expr call(const plc::Expr& e, const Scope& scope, Env& env);
  void exec(const plc::Statement& s, const Scope& scope, Env& env);
  void branch(const plc::Statement& s, const Scope& scope, Env& env);
  void case_of(const plc::Statement& s, const Scope& scope, Env& env);
  void for_loop(const plc::Statement& s, const Scope& scope, Env& env);
  void block_call(const plc::Statement& s, const Scope& scope, Env& env);
  void standard_block(plc::StandardBlock b, const std::string& k, plc::Position at, Env& env);
  void timer(plc::StandardBlock b, const std::string& k, Env& env);

  z3::context& ctx_;
  const plc::Program& program_;
  std::uint32_t scan_ms_;
  int conditional_ = 0;               // depth of IF/CASE/FOR around the statement executed
  std::map<std::string, int> timer_calls_;  // calls of each timer instance in this scan
  std::set<float> real_literals_;           // every REAL constant the encoding made
};

// Merges the environments of the branches of a choice: the value of each key
// is `values[i]` under `conditions[i]` (the first that holds), else `otherwise`.
Env merge(const std::vector<z3::expr>& conditions, const std::vector<Env>& values, const Env& otherwise);

}  // namespace cemv::plc_encoder
