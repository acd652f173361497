#include "sheets/import_record.hpp"

#include <filesystem>
#include <functional>
#include <set>

#include "formats/matrix_json.hpp"

namespace cemv::formats {

namespace {

using model::Cause;
using model::Effect;

template <class E>
struct DefaultField {
  const char* field;  // the key of docs/format.md
  const char* text;   // what the default means
  std::function<bool(const E&)> is_default;
};

bool all_tags(const std::vector<model::CauseTag>& tags, bool (*f)(const model::CauseTag&)) {
  for (const auto& t : tags)
    if (!f(t)) return false;
  return true;
}

const std::vector<DefaultField<Cause>>& cause_fields() {
  static const std::vector<DefaultField<Cause>> fields = {
      {"input", "a discrete input (input discrete)", [](const Cause& c) { return c.input == model::InputKind::Discrete; }},
      {"function", "one input tag, 1oo1 (function normal)",
       [](const Cause& c) { return c.function == model::CauseFunction::Normal; }},
      {"tags", "de-energize-to-trip: trips when its input is FALSE (tags[].ett false)",
       [](const Cause& c) { return all_tags(c.tags, [](const model::CauseTag& t) { return !t.ett; }); }},
      {"bad_quality", "a tag in bad quality trips (bad_quality trip)",
       [](const Cause& c) { return c.bad_quality == model::BadQuality::Trip; }},
      {"time", "no delay (time none)", [](const Cause& c) { return c.time.mode == model::TimeMode::None; }},
      {"auto_ack", "acknowledged automatically (auto_ack true)", [](const Cause& c) { return c.auto_ack; }},
      {"soft_bypass", "the operator may soft-bypass it without time limit (soft_bypass allowed, max_s 0)",
       [](const Cause& c) { return c.soft_bypass.allowed && c.soft_bypass.max_s == 0; }},
      {"tags", "the operator may soft-bypass its tags (tags[].soft_bypass_allowed true)",
       [](const Cause& c) { return all_tags(c.tags, [](const model::CauseTag& t) { return t.soft_bypass_allowed; }); }},
      {"tags", "the operator may simulate its input tags (tags[].simulation_allowed true)",
       [](const Cause& c) { return all_tags(c.tags, [](const model::CauseTag& t) { return t.simulation_allowed; }); }},
      {"bypass_tag", "no hard bypass tag", [](const Cause& c) { return !c.bypass_tag; }},
      {"inhibit_tag", "no inhibit tag", [](const Cause& c) { return !c.inhibit_tag; }},
      {"sil", "SIL not stated (sil 0)", [](const Cause& c) { return c.sil == 0; }},
      {"sif", "in no SIF group", [](const Cause& c) { return c.sif.empty(); }},
      {"sensor_ms", "no sensor response time declared (sensor_ms 0)", [](const Cause& c) { return c.sensor_ms == 0; }},
  };
  return fields;
}

const std::vector<DefaultField<Effect>>& effect_fields() {
  static const std::vector<DefaultField<Effect>> fields = {
      {"tags", "de-energize-to-trip: its output is 0 while active (tags[].ett false)",
       [](const Effect& e) {
         for (const auto& t : e.tags)
           if (t.ett) return false;
         return true;
       }},
      {"override", "no maximum override time (override null)", [](const Effect& e) { return !e.override_time; }},
      {"reset_tag", "no reset/override tag: reset and override by operator command only",
       [](const Effect& e) { return !e.reset_tag; }},
      {"output_delay_ms", "no output delay", [](const Effect& e) { return e.output_delay_ms == 0; }},
      {"soft_bypass_allowed", "no soft bypass", [](const Effect& e) { return !e.soft_bypass_allowed; }},
      {"bypass_tag", "no hard bypass tag", [](const Effect& e) { return !e.bypass_tag; }},
      {"process_data", "no pass-through or mask", [](const Effect& e) { return !e.process_data; }},
      {"tags", "the operator may simulate its output tags (tags[].simulation_allowed true)",
       [](const Effect& e) {
         for (const auto& t : e.tags)
           if (!t.simulation_allowed) return false;
         return true;
       }},
      {"sil", "SIL not stated (sil 0)", [](const Effect& e) { return e.sil == 0; }},
      {"sif", "in no SIF group", [](const Effect& e) { return e.sif.empty(); }},
      {"actuator_ms", "no actuator response time declared (actuator_ms 0)",
       [](const Effect& e) { return e.actuator_ms == 0; }},
  };
  return fields;
}

// What the parameters files set: (element label, key) pairs and the keys of
// their policies, so a value they state is not called a default.
struct Stated {
  std::set<std::pair<std::string, std::string>> fields;
  std::set<std::string> policies;
  explicit Stated(const model::Matrix& m) {
    for (const auto& r : m.provenance.parameters)
      for (const auto& v : r.values) {
        std::string key = v.field.substr(0, v.field.find_first_of(".["));
        if (v.element.rfind("every ", 0) == 0)
          policies.insert(v.field == "simulation_allowed"          ? "tags.simulation"
                          : v.field == "tags[].soft_bypass_allowed" ? "tags.soft_bypass"
                                                                    : key);
        else fields.insert({v.element, key});
      }
  }
  bool set(const std::string& label, const std::string& key) const {
    return fields.count({label, key}) > 0;
  }
};

bool processed(const Cause& c) { return c.function != model::CauseFunction::Comment; }
bool processed(const Effect& e) { return e.function != model::EffectFunction::Comment; }

template <class E>
void element_defaults(const std::vector<E>& elements, const char* kind, const std::vector<DefaultField<E>>& table,
                      const Stated& stated, std::vector<std::string>& out) {
  std::size_t count = 0;
  for (const auto& e : elements) count += processed(e);
  for (const auto& f : table) {
    std::size_t n = 0;
    for (const auto& e : elements) {
      if (!processed(e)) continue;  // comment-only elements are not processed (M.4)
      const std::string label = std::string(kind) + "[" + std::to_string(e.id) + "] " + e.name;
      const std::string text = f.text;
      const std::string policy = std::string(f.field) != "tags"                      ? f.field
                                 : text.find("simulate") != std::string::npos        ? "tags.simulation"
                                 : text.find("soft_bypass_allowed") != std::string::npos ? "tags.soft_bypass"
                                                                                      : "";
      bool by_policy = !policy.empty() && stated.policies.count(policy);
      if (f.is_default(e) && !stated.set(label, f.field) && !by_policy) ++n;
    }
    if (n)
      out.push_back(std::to_string(n) + " of " + std::to_string(count) + " " + kind + "s: " + f.text);
  }
}

}  // namespace

std::vector<std::string> adopted_defaults(const model::Matrix& m) {
  Stated stated(m);
  std::vector<std::string> out;
  if (m.cycle_ms == 100 && !stated.set("matrix", "cycle_ms")) out.push_back("matrix: scan cycle 100 ms (cycle_ms)");
  if (!m.secure_write && !stated.set("matrix", "secure_write"))
    out.push_back("matrix: no secure write: every operator command is accepted (M.3)");
  if (!m.group_deactivation && !stated.set("matrix", "group_deactivation"))
    out.push_back("matrix: no group deactivation of maintenance operations (6.1.7)");
  if (m.sif_groups.empty()) out.push_back("matrix: no SIF groups and no process safety time");
  element_defaults(m.causes, "cause", cause_fields(), stated, out);
  element_defaults(m.effects, "effect", effect_fields(), stated, out);
  return out;
}

void record_import(model::Matrix& m, const std::string& file, std::string_view bytes, const std::string& reader,
                   const std::string& encoding, const std::string& summary, std::vector<std::string> warnings) {
  model::ImportRecord r;
  r.file = std::filesystem::path(file).filename().string();
  r.sha256 = sha256_hex(bytes);
  r.reader = reader;
  r.encoding = encoding;
  r.summary = summary;
  r.warnings = std::move(warnings);
  r.defaults = adopted_defaults(m);
  m.provenance.imports.push_back(std::move(r));
}

}  // namespace cemv::formats
