// The record layout's columns, and one record's fields read by column name
// (formats/csv_records.hpp, docs/csv.md).
#include "formats/csv_records.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cemv::formats::csv_records {

using namespace csv_text;
using model::in_quotes;

const std::vector<RecordSchema>& record_schemas() {
  static const std::vector<RecordSchema> schemas = {
      {RecordType::Property, "property", {"key", "value"}},
      {RecordType::SifGroup, "sif_group", {"number", "name"}},
      {RecordType::Cause,
       "cause",
       {"id", "name", "description", "sil", "input", "function", "bad_quality", "time_mode",
        "time_ms", "auto_ack", "soft_bypass_allowed", "soft_bypass_max_s",
        "soft_bypass_prealarm_s", "bypass_tag", "inhibit_tag", "first_out_group",
        "mutually_locked_maintenance", "sif", "analog_limit_type", "analog_limit",
        "analog_hysteresis", "analog_prewarning", "analog_delta", "analog_unit", "note"}},
      {RecordType::CauseTag, "cause_tag", {"cause", "position", "name", "ett", "soft_bypass_allowed"}},
      {RecordType::Effect,
       "effect",
       {"id", "name", "description", "sil", "function", "output_delay_ms", "soft_bypass_allowed",
        "bypass_tag", "reset_tag", "override_max_s", "override_prealarm_s", "process_data_tag",
        "process_data_pass_through", "process_data_mask_tag", "mutually_locked_maintenance", "sif",
        "note"}},
      {RecordType::EffectTag, "effect_tag", {"effect", "position", "name", "ett"}},
      {RecordType::Intersection, "intersection", {"cause", "effect", "type", "xoon", "note"}},
  };
  return schemas;
}

const RecordSchema* find_schema(std::string_view type) {
  for (const auto& s : record_schemas())
    if (type == s.type) return &s;
  return nullptr;
}

const RecordSchema& schema_of(RecordType record) {
  for (const auto& s : record_schemas())
    if (s.record == record) return s;
  throw std::logic_error("csv_records: a record type without a schema");
}

namespace {

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

}  // namespace

void RecordFields::error(int line, int column, std::string what) {
  errors_.push_back({where_of(source_, line, column), std::move(what)});
}

void RecordFields::read_header(const CsvRecord& r) {
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

std::optional<Row> RecordFields::row(const CsvRecord& r, const RecordSchema& schema) {
  auto h = headers_.find(schema.type);
  if (h == headers_.end()) {
    error(r.line, 1, in_quotes(schema.type) + " record before its header row " +
                         in_quotes(std::string("#") + schema.type));
    return std::nullopt;
  }
  const std::size_t width = schema.columns.size() + 1;
  for (std::size_t i = width; i < r.fields.size(); ++i)
    if (!r.fields[i].text.empty()) {
      error(r.line, static_cast<int>(i + 1),
            "extra value " + in_quotes(r.fields[i].text) + " beyond the " +
                std::to_string(schema.columns.size()) + " columns of " +
                in_quotes(std::string("#") + schema.type));
      break;  // still read the row, so later rows do not report follow-on errors
    }
  return Row{&r, &h->second, &schema};
}

CsvField RecordFields::cell(const Row& row, std::string_view column) const {
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

std::optional<std::string> RecordFields::optional_text(const Row& row, std::string_view column) const {
  auto t = text(row, column);
  if (t.empty()) return std::nullopt;
  return t;
}

bool RecordFields::present(const Row& row, std::string_view column) const {
  return !trim(text(row, column)).empty();
}

// Integer in [lo, hi]; empty -> fallback (nullopt fallback: required).
template <typename T>
T RecordFields::integer(const Row& row, std::string_view column, std::optional<T> fallback, long long lo,
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

int RecordFields::int_value(const Row& row, std::string_view column, std::optional<int> fallback) {
  return integer<int>(row, column, fallback, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
}

std::uint32_t RecordFields::u32_value(const Row& row, std::string_view column, std::uint32_t fallback) {
  return integer<std::uint32_t>(row, column, fallback, 0, std::numeric_limits<std::uint32_t>::max());
}

float RecordFields::float_value(const Row& row, std::string_view column, float fallback) {
  auto f = cell(row, column);
  if (trim(f.text).empty()) return fallback;
  auto v = parse_float(f.text);
  if (!v) {
    error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not a finite number");
    return fallback;
  }
  return *v;
}

bool RecordFields::bool_value(const Row& row, std::string_view column, bool fallback) {
  auto f = cell(row, column);
  std::string t = lower(trim(f.text));
  if (t.empty()) return fallback;
  if (t == "true") return true;
  if (t == "false") return false;
  error(f.line, f.column, std::string(column) + ": " + in_quotes(f.text) + " is not true or false");
  return fallback;
}

std::vector<int> RecordFields::sif_value(const Row& row) {
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

}  // namespace cemv::formats::csv_records
