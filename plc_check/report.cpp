// The outputs of `cemv plc-check` (docs/plc.md "Outputs").
#include "plc_check/report.hpp"

#include <sstream>

#include <nlohmann/json.hpp>

#include "formats/plc_map.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::plc_check {

namespace {

using nlohmann::ordered_json;

std::string value_text(const plc::Value& v) {
  if (v.type == plc::Type::Real) return model::float_text(v.real);
  if (v.type == plc::Type::Bool) return v.integer ? "1" : "0";
  return std::to_string(v.integer);
}

ordered_json value_json(const plc::Value& v) {
  if (v.type == plc::Type::Real) return v.real;
  if (v.type == plc::Type::Bool) return v.integer != 0;
  return v.integer;
}

std::string effect_name(const model::Matrix& m, int id) {
  const auto* e = m.find_effect(id);
  return e ? e->name : "";
}

std::string outcome(const OutputResult& o) {
  switch (o.verdict) {
    case OutputVerdict::Related: {
      std::string s = "proved by " + o.method;
      if (o.k > 0) s += " (k = " + std::to_string(o.k) + ")";
      return s;
    }
    case OutputVerdict::Differs: {
      const auto& d = *o.difference;
      return "differs in scan " + std::to_string(d.scan + 1) + ": matrix " + std::to_string(d.matrix_values.back()) +
             ", program " + std::to_string(d.program_values.back()) + " (found by " + o.method + ")";
    }
    default: return "unknown: " + o.reason;
  }
}

}  // namespace

int exit_code(const PlcCheckReport& r) {
  bool unknown = r.interrupted;
  for (const auto& o : r.outputs) {
    if (o.verdict == OutputVerdict::Differs) return 1;
    if (o.verdict == OutputVerdict::Unknown) unknown = true;
  }
  return unknown ? 3 : 0;
}

std::string timing_table(const OutputResult& o, const model::Matrix& m) {
  const auto& d = *o.difference;
  const model::InputTable table(m);
  std::ostringstream s;
  s << "  scan  matrix " << o.question.tag << "  program " << o.question.variable << "  program inputs that changed\n";
  for (std::size_t c = 0; c < d.program_inputs.size(); ++c) {
    std::string changed;
    for (const auto& [name, v] : d.program_inputs[c])
      if (c == 0 || !(d.program_inputs[c - 1].at(name) == v)) changed += (changed.empty() ? "" : ", ") + name + " = " + value_text(v);
    const bool last = c + 1 == d.program_inputs.size();
    const bool outputs_changed = c == 0 || d.matrix_values[c] != d.matrix_values[c - 1] ||
                                 d.program_values[c] != d.program_values[c - 1];
    if (!last && changed.empty() && !outputs_changed) continue;
    s << "  " << (last ? ">" : " ") << std::to_string(c + 1) << std::string(5 - std::min<std::size_t>(5, std::to_string(c + 1).size()), ' ')
      << d.matrix_values[c] << std::string(7 + o.question.tag.size(), ' ') << d.program_values[c]
      << std::string(8 + o.question.variable.size(), ' ') << (changed.empty() ? "-" : changed)
      << (last ? "   <- first difference" : "") << "\n";
  }
  return s.str();
}

std::string to_text(const PlcCheckReport& r, const model::Matrix& m) {
  std::ostringstream s;
  s << "plc-check: matrix " << m.name << " (" << r.matrix_file << ", signature " << r.matrix_signature << ")\n";
  s << "program: " << r.pou << " in " << r.program_file << " (sha256 " << r.program_sha256 << ")\n";
  s << "relation: " << to_string(r.relation) << ", scan time " << r.map.scan_ms << " ms, map: " << r.map_source << "\n";
  s << "assumptions:" << (r.map.assumptions.empty() ? " none\n" : "\n");
  for (const auto& a : r.map.assumptions) s << "  - " << a << "\n";
  int related = 0, differs = 0, unknown = 0;
  for (std::size_t i = 0; i < r.outputs.size(); ++i) {
    const auto& o = r.outputs[i];
    s << o.question.tag << " (effect " << o.question.effect << " " << effect_name(m, o.question.effect) << ") = "
      << o.question.variable << ": " << outcome(o) << "\n";
    if (o.verdict == OutputVerdict::Differs) {
      const auto& d = *o.difference;
      if (d.assigned_at)
        s << "  " << r.program_file << ":" << d.assigned_at->line << ":" << d.assigned_at->column << ": the statement that set "
          << o.question.variable << " in scan " << d.scan + 1 << "\n";
      else
        s << "  no statement set " << o.question.variable << " in scan " << d.scan + 1 << " (it kept its value)\n";
      s << timing_table(o, m);
      if (!r.scenario_files[i].empty()) s << "  scenario: " << r.scenario_files[i] << "\n";
      if (!r.diagram_files[i].empty()) s << "  timing diagram: " << r.diagram_files[i] << "\n";
    }
    (o.verdict == OutputVerdict::Related ? related : o.verdict == OutputVerdict::Differs ? differs : unknown)++;
  }
  s << r.outputs.size() << " output" << (r.outputs.size() == 1 ? "" : "s") << ": " << related << " "
    << (r.relation == Relation::Equal ? "equal" : "safe-side") << ", " << differs << " differ, " << unknown << " unknown"
    << (r.interrupted ? " (--total-timeout reached)" : "") << "\n";
  return s.str();
}

std::string to_json(const PlcCheckReport& r) {
  ordered_json j;
  j["format"] = "cemv-plc-result/1";
  j["tool_version"] = r.tool_version;
  j["matrix"] = {{"file", r.matrix_file}, {"signature", r.matrix_signature}};
  j["program"] = {{"file", r.program_file}, {"sha256", r.program_sha256}, {"pou", r.pou}};
  j["relation"] = to_string(r.relation);
  j["scan_ms"] = r.map.scan_ms;
  j["map_source"] = r.map_source;
  j["map"] = ordered_json::parse(formats::plc_map_json(r.map.map));
  j["assumptions"] = r.map.assumptions;
  j["outputs"] = ordered_json::array();
  int counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < r.outputs.size(); ++i) {
    const auto& o = r.outputs[i];
    ordered_json e;
    e["tag"] = o.question.tag;
    e["effect"] = o.question.effect;
    e["position"] = o.question.position;
    e["variable"] = o.question.variable;
    e["verdict"] = to_string(o.verdict);
    e["method"] = o.method;
    e["k"] = o.k;
    if (o.verdict == OutputVerdict::Unknown) e["reason"] = o.reason;
    if (o.difference) {
      const auto& d = *o.difference;
      ordered_json x;
      x["scan"] = d.scan + 1;
      x["matrix_value"] = d.matrix_values.back();
      x["program_value"] = d.program_values.back();
      if (d.assigned_at) x["assigned_at"] = {{"line", d.assigned_at->line}, {"column", d.assigned_at->column}};
      else x["assigned_at"] = nullptr;
      x["scenario"] = r.scenario_files[i];
      x["diagram"] = r.diagram_files[i];
      x["scans"] = ordered_json::array();
      for (std::size_t c = 0; c < d.program_inputs.size(); ++c) {
        ordered_json in;
        for (const auto& [name, v] : d.program_inputs[c]) in[name] = value_json(v);
        x["scans"].push_back({{"matrix", d.matrix_values[c]}, {"program", d.program_values[c]}, {"program_inputs", in}});
      }
      e["difference"] = x;
    }
    counts[static_cast<int>(o.verdict)]++;
    j["outputs"].push_back(std::move(e));
  }
  j["summary"] = {{"related", counts[0]}, {"differs", counts[1]}, {"unknown", counts[2]}};
  j["interrupted"] = r.interrupted;
  return j.dump(2) + "\n";
}

checker::CheckResult as_check_result(const PlcCheckReport& r) {
  checker::CheckResult c;
  c.matrix_name = r.pou;
  c.matrix_signature = r.matrix_signature;
  c.tool_version = r.tool_version;
  c.property_files.push_back(r.program_file);
  c.interrupted = r.interrupted;
  for (std::size_t i = 0; i < r.outputs.size(); ++i) {
    const auto& o = r.outputs[i];
    checker::PropertyResult p;
    p.name = std::string("plc.") + to_string(r.relation) + "." + o.question.tag;
    p.description = o.question.variable + " of " + r.pou + " " +
                    (r.relation == Relation::Equal ? "equals" : "is safe whenever") + " output tag " + o.question.tag +
                    " of effect " + std::to_string(o.question.effect) + " at every scan";
    p.kind = "invariant";
    p.file = r.program_file;
    p.method = o.method;
    p.depth = o.k;
    if (o.verdict == OutputVerdict::Related) p.verdict = checker::PropertyVerdict::Proved;
    else if (o.verdict == OutputVerdict::Differs) p.verdict = checker::PropertyVerdict::Falsified;
    else {
      p.verdict = checker::PropertyVerdict::Unknown;
      p.reason = o.reason;
    }
    if (o.difference) {
      const auto& d = *o.difference;
      if (d.assigned_at) {
        p.line = static_cast<int>(d.assigned_at->line);
        p.column = static_cast<int>(d.assigned_at->column);
      }
      p.trace = d.runtime;
      p.violation_cycle = d.scan;
      p.scenario_file = r.scenario_files[i];
      p.diagram_file = r.diagram_files[i];
      p.matters.push_back("effect[" + std::to_string(o.question.effect) + "].tag[" + std::to_string(o.question.position) + "]");
    }
    c.properties.push_back(std::move(p));
  }
  return c;
}

}  // namespace cemv::plc_check
