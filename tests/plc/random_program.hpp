// A seeded generator of random, well-typed programs of the whole subset
// (docs/plc.md P.1-P.7): every statement, operator, function, literal kind
// and standard block, a user block with an in-out, nested.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "plc/ast.hpp"

namespace cemv::plc::test {

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  Program program() {
    Program p;
    p.pous.push_back(user_block());
    Pou main;
    main.name = "Main";
    auto add = [&](const std::string& name, Section s, VarType t, std::optional<Literal> init = {}) {
      main.variables.push_back(Variable{{}, name, s, t, init, {}, {}});
    };
    auto el = [](Type t) { return VarType{VarType::Kind::Elementary, t, {}, {}}; };
    for (int i = 0; i < 3; ++i) add("b" + std::to_string(i), Section::Input, el(Type::Bool));
    add("i0", Section::Input, el(Type::Int));
    add("r0", Section::Input, el(Type::Real));
    add("t0", Section::Input, el(Type::Time));
    add("ob", Section::Output, el(Type::Bool), Literal{Type::Bool, 1, 0});
    add("oi", Section::Output, el(Type::Int), Literal{Type::Int, -7, 0});
    add("od", Section::Output, el(Type::Dint));
    add("io", Section::InOut, el(Type::Int));
    add("lb", Section::Local, el(Type::Bool));
    add("li", Section::Local, el(Type::Int));
    add("ld", Section::Local, el(Type::Dint), Literal{Type::Dint, 100000, 0});
    add("lr", Section::Local, el(Type::Real), Literal{Type::Real, 0, -2.25f});
    add("lt", Section::Local, el(Type::Time), Literal{Type::Time, 90000, 0});
    add("k", Section::Local, el(Type::Int));
    add("KI", Section::Constant, el(Type::Int), Literal{Type::Int, 3, 0});
    add("KR", Section::Constant, el(Type::Real), Literal{Type::Real, 0, 2.5f});
    for (StandardBlock b : kBlocks)
      add(std::string(block_name(b)) + "_1", Section::Local, VarType{VarType::Kind::Standard, Type::Bool, b, {}});
    add("u", Section::Local, VarType{VarType::Kind::User, Type::Bool, {}, "Helper"});
    vars_ = &main.variables;
    const int n = 3 + pick(6);
    for (int i = 0; i < n; ++i) main.body.push_back(statement(3));
    p.pous.push_back(std::move(main));
    return p;
  }

 private:
  static constexpr StandardBlock kBlocks[] = {StandardBlock::Ton,   StandardBlock::Tof, StandardBlock::Tp,
                                              StandardBlock::RTrig, StandardBlock::FTrig, StandardBlock::Sr,
                                              StandardBlock::Rs};
  std::mt19937_64 rng_;
  const std::vector<Variable>* vars_ = nullptr;
  bool in_for_ = false;  // FOR loops do not nest: they share `k`

  int pick(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }
  bool coin() { return pick(2) == 0; }

  Pou user_block() {
    Pou fb;
    fb.kind = PouKind::FunctionBlock;
    fb.name = "Helper";
    fb.variables = {Variable{{}, "x", Section::Input, {VarType::Kind::Elementary, Type::Bool, {}, {}}, {}, {}, {}},
                    Variable{{}, "y", Section::Output, {VarType::Kind::Elementary, Type::Bool, {}, {}}, {}, {}, {}},
                    Variable{{}, "n", Section::InOut, {VarType::Kind::Elementary, Type::Int, {}, {}}, {}, {}, {}}};
    Statement s;
    s.target = "y";
    s.value = var("x", Type::Bool);
    fb.body.push_back(s);
    return fb;
  }

  static Expr var(const std::string& name, Type t) {
    Expr e;
    e.kind = Expr::Kind::Variable;
    e.name = name;
    e.type = t;
    return e;
  }
  static Expr lit(Type t, std::int64_t i, float r = 0) {
    Expr e;
    e.kind = Expr::Kind::Literal;
    e.type = t;
    e.literal = Literal{t, i, r};
    return e;
  }
  static Expr node(Expr::Kind k, Type t, std::vector<Expr> args) {
    Expr e;
    e.kind = k;
    e.type = t;
    e.args = std::move(args);
    return e;
  }

  std::vector<std::string> readable(Type t) const {
    std::vector<std::string> out;
    for (const Variable& v : *vars_)
      if (v.type.kind == VarType::Kind::Elementary && v.type.type == t) out.push_back(v.name);
    return out;
  }
  std::vector<std::string> writable(Type t) const {
    std::vector<std::string> out;
    for (const Variable& v : *vars_)
      if (v.type.kind == VarType::Kind::Elementary && v.type.type == t && v.name != "k" &&
          (v.section == Section::Local || v.section == Section::Output || v.section == Section::InOut))
        out.push_back(v.name);
    return out;
  }

  Expr literal(Type t) {
    switch (t) {
      case Type::Bool: return lit(t, pick(2));
      case Type::Int: return lit(t, pick(200) - 100);
      case Type::Dint: return lit(t, static_cast<std::int64_t>(rng_() % 4000000) - 2000000);
      case Type::Real: return lit(t, 0, static_cast<float>(pick(81) - 40) / 4.0f);
      case Type::Time: return lit(t, pick(5) * 60000 + pick(60) * 1000 + pick(3) * 250);
    }
    return lit(t, 0);
  }

  Expr leaf(Type t) {
    const auto vs = readable(t);
    if (t == Type::Bool && pick(3) == 0) {
      const StandardBlock b = kBlocks[pick(7)];
      Expr e;
      e.kind = Expr::Kind::Member;
      e.type = Type::Bool;
      e.name = std::string(block_name(b)) + "_1";
      e.pin = b == StandardBlock::Sr || b == StandardBlock::Rs ? Pin::Q1 : Pin::Q;
      e.member = std::string(pin_name(*e.pin));
      return e;
    }
    if (t == Type::Bool && pick(6) == 0) {
      Expr e;
      e.kind = Expr::Kind::Member;
      e.type = Type::Bool;
      e.name = "u";
      e.member = "y";
      return e;
    }
    if (t == Type::Time && pick(3) == 0) {
      Expr e;
      e.kind = Expr::Kind::Member;
      e.type = Type::Time;
      e.name = "TON_1";
      e.pin = Pin::Et;
      e.member = "ET";
      return e;
    }
    if (!vs.empty() && coin()) return var(vs[static_cast<std::size_t>(pick(static_cast<int>(vs.size())))], t);
    return literal(t);
  }

  Expr expression(Type t, int depth) {
    if (depth == 0 || pick(4) == 0) return leaf(t);
    auto bin = [&](BinaryOp op, Type operand) {
      Expr e = node(Expr::Kind::Binary, t, {expression(operand, depth - 1), expression(operand, depth - 1)});
      e.binary = op;
      return e;
    };
    auto fn = [&](Function f, std::vector<Expr> args) {
      Expr e = node(Expr::Kind::Call, t, std::move(args));
      e.function = f;
      return e;
    };
    if (t == Type::Bool) {
      switch (pick(6)) {
        case 0: {
          Expr e = node(Expr::Kind::Unary, t, {expression(t, depth - 1)});
          e.unary = UnaryOp::Not;
          return e;
        }
        case 1: return bin(static_cast<BinaryOp>(pick(3)), Type::Bool);  // OR, XOR, AND
        case 2: return bin(coin() ? BinaryOp::Eq : BinaryOp::Ne, Type::Bool);
        case 3: return fn(Function::Sel, {expression(Type::Bool, depth - 1), expression(t, depth - 1), expression(t, depth - 1)});
        default: {
          static constexpr Type kOrdered[] = {Type::Int, Type::Dint, Type::Real, Type::Time};
          return bin(static_cast<BinaryOp>(3 + pick(6)), kOrdered[pick(4)]);  // = <> < <= > >=
        }
      }
    }
    const bool integer = t == Type::Int || t == Type::Dint;
    switch (pick(7)) {
      case 0: return bin(coin() ? BinaryOp::Add : BinaryOp::Sub, t);
      case 1:
        if (t != Type::Time) return bin(BinaryOp::Mul, t);
        return fn(coin() ? Function::Min : Function::Max, {expression(t, depth - 1), expression(t, depth - 1)});
      case 2: {
        if (t == Type::Time) return leaf(t);
        Expr divisor = literal(t);
        if (divisor.literal.integer == 0 && divisor.literal.real == 0) divisor = t == Type::Real ? lit(t, 0, 0.5f) : lit(t, 3);
        if (integer && coin()) divisor = var("KI", Type::Int);
        if (divisor.kind == Expr::Kind::Variable && t != Type::Int) divisor = lit(t, 3);
        Expr e = node(Expr::Kind::Binary, t, {expression(t, depth - 1), divisor});
        e.binary = integer && coin() ? BinaryOp::Mod : BinaryOp::Div;
        return e;
      }
      case 3: {
        Expr e = node(Expr::Kind::Unary, t, {expression(t, depth - 1)});
        e.unary = UnaryOp::Negate;
        return e;
      }
      case 4:
        if (t == Type::Time) return leaf(t);
        return fn(Function::Abs, {expression(t, depth - 1)});
      case 5: return fn(Function::Limit, {expression(t, depth - 1), expression(t, depth - 1), expression(t, depth - 1)});
      default: {
        std::vector<Expr> args;
        for (int i = 0, n = 2 + pick(2); i < n; ++i) args.push_back(expression(t, depth - 1));
        return fn(coin() ? Function::Min : Function::Max, std::move(args));
      }
    }
  }

  std::vector<Statement> block(int depth) {
    std::vector<Statement> out;
    for (int i = 0, n = pick(3); i < n; ++i) out.push_back(statement(depth - 1));
    return out;
  }

  Statement assignment() {
    static constexpr Type kTypes[] = {Type::Bool, Type::Int, Type::Dint, Type::Real, Type::Time};
    const Type t = kTypes[pick(5)];
    const auto ws = writable(t);
    Statement s;
    s.target = ws[static_cast<std::size_t>(pick(static_cast<int>(ws.size())))];
    s.value = expression(t, 3);
    return s;
  }

  Statement call() {
    Statement s;
    s.kind = Statement::Kind::Call;
    if (pick(4) == 0) {
      s.target = "u";
      s.args.push_back(CallArg{{}, "x", {}, false, expression(Type::Bool, 2)});
      s.args.push_back(CallArg{{}, "n", {}, false, var(writable(Type::Int)[0], Type::Int)});
      if (coin()) s.args.push_back(CallArg{{}, "y", {}, true, var("lb", Type::Bool)});
      return s;
    }
    const StandardBlock b = kBlocks[pick(7)];
    s.target = std::string(block_name(b)) + "_1";
    for (const PinInfo& p : block_pins(b)) {
      if (coin()) continue;
      if (p.input) {
        s.args.push_back(CallArg{{}, std::string(pin_name(p.pin)), p.pin, false, expression(p.type, 2)});
      } else {
        const auto ws = writable(p.type);
        s.args.push_back(CallArg{{}, std::string(pin_name(p.pin)), p.pin, true,
                                 var(ws[static_cast<std::size_t>(pick(static_cast<int>(ws.size())))], p.type)});
      }
    }
    return s;
  }

  Statement statement(int depth) {
    if (depth <= 0) return assignment();
    switch (pick(6)) {
      case 0: {
        Statement s;
        s.kind = Statement::Kind::If;
        for (int i = 0, n = 1 + pick(3); i < n; ++i) s.branches.push_back(Branch{expression(Type::Bool, 2), block(depth)});
        s.has_else = coin();
        if (s.has_else) s.else_body = block(depth);
        return s;
      }
      case 1: {
        Statement s;
        s.kind = Statement::Kind::Case;
        s.value = expression(coin() ? Type::Int : Type::Dint, 1);
        std::int64_t next = -5 + pick(5);
        for (int i = 0, n = 1 + pick(3); i < n; ++i) {
          CaseArm arm;
          for (int j = 0, m = 1 + pick(2); j < m; ++j) {
            const std::int64_t lo = next + pick(3);
            const std::int64_t hi = coin() ? lo : lo + pick(4);
            arm.labels.push_back(CaseRange{lo, hi});
            next = hi + 1;
          }
          arm.body = block(depth);
          s.arms.push_back(std::move(arm));
        }
        s.has_else = coin();
        if (s.has_else) s.else_body = block(depth);
        return s;
      }
      case 2: {
        if (in_for_) return assignment();
        Statement s;
        s.kind = Statement::Kind::For;
        s.target = "k";
        s.value = coin() ? lit(Type::Int, pick(7) - 3) : var("KI", Type::Int);
        s.limit = lit(Type::Int, pick(7) - 3);
        s.step = lit(Type::Int, coin() ? 1 + pick(2) : -1 - pick(2));
        in_for_ = true;
        s.body = block(depth);
        in_for_ = false;
        return s;
      }
      case 3:
      case 4: return call();
      default: return assignment();
    }
  }
};

}  // namespace cemv::plc::test
