// The interface of the generated program (inputs, outputs, commands), the
// matrix level (M.1-M.3), the evaluation order (I.4) and the map.
#include "plc_export/export.hpp"
#include "model/simulation.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "plc/parser.hpp"
#include "plc_export/generator.hpp"
#include "plc_export/st_build.hpp"

namespace cemv::plc_export {

namespace {

using model::CommandOp;
using model::IntersectionType;

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

// Letters, digits and single underscores, not starting with a digit.
std::string identifier(const std::string& wanted) {
  std::string out;
  for (char ch : wanted) {
    const bool ok = std::isalnum(static_cast<unsigned char>(ch)) != 0;
    if (ok) out += ch;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty()) out = "X";
  if (std::isdigit(static_cast<unsigned char>(out.front()))) out = "T_" + out;
  return out;
}

bool processed(const model::Matrix& m, const model::Intersection& x) {
  const auto* c = m.find_cause(x.cause);
  const auto* e = m.find_effect(x.effect);
  return model::is_processed(x.type) && c && e && c->function != model::CauseFunction::Comment &&
         e->function != model::EffectFunction::Comment;
}

bool has_type(const model::Matrix& m, int effect, std::initializer_list<IntersectionType> types) {
  for (const auto* x : m.intersections_of_effect(effect))
    if (processed(m, *x) && std::find(types.begin(), types.end(), x->type) != types.end()) return true;
  return false;
}

bool has_ack_latch(const model::Cause& c) {
  return !c.auto_ack && (c.time.mode == model::TimeMode::None || c.time.mode == model::TimeMode::OnDelay);
}

std::string base_name(const std::string& name, const char* kind, int id) {
  return name.empty() ? std::string(kind) + "_" + std::to_string(id) : name;
}

}  // namespace

std::string element_label(const model::Cause& c) { return "cause " + std::to_string(c.id) + " " + c.name; }
std::string element_label(const model::Effect& e) { return "effect " + std::to_string(e.id) + " " + e.name; }

std::string Generator::claim(const std::string& wanted) {
  std::string name = identifier(wanted);
  if (plc::is_reserved_word(name)) name += "_V";
  std::string candidate = name;
  for (int n = 2; used_.count(upper(candidate)); ++n) candidate = name + "_" + std::to_string(n);
  used_.insert(upper(candidate));
  return candidate;
}

std::string Generator::local(const std::string& wanted, plc::Type type, const std::string& comment,
                             std::optional<plc::Literal> initial) {
  plc::Variable v = st::variable(claim(wanted), plc::Section::Local, type, comment);
  v.initial = initial;
  locals.push_back(v);
  return v.name;
}

std::string Generator::timer(const std::string& wanted, plc::StandardBlock b, const std::string& comment) {
  plc::Variable v = st::block(claim(wanted), b, comment);
  locals.push_back(v);
  return v.name;
}

plc::Expr Generator::tag_bool(const std::string& tag) const {
  if (auto ref = model::parse_internal_ref(tag)) {
    std::map<int, std::string>::const_iterator it;
    switch (ref->kind) {
      case model::InternalRef::Kind::Cause:
        it = cause_var.find(ref->id);
        return it == cause_var.end() ? st::boolean(false) : st::var(it->second);
      case model::InternalRef::Kind::Effect:
        it = effect_var.find(ref->id);
        return it == effect_var.end() ? st::boolean(false) : st::var(it->second);
      case model::InternalRef::Kind::EffectTag: {
        auto o = output_var.find({ref->id, ref->tag});
        return o == output_var.end() ? st::boolean(false) : st::var(o->second);
      }
    }
  }
  const auto i = inputs.find(tag);
  if (!i) return st::boolean(false);
  if (inputs.tags()[*i].kind == model::TagKind::Analog)
    return st::binary(plc::BinaryOp::Ne, st::var(input_var[*i], plc::Type::Real), st::real(0.0f), plc::Type::Bool);
  return st::var(input_var[*i]);
}

plc::Expr Generator::tag_real(const std::string& tag) const {
  const auto i = model::parse_internal_ref(tag) ? std::nullopt : inputs.find(tag);
  if (i && inputs.tags()[*i].kind == model::TagKind::Analog) return st::var(input_var[*i], plc::Type::Real);
  return st::sel(tag_bool(tag), st::real(0.0f), st::real(1.0f), plc::Type::Real);
}

plc::Expr Generator::tag_bad(const std::string& tag) const {
  const auto i = model::parse_internal_ref(tag) ? std::nullopt : inputs.find(tag);
  if (!i || bad_var[*i].empty()) return st::boolean(false);
  return st::var(bad_var[*i]);
}

plc::Expr Generator::command(const std::string& variable) const {
  plc::Expr c = st::var(variable);
  if (secure_write_var.empty()) return c;
  return st::and_(std::move(c), tag_bool(m.secure_write->enable_tag));
}

std::int64_t Generator::scans(std::uint64_t ms, const std::string& element) const {
  const std::uint64_t d = (ms + m.cycle_ms - 1) / m.cycle_ms;
  if (d > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
    throw Unsupported(element + ": a duration of " + std::to_string(ms) + " ms is " + std::to_string(d) +
                      " scans, more than a DINT counts");
  return static_cast<std::int64_t>(d);
}

plc::Expr Generator::preset(std::uint64_t ms, const std::string& element) const {
  if (ms > static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max()))
    throw Unsupported(element + ": a delay of " + std::to_string(ms) +
                      " ms is beyond the range of TIME (T#24d20h31m23s647ms)");
  return st::time_ms(static_cast<std::int64_t>(ms));
}

Generator::Generator(const model::Matrix& matrix) : m(matrix), inputs(matrix), graph(matrix) {
  // The interface first, so that tags keep their names: every input tag, the
  // bad quality of the cause inputs whose quality a cause reads, every output tag.
  input_var.resize(inputs.size());
  bad_var.resize(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const auto& t = inputs.tags()[i];
    const bool analog = t.kind == model::TagKind::Analog;
    input_var[i] = claim(t.name);
    in_vars.push_back(st::variable(input_var[i], plc::Section::Input, analog ? plc::Type::Real : plc::Type::Bool,
                                   "input tag " + t.name));
    bool quality = false;
    for (const auto& c : m.causes)
      if (c.function != model::CauseFunction::Comment && c.bad_quality != model::BadQuality::Ignore)
        for (const auto& ct : c.tags)
          if (model::tag_key(ct.name) == model::tag_key(t.name)) quality = true;
    if (quality) {
      bad_var[i] = claim(t.name + "_BQ");
      in_vars.push_back(st::variable(bad_var[i], plc::Section::Input, plc::Type::Bool,
                                     "TRUE while " + t.name + " is of bad quality (C.3)"));
    }
  }
  std::map<std::string, int> writers;
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment)
      for (const auto& t : e.tags) ++writers[model::tag_key(t.name)];
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    for (std::size_t j = 0; j < e.tags.size(); ++j) {
      const auto& t = e.tags[j];
      const bool shared = writers[model::tag_key(t.name)] > 1;
      const std::string name = claim(shared ? t.name + "_E" + std::to_string(e.id) : t.name);
      output_var[{e.id, static_cast<int>(j + 1)}] = name;
      out_vars.push_back(st::variable(name, plc::Section::Output, plc::Type::Bool,
                                      "output tag " + t.name + " of " + element_label(e) +
                                          (t.ett ? " (ETT: TRUE trips)" : " (DTT: FALSE trips)")));
    }
  }
  // The elements' own names, then the operator commands the program reads.
  for (const auto& c : m.causes)
    if (c.function != model::CauseFunction::Comment) {
      cause_var[c.id] = claim(base_name(c.name, "CAUSE", c.id));
      locals.push_back(st::variable(cause_var[c.id], plc::Section::Local, plc::Type::Bool,
                                    element_label(c) + " active (C.8), what Cause[" + std::to_string(c.id) + "] reads"));
    }
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment) {
      effect_var[e.id] = claim(base_name(e.name, "EFFECT", e.id));
      locals.push_back(st::variable(effect_var[e.id], plc::Section::Local, plc::Type::Bool,
                                    element_label(e) + " active (E.6), what Effect[" + std::to_string(e.id) + "] reads"));
    }
  auto command_input = [&](const std::string& wanted, const std::string& comment) {
    std::string name = claim(upper(identifier(wanted)));
    in_vars.push_back(st::variable(name, plc::Section::Input, plc::Type::Bool, comment));
    return name;
  };
  for (const auto& c : m.causes)
    if (c.function != model::CauseFunction::Comment && has_ack_latch(c))
      ack_var[c.id] = command_input(cause_var[c.id] + "_ACK", "operator command ack_cause of " + element_label(c) +
                                                                   ", TRUE in the scan it is issued (O.1)");
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment || e.reset_tag) continue;
    if (has_type(m, e.id, {IntersectionType::S, IntersectionType::R}))
      reset_var[e.id] = command_input(effect_var[e.id] + "_RESET", "operator command reset_effect of " +
                                                                     element_label(e) + " (O.2)");
    if (has_type(m, e.id, {IntersectionType::V, IntersectionType::R})) {
      override_var[e.id] = command_input(effect_var[e.id] + "_OVERRIDE", "operator command override_effect of " +
                                                                           element_label(e) + " (O.3)");
      stop_override_var[e.id] = command_input(effect_var[e.id] + "_STOP_OVERRIDE",
                                              "operator command stop_override of " + element_label(e) + " (O.3)");
    }
  }
  if (m.secure_write && !m.secure_write->enable_tag.empty()) secure_write_var = m.secure_write->enable_tag;
}

namespace {

// M.2: group deactivation ends the running overrides (and the soft bypasses
// and simulations, which the program does not have); only an override needs it.
void matrix_level(Generator& g) {
  bool override_possible = false;
  for (const auto& e : g.m.effects)
    if (e.function != model::EffectFunction::Comment && e.override_time &&
        has_type(g.m, e.id, {IntersectionType::V, IntersectionType::R}))
      override_possible = true;
  if (!g.m.group_deactivation || !override_possible) return;
  const auto& gd = *g.m.group_deactivation;
  g.group_deactivation = g.local("GROUP_DEACTIVATION", plc::Type::Bool, "M.2 fired in this scan");
  const std::string prev = g.local("GROUP_DEACTIVATION_SET_PREV", plc::Type::Bool,
                                   "the set tag in the previous scan; TRUE at start-up: no edge in scan 1 (T.4)",
                                   plc::Literal{plc::Type::Bool, 1, 0.0f});
  g.body.push_back(st::assign(
      g.group_deactivation,
      st::all({g.tag_bool(gd.enable_tag), g.tag_bool(gd.set_tag), st::not_(st::var(prev))}),
      "Group deactivation [6.1.7] (M.2): with " + gd.enable_tag + " TRUE, a rising edge of " + gd.set_tag +
          " ends every running override, without an alarm."));
  g.body.push_back(st::assign(prev, g.tag_bool(gd.set_tag)));
}

formats::PlcMap build_map(const Generator& g, const std::string& pou) {
  const model::Matrix& m = g.m;
  formats::PlcMap map;
  map.pou = pou;
  map.scan_ms = m.cycle_ms;
  for (std::size_t i = 0; i < g.inputs.size(); ++i) {
    formats::PlcInputBinding b;
    b.tag = g.inputs.tags()[i].name;
    b.variable = g.input_var[i];
    b.bad_quality = g.bad_var[i];
    bool cause_input = false;
    for (auto r : g.inputs.tags()[i].roles) cause_input = cause_input || r == model::TagRole::CauseInput;
    b.good_quality = cause_input && b.bad_quality.empty();
    map.inputs.push_back(b);
  }
  std::map<std::string, int> writers;
  for (const auto& [key, name] : g.output_var) {
    const auto* e = m.find_effect(key.first);
    ++writers[model::tag_key(e->tags[static_cast<std::size_t>(key.second - 1)].name)];
  }
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    for (std::size_t j = 0; j < e.tags.size(); ++j) {
      formats::PlcOutputBinding b;
      b.tag = e.tags[j].name;
      b.effect = writers[model::tag_key(b.tag)] > 1 ? e.id : 0;
      b.variable = g.output_var.at({e.id, static_cast<int>(j + 1)});
      map.outputs.push_back(b);
    }
  }
  auto bound = [&](CommandOp op, int cause, int effect, const std::string& variable) {
    formats::PlcCommandBinding b;
    b.op = op;
    b.cause = cause;
    b.effect = effect;
    b.variable = variable;
    map.commands.push_back(b);
  };
  for (const auto& [id, v] : g.ack_var) bound(CommandOp::AckCause, id, 0, v);
  for (const auto& e : m.effects) {
    if (auto it = g.reset_var.find(e.id); it != g.reset_var.end()) bound(CommandOp::ResetEffect, 0, e.id, it->second);
    if (auto it = g.override_var.find(e.id); it != g.override_var.end())
      bound(CommandOp::OverrideEffect, 0, e.id, it->second);
    if (auto it = g.stop_override_var.find(e.id); it != g.stop_override_var.end())
      bound(CommandOp::StopOverride, 0, e.id, it->second);
  }
  // Soft bypasses and simulation are operated on the matrix's faceplate, not
  // in this program: declared unused where the matrix accepts them.
  bool cause_bypass = false, tag_bypass = false, effect_bypass = false;
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    cause_bypass = cause_bypass || c.soft_bypass.allowed;
    for (const auto& t : c.tags)
      tag_bypass = tag_bypass || (t.soft_bypass_allowed && !model::parse_internal_ref(t.name));
  }
  for (const auto& e : m.effects)
    effect_bypass = effect_bypass || (e.function != model::EffectFunction::Comment && e.soft_bypass_allowed);
  bool simulation = false;
  const model::CommandOrder order(m);
  for (const auto& tag : order.simulatable_tags()) {
    simulation = simulation || model::simulation_permitted(m, tag);
  }
  auto unused = [&](CommandOp op) {
    formats::PlcCommandBinding b;
    b.op = op;
    map.commands.push_back(b);
  };
  if (cause_bypass) unused(CommandOp::SoftBypassCause);
  if (tag_bypass) unused(CommandOp::SoftBypassTag);
  if (effect_bypass) unused(CommandOp::SoftBypassEffect);
  if (simulation) unused(CommandOp::SimulateTag);
  return map;
}

std::string header(const model::Matrix& m) {
  std::string h = "The safety logic of the cause & effect matrix " + m.name +
                  (m.title.empty() ? std::string() : " (" + m.title + ")") +
                  ", generated by cemv export-st from the matrix of signature " + formats::signature(m) +
                  ". Scan time " + std::to_string(m.cycle_ms) +
                  " ms, the matrix's cycle_ms (T.1); every delay counts whole scans (T.2). Rule numbers (C.4, "
                  "E.9) are those of cemv's docs/semantics.md, section numbers in brackets those of the Safety "
                  "Matrix manual. Causes and effects follow the matrix's evaluation order (I.4): a reference to an "
                  "element evaluated later reads its value from the previous scan. Soft bypasses and the simulation "
                  "of tags are operated on the matrix's faceplate, not in this program (the map declares them "
                  "unused); status without an output tag (first out, prewarning, delta alarm, alarms) is not "
                  "computed.";
  return h;
}

}  // namespace

Export export_program(const model::Matrix& m) {
  Generator g(m);
  // Declarations that later sections read as "the previous scan" come first.
  bool delays = false;
  for (const auto& e : m.effects) delays = delays || (e.function != model::EffectFunction::Comment && e.output_delay_ms);
  if (delays)
    g.first_scan = g.local("FIRST_SCAN", plc::Type::Bool, "TRUE in scan 1 only (E.7: no output delay at start-up)",
                           plc::Literal{plc::Type::Bool, 1, 0.0f});
  matrix_level(g);
  for (const model::Node& n : g.graph.evaluation_order()) {
    if (n.kind == model::Node::Kind::Cause) g.cause(*m.find_cause(n.id));
    else g.effect(*m.find_effect(n.id));
  }
  if (!g.first_scan.empty()) g.body.push_back(st::assign(g.first_scan, st::boolean(false), "End of scan 1."));

  plc::Pou pou;
  pou.kind = plc::PouKind::Program;
  pou.name = g.claim(m.name.empty() ? "CE_MATRIX" : m.name);
  pou.comment = header(m);
  pou.variables = g.in_vars;
  pou.variables.insert(pou.variables.end(), g.out_vars.begin(), g.out_vars.end());
  pou.variables.insert(pou.variables.end(), g.locals.begin(), g.locals.end());
  pou.body = std::move(g.body);

  Export out;
  out.program.pous.push_back(std::move(pou));
  out.program.scan_time_ms = m.cycle_ms;
  out.map = build_map(g, out.program.pous.front().name);
  return out;
}

}  // namespace cemv::plc_export
