// The resolved property AST: what a requirements file means once every name in
// it has been resolved against one matrix. Data only. Two independent
// implementations give it meaning (docs/properties.md): the concrete evaluator
// (properties/evaluator.*) over a runtime trace, and the symbolic monitor
// (properties/monitor.*) over the encoder's transition system.
//
// Cycle semantics used throughout (docs/properties.md, "Semantics"): a trace is
// cycles 0, 1, 2, ...; every expression has a value at every cycle k, computed
// from the cycle input of cycle k (tag values, commands issued in cycle k) and
// the observables after the scan of cycle k.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/vocabulary.hpp"

namespace cemv::properties {

struct SourceLoc {
  int line = 0;    // 1-based; 0 = generated (standard properties)
  int column = 0;  // 1-based, in characters
};

// The type of an expression's value.
//   Bool   : false/true.
//   Int    : a mathematical integer (timers, counters, count(...)).
//   Float  : an IEEE single-precision value (analog input tags, float constants).
//   Voting : a model::Voting enumerator (the `voting` cause field).
enum class ExprType { Bool, Int, Float, Voting };

enum class CompareOp { Eq, Ne, Lt, Le, Gt, Ge };

// A pattern over the operator commands of one cycle (model::Command). Fields
// left empty match anything. tag_name compares by model::tag_key
// (case-insensitive). `on` only constrains the soft bypass commands.
struct CommandPattern {
  model::CommandOp op = model::CommandOp::AckCause;
  std::optional<int> cause;
  std::optional<int> effect;
  std::optional<int> tag;    // SoftBypassTag: 1-3
  std::optional<int> group;
  std::optional<bool> on;
  std::optional<std::string> tag_name;
};

struct Expr {
  enum class Kind {
    // ---- constants
    BoolConst,      // bool_value; type Bool
    IntConst,       // int_value; type Int, or Voting (int_value = model::Voting enumerator)
    FloatConst,     // float_value (already rounded to single precision); type Float
    // ---- atoms (value at cycle k)
    Observable,     // observable: its value after the scan of cycle k; type Bool, Int or
                    // Voting per observable.type. Output tags are effect[j].tag[k] observables.
    InputValue,     // input: InputTable index; the tag's value in the cycle input of
                    // cycle k (the plant value, before any simulate_tag). Type Bool for
                    // Bool tags (value != 0), Float for analog tags.
    InputBad,       // input: InputTable index; its bad-quality flag in cycle k. Type Bool.
    CommandIssued,  // command: true iff some command in the cycle input of cycle k
                    // matches the pattern (issued, whether or not the runtime accepts it).
                    // Type Bool.
    // ---- comparison: args[0] cmp args[1]; type Bool. Operand pairs:
    //   Int/Int (either may be IntConst or Count), Float/FloatConst or FloatConst/Float
    //   (compared in single precision, as the runtime compares), Voting/Voting (Eq/Ne).
    Compare,        // cmp
    // ---- Boolean connectives over Bool args; type Bool.
    Not,            // args[0]
    And,            // all args (n >= 0; empty = true)
    Or,             // any arg (n >= 0; empty = false)
    Implies,        // args[0] -> args[1]
    Iff,            // args[0] <-> args[1]
    // ---- count: the number of Bool args true at k; type Int. Appears as an operand
    //   of Compare with an IntConst (aggregates over sets are expanded at resolve time).
    Count,
    // ---- past-time operators over Bool args; type Bool. cycles = N >= 0.
    Prev,           // args[0] at k-1; false at k = 0
    Rose,           // args[0] at k and not Prev(args[0]) at k
    Fell,           // not args[0] at k and Prev(args[0]) at k
    Held,           // args[0] at every cycle of [k-N, k]; false when k < N
    Within,         // args[0] at some cycle of [max(0, k-N), k]
    Since,          // exists j <= k: args[1] at j and args[0] at every cycle of (j, k]
  };

  Kind kind = Kind::BoolConst;
  ExprType type = ExprType::Bool;

  bool bool_value = false;
  std::int64_t int_value = 0;
  float float_value = 0.0f;
  model::Observable observable;
  std::size_t input = 0;
  CommandPattern command;
  CompareOp cmp = CompareOp::Eq;
  int cycles = 0;               // Held / Within: N (a duration already in cycles)
  std::vector<Expr> args;

  SourceLoc loc;                // where the expression starts in the file

  // ---- factories (fill kind and type consistently)
  static Expr boolean(bool b) { Expr e; e.kind = Kind::BoolConst; e.bool_value = b; return e; }
  static Expr integer(std::int64_t v) {
    Expr e; e.kind = Kind::IntConst; e.type = ExprType::Int; e.int_value = v; return e;
  }
  static Expr voting(model::Voting v) {
    Expr e; e.kind = Kind::IntConst; e.type = ExprType::Voting;
    e.int_value = static_cast<int>(v); return e;
  }
  static Expr real(float v) {
    Expr e; e.kind = Kind::FloatConst; e.type = ExprType::Float; e.float_value = v; return e;
  }
  static Expr of_observable(const model::Observable& o) {
    Expr e; e.kind = Kind::Observable; e.observable = o;
    e.type = o.type == model::FieldType::Bool ? ExprType::Bool
             : o.type == model::FieldType::Int ? ExprType::Int : ExprType::Voting;
    return e;
  }
  static Expr input_value(std::size_t index, model::TagKind k) {
    Expr e; e.kind = Kind::InputValue; e.input = index;
    e.type = k == model::TagKind::Analog ? ExprType::Float : ExprType::Bool; return e;
  }
  static Expr input_bad(std::size_t index) {
    Expr e; e.kind = Kind::InputBad; e.input = index; return e;
  }
  static Expr issued(CommandPattern p) {
    Expr e; e.kind = Kind::CommandIssued; e.command = std::move(p); return e;
  }
  static Expr compare(CompareOp op, Expr a, Expr b) {
    Expr e; e.kind = Kind::Compare; e.cmp = op;
    e.args.push_back(std::move(a)); e.args.push_back(std::move(b)); return e;
  }
  static Expr unary(Kind k, Expr a, int cycles = 0) {
    Expr e; e.kind = k; e.cycles = cycles; e.args.push_back(std::move(a)); return e;
  }
  static Expr binary(Kind k, Expr a, Expr b) {
    Expr e; e.kind = k; e.args.push_back(std::move(a)); e.args.push_back(std::move(b)); return e;
  }
  static Expr nary(Kind k, std::vector<Expr> args) {
    Expr e; e.kind = k; e.args = std::move(args);
    if (k == Kind::Count) e.type = ExprType::Int;
    return e;
  }
};

// An assumption restricts the traces a property is judged on: a trace counts
// only while the assumption holds in every cycle (cycles 0..k for a verdict at k).
struct Assumption {
  std::string name;   // optional label ("" if none)
  Expr expr;          // Bool
  SourceLoc loc;
};

enum class PropertyKind {
  Invariant,  // body holds at every cycle
  Never,      // body holds at no cycle
  Reachable,  // body holds at some cycle (a cover; no witness = unreachable)
  Response,   // for every cycle k where trigger holds, response holds at some
              // cycle of [k, k + within_cycles]
};

// The kind's word, as results write it: "invariant", "never", "reachable",
// "response".
inline const char* to_string(PropertyKind k) {
  switch (k) {
    case PropertyKind::Invariant: return "invariant";
    case PropertyKind::Never: return "never";
    case PropertyKind::Reachable: return "reachable";
    case PropertyKind::Response: return "response";
  }
  return "invariant";
}

struct Property {
  std::string name;            // unique in its file, e.g. "req1.overfill_closes_xv101"
  std::string description;     // free text (may be empty)
  PropertyKind kind = PropertyKind::Invariant;
  Expr body;                   // Invariant / Never / Reachable
  Expr trigger;                // Response
  Expr response;               // Response
  int within_cycles = 0;       // Response: N
  std::vector<Assumption> assumptions;  // this property's own (file ones are in PropertyFile)
  SourceLoc loc;               // of the property's name
  std::vector<std::string> notes;  // e.g. "500 ms rounded up to 5 cycles of 100 ms"
  std::string expect;          // from a `# expect: VERDICT` comment; "" if none
};

struct PropertyFile {
  std::string file_name;
  std::vector<Assumption> assumptions;  // apply to every property of the file
  std::vector<Property> properties;
  // Traps found when the file was read (properties/traps.hpp), as
  // `FILE:LINE:COL: warning: ...`; the affected properties' notes say them too.
  std::vector<std::string> warnings;
};

}  // namespace cemv::properties
