// cemv-matrix/1: reading causes, effects and intersections (docs/format.md).
#include "formats/matrix_json_reader.hpp"

#include "model/names.hpp"

namespace cemv::formats::matrix_json_detail {

// `sif`: up to 4 group numbers of 1-64 (6.3, 6.4 "SIF Grouping"; 6.1 properties).
void read_sif_list(Reader& r, const InJson& j, const std::string& path, std::vector<int>& out) {
  std::vector<int> groups;
  read_array(r, j, path, groups, kMaxSifPerElement, "the 4 SIF groups an element can belong to (6.3.6)",
             [&](const InJson& v, const std::string& p, int& g) {
               return r.integer(v, p, 1, kMaxSifGroups, g, "SIF groups are numbered 1-64");
             });
  std::sort(groups.begin(), groups.end());
  auto dup = std::adjacent_find(groups.begin(), groups.end());
  if (dup != groups.end()) r.error(path, "lists SIF group " + std::to_string(*dup) + " twice");
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  out = std::move(groups);
}

void read_description(Reader& r, const InJson& j, const std::string& path, std::string& out) {
  r.text(j, path, out, kMaxDescriptionLength, "descriptions, 6.3.4 and 6.4.4");
}

Cause read_cause(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Cause c;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, c.id, "causes are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, c.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, c.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, c.sil, "0 = not stated"); }},
      {"input", false, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kInputKinds, c.input); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kCauseFunctions, c.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, c.tags, kMaxCauseTags, "the 3 input tags of a cause (3.4)",
                    [&](const InJson& t, const std::string& tp, CauseTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                          {"soft_bypass_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.soft_bypass_allowed); }},
                          {"simulation_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.simulation_allowed); }},
                      });
                      return named;
                    });
       }},
      {"analog", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         AnalogParams a;
         bool read = r.object(v, p, {
             {"limit_type", true, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kLimitTypes, a.limit_type); }},
             {"limit", true, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.limit); }},
             {"hysteresis", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.hysteresis); }},
             {"prewarning", false,
              [&](const InJson& v2, const std::string& p2) {
                float f = 0.0f;
                if (!v2.is_null() && r.real(v2, p2, f)) a.prewarning = f;
              }},
             {"delta", false, [&](const InJson& v2, const std::string& p2) { r.real(v2, p2, a.delta); }},
             {"unit", false, [&](const InJson& v2, const std::string& p2) { r.text(v2, p2, a.unit); }},
         });
         if (read) c.analog = a;
       }},
      {"bad_quality", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kBadQualities, c.bad_quality); }},
      {"time", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"mode", false, [&](const InJson& v2, const std::string& p2) { r.enumeration(v2, p2, kTimeModes, c.time.mode); }},
             {"ms", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.time.ms); }},
         });
       }},
      {"auto_ack", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.auto_ack); }},
      {"soft_bypass", false,
       [&](const InJson& v, const std::string& p) {
         r.object(v, p, {
             {"allowed", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, c.soft_bypass.allowed); }},
             {"max_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.max_s); }},
             {"prealarm_s", false,
              [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, c.soft_bypass.prealarm_s); }},
         });
       }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.bypass_tag); }},
      {"inhibit_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, c.inhibit_tag); }},
      {"first_out_group", false,
       [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 0, kMaxFirstOutGroup, c.first_out_group, "0 = none, groups 1-15");
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, c.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, c.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, c.note); }},
      {"sensor_ms", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, c.sensor_ms); }},
  });
  if (!ok) return c;
  // 3.4: 1-3 input tags; a comment-only cause is not processed and may have none.
  if (c.function != CauseFunction::Comment && c.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "a cause needs 1-3 input tags (3.4), got none");
  }
  if (c.input == InputKind::Analog && (!j.contains("analog") || j.at("analog").is_null()))
    r.error(member_path(path, "analog"), "required for an analog cause (limit_type and limit, 6.3.5)");
  return c;
}

Effect read_effect(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Effect e;
  bool has_tags = false;
  ok = r.object(j, path, {
      {"id", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, e.id, "effects are numbered 1-128, 3.4");
       }},
      {"name", true, [&](const InJson& v, const std::string& p) { r.element_name(v, p, e.name); }},
      {"description", false, [&](const InJson& v, const std::string& p) { read_description(r, v, p, e.description); }},
      {"sil", false, [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, 4, e.sil, "0 = not stated"); }},
      {"function", false,
       [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kEffectFunctions, e.function); }},
      {"tags", false,
       [&](const InJson& v, const std::string& p) {
         has_tags = true;
         read_array(r, v, p, e.tags, kMaxEffectTags, "the 4 output tags of an effect (3.4)",
                    [&](const InJson& t, const std::string& tp, EffectTag& tag) {
                      bool named = false;
                      r.object(t, tp, {
                          {"name", true, [&](const InJson& v2, const std::string& p2) { named = r.tag(v2, p2, tag.name); }},
                          {"ett", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.ett); }},
                          {"simulation_allowed", false,
                           [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, tag.simulation_allowed); }},
                      });
                      return named;
                    });
       }},
      {"output_delay_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, e.output_delay_ms); }},
      {"soft_bypass_allowed", false, [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.soft_bypass_allowed); }},
      {"bypass_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.bypass_tag); }},
      {"reset_tag", false, [&](const InJson& v, const std::string& p) { r.optional_tag(v, p, e.reset_tag); }},
      {"override", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         Override o;
         bool read = r.object(v, p, {
             {"max_s", true, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.max_s); }},
             {"prealarm_s", false, [&](const InJson& v2, const std::string& p2) { r.integer(v2, p2, 0, kU32Max, o.prealarm_s); }},
         });
         if (read) e.override_time = o;
       }},
      {"process_data", false,
       [&](const InJson& v, const std::string& p) {
         if (v.is_null()) return;
         ProcessData d;
         bool read = r.object(v, p, {
             {"tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.tag); }},
             {"pass_through", false, [&](const InJson& v2, const std::string& p2) { r.boolean(v2, p2, d.pass_through); }},
             {"mask_tag", false, [&](const InJson& v2, const std::string& p2) { r.optional_tag(v2, p2, d.mask_tag); }},
         });
         if (read) e.process_data = d;
       }},
      {"mutually_locked_maintenance", false,
       [&](const InJson& v, const std::string& p) { r.boolean(v, p, e.mutually_locked_maintenance); }},
      {"sif", false, [&](const InJson& v, const std::string& p) { read_sif_list(r, v, p, e.sif); }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, e.note); }},
      {"actuator_ms", false,
       [&](const InJson& v, const std::string& p) { r.integer(v, p, 0, kU32Max, e.actuator_ms); }},
  });
  if (!ok) return e;
  // 3.4: 1-4 output tags; a comment-only effect drives nothing and may have none.
  if (e.function != EffectFunction::Comment && e.tags.empty()) {
    if (!has_tags)
      r.error(member_path(path, "tags"), "required key is missing");
    else if (j.at("tags").is_array() && j.at("tags").empty())
      r.error(member_path(path, "tags"), "an effect needs 1-4 output tags (3.4), got none");
  }
  return e;
}

Intersection read_intersection(Reader& r, const InJson& j, const std::string& path, bool& ok) {
  Intersection x;
  ok = r.object(j, path, {
      {"cause", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxCauses, x.cause, "causes are numbered 1-128, 3.4");
       }},
      {"effect", true, [&](const InJson& v, const std::string& p) {
         r.integer(v, p, 1, kMaxEffects, x.effect, "effects are numbered 1-128, 3.4");
       }},
      {"type", true, [&](const InJson& v, const std::string& p) { r.enumeration(v, p, kIntersectionTypes, x.type); }},
      {"xoon", false,
       [&](const InJson& v, const std::string& p) {
         int k = 0;
         if (!v.is_null() && r.integer(v, p, kMinXooN, kMaxXooN, k, "the X of XooN, 6.5.2")) x.xoon = k;
       }},
      {"note", false, [&](const InJson& v, const std::string& p) { r.text(v, p, x.note); }},
  });
  return x;
}

}  // namespace cemv::formats::matrix_json_detail
