// The six tables back into a matrix (docs/workbook.md): the properties by
// label, causes and effects by the rule of 6.6.3 with their columns found by
// header, intersections from the overview's marks. Grey cells of the export
// (headers aside, which locate the columns) are never read. Every problem is
// collected; then the matrix passes the JSON loader, whose findings are placed
// at the cells they came from.
#include <algorithm>
#include <cctype>
#include <set>

#include "formats/matrix_extras.hpp"
#include "formats/matrix_json.hpp"
#include "sheets/workbook_cells.hpp"
#include "sheets/workbook_overview.hpp"
#include "sheets/workbook_rows.hpp"
#include "sheets/workbook_tables.hpp"
#include "model/text.hpp"

namespace cemv::formats::workbook {

using model::Cause;
using model::Effect;
using model::Matrix;

namespace {

template <typename E, std::size_t N>
std::vector<std::string> names_of(const E (&values)[N]) {
  std::vector<std::string> out;
  for (E v : values) out.push_back(model::to_string(v));
  return out;
}

const model::InputKind kInputs[] = {model::InputKind::Discrete, model::InputKind::Analog};
const model::CauseFunction kCauseFunctions[] = {model::CauseFunction::Normal, model::CauseFunction::And,
                                                model::CauseFunction::Or, model::CauseFunction::TwoOoThree,
                                                model::CauseFunction::Comment};
const model::LimitType kLimits[] = {model::LimitType::High, model::LimitType::Low};
const model::BadQuality kBadQualities[] = {model::BadQuality::Ignore, model::BadQuality::Trip, model::BadQuality::Degrade};
const model::TimeMode kTimeModes[] = {model::TimeMode::None, model::TimeMode::OnDelay, model::TimeMode::OffDelay,
                                      model::TimeMode::Timed};
const model::EffectFunction kEffectFunctions[] = {model::EffectFunction::Normal, model::EffectFunction::Comment};

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

class TablesReader {
 public:
  TablesReader(const Workbook& wb, const std::string& file) : wb_(wb), r_(file) {}

  TablesImport run() {
    const Sheet* props = need(kPropertiesSheet);
    const Sheet* causes = need(kCausesSheet);
    const Sheet* overview = need(kOverviewSheet);
    const Sheet* effects = need(kEffectsSheet);
    if (!r_.errors().empty()) throw LoadError(r_.errors());
    read_properties(*props);
    read_causes(*causes);
    read_effects(*effects);
    std::set<int> cause_ids, effect_ids;
    for (const Cause& c : causes_) cause_ids.insert(c.id);
    for (const Effect& e : effects_) effect_ids.insert(e.id);
    m_.intersections = read_overview(*overview, cause_ids, effect_ids, r_);
    if (!r_.errors().empty()) throw LoadError(r_.errors());
    sort_and_rename();
    for (const auto& [i, why] : apply_extra_properties(m_, extras_)) r_.error(*props, extra_rows_[i], 2, "", why);
    if (!r_.errors().empty()) throw LoadError(r_.errors());
    TablesImport out;
    try {
      out.matrix = parse_matrix(to_canonical_json(m_), r_.file());
    } catch (const LoadError& e) {
      std::vector<LoadIssue> issues;
      for (const auto& issue : e.issues()) issues.push_back(r_.locate(issue));
      throw LoadError(issues);
    }
    out.warnings = r_.warnings();
    out.summary = "read " + std::to_string(m_.causes.size()) + " causes, " + std::to_string(m_.effects.size()) +
                  " effects and " + std::to_string(m_.intersections.size()) + " intersections from the six tables";
    return out;
  }

 private:
  const Sheet* need(const char* name) {
    const Sheet* s = wb_.find(name);
    if (!s) {
      LoadIssue issue;
      issue.file = r_.file();
      issue.what = std::string("the workbook has no sheet '") + name + "' (6.6.2: Matrix properties, Alarm profiles, " +
                   "Causes configuration, Intersections overview, Effects configuration, Legend)";
      r_.errors().push_back(issue);
    }
    return s;
  }

  void read_properties(const Sheet& s) {
    std::vector<std::string> labels = {kPropName, kPropTitle, kPropCycle, kPropWatchdog, kPropSecureWrite, kPropGdmEnable, kPropGdmSet};
    std::map<std::string, std::size_t> seen;
    std::string gdm_enable, gdm_set;
    std::size_t gdm_row = 0;
    for (std::size_t row = 2; row <= s.last_row(); ++row) {
      const Cell* label_cell = s.find(row, 1);
      std::string label = label_cell ? trimmed(label_cell->text) : "";
      const Cell* value_cell = s.find(row, 2);
      std::string value = value_cell ? value_cell->text : "";
      const Cell* pst_cell = s.find(row, 3);
      if (label.empty()) {
        if (!trimmed(value).empty() || pst_cell) r_.error(s, row, 1, "", "a value without a property label in column A");
        continue;
      }
      auto repeat = seen.find(lower(label));
      if (repeat != seen.end()) {
        r_.error(s, row, 1, "", "property " + model::in_quotes(label) + " repeats row " + std::to_string(repeat->second));
        continue;
      }
      seen[lower(label)] = row;
      const std::string group_prefix = lower(kPropSifGroup) + " ";
      long long group = 0;
      if (lower(label).rfind(group_prefix, 0) == 0 && whole_number(trimmed(label.substr(group_prefix.size())), 1, 64, group)) {
        r_.remember("sif_groups['" + std::to_string(group) + "']", s, row, 2, "");
        m_.sif_groups[static_cast<int>(group)] = value;
        if (pst_cell) {
          long long pst = 0;
          if (whole_number(trimmed(pst_cell->text), 1, 4294967295LL, pst))
            m_.process_safety_time_ms[static_cast<int>(group)] = static_cast<std::uint32_t>(pst);
          else
            r_.error(s, row, 3, "", model::in_quotes(pst_cell->text) + " is not a whole number 1-4294967295");
        }
        continue;
      }
      if (pst_cell) r_.error(s, row, 3, "", "a process safety time belongs to a SIF group row only");
      auto known = std::find_if(labels.begin(), labels.end(), [&](const std::string& l) { return lower(l) == lower(label); });
      if (known == labels.end() && is_extra_property(label)) {  // formats/matrix_extras.hpp
        extras_.push_back({label, value});
        extra_rows_.push_back(row);
        continue;
      }
      if (known == labels.end()) {
        r_.error(s, row, 1, "", "unknown property " + model::in_quotes(label) + model::did_you_mean(label, labels) +
                                    " (or 'SIF group N', N = 1-64)");
        continue;
      }
      const std::string& key = *known;
      const std::string v = trimmed(value);
      auto number = [&](const char* path, long long min) -> std::optional<std::uint32_t> {
        r_.remember(path, s, row, 2, key);
        long long n = 0;
        if (v.empty()) return std::nullopt;
        if (!whole_number(v, min, 4294967295LL, n)) {
          r_.error(s, row, 2, key, model::in_quotes(v) + " is not a whole number " + std::to_string(min) + "-4294967295");
          return std::nullopt;
        }
        return static_cast<std::uint32_t>(n);
      };
      if (key == kPropName) {
        r_.remember("name", s, row, 2, key);
        m_.name = v;
      } else if (key == kPropTitle) {
        r_.remember("title", s, row, 2, key);
        m_.title = value;
      } else if (key == kPropCycle) {
        m_.cycle_ms = number("cycle_ms", 1).value_or(100);
      } else if (key == kPropWatchdog) {
        m_.watchdog_ms = number("watchdog_ms", 1);
      } else if (key == kPropSecureWrite) {
        r_.remember("secure_write", s, row, 2, key);
        if (!v.empty()) m_.secure_write = model::SecureWrite{v};
      } else if (key == kPropGdmEnable) {
        r_.remember("group_deactivation", s, row, 2, key);
        gdm_enable = v;
        gdm_row = row;
      } else if (key == kPropGdmSet) {
        r_.remember("group_deactivation.set_tag", s, row, 2, key);
        gdm_set = v;
        gdm_row = gdm_row ? gdm_row : row;
      }
    }
    if (!gdm_enable.empty() || !gdm_set.empty()) {
      if (gdm_enable.empty() || gdm_set.empty())
        r_.error(s, gdm_row, 2, "", "group deactivation needs both its enable tag and its set tag (6.1.7)");
      m_.group_deactivation = model::GroupDeactivation{gdm_enable, gdm_set};
    }
    if (!seen.count(lower(kPropName))) r_.error(s, 0, 0, "", "the property 'Name' is missing (6.1.2)");
  }

  // Rows of a causes or effects table by 6.6.3, in sheet order.
  std::vector<NumberedLine> element_rows(const Table& t, const char* kind) {
    return numbered_lines(*t.sheet, true, t.columns.at("No."), 2, kind, "No.", r_.file(), r_.errors(), r_.warnings());
  }

  // Flags of a tag slot that holds no tag must be empty; tags run 1, 2, ... without gaps.
  bool tag_slot(const Table& t, std::size_t row, int k, bool& gap, std::vector<const char*> flags) {
    bool has = !trimmed(r_.text(t, row, tag_header(k), "")).empty();
    if (!has) {
      for (const char* f : flags)
        if (r_.present(t, row, tag_header(k, f)))
          r_.error_at(t, row, tag_header(k, f), "a flag of tag " + std::to_string(k) + ", which is empty");
      gap = true;
      return false;
    }
    if (gap) r_.error_at(t, row, tag_header(k), "tag " + std::to_string(k) + " follows an empty tag (tags run 1, 2, ... without gaps)");
    return true;
  }

  void read_causes(const Sheet& s) {
    Table t = r_.header(s, cause_headers(), kOptionsHeader);
    if (t.columns.size() < cause_headers().size()) return;  // reported by header()
    for (const NumberedLine& line : element_rows(t, "cause")) {
      const std::size_t row = line.line;
      const std::string p = "causes[" + std::to_string(causes_.size()) + "]";
      Cause c;
      c.id = line.number;
      r_.remember(p, s, row, t.columns.at("No."), "No.");
      c.name = r_.text(t, row, "Name", p + ".name");
      c.description = r_.text(t, row, "Description", p + ".description", true);
      c.sil = static_cast<int>(r_.integer(t, row, "SIL", p + ".sil", 0, 4, 0));
      c.input = kInputs[r_.choice(t, row, "Input", p + ".input", names_of(kInputs), 0)];
      c.function = kCauseFunctions[r_.choice(t, row, "Function", p + ".function", names_of(kCauseFunctions), 0)];
      bool gap = false;
      for (int k = 1; k <= model::kMaxCauseTags; ++k) {
        if (!tag_slot(t, row, k, gap, {kTagEtt, kTagSoftBypass})) continue;
        const std::string tp = p + ".tags[" + std::to_string(c.tags.size()) + "]";
        model::CauseTag tag;
        tag.name = *r_.tag(t, row, tag_header(k), tp + ".name");
        tag.ett = r_.boolean(t, row, tag_header(k, kTagEtt), tp + ".ett", false);
        tag.soft_bypass_allowed = r_.boolean(t, row, tag_header(k, kTagSoftBypass), tp + ".soft_bypass_allowed", true);
        c.tags.push_back(tag);
      }
      if (r_.present(t, row, "Limit type")) {
        model::AnalogParams a;
        a.limit_type = kLimits[r_.choice(t, row, "Limit type", p + ".analog.limit_type", names_of(kLimits), 0)];
        if (!r_.present(t, row, "Limit")) r_.error_at(t, row, "Limit", "an analog cause needs its limit (6.3.5)");
        a.limit = r_.real(t, row, "Limit", p + ".analog.limit", 0);
        a.hysteresis = r_.real(t, row, "Hysteresis", p + ".analog.hysteresis", 0);
        if (r_.present(t, row, "Prewarning")) a.prewarning = r_.real(t, row, "Prewarning", p + ".analog.prewarning", 0);
        a.delta = r_.real(t, row, "Delta", p + ".analog.delta", 0);
        a.unit = r_.text(t, row, "Unit", p + ".analog.unit", true);
        c.analog = a;
      } else {
        for (const char* h : {"Limit", "Hysteresis", "Prewarning", "Delta", "Unit"})
          if (r_.present(t, row, h)) r_.error_at(t, row, h, "an analog value without a Limit type (high or low)");
      }
      c.bad_quality = kBadQualities[r_.choice(t, row, "Bad quality", p + ".bad_quality", names_of(kBadQualities), 1)];
      c.time.mode = kTimeModes[r_.choice(t, row, "Time mode", p + ".time.mode", names_of(kTimeModes), 0)];
      c.time.ms = r_.u32(t, row, "Time (ms)", p + ".time.ms");
      c.auto_ack = r_.boolean(t, row, "Auto ack", p + ".auto_ack", true);
      c.soft_bypass.allowed = r_.boolean(t, row, "Soft bypass allowed", p + ".soft_bypass.allowed", true);
      c.soft_bypass.max_s = r_.u32(t, row, "Soft bypass max (s)", p + ".soft_bypass.max_s");
      c.soft_bypass.prealarm_s = r_.u32(t, row, "Soft bypass prealarm (s)", p + ".soft_bypass.prealarm_s");
      c.bypass_tag = r_.tag(t, row, "Bypass tag", p + ".bypass_tag");
      c.inhibit_tag = r_.tag(t, row, "Inhibit tag", p + ".inhibit_tag");
      c.first_out_group = static_cast<int>(r_.integer(t, row, "First-out group", p + ".first_out_group", 0, 15, 0));
      c.mutually_locked_maintenance = r_.boolean(t, row, "Mutually locked maintenance", p + ".mutually_locked_maintenance", false);
      c.sif = r_.sif(t, row, "SIF", p + ".sif");
      c.sensor_ms = r_.u32(t, row, "Sensor time (ms)", p + ".sensor_ms");
      c.note = r_.text(t, row, "Note", p + ".note", true);
      causes_.push_back(std::move(c));
    }
  }

  void read_effects(const Sheet& s) {
    Table t = r_.header(s, effect_headers(), kOptionsHeader);
    if (t.columns.size() < effect_headers().size()) return;  // reported by header()
    for (const NumberedLine& line : element_rows(t, "effect")) {
      const std::size_t row = line.line;
      const std::string p = "effects[" + std::to_string(effects_.size()) + "]";
      Effect e;
      e.id = line.number;
      r_.remember(p, s, row, t.columns.at("No."), "No.");
      e.name = r_.text(t, row, "Name", p + ".name");
      e.description = r_.text(t, row, "Description", p + ".description", true);
      e.sil = static_cast<int>(r_.integer(t, row, "SIL", p + ".sil", 0, 4, 0));
      e.function = kEffectFunctions[r_.choice(t, row, "Function", p + ".function", names_of(kEffectFunctions), 0)];
      bool gap = false;
      for (int k = 1; k <= model::kMaxEffectTags; ++k) {
        if (!tag_slot(t, row, k, gap, {kTagEtt})) continue;
        const std::string tp = p + ".tags[" + std::to_string(e.tags.size()) + "]";
        model::EffectTag tag;
        tag.name = *r_.tag(t, row, tag_header(k), tp + ".name");
        tag.ett = r_.boolean(t, row, tag_header(k, kTagEtt), tp + ".ett", false);
        e.tags.push_back(tag);
      }
      e.output_delay_ms = r_.u32(t, row, "Output delay (ms)", p + ".output_delay_ms");
      e.soft_bypass_allowed = r_.boolean(t, row, "Soft bypass allowed", p + ".soft_bypass_allowed", false);
      e.bypass_tag = r_.tag(t, row, "Bypass tag", p + ".bypass_tag");
      e.reset_tag = r_.tag(t, row, "Reset tag", p + ".reset_tag");
      if (r_.present(t, row, "Override max (s)")) {
        model::Override o;
        o.max_s = r_.u32(t, row, "Override max (s)", p + ".override.max_s");
        o.prealarm_s = r_.u32(t, row, "Override prealarm (s)", p + ".override.prealarm_s");
        e.override_time = o;
      } else if (r_.present(t, row, "Override prealarm (s)")) {
        r_.error_at(t, row, "Override prealarm (s)", "an override prealarm without Override max (s) (6.5.2)");
      }
      if (r_.present(t, row, "Pass through")) {
        model::ProcessData d;
        d.tag = r_.tag(t, row, "Process data tag", p + ".process_data.tag");
        d.pass_through = r_.boolean(t, row, "Pass through", p + ".process_data.pass_through", false);
        d.mask_tag = r_.tag(t, row, "Mask tag", p + ".process_data.mask_tag");
        e.process_data = d;
      } else {
        for (const char* h : {"Process data tag", "Mask tag"})
          if (r_.present(t, row, h)) r_.error_at(t, row, h, "process data without Pass through (true or false, 13.2.5)");
      }
      e.mutually_locked_maintenance = r_.boolean(t, row, "Mutually locked maintenance", p + ".mutually_locked_maintenance", false);
      e.sif = r_.sif(t, row, "SIF", p + ".sif");
      e.actuator_ms = r_.u32(t, row, "Actuator time (ms)", p + ".actuator_ms");
      e.note = r_.text(t, row, "Note", p + ".note", true);
      effects_.push_back(std::move(e));
    }
  }

  // Elements in the loader's order (stable by id), and the remembered places renamed to match.
  void sort_and_rename() {
    std::map<std::string, std::string> renames;
    auto order = [&](auto& elements, const char* kind) {
      std::vector<std::size_t> idx(elements.size());
      for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
      std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return elements[a].id < elements[b].id; });
      std::vector<std::decay_t<decltype(elements[0])>> sorted;
      for (std::size_t k = 0; k < idx.size(); ++k) {
        renames[std::string(kind) + "[" + std::to_string(idx[k]) + "]"] = std::string(kind) + "[" + std::to_string(k) + "]";
        sorted.push_back(std::move(elements[idx[k]]));
      }
      return sorted;
    };
    m_.causes = order(causes_, "causes");
    m_.effects = order(effects_, "effects");
    r_.rename(renames);
  }

  std::vector<ExtraProperty> extras_;       // tag descriptions, simulation, provenance rows
  std::vector<std::size_t> extra_rows_;
  const Workbook& wb_;
  CellReader r_;
  Matrix m_;
  std::vector<Cause> causes_;
  std::vector<Effect> effects_;
};

}  // namespace

bool has_tables(const Workbook& wb) { return wb.find(kCausesSheet) != nullptr; }

TablesImport workbook_to_matrix(const Workbook& wb, const std::string& file) { return TablesReader(wb, file).run(); }

}  // namespace cemv::formats::workbook
