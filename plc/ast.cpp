#include "plc/ast.hpp"

#include <cctype>
#include <string>

#include "model/text.hpp"

namespace cemv::plc {

namespace {

template <class E>
struct Named {
  E value;
  std::string_view name;
};

constexpr Named<Type> kTypes[] = {
    {Type::Bool, "BOOL"}, {Type::Int, "INT"}, {Type::Dint, "DINT"}, {Type::Real, "REAL"}, {Type::Time, "TIME"}};
constexpr Named<StandardBlock> kBlocks[] = {
    {StandardBlock::Ton, "TON"},     {StandardBlock::Tof, "TOF"},     {StandardBlock::Tp, "TP"},
    {StandardBlock::RTrig, "R_TRIG"}, {StandardBlock::FTrig, "F_TRIG"}, {StandardBlock::Sr, "SR"},
    {StandardBlock::Rs, "RS"}};
constexpr Named<Pin> kPins[] = {{Pin::In, "IN"}, {Pin::Pt, "PT"}, {Pin::Q, "Q"},   {Pin::Et, "ET"}, {Pin::Clk, "CLK"},
                                {Pin::S1, "S1"}, {Pin::R, "R"},   {Pin::S, "S"},   {Pin::R1, "R1"}, {Pin::Q1, "Q1"}};
constexpr Named<Function> kFunctions[] = {{Function::Min, "MIN"},
                                          {Function::Max, "MAX"},
                                          {Function::Abs, "ABS"},
                                          {Function::Sel, "SEL"},
                                          {Function::Limit, "LIMIT"}};

template <class E, std::size_t N>
std::string_view name_of(const Named<E> (&table)[N], E v) {
  for (const auto& n : table)
    if (n.value == v) return n.name;
  return "?";
}
template <class E, std::size_t N>
std::optional<E> lookup(const Named<E> (&table)[N], std::string_view word) {
  for (const auto& n : table)
    if (same_name(n.name, word)) return n.value;
  return std::nullopt;
}

void clear(Expr& e) {
  e.position = {};
  for (Expr& a : e.args) clear(a);
}
void clear(std::vector<Statement>& body);
void clear(Statement& s) {
  s.position = {};
  s.comment.clear();
  clear(s.value);
  clear(s.limit);
  clear(s.step);
  for (Branch& b : s.branches) {
    clear(b.condition);
    clear(b.body);
  }
  for (CaseArm& a : s.arms) {
    a.position = {};
    clear(a.body);
  }
  clear(s.else_body);
  clear(s.body);
  for (CallArg& a : s.args) {
    a.position = {};
    clear(a.value);
  }
}
void clear(std::vector<Statement>& body) {
  for (Statement& s : body) clear(s);
}

}  // namespace

bool same_name(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != std::toupper(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

Program without_positions(Program program) {
  program.file.clear();
  for (Pou& pou : program.pous) {
    pou.position = {};
    pou.comment.clear();
    for (Variable& v : pou.variables) {
      v.position = {};
      v.comment.clear();
      v.initial_position = {};
    }
    clear(pou.body);
  }
  return program;
}

std::string_view type_name(Type t) { return name_of(kTypes, t); }
std::string_view block_name(StandardBlock b) { return name_of(kBlocks, b); }
std::string_view pin_name(Pin p) { return name_of(kPins, p); }
std::string_view function_name(Function f) { return name_of(kFunctions, f); }
std::optional<Type> type_from_name(std::string_view word) { return lookup(kTypes, word); }
std::optional<StandardBlock> block_from_name(std::string_view word) { return lookup(kBlocks, word); }
std::optional<Function> function_from_name(std::string_view word) { return lookup(kFunctions, word); }

std::string_view section_keyword(Section s) {
  switch (s) {
    case Section::Local: return "VAR";
    case Section::Input: return "VAR_INPUT";
    case Section::Output: return "VAR_OUTPUT";
    case Section::InOut: return "VAR_IN_OUT";
    case Section::Constant: return "VAR CONSTANT";
  }
  return "VAR";
}

std::string_view unary_text(UnaryOp op) { return op == UnaryOp::Not ? "NOT" : "-"; }

std::string_view binary_text(BinaryOp op) {
  switch (op) {
    case BinaryOp::Or: return "OR";
    case BinaryOp::Xor: return "XOR";
    case BinaryOp::And: return "AND";
    case BinaryOp::Eq: return "=";
    case BinaryOp::Ne: return "<>";
    case BinaryOp::Lt: return "<";
    case BinaryOp::Le: return "<=";
    case BinaryOp::Gt: return ">";
    case BinaryOp::Ge: return ">=";
    case BinaryOp::Add: return "+";
    case BinaryOp::Sub: return "-";
    case BinaryOp::Mul: return "*";
    case BinaryOp::Div: return "/";
    case BinaryOp::Mod: return "MOD";
  }
  return "?";
}

namespace {
std::string time_text(std::int64_t ms) {
  std::string out = "T#";
  if (ms < 0) out += '-';
  std::uint64_t rest = ms < 0 ? 0 - static_cast<std::uint64_t>(ms) : static_cast<std::uint64_t>(ms);
  if (rest == 0) return out + "0s";
  struct Unit {
    std::uint64_t ms;
    const char* name;
  };
  static constexpr Unit units[] = {{86400000, "d"}, {3600000, "h"}, {60000, "m"}, {1000, "s"}, {1, "ms"}};
  for (const Unit& u : units) {
    if (rest >= u.ms) {
      out += std::to_string(rest / u.ms) + u.name;
      rest %= u.ms;
    }
  }
  return out;
}
}  // namespace

std::string literal_text(const Literal& l) {
  switch (l.type) {
    case Type::Bool: return l.integer ? "TRUE" : "FALSE";
    case Type::Int:
    case Type::Dint: return std::to_string(l.integer);
    case Type::Time: return time_text(l.integer);
    case Type::Real: {
      std::string s = model::float_text(l.real);
      // the ST reader wants a decimal point in every REAL literal
      if (s.find('.') == std::string::npos) {
        const std::size_t e = s.find_first_of("eE");
        s.insert(e == std::string::npos ? s.size() : e, ".0");
      }
      return s;
    }
  }
  return "?";
}

const std::vector<PinInfo>& block_pins(StandardBlock b) {
  static const std::vector<PinInfo> timer = {
      {Pin::In, Type::Bool, true}, {Pin::Pt, Type::Time, true}, {Pin::Q, Type::Bool, false}, {Pin::Et, Type::Time, false}};
  static const std::vector<PinInfo> trig = {{Pin::Clk, Type::Bool, true}, {Pin::Q, Type::Bool, false}};
  static const std::vector<PinInfo> sr = {
      {Pin::S1, Type::Bool, true}, {Pin::R, Type::Bool, true}, {Pin::Q1, Type::Bool, false}};
  static const std::vector<PinInfo> rs = {
      {Pin::S, Type::Bool, true}, {Pin::R1, Type::Bool, true}, {Pin::Q1, Type::Bool, false}};
  switch (b) {
    case StandardBlock::Ton:
    case StandardBlock::Tof:
    case StandardBlock::Tp: return timer;
    case StandardBlock::RTrig:
    case StandardBlock::FTrig: return trig;
    case StandardBlock::Sr: return sr;
    case StandardBlock::Rs: return rs;
  }
  return timer;
}

const Pou* find_pou(const Program& p, std::string_view name) {
  for (const Pou& pou : p.pous)
    if (same_name(pou.name, name)) return &pou;
  return nullptr;
}

const Variable* find_variable(const Pou& pou, std::string_view name) {
  for (const Variable& v : pou.variables)
    if (same_name(v.name, name)) return &v;
  return nullptr;
}

}  // namespace cemv::plc
