// cemv-result/1 (docs/checker.md, "cemv-result/1"): every field always
// present, in the documented order, so consumers need no existence checks and
// two runs give the same bytes. No times and no dates.
#include "reports/check_json.hpp"

#include <nlohmann/json.hpp>

namespace cemv::reports {

namespace {

using nlohmann::ordered_json;
using checker::PropertyVerdict;

ordered_json support_json(const std::vector<checker::SupportElement>& elements) {
  ordered_json a = ordered_json::array();
  for (const auto& e : elements) {
    ordered_json j;
    j["key"] = e.key;
    j["description"] = e.description;
    a.push_back(std::move(j));
  }
  return a;
}

ordered_json optional_text(const std::string& s) { return s.empty() ? ordered_json() : ordered_json(s); }

ordered_json property_json(const checker::PropertyResult& p) {
  ordered_json j;
  j["name"] = p.name;
  j["description"] = p.description;
  j["kind"] = p.kind;
  j["file"] = is_standard(p) ? ordered_json() : ordered_json(p.file);  // null for the standard set
  j["line"] = p.line > 0 ? ordered_json(p.line) : ordered_json();
  j["column"] = p.line > 0 ? ordered_json(p.column) : ordered_json();
  j["verdict"] = verdict_name(p.verdict);
  j["method"] = optional_text(p.method);
  j["depth"] = p.depth;
  j["reason"] = optional_text(p.reason);
  j["notes"] = p.notes;
  j["elements"] = property_elements(p);
  j["support"] = support_json(p.support);
  j["support_minimal"] = p.verdict == PropertyVerdict::Proved ? ordered_json(p.support_minimal) : ordered_json();
  j["invariant"] = optional_text(p.invariant);
  j["scenario"] = optional_text(p.scenario_file);
  j["diagram"] = optional_text(p.diagram_file);
  j["waveforms"] = optional_text(p.vcd_file);
  j["violation_cycle"] = p.violation_cycle >= 0 ? ordered_json(p.violation_cycle) : ordered_json();
  j["expected"] = optional_text(p.expected);
  ordered_json why = ordered_json::array();  // "why, per step": one entry per change of a signal it reads
  for (const auto& s : p.explanation)
    why.push_back({{"cycle", s.cycle}, {"signal", s.signal}, {"before", s.before}, {"after", s.after}, {"why", s.why}});
  j["explanation"] = std::move(why);
  return j;
}

}  // namespace

std::string check_json(const checker::CheckResult& r, const CheckReportInputs& in) {
  ordered_json j;
  j["format"] = "cemv-result/1";
  j["tool"] = {{"name", "cemv"}, {"version", r.tool_version}};
  j["matrix"] = {{"name", r.matrix_name}, {"signature", r.matrix_signature}, {"file", in.matrix_file}};
  j["property_files"] = r.property_files;
  j["standard"] = r.standard;
  j["shard"] = optional_text(r.shard);
  j["interrupted"] = r.interrupted;
  j["support_mode"] = checker::to_string(r.support_mode);
  auto counts = verdict_counts(r);
  ordered_json summary;
  summary["properties"] = r.properties.size();
  for (std::size_t v = 0; v < counts.size(); ++v)
    summary[verdict_name(static_cast<PropertyVerdict>(v))] = counts[v];
  j["summary"] = summary;
  ordered_json props = ordered_json::array();
  for (const auto& p : r.properties) props.push_back(property_json(p));
  j["properties"] = std::move(props);
  j["unsupported"] = support_json(r.unsupported);
  // Invalid UTF-8 in a name must not make the output invalid JSON.
  return j.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace cemv::reports
