#include "properties/build.hpp"

#include <stdexcept>
#include <variant>

#include "properties/print.hpp"

namespace cemv::properties::build {

const char* to_string(CauseField f) {
  switch (f) {
    case CauseField::Active: return "active";
    case CauseField::TripRequested: return "trip_requested";
    case CauseField::TrippedTags: return "tripped_tags";
    case CauseField::Voting: return "voting";
    case CauseField::Degraded: return "degraded";
    case CauseField::Bypassed: return "bypassed";
    case CauseField::SoftBypassed: return "soft_bypassed";
    case CauseField::Inhibited: return "inhibited";
    case CauseField::AckRequired: return "ack_required";
    case CauseField::FirstOut: return "first_out";
    case CauseField::HysteresisActive: return "hysteresis_active";
    case CauseField::DeltaAlarm: return "delta_alarm";
    case CauseField::Prewarning: return "prewarning";
    case CauseField::TimerRunning: return "timer_running";
    case CauseField::BypassTimeout: return "bypass_timeout";
    case CauseField::BypassPrealarm: return "bypass_prealarm";
  }
  return "active";
}

const char* to_string(EffectField f) {
  switch (f) {
    case EffectField::Active: return "active";
    case EffectField::Latched: return "latched";
    case EffectField::OkToReset: return "ok_to_reset";
    case EffectField::OverrideActive: return "override_active";
    case EffectField::OverrideFailedTimeout: return "override_failed_timeout";
    case EffectField::OverrideFailedCause: return "override_failed_cause";
    case EffectField::OverridePrealarm: return "override_prealarm";
    case EffectField::Bypassed: return "bypassed";
    case EffectField::SoftBypassed: return "soft_bypassed";
    case EffectField::Masked: return "masked";
    case EffectField::PassThroughActive: return "pass_through_active";
    case EffectField::OutputDelayRunning: return "output_delay_running";
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

Expr Builder::effect_tag(int id, int k) const { return Expr::of_observable(resolved(names_.effect_tag(id, k))); }

Expr Builder::tag(const std::string& name) const {
  auto r = names_.tag(name);
  if (auto* why = std::get_if<std::string>(&r)) throw std::logic_error("generated property: " + *why);
  const TagRef t = std::get<TagRef>(std::move(r));
  if (t.input) return Expr::input_value(*t.input, names_.inputs().tags()[*t.input].kind);
  return Expr::of_observable(*t.value);
}

Expr Builder::bad(const std::string& tag) const { return Expr::input_bad(*input_tag(names_, tag).input); }

Expr Builder::issued(model::CommandOp op, int cause, int effect, std::optional<bool> on) {
  CommandPattern p;
  p.op = op;
  if (cause > 0) p.cause = cause;
  if (effect > 0) p.effect = effect;
  p.on = on;
  return Expr::issued(std::move(p));
}

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

Property Builder::reachable(std::string name, std::string description, Expr body, std::vector<Expr> assumptions) {
  Property p = invariant(std::move(name), std::move(description), std::move(body), std::move(assumptions));
  p.kind = PropertyKind::Reachable;
  return p;
}

Property Builder::never(std::string name, std::string description, Expr body, std::vector<Expr> assumptions) {
  Property p = invariant(std::move(name), std::move(description), std::move(body), std::move(assumptions));
  p.kind = PropertyKind::Never;
  return p;
}

Property Builder::response(std::string name, std::string description, Expr trigger, Expr response, int cycles,
                           std::vector<Expr> assumptions) {
  Property p = invariant(std::move(name), std::move(description), Expr::boolean(true), std::move(assumptions));
  p.kind = PropertyKind::Response;
  p.body = Expr{};
  p.trigger = std::move(trigger);
  p.response = std::move(response);
  p.within_cycles = cycles;
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

std::string file_text(const PropertyFile& f, const model::InputTable& inputs) {
  std::string out;
  for (const auto& a : f.assumptions) out += "assume " + to_text(a.expr, inputs) + "\n";
  for (const auto& p : f.properties) out += block_text(p, inputs);
  return out;
}

}  // namespace cemv::properties::build
