// The matrix as the six tables of 6.6.2 (docs/workbook.md). Every value the
// importer reads is written; what is only there for the reader (headers,
// names repeated in the overview, options, the legend, the alarm profiles) is
// grey, information only.
#include <algorithm>
#include <set>

#include "formats/matrix_extras.hpp"
#include "sheets/workbook_tables.hpp"
#include "sheets/workbook_tags.hpp"
#include "model/text.hpp"

namespace cemv::formats::workbook {

using model::Cause;
using model::Effect;
using model::Matrix;

std::string tag_header(int k, const char* field) { return "Tag " + std::to_string(k) + field; }

std::vector<std::string> cause_headers() {
  std::vector<std::string> h = {"No.", "Name", "Description", "SIL", "Input", "Function"};
  for (int k = 1; k <= model::kMaxCauseTags; ++k)
    for (const char* f : {"", kTagEtt, kTagSoftBypass}) h.push_back(tag_header(k, f));
  for (const char* s : {"Limit type", "Limit", "Hysteresis", "Prewarning", "Delta", "Unit", "Bad quality",
                        "Time mode", "Time (ms)", "Auto ack", "Soft bypass allowed", "Soft bypass max (s)",
                        "Soft bypass prealarm (s)", "Bypass tag", "Inhibit tag", "First-out group",
                        "Mutually locked maintenance", "SIF", "Sensor time (ms)", "Note"})
    h.push_back(s);
  return h;
}

std::vector<std::string> effect_headers() {
  std::vector<std::string> h = {"No.", "Name", "Description", "SIL", "Function"};
  for (int k = 1; k <= model::kMaxEffectTags; ++k)
    for (const char* f : {"", kTagEtt}) h.push_back(tag_header(k, f));
  for (const char* s : {"Output delay (ms)", "Soft bypass allowed", "Bypass tag", "Reset tag", "Override max (s)",
                        "Override prealarm (s)", "Process data tag", "Pass through", "Mask tag",
                        "Mutually locked maintenance", "SIF", "Actuator time (ms)", "Note"})
    h.push_back(s);
  return h;
}

namespace {

std::string num(long long v) { return std::to_string(v); }
const char* yes(bool b) { return b ? "true" : "false"; }

std::string sif_text(const std::vector<int>& sif) {
  std::string s;
  for (int g : sif) s += (s.empty() ? "" : " ") + std::to_string(g);
  return s;
}

// One table row from header -> (text, kind) in header order.
class RowWriter {
 public:
  RowWriter(Sheet& sheet, const std::vector<std::string>& headers, std::size_t row)
      : sheet_(sheet), headers_(headers), row_(row) {}
  void text(const std::string& header, const std::string& value) { put(header, value, CellKind::Text); }
  void number(const std::string& header, long long value) { put(header, num(value), CellKind::Number); }
  void real(const std::string& header, float value) { put(header, model::float_text(value), CellKind::Number); }

 private:
  void put(const std::string& header, std::string value, CellKind kind) {
    auto it = std::find(headers_.begin(), headers_.end(), header);
    sheet_.put(row_, static_cast<std::size_t>(it - headers_.begin()) + 1, std::move(value), false, kind);
  }
  Sheet& sheet_;
  const std::vector<std::string>& headers_;
  std::size_t row_;
};

void header_row(Sheet& s, const std::vector<std::string>& headers) {
  for (std::size_t i = 0; i < headers.size(); ++i) {
    s.put(1, i + 1, headers[i], true);
    s.widths[i + 1] = std::clamp<double>(static_cast<double>(headers[i].size()) + 2, 8, 28);
  }
}

Sheet properties(const Matrix& m) {
  Sheet s{kPropertiesSheet, {}, {{1, 32}, {2, 40}, {3, 24}, {4, 60}}, {}, false};
  for (const char* h : {"Property", "Value", "Process safety time (ms)", "Meaning"}) s.put(1, s.cells.size() + 1, h, true);
  std::size_t r = 2;
  auto row = [&](const std::string& key, std::string value, CellKind kind, const char* meaning) {
    s.put(r, 1, key);
    s.put(r, 2, std::move(value), false, kind);
    s.put(r, 4, meaning, true);
    ++r;
  };
  row(kPropName, m.name, CellKind::Text, "name of the matrix: letters, digits, _ (6.1.2)");
  row(kPropTitle, m.title, CellKind::Text, "title shown above the matrix (6.2.1)");
  row(kPropCycle, num(m.cycle_ms), CellKind::Number, "scan cycle of the matrix, ms (6.2.1, 13)");
  row(kPropWatchdog, m.watchdog_ms ? num(*m.watchdog_ms) : "", CellKind::Number,
      "watchdog time of the controller, ms; empty = not declared (HIMatrix 3.2.3)");
  row(kPropSecureWrite, m.secure_write ? m.secure_write->enable_tag : "", CellKind::Text,
      "EN_SWC: enables operator commands; empty = no secure write (10.7.2)");
  row(kPropGdmEnable, m.group_deactivation ? m.group_deactivation->enable_tag : "", CellKind::Text,
      "EN_GDM: enables group deactivation; empty = none (6.1.7)");
  row(kPropGdmSet, m.group_deactivation ? m.group_deactivation->set_tag : "", CellKind::Text,
      "SET_GDM: executes the group deactivation (6.1.7)");
  for (const auto& [group, name] : m.sif_groups) {
    s.put(r, 1, std::string(kPropSifGroup) + " " + std::to_string(group));
    s.put(r, 2, name);
    if (auto it = m.process_safety_time_ms.find(group); it != m.process_safety_time_ms.end())
      s.put(r, 3, num(it->second), false, CellKind::Number);
    s.put(r, 4, "name of SIF group (3.4, 6.2.1) and its process safety time, ms (HIMatrix 3.2.1)", true);
    ++r;
  }
  // Tag descriptions, simulation permissions and provenance records, as the
  // record layout carries them (formats/matrix_extras.hpp).
  for (const auto& x : extra_properties(m)) {
    s.put(r, 1, x.key);
    s.put(r, 2, x.value);
    s.put(r, 4, "cemv-matrix/1 field kept as a property row (docs/workbook.md)", true);
    ++r;
  }
  // A process safety time of a group that has no name entry cannot occur:
  // the JSON form keeps both in one sif_groups entry.
  return s;
}

Sheet causes(const Matrix& m) {
  Sheet s{kCausesSheet, {}, {}, {}, false};
  std::vector<std::string> h = cause_headers();
  h.push_back(kOptionsHeader);
  header_row(s, h);
  std::size_t r = 2;
  for (const Cause& c : m.causes) {
    RowWriter w(s, h, r);
    w.number("No.", c.id);
    w.text("Name", c.name);
    w.text("Description", c.description);
    w.number("SIL", c.sil);
    w.text("Input", model::to_string(c.input));
    w.text("Function", model::to_string(c.function));
    for (std::size_t k = 0; k < c.tags.size() && k < static_cast<std::size_t>(model::kMaxCauseTags); ++k) {
      int n = static_cast<int>(k + 1);
      w.text(tag_header(n), tag_cell_text(c.tags[k].name));
      w.text(tag_header(n, kTagEtt), yes(c.tags[k].ett));
      w.text(tag_header(n, kTagSoftBypass), yes(c.tags[k].soft_bypass_allowed));
    }
    if (c.analog) {
      w.text("Limit type", model::to_string(c.analog->limit_type));
      w.real("Limit", c.analog->limit);
      w.real("Hysteresis", c.analog->hysteresis);
      if (c.analog->prewarning) w.real("Prewarning", *c.analog->prewarning);
      w.real("Delta", c.analog->delta);
      w.text("Unit", c.analog->unit);
    }
    w.text("Bad quality", model::to_string(c.bad_quality));
    w.text("Time mode", model::to_string(c.time.mode));
    w.number("Time (ms)", c.time.ms);
    w.text("Auto ack", yes(c.auto_ack));
    w.text("Soft bypass allowed", yes(c.soft_bypass.allowed));
    w.number("Soft bypass max (s)", c.soft_bypass.max_s);
    w.number("Soft bypass prealarm (s)", c.soft_bypass.prealarm_s);
    if (c.bypass_tag) w.text("Bypass tag", tag_cell_text(*c.bypass_tag));
    if (c.inhibit_tag) w.text("Inhibit tag", tag_cell_text(*c.inhibit_tag));
    w.number("First-out group", c.first_out_group);
    w.text("Mutually locked maintenance", yes(c.mutually_locked_maintenance));
    w.text("SIF", sif_text(c.sif));
    w.number("Sensor time (ms)", c.sensor_ms);
    w.text("Note", c.note);
    s.put(r, h.size(), cause_options(c), true);
    ++r;
  }
  s.sort();
  return s;
}

Sheet effects(const Matrix& m) {
  Sheet s{kEffectsSheet, {}, {}, {}, false};
  std::vector<std::string> h = effect_headers();
  h.push_back(kOptionsHeader);
  header_row(s, h);
  std::size_t r = 2;
  for (const Effect& e : m.effects) {
    RowWriter w(s, h, r);
    w.number("No.", e.id);
    w.text("Name", e.name);
    w.text("Description", e.description);
    w.number("SIL", e.sil);
    w.text("Function", model::to_string(e.function));
    for (std::size_t k = 0; k < e.tags.size() && k < static_cast<std::size_t>(model::kMaxEffectTags); ++k) {
      int n = static_cast<int>(k + 1);
      w.text(tag_header(n), tag_cell_text(e.tags[k].name));
      w.text(tag_header(n, kTagEtt), yes(e.tags[k].ett));
    }
    w.number("Output delay (ms)", e.output_delay_ms);
    w.text("Soft bypass allowed", yes(e.soft_bypass_allowed));
    if (e.bypass_tag) w.text("Bypass tag", tag_cell_text(*e.bypass_tag));
    if (e.reset_tag) w.text("Reset tag", tag_cell_text(*e.reset_tag));
    if (e.override_time) {
      w.number("Override max (s)", e.override_time->max_s);
      w.number("Override prealarm (s)", e.override_time->prealarm_s);
    }
    if (e.process_data) {
      if (e.process_data->tag) w.text("Process data tag", tag_cell_text(*e.process_data->tag));
      w.text("Pass through", yes(e.process_data->pass_through));
      if (e.process_data->mask_tag) w.text("Mask tag", tag_cell_text(*e.process_data->mask_tag));
    }
    w.text("Mutually locked maintenance", yes(e.mutually_locked_maintenance));
    w.text("SIF", sif_text(e.sif));
    w.number("Actuator time (ms)", e.actuator_ms);
    w.text("Note", e.note);
    s.put(r, h.size(), effect_options(e), true);
    ++r;
  }
  s.sort();
  return s;
}

std::string mark_text(const Matrix& m, const model::Intersection& x) {
  std::string t = model::to_string(x.type);
  if (x.xoon) {
    std::size_t n = 0;
    for (const auto* y : m.intersections_of_effect(x.effect)) n += y->xoon ? 1 : 0;
    t += " " + std::to_string(*x.xoon) + "oo" + std::to_string(n);
  }
  if (!x.note.empty()) t += "; " + x.note;
  return t;
}

Sheet overview(const Matrix& m) {
  Sheet s{kOverviewSheet, {}, {{1, 10}, {2, 24}}, {}, false};
  s.put(1, 2, "Effect", true);
  s.put(2, 1, "Cause No.", true);
  s.put(2, 2, "Cause  \\  Effect No.", true);
  // One line per number: a number twice (validate reports it) gets one line,
  // and an intersection's number without its element gets one too, so that
  // no intersection is lost.
  std::set<int> cause_ids, effect_ids;
  for (const Cause& c : m.causes) cause_ids.insert(c.id);
  for (const Effect& e : m.effects) effect_ids.insert(e.id);
  for (const auto& x : m.intersections) {
    cause_ids.insert(x.cause);
    effect_ids.insert(x.effect);
  }
  std::map<int, std::size_t> column_of, row_of;
  std::size_t col = kOverviewFirstColumn;
  for (int id : effect_ids) {
    const Effect* e = m.find_effect(id);
    if (e) s.put(1, col, e->name, true);
    s.put(kOverviewNumberRow, col, num(id), false, CellKind::Number);
    s.widths[col] = 8;
    column_of[id] = col++;
  }
  std::size_t row = kOverviewFirstRow;
  for (int id : cause_ids) {
    s.put(row, 1, num(id), false, CellKind::Number);
    if (const Cause* c = m.find_cause(id)) s.put(row, 2, c->name, true);
    row_of[id] = row++;
  }
  for (const auto& x : m.intersections) s.put(row_of[x.cause], column_of[x.effect], mark_text(m, x));
  s.sort();
  return s;
}

Sheet info_sheet(const char* name, const std::vector<std::vector<std::string>>& rows) {
  Sheet s{name, {}, {{1, 28}, {2, 80}}, {}, false};
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < rows[r].size(); ++c) s.put(r + 1, c + 1, rows[r][c], true);
  return s;
}

}  // namespace

std::string cause_options(const Cause& c) {
  std::string o;
  auto add = [&](const std::string& a) { o += (o.empty() ? "" : " ") + a; };
  if (c.time.mode == model::TimeMode::OnDelay || c.time.mode == model::TimeMode::OffDelay) add("D");
  if (c.inhibit_tag) add("I");
  if (c.soft_bypass.allowed) add(c.soft_bypass.max_s > 0 ? "Bt" : "B");
  for (std::size_t k = 0; k < c.tags.size(); ++k)
    if (c.tags[k].soft_bypass_allowed && c.soft_bypass.allowed) add("B" + std::to_string(k + 1));
  if (c.bypass_tag) add("H");
  if (std::any_of(c.tags.begin(), c.tags.end(), [](const model::CauseTag& t) { return !t.name.empty() && t.name[0] == '#'; }))
    add("N");
  if (c.auto_ack) add("A");
  if (c.time.mode == model::TimeMode::Timed) add("T");
  if (c.bad_quality == model::BadQuality::Degrade) add("V");
  return o;
}

std::string effect_options(const Effect& e) {
  std::string o;
  auto add = [&](const std::string& a) { o += (o.empty() ? "" : " ") + a; };
  if (e.output_delay_ms > 0) add("D");
  if (e.process_data && e.process_data->mask_tag) add("M");
  if (e.soft_bypass_allowed) add("B");
  if (e.bypass_tag) add("H");
  if (std::any_of(e.tags.begin(), e.tags.end(), [](const model::EffectTag& t) { return !t.name.empty() && t.name[0] == '#'; }))
    add("N");
  if (e.process_data && e.process_data->pass_through) add("P");
  return o;
}

Workbook matrix_to_workbook(const Matrix& m) {
  Workbook wb;
  wb.sheets.push_back(properties(m));
  wb.sheets.push_back(info_sheet(kAlarmSheet, {
      {"Alarm profile", "Information only: cemv-matrix/1 holds no message configuration (6.2.4 \"Alarms\")"},
      {"Causes: Standard", "pre-defined alarm profile of causes (default)"},
      {"Causes: Sequential", "pre-defined alarm profile of causes"},
      {"Causes: Energized", "pre-defined alarm profile of causes"},
      {"Effects: Standard", "pre-defined alarm profile of effects (default)"},
      {"Effects: Sequential", "pre-defined alarm profile of effects"},
      {"Acknowledgement", "of each cause: the Auto ack column of Causes configuration (13.1.4)"}}));
  wb.sheets.push_back(causes(m));
  wb.sheets.push_back(overview(m));
  wb.sheets.push_back(effects(m));
  wb.sheets.push_back(info_sheet(kLegendSheet, {
      {"Legend", "Information only (grey cells are never imported, 6.6.2)"},
      {"N", "intersection: normal (6.5.2)"},
      {"S", "intersection: stored, reset by the effect's reset tag"},
      {"V", "intersection: overridable"},
      {"R", "intersection: resettable (stored and overridable)"},
      {"X", "intersection: not yet specified; cannot be transferred"},
      {"*", "intersection: note only, not processed"},
      {"N 2oo3", "XooN majority: 2 of the 3 intersections of the effect that carry XooN"},
      {"N; text", "a note after '; '"},
      {"#TAG", "tag prefix #: external connection"},
      {"TAG#", "tag suffix #: F-channel driver with monitoring"},
      {"@TAG ~TAG *TAG", "F-channel driver used externally / customized / with preprocessing: ignored on import"},
      {"Cause[x], Effect[x][y]", "internal reference to cause x, effect x, tag y of effect x (6.1.3)"},
      {"Options D I M B Bt Bx H N P A T V", "delay, inhibit, mask, soft bypass, timed soft bypass, bypass of tag x, "
                                           "hard bypass, non-physical tag (#), pass through, auto ack, timed cause, "
                                           "degraded voting"},
      {"Rows", "each table is read from its first number down to the first empty number cell, at most 128 (6.6.3)"}}));
  return wb;
}

}  // namespace cemv::formats::workbook
