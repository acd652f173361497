// A PLC program as data: the IEC 61131-3 Structured Text subset of docs/plc.md
// (rules P.1-P.9). The parser (parser.hpp) and the PLCopen reader
// (plcopen.hpp) build it, resolved and type-checked; the interpreter
// (interpreter.hpp) and the SMT encoding read it; print.hpp writes it back as
// ST. Every node carries the line and column of its first token in the file
// it was read from (0 when it was built by a generator).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cemv::plc {

// 1-based line and column (in bytes) in the source file; 0 when none.
struct Position {
  std::size_t line = 0;
  std::size_t column = 0;
  bool operator==(const Position&) const = default;
};

// The elementary types of the subset (P.2). INT is 16-bit and DINT 32-bit
// two's complement, REAL IEEE single precision, TIME a signed 32-bit count of
// milliseconds.
enum class Type { Bool, Int, Dint, Real, Time };

// The standard function blocks of the subset (P.6).
enum class StandardBlock { Ton, Tof, Tp, RTrig, FTrig, Sr, Rs };

// The pins of the standard blocks (IEC 61131-3 names).
enum class Pin { In, Pt, Q, Et, Clk, S1, R, S, R1, Q1 };

// The standard functions of the subset (P.5.6).
enum class Function { Min, Max, Abs, Sel, Limit };

enum class PouKind { Program, FunctionBlock };

// VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR CONSTANT (P.3).
enum class Section { Local, Input, Output, InOut, Constant };

enum class UnaryOp { Not, Negate };
enum class BinaryOp { Or, Xor, And, Eq, Ne, Lt, Le, Gt, Ge, Add, Sub, Mul, Div, Mod };

// A constant of an elementary type. BOOL, INT, DINT and TIME (milliseconds)
// use `integer`, REAL uses `real`.
struct Literal {
  Type type = Type::Bool;
  std::int64_t integer = 0;
  float real = 0;
  bool operator==(const Literal&) const = default;
};

struct Expr {
  enum class Kind {
    Literal,   // literal
    Variable,  // name: a variable of the POU (the declared spelling)
    Member,    // name.member: an output (or input) of a block instance
    Unary,     // unary op, args[0]
    Binary,    // binary op, args[0] op args[1]
    Call,      // function(args...)
  };
  Kind kind = Kind::Literal;
  Position position;
  Type type = Type::Bool;  // the resolved type
  Literal literal;
  std::string name;    // Variable, Member: the instance; declared spelling after checking
  std::string member;  // Member: the parameter, declared spelling (IEC name for standard blocks)
  std::optional<Pin> pin;  // Member of a standard block instance
  UnaryOp unary = UnaryOp::Not;
  BinaryOp binary = BinaryOp::Or;
  Function function = Function::Min;
  std::vector<Expr> args;
  bool operator==(const Expr&) const = default;
};

// One argument of a block call: `name := expr` (an input, or a VAR_IN_OUT
// bound to the variable `expr` names) or `name => variable` (an output copied
// to a variable after the call).
struct CallArg {
  Position position;
  std::string name;  // the parameter, declared spelling after checking
  std::optional<Pin> pin;  // for a standard block instance
  bool output = false;     // `=>`
  Expr value;              // `:=`: the expression; `=>`: a Variable, the target
  bool operator==(const CallArg&) const = default;
};

struct Statement;

struct Branch {  // IF / ELSIF condition THEN body
  Expr condition;
  std::vector<Statement> body;
  bool operator==(const Branch&) const;
};

struct CaseRange {  // a CASE label: `lo` alone (lo == hi) or `lo..hi`
  std::int64_t low = 0;
  std::int64_t high = 0;
  bool operator==(const CaseRange&) const = default;
};

struct CaseArm {
  Position position;
  std::vector<CaseRange> labels;
  std::vector<Statement> body;
  bool operator==(const CaseArm&) const;
};

struct Statement {
  enum class Kind {
    Assign,  // target := value
    If,      // branches (IF, ELSIF...), else_body
    Case,    // CASE value OF arms ELSE else_body END_CASE
    For,     // FOR target := value TO limit BY step DO body END_FOR (constant bounds)
    Call,    // target(args) for the block instance `target`
  };
  Kind kind = Kind::Assign;
  Position position;
  std::string target;  // Assign, For: the variable; Call: the instance (declared spelling)
  Expr value;          // Assign: the value; Case: the selector; For: the start
  std::vector<Branch> branches;
  std::vector<CaseArm> arms;
  std::vector<Statement> else_body;
  bool has_else = false;  // IF/CASE with an ELSE (possibly empty)
  // For: the bounds as written (literals or VAR CONSTANT names, possibly
  // negated; `step` is the literal 1 when BY is not written) and their values.
  Expr limit;
  Expr step;
  std::int64_t from = 0, to = 0, by = 1;
  std::vector<Statement> body;  // For
  std::vector<CallArg> args;              // Call
  // Printed as `(* ... *)` on the lines before the statement; never read
  // back (a generator's explanation for reviewers, cleared by without_positions).
  std::string comment;
  bool operator==(const Statement&) const = default;
};

inline bool Branch::operator==(const Branch& o) const { return condition == o.condition && body == o.body; }
inline bool CaseArm::operator==(const CaseArm& o) const {
  return position == o.position && labels == o.labels && body == o.body;
}

// The type of a variable: elementary, a standard block, or a user
// FUNCTION_BLOCK of the program (by its declared name).
struct VarType {
  enum class Kind { Elementary, Standard, User };
  Kind kind = Kind::Elementary;
  Type type = Type::Bool;
  StandardBlock block = StandardBlock::Ton;
  std::string user;  // Kind::User: the block's declared name
  bool operator==(const VarType&) const = default;
};

struct Variable {
  Position position;
  std::string name;
  Section section = Section::Local;
  VarType type;
  std::optional<Literal> initial;  // `:= literal` (elementary types only)
  Position initial_position;
  std::string comment;  // printed after the declaration; never read back
  bool operator==(const Variable&) const = default;
};

struct Pou {
  Position position;
  PouKind kind = PouKind::Program;
  std::string name;
  std::vector<Variable> variables;  // in declaration order
  std::vector<Statement> body;
  std::string comment;  // printed before the POU; never read back
  bool operator==(const Pou&) const = default;
};

struct Program {
  std::string file;  // the file it was read from ("<stdin>"), for messages
  std::vector<Pou> pous;
  // The task interval in milliseconds when the file states one (a PLCopen
  // task's `interval`); ST files state none.
  std::optional<std::int64_t> scan_time_ms;
  bool operator==(const Program&) const = default;
};

// The same program with every position and comment cleared and `file` emptied: what
// `parse(print(ast))` must give back, whatever the layout.
Program without_positions(Program program);

// Names of the closed sets as ST writes them (upper case).
std::string_view type_name(Type t);
std::string_view block_name(StandardBlock b);
std::string_view pin_name(Pin p);
std::string_view function_name(Function f);
std::string_view section_keyword(Section s);  // VAR, VAR_INPUT, ..., "VAR CONSTANT"
std::string_view unary_text(UnaryOp op);      // NOT, -
std::string_view binary_text(BinaryOp op);    // OR, XOR, AND, =, <>, <, <=, >, >=, +, -, *, /, MOD

// The ST spelling of a literal: TRUE, 42, 1.5, T#1m30s (typed so that it
// reads back as the same literal).
std::string literal_text(const Literal& l);

// Case-insensitive lookup of the closed sets (the words of ST are).
std::optional<Type> type_from_name(std::string_view word);
std::optional<StandardBlock> block_from_name(std::string_view word);
std::optional<Function> function_from_name(std::string_view word);
// The pins of a standard block: inputs first, in IEC order.
struct PinInfo {
  Pin pin;
  Type type;
  bool input;
};
const std::vector<PinInfo>& block_pins(StandardBlock b);

// Lookups by name, case-insensitive as ST is; nullptr when absent.
const Pou* find_pou(const Program& p, std::string_view name);
const Variable* find_variable(const Pou& pou, std::string_view name);
bool same_name(std::string_view a, std::string_view b);  // ASCII case-insensitive

}  // namespace cemv::plc
