// cemv-evidence/1 (docs/reports.md, "cemv-evidence/1"): the evidence report's
// content as JSON for a quality system to file. Rendered from the same
// document as the HTML pages; every key always present, in the documented
// order, no times but the report's date.
#include <nlohmann/json.hpp>

#include "reports/check_report.hpp"
#include "reports/evidence.hpp"
#include "reports/evidence_document.hpp"

namespace cemv::reports {

namespace {

using json = nlohmann::ordered_json;
using checker::PropertyResult;

json cells_json(const std::set<evidence_detail::Cell2>& cells) {
  json a = json::array();
  for (const auto& [c, e] : cells) a.push_back({{"cause", c}, {"effect", e}});
  return a;
}

json text_or_null(const std::string& s) { return s.empty() ? json() : json(s); }

json property_json(const PropertyResult& p, const PropertyText* text, const std::string& sha) {
  json j;
  j["name"] = p.name;
  j["description"] = p.description;
  j["kind"] = p.kind;
  j["file"] = p.line > 0 ? text_or_null(p.file) : json();  // null for the standard set
  j["line"] = p.line > 0 ? json(p.line) : json();
  j["column"] = p.line > 0 ? json(p.column) : json();
  j["file_sha256"] = text_or_null(sha);
  j["statement"] = text ? json(text->statement) : json();
  j["assumptions"] = text ? json(text->assumptions) : json::array();
  j["verdict"] = verdict_name(p.verdict);
  j["outcome"] = outcome_text(p);
  j["method"] = text_or_null(p.method);
  j["depth"] = p.depth;
  j["reason"] = text_or_null(p.reason);
  j["notes"] = p.notes;
  json support = json::array();
  for (const auto& s : p.support) support.push_back({{"key", s.key}, {"description", s.description}});
  j["support"] = support;
  j["support_minimal"] = p.verdict == checker::PropertyVerdict::Proved ? json(p.support_minimal) : json();
  j["violation_cycle"] = p.violation_cycle >= 0 ? json(p.violation_cycle) : json();
  j["trace_cycles"] = p.trace ? json(p.trace->inputs.size()) : json();
  j["scenario"] = text_or_null(p.scenario_file);
  json why = json::array();
  for (const auto& s : p.explanation)
    why.push_back({{"cycle", s.cycle}, {"signal", s.signal}, {"before", s.before}, {"after", s.after}, {"why", s.why}});
  j["explanation"] = why;
  return j;
}

std::array<int, 6> count_of(const std::vector<const PropertyResult*>& ps) {
  std::array<int, 6> c{};
  for (const auto* p : ps) c[static_cast<int>(p->verdict)]++;
  return c;
}

json counts_json(const std::array<int, 6>& c) {
  json j;
  int total = 0;
  for (int v : c) total += v;
  j["properties"] = total;
  for (std::size_t v = 0; v < c.size(); ++v) j[verdict_name(static_cast<checker::PropertyVerdict>(v))] = c[v];
  return j;
}

json matrix_json(const model::Matrix& m, const EvidenceInputs& in) {
  return {{"name", m.name},
          {"title", m.title},
          {"file", in.matrix_file},
          {"signature", in.check.matrix_signature},
          {"causes", m.causes.size()},
          {"effects", m.effects.size()},
          {"intersections", m.intersections.size()},
          {"cycle_ms", m.cycle_ms}};
}

// The foreign sheets the matrix was read from.
json sources_json(const model::Matrix& m) {
  json sources = json::array();
  for (const auto& r : m.provenance.imports)
    sources.push_back({{"file", r.file}, {"sha256", r.sha256}, {"reader", r.reader}, {"encoding", r.encoding},
                       {"summary", r.summary}, {"warnings", r.warnings}, {"defaults", r.defaults}});
  return sources;
}

// The parameter files applied to it.
json parameters_json(const model::Matrix& m) {
  json params = json::array();
  for (const auto& r : m.provenance.parameters) {
    json values = json::array();
    for (const auto& v : r.values)
      values.push_back({{"element", v.element}, {"field", v.field}, {"value", v.value}, {"previous", v.previous},
                        {"origin", v.origin}});
    json notes = json::array();
    for (const auto& f : r.footnotes)
      notes.push_back({{"mark", f.mark}, {"text", f.text}, {"modelled", f.modelled}, {"not_modelled", f.not_modelled}});
    params.push_back({{"file", r.file}, {"sha256", r.sha256}, {"origin", r.origin}, {"values", values},
                      {"footnotes", notes}, {"limitations", r.limitations}});
  }
  return params;
}

json property_files_json(const EvidenceInputs& in) {
  json files = json::array();
  for (const auto& f : in.property_files)
    files.push_back({{"file", f.file}, {"sha256", f.sha256}, {"properties", f.properties},
                     {"assumptions", f.assumptions}, {"warnings", f.warnings}});
  return files;
}

json validation_json(const evidence_detail::Document& d, const EvidenceInputs& in) {
  json diagnostics = json::array();
  for (const auto& v : in.validation)
    diagnostics.push_back({{"severity", model::to_string(v.severity)}, {"rule", v.rule}, {"element", v.element},
                           {"section", v.section}, {"message", v.message}});
  return {{"errors", d.errors}, {"warnings", d.warnings}, {"diagnostics", diagnostics}};
}

json requirements_json(const evidence_detail::Document& d) {
  json reqs = json::array();
  for (const auto& r : d.requirements) {
    json x = property_json(*r.result, r.text, r.file_sha256);
    x["support_cells"] = cells_json(r.support_cells);
    x["trace_cells"] = cells_json(r.trace_cells);
    reqs.push_back(std::move(x));
  }
  return reqs;
}

// The standard set: counts by element, then every property.
json standard_json(const evidence_detail::Document& d, const EvidenceInputs& in) {
  std::map<std::pair<std::string, std::string>, const PropertyText*> texts;
  for (const auto& t : in.texts) texts[{t.file, t.name}] = &t;
  json elements = json::array();
  for (const auto& e : d.standard_by_element) {
    json names = json::array();
    for (const auto* p : e.properties) names.push_back(p->name);
    elements.push_back({{"element", e.key}, {"label", e.label}, {"counts", counts_json(e.verdicts)}, {"properties", names}});
  }
  json standard = json::array();
  for (const auto* p : d.standard) {
    auto t = texts.find({p->file, p->name});
    standard.push_back(property_json(*p, t == texts.end() ? nullptr : t->second, ""));
  }
  return {{"included", in.check.standard}, {"by_element", elements}, {"properties", standard}};
}

json limitations_json(const evidence_detail::Document& d) {
  json limits = json::array();
  for (const auto& l : d.limitations) limits.push_back({{"kind", l.kind}, {"text", l.text}, {"source", l.source}});
  return limits;
}

json response_json(const EvidenceInputs& in) {
  if (!in.response) return nullptr;
  json paths = json::array();
  for (const auto& p : in.response->paths)
    paths.push_back({{"sif", p.sif}, {"path", p.path}, {"logic", p.logic},
                     {"total_ms", p.total_ms ? json(*p.total_ms) : json()},
                     {"process_safety_time_ms", p.process_safety_time_ms ? json(*p.process_safety_time_ms) : json()},
                     {"margin_ms", p.margin_ms ? json(*p.margin_ms) : json()}, {"verdict", p.verdict}});
  return {{"controller", in.response->controller}, {"paths", paths}};
}

json defeats_json(const EvidenceInputs& in) {
  if (!in.defeats) return nullptr;
  json paths = json::array();
  for (const auto& p : in.defeats->paths) {
    json sets = json::array();
    for (const auto& s : p.sets)
      sets.push_back({{"actions", s.actions}, {"class", s.set_class}, {"counterexample", s.counterexample},
                      {"touches", s.touches}});
    paths.push_back({{"sif", p.sif}, {"sil", p.sil}, {"path", p.path}, {"requirement", p.requirement},
                     {"status", p.status}, {"distance", p.distance}, {"sets", sets}});
  }
  return {{"file", in.defeats->file}, {"max_size", in.defeats->max_size}, {"paths", paths}};
}

json plc_output_json(const PlcFigures::Output& o) {
  json x = {{"tag", o.tag}, {"effect", o.effect}, {"variable", o.variable}, {"verdict", o.verdict},
            {"method", o.method}, {"k", o.k}};
  if (o.verdict == "unknown") x["reason"] = o.reason;
  if (o.verdict == "differs") {
    json scans = json::array();
    for (const auto& s : o.scans)
      scans.push_back({{"scan", s.scan}, {"matrix", s.matrix}, {"program", s.program}, {"inputs", s.inputs}});
    x["difference"] = {{"scan", o.scan}, {"matrix_value", o.matrix_value}, {"program_value", o.program_value},
                       {"assigned_at", o.assigned_at}, {"scans", scans}};
  }
  return x;
}

json plc_json(const EvidenceInputs& in) {
  if (!in.plc) return nullptr;
  const auto& p = *in.plc;
  json outputs = json::array();
  for (const auto& o : p.outputs) outputs.push_back(plc_output_json(o));
  json map = json::array();
  for (const auto& b : p.map) map.push_back({{"matrix", b.what}, {"variable", b.variable}, {"note", b.note}});
  return {{"file", p.file}, {"sha256", p.sha256}, {"pou", p.pou}, {"relation", p.relation},
          {"scan_ms", p.scan_ms}, {"map_source", p.map_source}, {"map", map}, {"assumptions", p.assumptions},
          {"outputs", outputs}, {"interrupted", p.interrupted}};
}

json conclusion_json(const evidence_detail::Document& d) {
  std::vector<const PropertyResult*> requirement_results;
  for (const auto& r : d.requirements) requirement_results.push_back(r.result);
  return {{"counts", counts_json(d.counts)},
          {"requirements", counts_json(count_of(requirement_results))},
          {"standard", counts_json(count_of(d.standard))},
          {"requirements_not_passed", d.requirements_not_passed},
          {"statement", d.conclusion}};
}

}  // namespace

std::string evidence_json(const model::Matrix& m, const EvidenceInputs& in) {
  const evidence_detail::Document d = evidence_detail::build_document(m, in);
  json j;
  j["format"] = "cemv-evidence/1";
  j["tool"] = {{"name", "cemv"}, {"version", in.check.tool_version}};
  j["date"] = in.date;
  j["support_mode"] = checker::to_string(in.check.support_mode);
  j["matrix"] = matrix_json(m, in);
  j["sources"] = sources_json(m);
  j["parameters"] = parameters_json(m);
  j["property_files"] = property_files_json(in);
  j["validation"] = validation_json(d, in);
  j["checked"] = d.valid;
  j["requirements"] = requirements_json(d);
  j["standard"] = standard_json(d, in);
  j["grid"] = {{"support_cells", cells_json(d.support_cells)}, {"trace_cells", cells_json(d.trace_cells)}};
  j["limitations"] = limitations_json(d);
  j["response"] = response_json(in);
  j["defeats"] = defeats_json(in);
  j["plc"] = plc_json(in);
  j["coverage"] = in.coverage ? json{{"file", in.coverage->file}, {"objectives", in.coverage->objectives},
                                     {"covered", in.coverage->covered}, {"infeasible", in.coverage->infeasible},
                                     {"undecided", in.coverage->undecided}, {"tests", in.coverage->tests}}
                              : json();
  j["mutation"] = in.mutation ? json{{"file", in.mutation->file}, {"mutants", in.mutation->mutants},
                                     {"equivalent", in.mutation->equivalent}, {"detected", in.mutation->detected},
                                     {"survived", in.mutation->survived}, {"undecided", in.mutation->undecided}}
                              : json();
  j["conclusion"] = conclusion_json(d);
  j["signoff"] = {{"assessor", nullptr}, {"role", nullptr}, {"date", nullptr}, {"conclusion", nullptr},
                  {"remarks", nullptr}, {"signature", nullptr}};
  return j.dump(1) + "\n";
}

}  // namespace cemv::reports
