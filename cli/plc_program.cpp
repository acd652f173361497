#include "cli/plc_program.hpp"

#include <chrono>

#include "checker/work_queue.hpp"
#include "plc_check/check.hpp"
#include "plc_encoder/encode.hpp"

#include "cli/matrix_input.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "formats/plc_map.hpp"
#include "plc/parser.hpp"

namespace cemv::cli {

namespace {

plc_check::VarType var_type(const plc::VarType& t) {
  if (t.kind != plc::VarType::Kind::Elementary) return plc_check::VarType::Other;
  switch (t.type) {
    case plc::Type::Bool: return plc_check::VarType::Bool;
    case plc::Type::Int:
    case plc::Type::Dint: return plc_check::VarType::Int;
    case plc::Type::Real: return plc_check::VarType::Real;
    case plc::Type::Time: return plc_check::VarType::Time;
  }
  return plc_check::VarType::Other;
}

plc_check::VarKind var_kind(plc::Section s) {
  switch (s) {
    case plc::Section::Input: return plc_check::VarKind::Input;
    case plc::Section::Output: return plc_check::VarKind::Output;
    case plc::Section::InOut: return plc_check::VarKind::InOut;
    default: return plc_check::VarKind::Local;
  }
}

// Whether a map entry names a command (a field left out matches every value).
bool covers(const formats::PlcCommandBinding& b, const model::Command& c) {
  return b.op == c.op && (!b.cause || b.cause == c.cause) && (!b.effect || b.effect == c.effect) &&
         (!b.tag || b.tag == c.tag) &&
         (b.tag_name.empty() || model::tag_key(b.tag_name) == model::tag_key(c.tag_name)) && (!b.on || *b.on == c.on);
}

plc::Value value_of(const plc::Pou& pou, const std::string& variable, double v) {
  const plc::Variable* var = plc::find_variable(pou, variable);
  if (var && var->type.type == plc::Type::Real) return plc::Value{plc::Type::Real, 0, static_cast<float>(v)};
  return plc::Value{plc::Type::Bool, v != 0.0 ? 1 : 0, 0.0f};
}

}  // namespace

const plc::Pou& choose_pou(const plc::Program& p, const std::string& wanted, const std::string& file) {
  if (!wanted.empty()) {
    const plc::Pou* pou = plc::find_pou(p, wanted);
    if (!pou || pou->kind != plc::PouKind::Program)
      throw formats::LoadError({{"", "no PROGRAM " + wanted + " in the program", file}});
    return *pou;
  }
  const plc::Pou* only = nullptr;
  int programs = 0;
  for (const auto& pou : p.pous)
    if (pou.kind == plc::PouKind::Program) {
      only = &pou;
      ++programs;
    }
  if (programs != 1)
    throw formats::LoadError({{"", std::to_string(programs) + " PROGRAMs in the file: name the one to check with --pou", file}});
  return *only;
}

plc_check::ProgramInterface program_interface(const plc::Program& program, const plc::Pou& pou, const std::string& file) {
  plc_check::ProgramInterface iface;
  iface.file = file;
  iface.pou = pou.name;
  if (program.scan_time_ms) iface.task_ms = static_cast<std::uint32_t>(*program.scan_time_ms);
  for (const auto& v : pou.variables) iface.variables.push_back({v.name, var_kind(v.section), var_type(v.type)});
  return iface;
}

std::unique_ptr<PlcProgram> load_plc_program(const model::Matrix& m, const std::string& program, const std::string& map,
                                             const std::string& pou) {
  auto p = std::make_unique<PlcProgram>();
  p->file = input_name(program);
  const std::string text = read_input(program);
  p->sha256 = formats::sha256_hex(text);
  p->program = plc::parse_program_text(text, p->file);
  std::optional<formats::PlcMap> given;
  if (!map.empty()) given = formats::parse_plc_map(read_input(map), input_name(map));
  const plc::Pou& chosen = choose_pou(p->program, !pou.empty() ? pou : given ? given->pou : "", p->file);
  p->pou = chosen.name;
  p->map = plc_check::resolve_map(m, program_interface(p->program, chosen, p->file), given ? &*given : nullptr,
                                  input_name(map));
  p->map_source = given ? input_name(map) : "found by name";
  return p;
}

void decide_outputs(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                    plc_check::PlcCheckReport& r, double timeout_s, double total_timeout_s, int jobs) {
  const auto start = checker::Clock::now();
  auto seconds = [](double s) {
    return std::chrono::duration_cast<checker::Clock::duration>(std::chrono::duration<double>(s));
  };
  checker::CancelToken cancel(total_timeout_s > 0 ? start + seconds(total_timeout_s) : checker::Clock::time_point::max());
  const auto qs = plc_check::questions(m, r.map);
  std::vector<std::optional<plc_check::OutputResult>> slots(qs.size());
  std::vector<std::optional<plc_encoder::Unsupported>> refused(qs.size());
  checker::WorkQueue(jobs, cancel).run(qs.size(), [&](std::size_t i) {
    plc_check::CheckOptions o;
    o.relation = r.relation;
    o.limits.cancel = &cancel;
    if (timeout_s > 0) o.limits.deadline = checker::Clock::now() + seconds(timeout_s);
    try {
      slots[i] = plc_check::check_output(m, program, pou, r.map, qs[i], o);
    } catch (const plc_encoder::Unsupported& e) {
      refused[i] = e;
    }
  });
  for (const auto& e : refused)
    if (e) throw formats::LoadError({{"", e->what(), r.program_file, e->at.line, e->at.column}});
  for (std::size_t i = 0; i < qs.size(); ++i) {
    if (slots[i]) {
      r.outputs.push_back(*slots[i]);
    } else {
      r.interrupted = true;
      plc_check::OutputResult u;
      u.question = qs[i];
      u.reason = "total time limit";
      r.outputs.push_back(u);
    }
    r.scenario_files.emplace_back();
    r.diagram_files.emplace_back();
  }
}

PlcReplayTarget::PlcReplayTarget(const model::Matrix& m, const PlcProgram& p)
    : m_(m), p_(p), table_(m), run_(p.program, p.pou) {}

void PlcReplayTarget::start() { run_.reset(); }

std::string PlcReplayTarget::cannot_run(const model::CycleInput& in) const {
  for (const auto& c : in.commands)
    for (const auto& b : p_.map.map.commands)
      if (b.variable.empty() && covers(b, c))
        return std::string("it issues ") + model::to_string(c.op) +
               ", which the map declares unused: the program does not implement it";
  return "";
}

void PlcReplayTarget::step(const model::CycleInput& in) {
  const plc::Pou& pou = run_.pou();
  std::map<std::string, plc::Value> frame;
  for (const auto& b : p_.map.map.inputs) {
    if (b.variable.empty()) continue;  // held at its value: an assumption of the map
    const auto i = table_.find(b.tag);
    if (!i) continue;
    frame[b.variable] = value_of(pou, b.variable, in.tags[*i].value);
    if (!b.bad_quality.empty()) frame[b.bad_quality] = plc::Value{plc::Type::Bool, in.tags[*i].bad_quality ? 1 : 0, 0.0f};
  }
  for (const auto& b : p_.map.map.commands) {
    if (b.variable.empty()) continue;
    bool issued = false;
    for (const auto& c : in.commands) issued = issued || covers(b, c);
    frame[b.variable] = plc::Value{plc::Type::Bool, issued ? 1 : 0, 0.0f};
  }
  for (const auto& h : p_.map.map.program_inputs) frame[h.variable] = value_of(pou, h.variable, h.value);
  run_.step(frame, p_.map.scan_ms);
}

std::string PlcReplayTarget::output_variable(const formats::ExpectTarget& t) const {
  const model::Observable& o = t.observable;
  if (o.kind != model::Node::Kind::Effect || o.field != "tag" || o.tag < 1) return "";
  const model::Effect* e = m_.find_effect(o.id);
  if (!e || static_cast<std::size_t>(o.tag) > e->tags.size()) return "";
  const std::string key = model::tag_key(e->tags[static_cast<std::size_t>(o.tag - 1)].name);
  for (const auto& b : p_.map.map.outputs)
    if (model::tag_key(b.tag) == key && (b.effect == 0 || b.effect == e->id)) return b.variable;
  return "";
}

bool PlcReplayTarget::observes(const formats::ExpectTarget& t) const { return !output_variable(t).empty(); }

int PlcReplayTarget::value(const formats::ExpectTarget& t) const {
  return static_cast<int>(run_.value(output_variable(t)).integer);
}

}  // namespace cemv::cli
