#include "properties/print.hpp"

#include <algorithm>
#include <cctype>

#include "model/text.hpp"

namespace cemv::properties {

namespace {

using Kind = Expr::Kind;

const char* op_text(CompareOp op) {
  switch (op) {
    case CompareOp::Eq: return "==";
    case CompareOp::Ne: return "!=";
    case CompareOp::Lt: return "<";
    case CompareOp::Le: return "<=";
    case CompareOp::Gt: return ">";
    case CompareOp::Ge: return ">=";
  }
  return "?";
}

// A tag name as the language reads it back: bare when it is an identifier that
// cannot be a keyword (keywords are lower case), else quoted.
std::string tag_text(const std::string& name) {
  bool bare = !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
  bool lower = true;
  for (char c : name) {
    bare = bare && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    lower = lower && !std::isupper(static_cast<unsigned char>(c));
  }
  bare = bare && !lower;
  if (bare) return name;
  std::string out = "\"";
  for (char c : name) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// Binding strength, loosest 0: iff, implies, or, and, not, comparison/operand.
int strength(const Expr& e) {
  switch (e.kind) {
    case Kind::Iff: return 0;
    case Kind::Implies: return 1;
    case Kind::Or: return e.args.empty() ? 5 : 2;
    case Kind::And: return e.args.empty() ? 5 : 3;
    case Kind::Not: return 4;
    default: return 5;
  }
}

class Printer {
 public:
  explicit Printer(const model::InputTable& inputs) : inputs_(inputs) {}

  std::string text(const Expr& e) const {
    switch (e.kind) {
      case Kind::BoolConst: return e.bool_value ? "true" : "false";
      case Kind::IntConst:
        return e.type == ExprType::Voting ? model::to_string(static_cast<model::Voting>(e.int_value))
                                          : std::to_string(e.int_value);
      case Kind::FloatConst: {
        std::string s = model::float_text(e.float_value);
        return s.find_first_of(".eEn") == std::string::npos ? s + ".0" : s;
      }
      case Kind::Observable: return e.observable.key;
      case Kind::InputValue: return tag_text(inputs_.tags().at(e.input).name);
      case Kind::InputBad: return "bad(" + tag_text(inputs_.tags().at(e.input).name) + ")";
      case Kind::CommandIssued: return issued(e.command);
      case Kind::Compare: return text(e.args[0]) + " " + op_text(e.cmp) + " " + text(e.args[1]);
      case Kind::Not: return "not " + child(e.args[0], 4);
      case Kind::And:
      case Kind::Or: {
        if (e.args.empty()) return e.kind == Kind::And ? "true" : "false";
        std::string out;
        int own = strength(e);
        for (const auto& a : e.args) out += (out.empty() ? "" : e.kind == Kind::And ? " and " : " or ") + child(a, own + 1);
        return out;
      }
      case Kind::Implies: return child(e.args[0], 2) + " implies " + child(e.args[1], 1);
      case Kind::Iff: return child(e.args[0], 1) + " iff " + child(e.args[1], 1);
      case Kind::Count: {
        std::string out;
        for (const auto& a : e.args) out += (out.empty() ? "" : ", ") + text(a);
        return "count(" + out + ")";
      }
      case Kind::Prev: return "prev(" + text(e.args[0]) + ")";
      case Kind::Rose: return "rose(" + text(e.args[0]) + ")";
      case Kind::Fell: return "fell(" + text(e.args[0]) + ")";
      case Kind::Held:
      case Kind::Within:
        return std::string(e.kind == Kind::Held ? "held(" : "within(") + text(e.args[0]) + ", " +
               std::to_string(e.cycles) + " cycles)";
      case Kind::Since: return "since(" + text(e.args[0]) + ", " + text(e.args[1]) + ")";
    }
    return "?";
  }

 private:
  // A sub-expression, parenthesised when it binds more loosely than its place needs.
  std::string child(const Expr& e, int needed) const {
    std::string t = text(e);
    return strength(e) < needed ? "(" + t + ")" : t;
  }

  static std::string issued(const CommandPattern& p) {
    std::string out = std::string("issued(") + model::to_string(p.op);
    if (p.cause) out += ", cause = " + std::to_string(*p.cause);
    if (p.effect) out += ", effect = " + std::to_string(*p.effect);
    if (p.tag) out += ", tag = " + std::to_string(*p.tag);
    if (p.tag_name) out += ", tag = " + tag_text(*p.tag_name);
    if (p.group) out += ", group = " + std::to_string(*p.group);
    if (p.on) out += std::string(", on = ") + (*p.on ? "true" : "false");
    return out + ")";
  }

  const model::InputTable& inputs_;
};

void collect(const Expr& e, Signals& s) {
  if (e.kind == Kind::InputValue || e.kind == Kind::InputBad) {
    if (std::find(s.inputs.begin(), s.inputs.end(), e.input) == s.inputs.end()) s.inputs.push_back(e.input);
  } else if (e.kind == Kind::Observable) {
    if (std::find(s.observables.begin(), s.observables.end(), e.observable.key) == s.observables.end())
      s.observables.push_back(e.observable.key);
  } else if (e.kind == Kind::CommandIssued) {
    s.commands = true;
  }
  for (const auto& a : e.args) collect(a, s);
}

}  // namespace

std::string to_text(const Expr& e, const model::InputTable& inputs) { return Printer(inputs).text(e); }

std::string statement_text(const Property& p, const model::InputTable& inputs) {
  Printer printer(inputs);
  switch (p.kind) {
    case PropertyKind::Invariant: return "always " + printer.text(p.body);
    case PropertyKind::Never: return "never " + printer.text(p.body);
    case PropertyKind::Reachable: return "reachable " + printer.text(p.body);
    case PropertyKind::Response:
      return "whenever " + printer.text(p.trigger) + " then " + printer.text(p.response) + " within " +
             std::to_string(p.within_cycles) + " cycles";
  }
  return "?";
}

Signals signals_of(const Property& p, const std::vector<Assumption>& file_assumptions) {
  Signals s;
  if (p.kind == PropertyKind::Response) {
    collect(p.trigger, s);
    collect(p.response, s);
  } else {
    collect(p.body, s);
  }
  for (const auto& a : p.assumptions) collect(a.expr, s);
  for (const auto& a : file_assumptions) collect(a.expr, s);
  return s;
}

}  // namespace cemv::properties
