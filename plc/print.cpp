#include "plc/print.hpp"

namespace cemv::plc {

namespace {

// Binding strength, loosest first (IEC 61131-3 Table 71).
int precedence(const Expr& e) {
  if (e.kind == Expr::Kind::Unary) return 7;
  if (e.kind != Expr::Kind::Binary) return 8;
  switch (e.binary) {
    case BinaryOp::Or: return 0;
    case BinaryOp::Xor: return 1;
    case BinaryOp::And: return 2;
    case BinaryOp::Eq:
    case BinaryOp::Ne: return 3;
    case BinaryOp::Lt:
    case BinaryOp::Le:
    case BinaryOp::Gt:
    case BinaryOp::Ge: return 4;
    case BinaryOp::Add:
    case BinaryOp::Sub: return 5;
    default: return 6;
  }
}

std::string wrapped(const Expr& e, bool parens) {
  return parens ? "(" + print_expression(e) + ")" : print_expression(e);
}

// A comment as `(* ... *)` lines of at most about 100 columns at `indent`;
// a `*)` inside the text would end it early, so it is written `* )`.
std::string comment_lines(const std::string& text, const std::string& pad) {
  std::string safe;
  for (std::size_t i = 0; i < text.size(); ++i) {
    safe += text[i];
    if (text[i] == '*' && i + 1 < text.size() && text[i + 1] == ')') safe += ' ';
    if (text[i] == '(' && i + 1 < text.size() && text[i + 1] == '*') safe += ' ';
  }
  std::string out;
  std::string line = pad + "(*";
  std::size_t start = 0;
  while (start < safe.size()) {
    std::size_t end = safe.find_first_of(" \n", start);
    if (end == std::string::npos) end = safe.size();
    const std::string word = safe.substr(start, end - start);
    if (!word.empty()) {
      if (line.size() + 1 + word.size() > 100 && line.size() > pad.size() + 3) {
        out += line + "\n";
        line = pad + "  ";
      }
      line += " " + word;
    }
    if (end < safe.size() && safe[end] == '\n' && line.size() > pad.size() + 3) {
      out += line + "\n";
      line = pad + "  ";
    }
    start = end + 1;
  }
  return out + line + " *)\n";
}

void body(std::string& out, const std::vector<Statement>& statements, int indent) {
  for (const Statement& s : statements) out += print_statement(s, indent);
}

}  // namespace

std::string print_expression(const Expr& e) {
  switch (e.kind) {
    case Expr::Kind::Literal: return literal_text(e.literal);
    case Expr::Kind::Variable: return e.name;
    case Expr::Kind::Member: return e.name + "." + e.member;
    case Expr::Kind::Unary: {
      const Expr& a = e.args[0];
      if (e.unary == UnaryOp::Not) return "NOT " + wrapped(a, precedence(a) < 7);
      // `-(5)`: `-5` would read back as a signed literal
      return "-" + wrapped(a, a.kind != Expr::Kind::Variable && a.kind != Expr::Kind::Member &&
                                  a.kind != Expr::Kind::Call);
    }
    case Expr::Kind::Binary: {
      const int p = precedence(e);
      return wrapped(e.args[0], precedence(e.args[0]) < p) + " " + std::string(binary_text(e.binary)) + " " +
             wrapped(e.args[1], precedence(e.args[1]) <= p);
    }
    case Expr::Kind::Call: {
      std::string out = std::string(function_name(e.function)) + "(";
      for (std::size_t i = 0; i < e.args.size(); ++i) out += (i ? ", " : "") + print_expression(e.args[i]);
      return out + ")";
    }
  }
  return "";
}

std::string print_statement(const Statement& s, int indent) {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::string out = s.comment.empty() ? "" : comment_lines(s.comment, pad);
  switch (s.kind) {
    case Statement::Kind::Assign: return out + pad + s.target + " := " + print_expression(s.value) + ";\n";
    case Statement::Kind::If:
      for (std::size_t i = 0; i < s.branches.size(); ++i) {
        out += pad + (i ? "ELSIF " : "IF ") + print_expression(s.branches[i].condition) + " THEN\n";
        body(out, s.branches[i].body, indent + 2);
      }
      if (s.has_else) {
        out += pad + "ELSE\n";
        body(out, s.else_body, indent + 2);
      }
      return out + pad + "END_IF;\n";
    case Statement::Kind::Case:
      out += pad + "CASE " + print_expression(s.value) + " OF\n";
      for (const CaseArm& arm : s.arms) {
        out += pad + "  ";
        for (std::size_t i = 0; i < arm.labels.size(); ++i) {
          const CaseRange& r = arm.labels[i];
          out += (i ? ", " : "") + std::to_string(r.low);
          if (r.high != r.low) out += ".." + std::to_string(r.high);
        }
        out += ":\n";
        body(out, arm.body, indent + 4);
      }
      if (s.has_else) {
        out += pad + "  ELSE\n";
        body(out, s.else_body, indent + 4);
      }
      return out + pad + "END_CASE;\n";
    case Statement::Kind::For:
      out += pad + "FOR " + s.target + " := " + print_expression(s.value) + " TO " + print_expression(s.limit) +
             " BY " + print_expression(s.step) + " DO\n";
      body(out, s.body, indent + 2);
      return out + pad + "END_FOR;\n";
    case Statement::Kind::Call:
      out += pad + s.target + "(";
      for (std::size_t i = 0; i < s.args.size(); ++i)
        out += (i ? ", " : "") + s.args[i].name + (s.args[i].output ? " => " : " := ") + print_expression(s.args[i].value);
      return out + ");\n";
  }
  return out;
}

std::string print_pou(const Pou& pou) {
  std::string out = pou.comment.empty() ? "" : comment_lines(pou.comment, "");
  out += (pou.kind == PouKind::Program ? "PROGRAM " : "FUNCTION_BLOCK ") + pou.name + "\n";
  for (std::size_t i = 0; i < pou.variables.size();) {
    const Section section = pou.variables[i].section;
    out += std::string(section_keyword(section)) + "\n";
    for (; i < pou.variables.size() && pou.variables[i].section == section; ++i) {
      const Variable& v = pou.variables[i];
      out += "  " + v.name + " : ";
      switch (v.type.kind) {
        case VarType::Kind::Elementary: out += type_name(v.type.type); break;
        case VarType::Kind::Standard: out += block_name(v.type.block); break;
        case VarType::Kind::User: out += v.type.user; break;
      }
      if (v.initial) out += " := " + literal_text(*v.initial);
      out += ";";
      if (!v.comment.empty()) out += " " + comment_lines(v.comment, "");
      else out += "\n";
    }
    out += "END_VAR\n";
  }
  body(out, pou.body, 2);
  return out + (pou.kind == PouKind::Program ? "END_PROGRAM\n" : "END_FUNCTION_BLOCK\n");
}

std::string print_program(const Program& p) {
  std::string out;
  for (std::size_t i = 0; i < p.pous.size(); ++i) out += (i ? "\n" : "") + print_pou(p.pous[i]);
  return out;
}

}  // namespace cemv::plc
