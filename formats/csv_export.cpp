// The record layout cemv-csv/1 written (6.6, docs/csv.md): every field of
// cemv-matrix/1, so export then import is lossless.
#include "formats/csv.hpp"
#include "formats/csv_records.hpp"
#include "formats/matrix_extras.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

using namespace cemv::model;
using namespace csv_records;
using namespace csv_text;

namespace {

class CsvWriter {
 public:
  void row(const std::vector<std::string>& fields) {
    for (std::size_t i = 0; i < fields.size(); ++i) {
      if (i) out_ += ',';
      out_ += csv_quote(fields[i]);
    }
    out_ += "\r\n";
  }
  void header(const RecordSchema& s) {
    std::vector<std::string> f{std::string("#") + s.type};
    f.insert(f.end(), s.columns.begin(), s.columns.end());
    row(f);
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

std::string bool_text(bool b) { return b ? "true" : "false"; }
std::string opt_text(const std::optional<std::string>& s) { return s ? *s : ""; }
std::string sif_text(const std::vector<int>& sif) {
  std::string out;
  for (int g : sif) join_to(out, " ", std::to_string(g));
  return out;
}

}  // namespace

std::string export_csv(const Matrix& m) {
  CsvWriter w;

  w.header(schema_of(RecordType::Property));
  w.row({"property", "format", kMatrixFormat});
  w.row({"property", "name", m.name});
  w.row({"property", "title", m.title});
  w.row({"property", "cycle_ms", std::to_string(m.cycle_ms)});
  if (m.secure_write) w.row({"property", "secure_write.enable_tag", m.secure_write->enable_tag});
  if (m.group_deactivation) {
    w.row({"property", "group_deactivation.enable_tag", m.group_deactivation->enable_tag});
    w.row({"property", "group_deactivation.set_tag", m.group_deactivation->set_tag});
  }
  // Timing keys (docs/response-time.md), only where declared.
  if (m.watchdog_ms) w.row({"property", "watchdog_ms", std::to_string(*m.watchdog_ms)});
  for (const auto& [n, ms] : m.process_safety_time_ms)
    w.row({"property", "sif_group." + std::to_string(n) + ".process_safety_time_ms", std::to_string(ms)});
  for (const auto& c : m.causes)
    if (c.sensor_ms) w.row({"property", "cause." + std::to_string(c.id) + ".sensor_ms", std::to_string(c.sensor_ms)});
  for (const auto& e : m.effects)
    if (e.actuator_ms)
      w.row({"property", "effect." + std::to_string(e.id) + ".actuator_ms", std::to_string(e.actuator_ms)});
  // Tag descriptions, simulation permissions, provenance (formats/matrix_extras.hpp).
  for (const auto& x : extra_properties(m)) w.row({"property", x.key, x.value});

  w.header(schema_of(RecordType::SifGroup));
  for (const auto& [n, name] : m.sif_groups) w.row({"sif_group", std::to_string(n), name});

  w.header(schema_of(RecordType::Cause));
  for (const auto& c : m.causes) {
    const auto& a = c.analog;
    w.row({"cause", std::to_string(c.id), c.name, c.description, std::to_string(c.sil),
           to_string(c.input), to_string(c.function), to_string(c.bad_quality),
           to_string(c.time.mode), std::to_string(c.time.ms), bool_text(c.auto_ack),
           bool_text(c.soft_bypass.allowed), std::to_string(c.soft_bypass.max_s),
           std::to_string(c.soft_bypass.prealarm_s), opt_text(c.bypass_tag), opt_text(c.inhibit_tag),
           std::to_string(c.first_out_group), bool_text(c.mutually_locked_maintenance),
           sif_text(c.sif), a ? to_string(a->limit_type) : "", a ? float_text(a->limit) : "",
           a ? float_text(a->hysteresis) : "",
           a && a->prewarning ? float_text(*a->prewarning) : "", a ? float_text(a->delta) : "",
           a ? a->unit : "", c.note});
  }
  w.header(schema_of(RecordType::CauseTag));
  for (const auto& c : m.causes)
    for (std::size_t k = 0; k < c.tags.size(); ++k)
      w.row({"cause_tag", std::to_string(c.id), std::to_string(k + 1), c.tags[k].name,
             bool_text(c.tags[k].ett), bool_text(c.tags[k].soft_bypass_allowed)});

  w.header(schema_of(RecordType::Effect));
  for (const auto& e : m.effects) {
    const auto& o = e.override_time;
    const auto& p = e.process_data;
    w.row({"effect", std::to_string(e.id), e.name, e.description, std::to_string(e.sil),
           to_string(e.function), std::to_string(e.output_delay_ms), bool_text(e.soft_bypass_allowed),
           opt_text(e.bypass_tag), opt_text(e.reset_tag), o ? std::to_string(o->max_s) : "",
           o ? std::to_string(o->prealarm_s) : "", p ? opt_text(p->tag) : "",
           p ? bool_text(p->pass_through) : "", p ? opt_text(p->mask_tag) : "",
           bool_text(e.mutually_locked_maintenance), sif_text(e.sif), e.note});
  }
  w.header(schema_of(RecordType::EffectTag));
  for (const auto& e : m.effects)
    for (std::size_t k = 0; k < e.tags.size(); ++k)
      w.row({"effect_tag", std::to_string(e.id), std::to_string(k + 1), e.tags[k].name,
             bool_text(e.tags[k].ett)});

  w.header(schema_of(RecordType::Intersection));
  for (const auto& x : m.intersections)
    w.row({"intersection", std::to_string(x.cause), std::to_string(x.effect), to_string(x.type),
           x.xoon ? std::to_string(*x.xoon) : "", x.note});
  return w.take();
}

}  // namespace cemv::formats
