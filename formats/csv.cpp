// The record layout cemv-csv/1 read (6.6, docs/csv.md): records in any order
// under their headers, every problem at its line and column, and the result
// checked by the matrix loader. Written in csv_export.cpp; the columns and the
// typed reads of a record are csv_records.*.
#include "formats/csv.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <regex>
#include <utility>

#include "formats/csv_records.hpp"
#include "formats/matrix_json.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats {

using namespace cemv::model;
using namespace csv_records;
using namespace csv_text;

namespace {

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

class RecordImporter {
 public:
  RecordImporter(const std::vector<CsvRecord>& records, const std::string& source)
      : records_(records), fields_(source, errors_), properties_(m_, fields_) {}

  Matrix run() {
    for (const auto& r : records_) handle(r);
    finish_tags();
    properties_.finish();
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
  void handle(const CsvRecord& r) {
    bool all_empty = std::all_of(r.fields.begin(), r.fields.end(),
                                 [](const CsvField& f) { return f.text.empty(); });
    if (all_empty) return;
    const std::string& type = r.fields[0].text;
    if (!type.empty() && type[0] == '#') return fields_.read_header(r);
    const RecordSchema* schema = find_schema(type);
    if (!schema) {
      fields_.error(r.line, 1, "unknown record type " + in_quotes(type) +
                                   " (expected property, sif_group, cause, cause_tag, effect, "
                                   "effect_tag, intersection or a '#' header)");
      return;
    }
    auto row = fields_.row(r, *schema);
    if (!row) return;
    switch (schema->record) {
      case RecordType::Property: return properties_.read(*row);
      case RecordType::SifGroup: return read_sif_group(*row);
      case RecordType::Cause: return read_cause(*row);
      case RecordType::CauseTag: return read_cause_tag(*row);
      case RecordType::Effect: return read_effect(*row);
      case RecordType::EffectTag: return read_effect_tag(*row);
      case RecordType::Intersection: return read_intersection(*row);
    }
  }

  void read_sif_group(const Row& row) {
    int n = fields_.int_value(row, "number", std::nullopt);
    auto f = fields_.cell(row, "number");
    if (!m_.sif_groups.emplace(n, fields_.text(row, "name")).second)
      fields_.error(f.line, f.column, "SIF group " + std::to_string(n) + " repeated");
  }

  void read_cause(const Row& row) {
    Cause c;
    const std::size_t errors_before = fields_.error_count();
    c.id = fields_.int_value(row, "id", std::nullopt);
    if (fields_.error_count() != errors_before) unreadable_owner_ = true;
    auto id_field = fields_.cell(row, "id");
    if (!cause_lines_.emplace(c.id, row.record->line).second) {
      fields_.error(id_field.line, id_field.column,
            "cause id " + std::to_string(c.id) + " repeats line " +
                std::to_string(cause_lines_[c.id]));
      return;
    }
    c.name = fields_.text(row, "name");
    c.description = fields_.text(row, "description");
    c.sil = fields_.int_value(row, "sil", 0);
    c.input = fields_.enum_value(row, "input", InputKind::Discrete, kInputKinds);
    c.function = fields_.enum_value(row, "function", CauseFunction::Normal, kCauseFunctions);
    c.bad_quality = fields_.enum_value(row, "bad_quality", BadQuality::Trip, kBadQualities);
    c.time.mode = fields_.enum_value(row, "time_mode", TimeMode::None, kTimeModes);
    c.time.ms = fields_.u32_value(row, "time_ms", 0);
    c.auto_ack = fields_.bool_value(row, "auto_ack", true);
    c.soft_bypass.allowed = fields_.bool_value(row, "soft_bypass_allowed", true);
    c.soft_bypass.max_s = fields_.u32_value(row, "soft_bypass_max_s", 0);
    c.soft_bypass.prealarm_s = fields_.u32_value(row, "soft_bypass_prealarm_s", 0);
    c.bypass_tag = fields_.optional_text(row, "bypass_tag");
    c.inhibit_tag = fields_.optional_text(row, "inhibit_tag");
    c.first_out_group = fields_.int_value(row, "first_out_group", 0);
    c.mutually_locked_maintenance = fields_.bool_value(row, "mutually_locked_maintenance", false);
    c.sif = fields_.sif_value(row);
    // The analog block exists exactly when its limit type is given.
    if (fields_.present(row, "analog_limit_type")) {
      AnalogParams a;
      a.limit_type = fields_.enum_value(row, "analog_limit_type", LimitType::High, kLimitTypes);
      auto limit = fields_.cell(row, "analog_limit");
      if (trim(limit.text).empty())
        fields_.error(limit.line, limit.column, "analog_limit: value required with analog_limit_type");
      a.limit = fields_.float_value(row, "analog_limit", 0.0f);
      a.hysteresis = fields_.float_value(row, "analog_hysteresis", 0.0f);
      if (fields_.present(row, "analog_prewarning")) a.prewarning = fields_.float_value(row, "analog_prewarning", 0.0f);
      a.delta = fields_.float_value(row, "analog_delta", 0.0f);
      a.unit = fields_.text(row, "analog_unit");
      c.analog = a;
    } else {
      for (const char* col : {"analog_limit", "analog_hysteresis", "analog_prewarning",
                              "analog_delta", "analog_unit"})
        if (!fields_.text(row, col).empty()) {
          auto f = fields_.cell(row, col);
          fields_.error(f.line, f.column, std::string(col) + " given without analog_limit_type");
        }
    }
    c.note = fields_.text(row, "note");
    m_.causes.push_back(std::move(c));
  }

  void read_effect(const Row& row) {
    Effect e;
    const std::size_t errors_before = fields_.error_count();
    e.id = fields_.int_value(row, "id", std::nullopt);
    if (fields_.error_count() != errors_before) unreadable_owner_ = true;
    auto id_field = fields_.cell(row, "id");
    if (!effect_lines_.emplace(e.id, row.record->line).second) {
      fields_.error(id_field.line, id_field.column,
            "effect id " + std::to_string(e.id) + " repeats line " +
                std::to_string(effect_lines_[e.id]));
      return;
    }
    e.name = fields_.text(row, "name");
    e.description = fields_.text(row, "description");
    e.sil = fields_.int_value(row, "sil", 0);
    e.function = fields_.enum_value(row, "function", EffectFunction::Normal, kEffectFunctions);
    e.output_delay_ms = fields_.u32_value(row, "output_delay_ms", 0);
    e.soft_bypass_allowed = fields_.bool_value(row, "soft_bypass_allowed", false);
    e.bypass_tag = fields_.optional_text(row, "bypass_tag");
    e.reset_tag = fields_.optional_text(row, "reset_tag");
    // The override block exists exactly when its maximum time is given.
    if (fields_.present(row, "override_max_s")) {
      Override o;
      o.max_s = fields_.u32_value(row, "override_max_s", 0);
      o.prealarm_s = fields_.u32_value(row, "override_prealarm_s", 0);
      e.override_time = o;
    } else if (fields_.present(row, "override_prealarm_s")) {
      auto f = fields_.cell(row, "override_prealarm_s");
      fields_.error(f.line, f.column, "override_prealarm_s given without override_max_s");
    }
    // The process-data block exists exactly when pass_through is given.
    if (fields_.present(row, "process_data_pass_through")) {
      ProcessData p;
      p.tag = fields_.optional_text(row, "process_data_tag");
      p.pass_through = fields_.bool_value(row, "process_data_pass_through", false);
      p.mask_tag = fields_.optional_text(row, "process_data_mask_tag");
      e.process_data = p;
    } else {
      for (const char* col : {"process_data_tag", "process_data_mask_tag"})
        if (!fields_.text(row, col).empty()) {
          auto f = fields_.cell(row, col);
          fields_.error(f.line, f.column, std::string(col) + " given without process_data_pass_through");
        }
    }
    e.mutually_locked_maintenance = fields_.bool_value(row, "mutually_locked_maintenance", false);
    e.sif = fields_.sif_value(row);
    e.note = fields_.text(row, "note");
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
    int owner = fields_.int_value(row, "cause", std::nullopt);
    PendingTag t{fields_.int_value(row, "position", std::nullopt), row.record->line,
                 fields_.cell(row, "position").column, {}, {}};
    t.cause_tag.name = fields_.text(row, "name");
    t.cause_tag.ett = fields_.bool_value(row, "ett", false);
    t.cause_tag.soft_bypass_allowed = fields_.bool_value(row, "soft_bypass_allowed", true);
    cause_tags_[owner].push_back(t);
  }

  void read_effect_tag(const Row& row) {
    int owner = fields_.int_value(row, "effect", std::nullopt);
    PendingTag t{fields_.int_value(row, "position", std::nullopt), row.record->line,
                 fields_.cell(row, "position").column, {}, {}};
    t.effect_tag.name = fields_.text(row, "name");
    t.effect_tag.ett = fields_.bool_value(row, "ett", false);
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
        fields_.error(tags.front().line, 2,
              std::string(kind) + "_tag of " + kind + " " + std::to_string(owner) +
                  ", which has no '" + kind + "' row");
        continue;
      }
      std::stable_sort(tags.begin(), tags.end(),
                       [](const PendingTag& a, const PendingTag& b) { return a.position < b.position; });
      for (std::size_t i = 0; i < tags.size(); ++i) {
        if (tags[i].position != static_cast<int>(i + 1)) {
          fields_.error(tags[i].line, tags[i].column,
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
    x.cause = fields_.int_value(row, "cause", std::nullopt);
    x.effect = fields_.int_value(row, "effect", std::nullopt);
    auto type_field = fields_.cell(row, "type");
    auto type = enum_from<IntersectionType>(type_field.text, kIntersectionTypes);
    if (!type) {
      fields_.error(type_field.line, type_field.column,
            "type: " + in_quotes(type_field.text) + " is not one of N, S, V, R, X, *");
    } else {
      x.type = *type;
    }
    if (fields_.present(row, "xoon")) x.xoon = fields_.int_value(row, "xoon", 0);
    x.note = fields_.text(row, "note");
    if (!intersection_lines_.emplace(std::pair{x.cause, x.effect}, row.record->line).second) {
      fields_.error(row.record->line, 2,
            "intersection of cause " + std::to_string(x.cause) + " and effect " +
                std::to_string(x.effect) + " repeats line " +
                std::to_string(intersection_lines_[{x.cause, x.effect}]));
      return;
    }
    m_.intersections.push_back(std::move(x));
  }

  const std::vector<CsvRecord>& records_;
  Matrix m_;
  std::vector<LoadIssue> errors_;
  RecordFields fields_;
  PropertyRecords properties_;
  bool unreadable_owner_ = false;
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
