#include "properties/build.hpp"

#include <stdexcept>
#include <variant>

#include "properties/print.hpp"

namespace cemv::properties::build {

const char* to_string(CauseField f) {
  switch (f) {
    case CauseField::Active: return "active";
    case CauseField::TripRequested: return "trip_requested";
    case CauseField::Voting: return "voting";
  }
  return "active";
}

const char* to_string(EffectField f) {
  switch (f) {
    case EffectField::Active: return "active";
    case EffectField::Bypassed: return "bypassed";
    case EffectField::OverrideActive: return "override_active";
    case EffectField::OutputDelayRunning: return "output_delay_running";
    case EffectField::Latched: return "latched";
  }
  return "active";
}

namespace {

model::Observable resolved(std::variant<model::Observable, std::string> r) {
  if (auto* why = std::get_if<std::string>(&r)) throw std::logic_error("generated property: " + *why);
  return std::get<model::Observable>(std::move(r));
}

TagRef input_tag(const MatrixNames& names, const std::string& tag) {
  auto r = names.tag(tag);
  if (auto* why = std::get_if<std::string>(&r)) throw std::logic_error("generated property: " + *why);
  TagRef t = std::get<TagRef>(std::move(r));
  if (!t.input) throw std::logic_error("generated property: " + tag + " is no input tag");
  return t;
}

}  // namespace

Expr Builder::cause(int id, CauseField f) const {
  return Expr::of_observable(resolved(names_.cause_field(id, to_string(f))));
}

Expr Builder::effect(int id, EffectField f) const {
  return Expr::of_observable(resolved(names_.effect_field(id, to_string(f))));
}

Expr Builder::bad(const std::string& tag) const { return Expr::input_bad(*input_tag(names_, tag).input); }

Expr Builder::simulate_issued(const std::string& tag) const {
  CommandPattern p;
  p.op = model::CommandOp::SimulateTag;
  p.tag_name = input_tag(names_, tag).name;
  return Expr::issued(std::move(p));
}

Expr Builder::at_least(std::vector<Expr> args, int n) {
  return Expr::compare(CompareOp::Ge, Expr::nary(Expr::Kind::Count, std::move(args)), Expr::integer(n));
}

Expr Builder::voting_is_not(Expr voting, model::Voting v) {
  return Expr::compare(CompareOp::Ne, std::move(voting), Expr::voting(v));
}

Property Builder::invariant(std::string name, std::string description, Expr body, std::vector<Expr> assumptions) {
  Property p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.kind = PropertyKind::Invariant;
  p.body = std::move(body);
  for (auto& a : assumptions) p.assumptions.push_back(Assumption{"", std::move(a), {}});
  return p;
}

Property Builder::reachable(std::string name, std::string description, Expr body) {
  Property p;
  p.name = std::move(name);
  p.description = std::move(description);
  p.kind = PropertyKind::Reachable;
  p.body = std::move(body);
  return p;
}

std::string block_text(const Property& p, const model::InputTable& inputs) {
  std::string out = "property " + p.name;
  if (!p.description.empty()) {
    out += " \"";
    for (char ch : p.description) {
      if (ch == '\\' || ch == '"') out += '\\';
      out += ch;
    }
    out += "\"";
  }
  out += " {\n";
  for (const auto& a : p.assumptions) out += "  assume " + to_text(a.expr, inputs) + "\n";
  return out + "  " + statement_text(p, inputs) + "\n}\n";
}

}  // namespace cemv::properties::build
