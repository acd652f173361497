// The record layout cemv-csv/1 (6.6), docs/csv.md.
#include "formats/csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <utility>

#include "formats/csv_text.hpp"
#include "formats/matrix_extras.hpp"
#include "formats/matrix_json.hpp"
#include "model/names.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

using namespace cemv::model;

namespace {

// ---- small text helpers: formats/csv_text.hpp -----------------------------------

using namespace csv_text;

// ---- value parsing (record layout) -------------------------------------------

std::optional<long long> parse_integer(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  long long v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size()) return std::nullopt;
  return v;
}

std::optional<float> parse_float(std::string_view text) {
  text = trim(text);
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);
  float v = 0;
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || p != text.data() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

template <typename E>
std::optional<E> enum_from(std::string_view text, std::initializer_list<E> values) {
  std::string t = lower(trim(text));
  for (E v : values)
    if (t == lower(to_string(v))) return v;
  return std::nullopt;
}

template <typename E>
std::string enum_choices(std::initializer_list<E> values) {
  std::string out;
  for (E v : values) join_to(out, ", ", std::string(to_string(v)));
  return out;
}

constexpr std::initializer_list<InputKind> kInputKinds = {InputKind::Discrete, InputKind::Analog};
constexpr std::initializer_list<CauseFunction> kCauseFunctions = {
    CauseFunction::Normal, CauseFunction::And, CauseFunction::Or, CauseFunction::TwoOoThree,
    CauseFunction::Comment};
constexpr std::initializer_list<LimitType> kLimitTypes = {LimitType::High, LimitType::Low};
constexpr std::initializer_list<BadQuality> kBadQualities = {BadQuality::Ignore, BadQuality::Trip,
                                                             BadQuality::Degrade};
constexpr std::initializer_list<TimeMode> kTimeModes = {TimeMode::None, TimeMode::OnDelay,
                                                        TimeMode::OffDelay, TimeMode::Timed};
constexpr std::initializer_list<EffectFunction> kEffectFunctions = {EffectFunction::Normal,
                                                                    EffectFunction::Comment};
constexpr std::initializer_list<IntersectionType> kIntersectionTypes = {
    IntersectionType::N, IntersectionType::S, IntersectionType::V,
    IntersectionType::R, IntersectionType::X, IntersectionType::Note};

// ---- record layout schema -------------------------------------------------------

// Column names per record type, in the order export writes them (docs/csv.md).
struct RecordSchema {
  const char* type;
  std::vector<std::string> columns;
};

const std::vector<RecordSchema>& record_schemas() {
  static const std::vector<RecordSchema> schemas = {
      {"property", {"key", "value"}},
      {"sif_group", {"number", "name"}},
      {"cause",
       {"id", "name", "description", "sil", "input", "function", "bad_quality", "time_mode",
        "time_ms", "auto_ack", "soft_bypass_allowed", "soft_bypass_max_s",
        "soft_bypass_prealarm_s", "bypass_tag", "inhibit_tag", "first_out_group",
        "mutually_locked_maintenance", "sif", "analog_limit_type", "analog_limit",
        "analog_hysteresis", "analog_prewarning", "analog_delta", "analog_unit", "note"}},
      {"cause_tag", {"cause", "position", "name", "ett", "soft_bypass_allowed"}},
      {"effect",
       {"id", "name", "description", "sil", "function", "output_delay_ms", "soft_bypass_allowed",
        "bypass_tag", "reset_tag", "override_max_s", "override_prealarm_s", "process_data_tag",
        "process_data_pass_through", "process_data_mask_tag", "mutually_locked_maintenance", "sif",
        "note"}},
      {"effect_tag", {"effect", "position", "name", "ett"}},
      {"intersection", {"cause", "effect", "type", "xoon", "note"}},
  };
  return schemas;
}

const RecordSchema* find_schema(std::string_view type) {
  for (const auto& s : record_schemas())
    if (type == s.type) return &s;
  return nullptr;
}

// ---- export -------------------------------------------------------------------

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

// ---- import: record layout --------------------------------------------------------

class RecordImporter {
 public:
  RecordImporter(const std::vector<CsvRecord>& records, const std::string& source)
      : records_(records), source_(source) {}

  Matrix run() {
    for (const auto& r : records_) handle(r);
    finish_tags();
    finish_timing();
    finish_extras();
    if (!errors_.empty()) throw LoadError(errors_);
    m_.sort_by_id();
    return m_;
  }

  // The CSV line of the element a loader path such as `causes[3].tags[1]` names.
  std::optional<int> line_of_path(const std::string& path) const {
    static const std::regex re(R"((causes|effects|intersections)\[(\d+)\])");
    std::smatch mt;
    if (!std::regex_search(path, mt, re)) return std::nullopt;
    std::size_t i = std::stoul(mt[2].str());
    std::vector<std::pair<std::pair<int, int>, int>> keyed;
    if (mt[1] == "causes")
      for (auto& [id, line] : cause_lines_) keyed.push_back({{id, 0}, line});
    else if (mt[1] == "effects")
      for (auto& [id, line] : effect_lines_) keyed.push_back({{id, 0}, line});
    else
      for (auto& [key, line] : intersection_lines_) keyed.push_back({key, line});
    if (i >= keyed.size()) return std::nullopt;
    return keyed[i].second;  // maps are ordered like the canonical arrays
  }

 private:
  struct Row {
    const CsvRecord* record;
    const std::vector<int>* index;  // schema column -> field position (-1: absent)
    const RecordSchema* schema;
  };

  void error(int line, int column, std::string what) {
    errors_.push_back({where_of(source_, line, column), std::move(what)});
  }

  void handle(const CsvRecord& r) {
    bool all_empty = std::all_of(r.fields.begin(), r.fields.end(),
                                 [](const CsvField& f) { return f.text.empty(); });
    if (all_empty) return;
    const std::string& type = r.fields[0].text;
    if (!type.empty() && type[0] == '#') return read_header(r);
    const RecordSchema* schema = find_schema(type);
    if (!schema) {
      error(r.line, 1, "unknown record type " + in_quotes(type) +
                           " (expected property, sif_group, cause, cause_tag, effect, "
                           "effect_tag, intersection or a '#' header)");
      return;
    }
    auto h = headers_.find(type);
    if (h == headers_.end()) {
      error(r.line, 1, in_quotes(type) + " record before its header row " + in_quotes("#" + type));
      return;
    }
    const std::size_t width = schema->columns.size() + 1;
    for (std::size_t i = width; i < r.fields.size(); ++i)
      if (!r.fields[i].text.empty()) {
        error(r.line, static_cast<int>(i + 1),
              "extra value " + in_quotes(r.fields[i].text) + " beyond the " +
                  std::to_string(schema->columns.size()) + " columns of " + in_quotes("#" + type));
        break;  // still read the row, so later rows do not report follow-on errors
      }
    Row row{&r, &h->second, schema};
    if (type == "property") read_property(row);
    else if (type == "sif_group") read_sif_group(row);
    else if (type == "cause") read_cause(row);
    else if (type == "cause_tag") read_cause_tag(row);
    else if (type == "effect") read_effect(row);
    else if (type == "effect_tag") read_effect_tag(row);
    else read_intersection(row);
  }

  void read_header(const CsvRecord& r) {
    std::string type = r.fields[0].text.substr(1);
    const RecordSchema* schema = find_schema(type);
    if (!schema) {
      error(r.line, 1, "unknown header " + in_quotes(r.fields[0].text));
      return;
    }
    if (headers_.count(type)) {
      error(r.line, 1, "header " + in_quotes("#" + type) + " repeated");
      return;
    }
    std::vector<int> index(schema->columns.size(), -1);
    bool ok = true;
    for (std::size_t i = 1; i < r.fields.size(); ++i) {
      const std::string& name = r.fields[i].text;
      if (name.empty()) continue;  // trailing empty cells a spreadsheet may add
      auto it = std::find(schema->columns.begin(), schema->columns.end(), name);
      if (it == schema->columns.end()) {
        error(r.line, static_cast<int>(i + 1), "unknown column " + in_quotes(name) + " for " + in_quotes(type));
        ok = false;
        continue;
      }
      auto k = static_cast<std::size_t>(it - schema->columns.begin());
      if (index[k] >= 0) {
        error(r.line, static_cast<int>(i + 1), "column " + in_quotes(name) + " repeated");
        ok = false;
        continue;
      }
      index[k] = static_cast<int>(i);
    }
    for (std::size_t k = 0; k < index.size(); ++k)
      if (index[k] < 0) {
        error(r.line, 1, "header " + in_quotes("#" + type) + " lacks column " + in_quotes(schema->columns[k]));
        ok = false;
      }
    if (ok) headers_[type] = std::move(index);
  }

  // The field of a named column; an absent trailing cell reads as empty.
  CsvField cell(const Row& row, std::string_view column) const {
    const auto& cols = row.schema->columns;
    auto k = static_cast<std::size_t>(std::find(cols.begin(), cols.end(), column) - cols.begin());
    int pos = (*row.index)[k];
    if (pos >= 0 && static_cast<std::size_t>(pos) < row.record->fields.size())
      return row.record->fields[static_cast<std::size_t>(pos)];
    CsvField f;
    f.line = row.record->line;
    f.column = pos + 1;
    return f;
  }

  std::string text(const Row& row, std::string_view column) const { return cell(row, column).text; }

  std::optional<std::string> optional_text(const Row& row, std::string_view column) const {
    auto t = text(row, column);
    if (t.empty()) return std::nullopt;
    return t;
  }

  bool present(const Row& row, std::string_view column) const {
    return !trim(text(row, column)).empty();
  }

  // Integer in [lo, hi]; empty -> fallback (nullopt fallback: required).
  template <typename T>
  T integer(const Row& row, std::string_view column, std::optional<T> fallback, long long lo,
            long long hi) {
    auto f = cell(row, column);
    if (trim(f.text).empty()) {
      if (fallback) return *fallback;
      error(f.line, f.column, std::string(column) + ": value required");
      return T{};
    }
    auto v = parse_integer(f.text);
    if (!v || *v < lo || *v > hi) {
      error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not an integer in " +
                                  std::to_string(lo) + ".." + std::to_string(hi));
      return T{};
    }
    return static_cast<T>(*v);
  }

  int int_value(const Row& row, std::string_view column, std::optional<int> fallback) {
    return integer<int>(row, column, fallback, std::numeric_limits<int>::min(),
                        std::numeric_limits<int>::max());
  }
  std::uint32_t u32_value(const Row& row, std::string_view column, std::uint32_t fallback) {
    return integer<std::uint32_t>(row, column, fallback, 0, std::numeric_limits<std::uint32_t>::max());
  }

  float float_value(const Row& row, std::string_view column, float fallback) {
    auto f = cell(row, column);
    if (trim(f.text).empty()) return fallback;
    auto v = parse_float(f.text);
    if (!v) {
      error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not a finite number");
      return fallback;
    }
    return *v;
  }

  bool bool_value(const Row& row, std::string_view column, bool fallback) {
    auto f = cell(row, column);
    std::string t = lower(trim(f.text));
    if (t.empty()) return fallback;
    if (t == "true") return true;
    if (t == "false") return false;
    error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not true or false");
    return fallback;
  }

  template <typename E>
  E enum_value(const Row& row, std::string_view column, E fallback,
               std::initializer_list<E> values) {
    auto f = cell(row, column);
    if (trim(f.text).empty()) return fallback;
    auto v = enum_from<E>(f.text, values);
    if (!v) {
      error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not one of " +
                                  enum_choices<E>(values));
      return fallback;
    }
    return *v;
  }

  std::vector<int> sif_value(const Row& row) {
    auto f = cell(row, "sif");
    std::vector<int> out;
    std::string token;
    auto flush = [&] {
      if (token.empty()) return;
      auto v = parse_integer(token);
      if (!v || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
        error(f.line, f.column, "sif: " + in_quotes(token) + " is not a SIF group number");
      else
        out.push_back(static_cast<int>(*v));
      token.clear();
    };
    for (char c : f.text) {
      if (c == ' ' || c == ';' || c == ',' || c == '\t') flush();
      else token += c;
    }
    flush();
    return out;
  }

  void read_property(const Row& row) {
    auto key_field = cell(row, "key");
    const std::string key = std::string(trim(key_field.text));
    const std::string value = text(row, "value");
    if (!properties_seen_.insert(key).second) {
      error(key_field.line, key_field.column, "property " + in_quotes(key) + " repeated");
      return;
    }
    if (key == "format") {
      if (value != kMatrixFormat)
        error(key_field.line, key_field.column + 1,
              "format: " + in_quotes(value) + " is not " + in_quotes(kMatrixFormat));
    } else if (key == "name") {
      m_.name = value;
    } else if (key == "title") {
      m_.title = value;
    } else if (key == "cycle_ms") {
      m_.cycle_ms = u32_value(row, "value", 100);
    } else if (key == "secure_write.enable_tag") {
      m_.secure_write = SecureWrite{value};
    } else if (key == "group_deactivation.enable_tag") {
      if (!m_.group_deactivation) m_.group_deactivation.emplace();
      m_.group_deactivation->enable_tag = value;
    } else if (key == "group_deactivation.set_tag") {
      if (!m_.group_deactivation) m_.group_deactivation.emplace();
      m_.group_deactivation->set_tag = value;
    } else if (timing_property(key, row, key_field.line, key_field.column)) {
    } else if (is_extra_property(key)) {
      extras_.push_back({key, value});
      extra_places_.emplace_back(key_field.line, key_field.column);
    } else {
      error(key_field.line, key_field.column,
            "unknown property " + in_quotes(key) +
                " (expected format, name, title, cycle_ms, secure_write.enable_tag, "
                "group_deactivation.enable_tag, group_deactivation.set_tag, watchdog_ms, "
                "sif_group.N.process_safety_time_ms, cause.ID.sensor_ms, effect.ID.actuator_ms, "
                "tag.NAME.description, cause.ID.tag.N.simulation_allowed, effect.ID.tag.N.simulation_allowed, "
                "provenance.import.K, provenance.parameters.K)");
    }
  }

  // The timing keys of docs/response-time.md as property rows (watchdog_ms,
  // sif_group.N.process_safety_time_ms, cause.ID.sensor_ms,
  // effect.ID.actuator_ms), so the record layout's columns stay as they were.
  // Element keys are applied once every record is read.
  struct PendingTiming {
    std::string kind;
    int id = 0;
    std::uint32_t ms = 0;
    int line = 0;
    int column = 0;
  };
  std::vector<PendingTiming> timing_;
  // Tag descriptions, simulation permissions and provenance records
  // (formats/matrix_extras.hpp), applied once every record is read.
  std::vector<ExtraProperty> extras_;
  std::vector<std::pair<int, int>> extra_places_;

  void finish_extras() {
    for (const auto& [row, why] : apply_extra_properties(m_, extras_))
      error(extra_places_[row].first, extra_places_[row].second, why);
  }

  bool timing_property(const std::string& key, const Row& row, int line, int column) {
    if (key == "watchdog_ms") {
      std::uint32_t ms = u32_value(row, "value", 0);
      if (ms == 0) error(line, column, "watchdog_ms must be positive");
      else m_.watchdog_ms = ms;
      return true;
    }
    for (const char* kind : {"sif_group.", "cause.", "effect."}) {
      const std::string prefix = kind;
      const std::string suffix = prefix == "sif_group." ? ".process_safety_time_ms"
                                 : prefix == "cause."   ? ".sensor_ms" : ".actuator_ms";
      if (key.size() <= prefix.size() + suffix.size() || key.compare(0, prefix.size(), prefix) != 0 ||
          key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      const std::string number = key.substr(prefix.size(), key.size() - prefix.size() - suffix.size());
      int id = 0;
      auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), id);
      if (ec != std::errc{} || end != number.data() + number.size()) return false;
      timing_.push_back({prefix, id, u32_value(row, "value", 0), line, column});
      return true;
    }
    return false;
  }

  void finish_timing() {
    for (const auto& t : timing_) {
      if (t.kind == "sif_group.") {
        if (!m_.sif_groups.count(t.id)) error(t.line, t.column, "SIF group " + std::to_string(t.id) + " is not defined");
        else if (t.ms == 0) error(t.line, t.column, "a process safety time must be positive");
        else m_.process_safety_time_ms[t.id] = t.ms;
        continue;
      }
      bool found = false;
      if (t.kind == "cause.")
        for (auto& c : m_.causes) if (c.id == t.id) { c.sensor_ms = t.ms; found = true; }
      if (t.kind == "effect.")
        for (auto& e : m_.effects) if (e.id == t.id) { e.actuator_ms = t.ms; found = true; }
      if (!found) error(t.line, t.column, "no " + t.kind.substr(0, t.kind.size() - 1) + " " + std::to_string(t.id));
    }
  }

  void read_sif_group(const Row& row) {
    int n = int_value(row, "number", std::nullopt);
    auto f = cell(row, "number");
    if (!m_.sif_groups.emplace(n, text(row, "name")).second)
      error(f.line, f.column, "SIF group " + std::to_string(n) + " repeated");
  }

  void read_cause(const Row& row) {
    Cause c;
    const std::size_t errors_before = errors_.size();
    c.id = int_value(row, "id", std::nullopt);
    if (errors_.size() != errors_before) unreadable_owner_ = true;
    auto id_field = cell(row, "id");
    if (!cause_lines_.emplace(c.id, row.record->line).second) {
      error(id_field.line, id_field.column,
            "cause id " + std::to_string(c.id) + " repeats line " +
                std::to_string(cause_lines_[c.id]));
      return;
    }
    c.name = text(row, "name");
    c.description = text(row, "description");
    c.sil = int_value(row, "sil", 0);
    c.input = enum_value(row, "input", InputKind::Discrete, kInputKinds);
    c.function = enum_value(row, "function", CauseFunction::Normal, kCauseFunctions);
    c.bad_quality = enum_value(row, "bad_quality", BadQuality::Trip, kBadQualities);
    c.time.mode = enum_value(row, "time_mode", TimeMode::None, kTimeModes);
    c.time.ms = u32_value(row, "time_ms", 0);
    c.auto_ack = bool_value(row, "auto_ack", true);
    c.soft_bypass.allowed = bool_value(row, "soft_bypass_allowed", true);
    c.soft_bypass.max_s = u32_value(row, "soft_bypass_max_s", 0);
    c.soft_bypass.prealarm_s = u32_value(row, "soft_bypass_prealarm_s", 0);
    c.bypass_tag = optional_text(row, "bypass_tag");
    c.inhibit_tag = optional_text(row, "inhibit_tag");
    c.first_out_group = int_value(row, "first_out_group", 0);
    c.mutually_locked_maintenance = bool_value(row, "mutually_locked_maintenance", false);
    c.sif = sif_value(row);
    // The analog block exists exactly when its limit type is given.
    if (present(row, "analog_limit_type")) {
      AnalogParams a;
      a.limit_type = enum_value(row, "analog_limit_type", LimitType::High, kLimitTypes);
      auto limit = cell(row, "analog_limit");
      if (trim(limit.text).empty())
        error(limit.line, limit.column, "analog_limit: value required with analog_limit_type");
      a.limit = float_value(row, "analog_limit", 0.0f);
      a.hysteresis = float_value(row, "analog_hysteresis", 0.0f);
      if (present(row, "analog_prewarning")) a.prewarning = float_value(row, "analog_prewarning", 0.0f);
      a.delta = float_value(row, "analog_delta", 0.0f);
      a.unit = text(row, "analog_unit");
      c.analog = a;
    } else {
      for (const char* col : {"analog_limit", "analog_hysteresis", "analog_prewarning",
                              "analog_delta", "analog_unit"})
        if (!text(row, col).empty()) {
          auto f = cell(row, col);
          error(f.line, f.column, std::string(col) + " given without analog_limit_type");
        }
    }
    c.note = text(row, "note");
    m_.causes.push_back(std::move(c));
  }

  void read_effect(const Row& row) {
    Effect e;
    const std::size_t errors_before = errors_.size();
    e.id = int_value(row, "id", std::nullopt);
    if (errors_.size() != errors_before) unreadable_owner_ = true;
    auto id_field = cell(row, "id");
    if (!effect_lines_.emplace(e.id, row.record->line).second) {
      error(id_field.line, id_field.column,
            "effect id " + std::to_string(e.id) + " repeats line " +
                std::to_string(effect_lines_[e.id]));
      return;
    }
    e.name = text(row, "name");
    e.description = text(row, "description");
    e.sil = int_value(row, "sil", 0);
    e.function = enum_value(row, "function", EffectFunction::Normal, kEffectFunctions);
    e.output_delay_ms = u32_value(row, "output_delay_ms", 0);
    e.soft_bypass_allowed = bool_value(row, "soft_bypass_allowed", false);
    e.bypass_tag = optional_text(row, "bypass_tag");
    e.reset_tag = optional_text(row, "reset_tag");
    // The override block exists exactly when its maximum time is given.
    if (present(row, "override_max_s")) {
      Override o;
      o.max_s = u32_value(row, "override_max_s", 0);
      o.prealarm_s = u32_value(row, "override_prealarm_s", 0);
      e.override_time = o;
    } else if (present(row, "override_prealarm_s")) {
      auto f = cell(row, "override_prealarm_s");
      error(f.line, f.column, "override_prealarm_s given without override_max_s");
    }
    // The process-data block exists exactly when pass_through is given.
    if (present(row, "process_data_pass_through")) {
      ProcessData p;
      p.tag = optional_text(row, "process_data_tag");
      p.pass_through = bool_value(row, "process_data_pass_through", false);
      p.mask_tag = optional_text(row, "process_data_mask_tag");
      e.process_data = p;
    } else {
      for (const char* col : {"process_data_tag", "process_data_mask_tag"})
        if (!text(row, col).empty()) {
          auto f = cell(row, col);
          error(f.line, f.column, std::string(col) + " given without process_data_pass_through");
        }
    }
    e.mutually_locked_maintenance = bool_value(row, "mutually_locked_maintenance", false);
    e.sif = sif_value(row);
    e.note = text(row, "note");
    m_.effects.push_back(std::move(e));
  }

  // Tags are collected first and attached once every cause/effect row is known,
  // so tag rows may come before or after their element.
  struct PendingTag {
    int position;
    int line;
    int column;
    CauseTag cause_tag;
    EffectTag effect_tag;
  };

  void read_cause_tag(const Row& row) {
    int owner = int_value(row, "cause", std::nullopt);
    PendingTag t{int_value(row, "position", std::nullopt), row.record->line,
                 cell(row, "position").column, {}, {}};
    t.cause_tag.name = text(row, "name");
    t.cause_tag.ett = bool_value(row, "ett", false);
    t.cause_tag.soft_bypass_allowed = bool_value(row, "soft_bypass_allowed", true);
    cause_tags_[owner].push_back(t);
  }

  void read_effect_tag(const Row& row) {
    int owner = int_value(row, "effect", std::nullopt);
    PendingTag t{int_value(row, "position", std::nullopt), row.record->line,
                 cell(row, "position").column, {}, {}};
    t.effect_tag.name = text(row, "name");
    t.effect_tag.ett = bool_value(row, "ett", false);
    effect_tags_[owner].push_back(t);
  }

  template <typename Element, typename Get>
  void attach(std::map<int, std::vector<PendingTag>>& pending, std::vector<Element>& elements,
              const char* kind, Get get) {
    for (auto& entry : pending) {
      // Not a structured binding: clang before 16 cannot capture one in a lambda.
      const int owner = entry.first;
      auto& tags = entry.second;
      auto it = std::find_if(elements.begin(), elements.end(),
                             [&](const Element& e) { return e.id == owner; });
      if (it == elements.end()) {
        // An element row whose id could not be read was reported already.
        if (unreadable_owner_) continue;
        error(tags.front().line, 2,
              std::string(kind) + "_tag of " + kind + " " + std::to_string(owner) +
                  ", which has no '" + kind + "' row");
        continue;
      }
      std::stable_sort(tags.begin(), tags.end(),
                       [](const PendingTag& a, const PendingTag& b) { return a.position < b.position; });
      for (std::size_t i = 0; i < tags.size(); ++i) {
        if (tags[i].position != static_cast<int>(i + 1)) {
          error(tags[i].line, tags[i].column,
                std::string(kind) + " " + std::to_string(owner) + ": tag position " +
                    std::to_string(tags[i].position) + " where " + std::to_string(i + 1) +
                    " was expected (positions run 1, 2, ... without gaps or repeats)");
          break;
        }
        it->tags.push_back(get(tags[i]));
      }
    }
  }

  void finish_tags() {
    attach(cause_tags_, m_.causes, "cause", [](const PendingTag& t) { return t.cause_tag; });
    attach(effect_tags_, m_.effects, "effect", [](const PendingTag& t) { return t.effect_tag; });
  }

  void read_intersection(const Row& row) {
    Intersection x;
    x.cause = int_value(row, "cause", std::nullopt);
    x.effect = int_value(row, "effect", std::nullopt);
    auto type_field = cell(row, "type");
    auto type = enum_from<IntersectionType>(type_field.text, kIntersectionTypes);
    if (!type) {
      error(type_field.line, type_field.column,
            "type: " + in_quotes(type_field.text) + " is not one of N, S, V, R, X, *");
    } else {
      x.type = *type;
    }
    if (present(row, "xoon")) x.xoon = int_value(row, "xoon", 0);
    x.note = text(row, "note");
    if (!intersection_lines_.emplace(std::pair{x.cause, x.effect}, row.record->line).second) {
      error(row.record->line, 2,
            "intersection of cause " + std::to_string(x.cause) + " and effect " +
                std::to_string(x.effect) + " repeats line " +
                std::to_string(intersection_lines_[{x.cause, x.effect}]));
      return;
    }
    m_.intersections.push_back(std::move(x));
  }

  const std::vector<CsvRecord>& records_;
  std::string source_;
  Matrix m_;
  std::vector<LoadIssue> errors_;
  bool unreadable_owner_ = false;
  std::map<std::string, std::vector<int>> headers_;
  std::set<std::string> properties_seen_;
  std::map<int, int> cause_lines_;
  std::map<int, int> effect_lines_;
  std::map<std::pair<int, int>, int> intersection_lines_;
  std::map<int, std::vector<PendingTag>> cause_tags_;
  std::map<int, std::vector<PendingTag>> effect_tags_;
};

// Loads the imported matrix back through the JSON loader so that every rule the
// loader enforces holds for an imported matrix too.
Matrix check_with_loader(const Matrix& m, const std::string& source,
                         const RecordImporter* importer) {
  try {
    return parse_matrix(to_canonical_json(m), source);
  } catch (const LoadError& e) {
    std::vector<LoadIssue> issues;
    for (const auto& issue : e.issues()) {
      LoadIssue mapped = issue;
      std::optional<int> line = importer ? importer->line_of_path(issue.where) : std::nullopt;
      if (line) mapped.where = where_of(source, *line) + " (" + issue.where + ")";
      issues.push_back(mapped);
    }
    throw LoadError(issues);
  }
}

}  // namespace

// ---- export -------------------------------------------------------------------------

std::string export_csv(const Matrix& m) {
  CsvWriter w;
  const auto& schemas = record_schemas();
  auto schema = [&](const char* type) -> const RecordSchema& { return *find_schema(type); };

  w.header(schema("property"));
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

  w.header(schema("sif_group"));
  for (const auto& [n, name] : m.sif_groups) w.row({"sif_group", std::to_string(n), name});

  w.header(schema("cause"));
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
  w.header(schema("cause_tag"));
  for (const auto& c : m.causes)
    for (std::size_t k = 0; k < c.tags.size(); ++k)
      w.row({"cause_tag", std::to_string(c.id), std::to_string(k + 1), c.tags[k].name,
             bool_text(c.tags[k].ett), bool_text(c.tags[k].soft_bypass_allowed)});

  w.header(schema("effect"));
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
  w.header(schema("effect_tag"));
  for (const auto& e : m.effects)
    for (std::size_t k = 0; k < e.tags.size(); ++k)
      w.row({"effect_tag", std::to_string(e.id), std::to_string(k + 1), e.tags[k].name,
             bool_text(e.tags[k].ett)});

  w.header(schema("intersection"));
  for (const auto& x : m.intersections)
    w.row({"intersection", std::to_string(x.cause), std::to_string(x.effect), to_string(x.type),
           x.xoon ? std::to_string(*x.xoon) : "", x.note});
  (void)schemas;
  return w.take();
}

// ---- import -------------------------------------------------------------------------

bool starts_as_csv_records(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::string_view first = text.substr(0, text.find_first_of(",\r\n"));
  if (!first.empty() && first.front() == '#') first.remove_prefix(1);
  return find_schema(first) != nullptr;
}

Matrix import_csv_records(std::string_view text, const std::string& source_name) {
  auto records = parse_csv(text, ',', true, source_name);
  RecordImporter importer(records, source_name);
  Matrix m = importer.run();
  return check_with_loader(m, source_name, &importer);
}

}  // namespace cemv::formats
