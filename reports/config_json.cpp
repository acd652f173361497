// The configuration report as cemv-report/1 JSON: the sections as data, in a
// fixed key order, and the canonical matrix itself.
#include "reports/config_document.hpp"

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "model/vocabulary.hpp"

namespace cemv::reports::config {

using namespace cemv::model;
using namespace cemv::formats;

namespace {

using ojson = nlohmann::ordered_json;

ojson counts_json(const std::map<std::string, int>& counts, const std::vector<std::string>& order) {
  ojson j = ojson::object();
  for (const auto& k : order) j[k] = counts.at(k);
  return j;
}

ojson statistics_json(const Matrix& m, const Statistics& s) {
  ojson st;
  st["causes"] = {{"configured", m.causes.size()}, {"limit", kMaxCauses}};
  st["effects"] = {{"configured", m.effects.size()}, {"limit", kMaxEffects}};
  st["intersections"] = {{"configured", m.intersections.size()}, {"limit", kMaxIntersections}};
  st["intersection_types"] = counts_json(s.by_type, {"N", "S", "V", "R", "X", "*"});
  st["cause_functions"] = counts_json(s.by_function, {"normal", "and", "or", "2oo3", "comment"});
  st["cause_inputs"] = counts_json(s.by_input, {"discrete", "analog"});
  st["cause_time_modes"] = counts_json(s.by_time, {"none", "on_delay", "off_delay", "timed"});
  st["cause_bad_quality"] = counts_json(s.by_bad_quality, {"ignore", "trip", "degrade"});
  st["effect_functions"] = counts_json(s.by_effect_function, {"normal", "comment"});
  st["tags"] = {
      {"cause_input_tags", s.cause_tags},
      {"effect_output_tags", s.effect_tags},
      {"internal_references", s.internal_refs},
      {"external_inputs", s.external_inputs},
      {"cause_bypass_tags", s.bypass_tags},
      {"cause_inhibit_tags", s.inhibit_tags},
      {"effect_bypass_tags", s.effect_bypass_tags},
      {"effect_reset_tags", s.reset_tags},
  };
  st["xoon_effects"] = s.xoon_effects;
  st["noted_intersections"] = s.noted_intersections;
  st["first_out_groups_used"] = s.first_out_groups.size();
  st["sif_groups_defined"] = m.sif_groups.size();
  return st;
}

ojson validation_json(const std::vector<Diagnostic>& diags) {
  std::size_t errors = 0, warnings = 0;
  ojson list = ojson::array();
  for (const auto& x : diags) {
    (x.severity == Severity::Error ? errors : warnings)++;
    list.push_back({{"severity", x.severity == Severity::Error ? "error" : "warning"},
                    {"rule", x.rule},
                    {"element", x.element},
                    {"section", x.section},
                    {"message", x.message}});
  }
  return {{"errors", errors}, {"warnings", warnings}, {"diagnostics", list}};
}

ojson sif_groups_json(const Matrix& m, const Statistics& s) {
  std::set<int> groups(s.sif_used);
  for (const auto& [g, name] : m.sif_groups) groups.insert(g);
  ojson sif = ojson::array();
  for (int g : groups) {
    ojson causes = ojson::array(), effects = ojson::array();
    for (const auto& c : m.causes)
      for (int x : c.sif)
        if (x == g) causes.push_back(c.id);
    for (const auto& e : m.effects)
      for (int x : e.sif)
        if (x == g) effects.push_back(e.id);
    auto name = m.sif_groups.find(g);
    sif.push_back({{"group", g},
                   {"name", name != m.sif_groups.end() ? ojson(name->second) : ojson(nullptr)},
                   {"causes", causes},
                   {"effects", effects}});
  }
  return sif;
}

ojson first_out_groups_json(const Matrix& m, const Statistics& s) {
  ojson first_out = ojson::array();
  for (int g : s.first_out_groups) {
    ojson causes = ojson::array();
    for (const auto& c : m.causes)
      if (c.first_out_group == g) causes.push_back(c.id);
    first_out.push_back({{"group", g}, {"causes", causes}});
  }
  return first_out;
}

ojson grid_json(const Matrix& m) {
  ojson grid = ojson::array();
  for (const auto& c : m.causes) {
    std::string row;
    for (const auto& e : m.effects) {
      const Intersection* x = m.find_intersection(c.id, e.id);
      row += x ? to_string(x->type) : ".";
    }
    grid.push_back({{"cause", c.id}, {"cells", row}});
  }
  ojson effects = ojson::array();
  for (const auto& e : m.effects) effects.push_back(e.id);
  return {{"effects", effects}, {"rows", grid}};
}

}  // namespace

std::string render_json(const Matrix& m, const std::string& sig, const std::vector<Diagnostic>& diags) {
  const Statistics s = statistics(m);
  ojson j;
  j["format"] = "cemv-report/1";
  j["report"] = "configuration";
  j["signature"] = sig;
  if (has_errors(diags))
    j["banner"] = "INVALID MATRIX: it has validation errors (manual section 11.5), listed under "
                  "\"validation\"; cemv refuses to simulate, encode or check it until they are fixed";
  j["properties"] = {
      {"name", m.name},
      {"title", m.title},
      {"cycle_ms", m.cycle_ms},
      {"secure_write_enable_tag", m.secure_write ? ojson(m.secure_write->enable_tag) : ojson(nullptr)},
      {"group_deactivation_enable_tag",
       m.group_deactivation ? ojson(m.group_deactivation->enable_tag) : ojson(nullptr)},
      {"group_deactivation_set_tag",
       m.group_deactivation ? ojson(m.group_deactivation->set_tag) : ojson(nullptr)},
  };
  j["statistics"] = statistics_json(m, s);
  j["validation"] = validation_json(diags);

  j["sif_groups"] = sif_groups_json(m, s);
  j["first_out_groups"] = first_out_groups_json(m, s);
  j["grid"] = grid_json(m);
  // Every cause, effect and intersection with every field, exactly as the
  // canonical form writes them (the text the signature is computed over).
  j["matrix"] = ojson::parse(to_canonical_json(m));
  j["signature_end"] = sig;
  return j.dump(2, ' ', false, ojson::error_handler_t::replace) + "\n";
}

}  // namespace cemv::reports::config
