#include "testgen/field_words.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "testgen/field.hpp"

namespace cemv::testgen {

std::string field_value_text(double v, double resolution) {
  int decimals = 0;
  for (double r = resolution; r < 0.999999 && decimals < 6; r *= 10) ++decimals;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v == 0.0 ? 0.0 : v);
  return buf;
}

}  // namespace cemv::testgen

namespace cemv::testgen::detail {

namespace {

double round_away(double v, double step, bool up) {
  const double q = v / step;
  const double r = up ? std::ceil(q - 1e-9) : std::floor(q + 1e-9);
  return r * step;
}

std::string upper_key(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '-' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

struct PlantWords {
  const char* acting;
  const char* rest;
};

// The verb or device word nearest before the tag's mention in a description.
std::optional<PlantWords> plant_words(const std::string& text, const std::string& tag) {
  if (text.empty()) return std::nullopt;
  const std::string key = upper_key(text), name = upper_key(tag);
  std::size_t at = key.find(name);
  std::string bare = name;  // "XV_221B" is written "XV-221A/B"
  while (!bare.empty() && std::isalpha(static_cast<unsigned char>(bare.back()))) bare.pop_back();
  if (at == std::string::npos && bare.size() > 2 && bare.back() != '_') at = key.find(bare);
  for (std::string prefix = name; at == std::string::npos;) {
    const std::size_t cut = prefix.rfind('_');
    if (cut == std::string::npos || prefix.find('_') == cut) break;
    prefix = prefix.substr(0, cut);
    at = key.find(prefix);
  }
  if (at == std::string::npos) at = key.size();
  static const std::vector<std::pair<std::string, PlantWords>> words = {
      {"CLOSE", {"closed", "open"}},   {"ISOLATE", {"closed", "open"}}, {"SHUT", {"closed", "open"}},
      {"OPEN", {"open", "closed"}},    {"STOP", {"stopped", "running"}}, {"START", {"running", "stopped"}},
      {"HORN", {"on", "off"}},         {"BEACON", {"on", "off"}},       {"ALARM", {"on", "off"}}};
  std::optional<PlantWords> found;
  std::size_t i = 0;
  while (i < at) {
    while (i < at && !std::isalpha(static_cast<unsigned char>(key[i]))) ++i;
    std::size_t j = i;
    while (j < key.size() && std::isalpha(static_cast<unsigned char>(key[j]))) ++j;
    if (j > at) break;
    const std::string w = key.substr(i, j - i);
    for (const auto& [k, pw] : words)
      if (w == k) found = pw;
    i = j;
  }
  return found;
}

const char* cause_field_words(const std::string& f) {
  if (f == "active") return "Cause active";
  if (f == "trip_requested") return "Trip requested";
  if (f == "ack_required") return "Ackn. Cause required (attention required)";
  if (f == "first_out") return "First Out active";
  if (f == "bypassed") return "Bypass active";
  if (f == "soft_bypassed") return "Soft bypass active";
  if (f == "inhibited") return "Inhibit active";
  if (f == "prewarning") return "Trip prewarning";
  if (f == "delta_alarm") return "Discrepancy error";
  if (f == "degraded") return "Degraded Voting active";
  if (f == "bypass_prealarm") return "Bypass prewarning";
  if (f == "bypass_timeout") return "Bypass error: Timeout";
  return nullptr;
}

const char* effect_field_words(const std::string& f) {
  if (f == "active") return "Effect active";
  if (f == "ok_to_reset") return "OK to reset";
  if (f == "override_active") return "Override active";
  if (f == "override_prealarm") return "Prewarning override active";
  if (f == "override_failed_timeout") return "Override error (timeout)";
  if (f == "override_failed_cause") return "Override error (new cause)";
  if (f == "bypassed") return "Bypass active";
  if (f == "masked") return "Mask active";
  return nullptr;
}

}  // namespace

AnalogValues analog_values(const model::AnalogParams& a, double r) {
  const bool high = a.limit_type == model::LimitType::High;
  const double limit = a.limit, h = a.hysteresis, margin = h + r;
  AnalogValues v;
  v.trip = high ? round_away(limit + margin, r, true) : round_away(limit - margin, r, false);
  double healthy = high ? limit - 2 * margin : limit + 2 * margin;
  if (a.prewarning) healthy = high ? std::min(healthy, *a.prewarning - margin) : std::max(healthy, *a.prewarning + margin);
  v.healthy = high ? round_away(healthy, 10 * r, false) : round_away(healthy, 10 * r, true);
  if (a.prewarning) {
    const double mid = std::round((*a.prewarning + limit) / 2.0 / r) * r;
    if (high ? (mid > *a.prewarning && mid < limit) : (mid < *a.prewarning && mid > limit)) v.prewarning = mid;
  }
  return v;
}

model::TagValue cause_tag_value(const model::Cause& c, const model::CauseTag& t, bool tripped, double resolution) {
  model::TagValue v;
  if (c.input == model::InputKind::Analog && c.analog) {
    const AnalogValues a = analog_values(*c.analog, resolution);
    v.value = static_cast<float>(tripped ? a.trip : a.healthy);
  } else {
    v.value = tripped == t.ett ? 1.0f : 0.0f;
  }
  return v;
}

std::string tag_value_words(const model::Cause& c, const model::CauseTag& t, const model::TagValue& v,
                            double resolution) {
  if (c.input == model::InputKind::Analog && c.analog)
    return field_value_text(v.value, resolution) + (c.analog->unit.empty() ? "" : " " + c.analog->unit);
  (void)t;
  return v.value != 0.0f ? "1 (energized / contact closed)" : "0 (de-energized / contact open)";
}

std::vector<model::Observable> technician_observables(const model::Matrix& m) {
  std::vector<model::Observable> out;
  for (const auto& o : model::observables(m)) {
    bool keep = false;
    if (o.kind == model::Node::Kind::Cause) {
      const model::Cause& c = *m.find_cause(o.id);
      const bool analog = c.input == model::InputKind::Analog && c.analog;
      const bool bypass = c.bypass_tag || c.soft_bypass.allowed;
      keep = o.field == "active" || o.field == "trip_requested" || (o.field == "ack_required" && !c.auto_ack) ||
             (o.field == "first_out" && c.first_out_group > 0) || (o.field == "bypassed" && bypass) ||
             (o.field == "soft_bypassed" && c.soft_bypass.allowed) || (o.field == "inhibited" && c.inhibit_tag) ||
             (o.field == "prewarning" && analog && c.analog->prewarning) ||
             (o.field == "delta_alarm" && analog && c.analog->delta > 0.0f && c.tags.size() >= 2) ||
             (o.field == "degraded" && c.bad_quality == model::BadQuality::Degrade) ||
             ((o.field == "bypass_timeout" || o.field == "bypass_prealarm") && c.soft_bypass.allowed &&
              c.soft_bypass.max_s > 0);
    } else {
      const model::Effect& e = *m.find_effect(o.id);
      bool latching = e.reset_tag.has_value();
      for (const auto* i : m.intersections_of_effect(e.id))
        latching = latching || i->type == model::IntersectionType::S || i->type == model::IntersectionType::R;
      keep = o.field == "tag" || o.field == "active" || (o.field == "ok_to_reset" && latching) ||
             ((o.field == "override_active" || o.field == "override_prealarm" || o.field == "override_failed_timeout" ||
               o.field == "override_failed_cause") && e.override_time) ||
             (o.field == "bypassed" && (e.bypass_tag || e.soft_bypass_allowed)) ||
             (o.field == "masked" && e.process_data && e.process_data->mask_tag);
    }
    if (keep) out.push_back(o);
  }
  return out;
}

std::string cause_name(const model::Matrix& m, int id) {
  const model::Cause* c = m.find_cause(id);
  return "cause " + std::to_string(id) + (c ? " " + c->name : "");
}
std::string effect_name(const model::Matrix& m, int id) {
  const model::Effect* e = m.find_effect(id);
  return "effect " + std::to_string(id) + (e ? " " + e->name : "");
}

std::string seconds_text(std::uint64_t ms) {
  char buf[64];
  // Tenths unless the time needs hundredths or thousandths (a 50 ms scan cycle).
  if (ms < 120000) std::snprintf(buf, sizeof buf, "%.*f s", ms % 100 == 0 ? 1 : ms % 10 == 0 ? 2 : 3,
                                 static_cast<double>(ms) / 1000.0);
  else if (ms < 7200000) std::snprintf(buf, sizeof buf, "%.1f min", static_cast<double>(ms) / 60000.0);
  else std::snprintf(buf, sizeof buf, "%.2f h", static_cast<double>(ms) / 3600000.0);
  return buf;
}

std::string observation_words(const model::Matrix& m, const model::Observable& o, int value) {
  if (o.field == "tag") {
    const model::Effect& e = *m.find_effect(o.id);
    const model::EffectTag& t = e.tags[static_cast<std::size_t>(o.tag - 1)];
    std::optional<PlantWords> w;
    const auto d = m.tag_descriptions.find(t.name);
    if (d != m.tag_descriptions.end()) w = plant_words(d->second, t.name);
    if (!w) w = plant_words(e.description, t.name);
    const bool acting = (value != 0) == t.ett;
    const std::string electric = value != 0 ? "energized" : "de-energized";
    return t.name + " " + (w ? std::string(acting ? w->acting : w->rest) + " (" + electric + ")" : electric);
  }
  return "Viewer, " + viewer_element(m, o) + ": " + viewer_field(o) + (value ? " ON" : " OFF");
}

std::string viewer_element(const model::Matrix& m, const model::Observable& o) {
  return o.kind == model::Node::Kind::Cause ? cause_name(m, o.id) : effect_name(m, o.id);
}

std::string viewer_field(const model::Observable& o) {
  const char* f = o.kind == model::Node::Kind::Cause ? cause_field_words(o.field) : effect_field_words(o.field);
  return f ? f : o.field;
}

}  // namespace cemv::testgen::detail
