// What the record layout's reader and writer share (formats/csv*.cpp; not part
// of the public interface): the record types and their columns, and one
// record's fields read by column name, each value checked and every problem
// placed at its line and column.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/csv_rfc4180.hpp"
#include "formats/csv_text.hpp"
#include "formats/diagnostics.hpp"
#include "formats/matrix_extras.hpp"
#include "model/matrix.hpp"
#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::csv_records {

enum class RecordType { Property, SifGroup, Cause, CauseTag, Effect, EffectTag, Intersection };

// Column names per record type, in the order export writes them (docs/csv.md).
struct RecordSchema {
  RecordType record;
  const char* type;
  std::vector<std::string> columns;
};

const std::vector<RecordSchema>& record_schemas();
const RecordSchema* find_schema(std::string_view type);
const RecordSchema& schema_of(RecordType record);

// The value of an enum named by its text, case ignored.
template <typename E>
std::optional<E> enum_from(std::string_view text, std::initializer_list<E> values) {
  std::string t = csv_text::lower(csv_text::trim(text));
  for (E v : values)
    if (t == csv_text::lower(model::to_string(v))) return v;
  return std::nullopt;
}

template <typename E>
std::string enum_choices(std::initializer_list<E> values) {
  std::string out;
  for (E v : values) csv_text::join_to(out, ", ", std::string(model::to_string(v)));
  return out;
}

// A data record under its type's header.
struct Row {
  const CsvRecord* record;
  const std::vector<int>* index;  // schema column -> field position (-1: absent)
  const RecordSchema* schema;
};

// The header rows read so far, and the typed reads of the records under them.
// A value that cannot be read is reported and read as its fallback, so one
// pass reports every problem of the file.
class RecordFields {
 public:
  RecordFields(std::string source, std::vector<LoadIssue>& errors)
      : source_(std::move(source)), errors_(errors) {}

  void error(int line, int column, std::string what);
  std::size_t error_count() const { return errors_.size(); }

  void read_header(const CsvRecord& r);
  // The record as a row of its type; nullopt (reported) before its header.
  std::optional<Row> row(const CsvRecord& r, const RecordSchema& schema);

  // The field of a named column; an absent trailing cell reads as empty.
  CsvField cell(const Row& row, std::string_view column) const;
  std::string text(const Row& row, std::string_view column) const { return cell(row, column).text; }
  std::optional<std::string> optional_text(const Row& row, std::string_view column) const;
  bool present(const Row& row, std::string_view column) const;

  // An empty cell reads as the fallback; a nullopt fallback makes the value required.
  int int_value(const Row& row, std::string_view column, std::optional<int> fallback);
  std::uint32_t u32_value(const Row& row, std::string_view column, std::uint32_t fallback);
  float float_value(const Row& row, std::string_view column, float fallback);
  bool bool_value(const Row& row, std::string_view column, bool fallback);
  std::vector<int> sif_value(const Row& row);

  template <typename E>
  E enum_value(const Row& row, std::string_view column, E fallback, std::initializer_list<E> values) {
    auto f = cell(row, column);
    if (csv_text::trim(f.text).empty()) return fallback;
    auto v = enum_from<E>(f.text, values);
    if (!v) {
      error(f.line, f.column, std::string(column) + ": " + model::in_quotes(f.text) + " is not one of " +
                                  enum_choices<E>(values));
      return fallback;
    }
    return *v;
  }

 private:
  template <typename T>
  T integer(const Row& row, std::string_view column, std::optional<T> fallback, long long lo, long long hi);

  std::string source_;
  std::vector<LoadIssue>& errors_;
  std::map<std::string, std::vector<int>> headers_;
};

// The property records: the matrix's own keys, the timing keys of
// docs/response-time.md, and the extras of formats/matrix_extras.hpp. Element
// keys are applied by finish(), once every record is read.
class PropertyRecords {
 public:
  PropertyRecords(model::Matrix& m, RecordFields& fields) : m_(m), fields_(fields) {}
  void read(const Row& row);
  void finish();

 private:
  enum class TimingKey { ProcessSafetyTime, SensorTime, ActuatorTime };
  struct PendingTiming {
    TimingKey key;
    int id = 0;
    std::uint32_t ms = 0;
    int line = 0;
    int column = 0;
  };
  struct PendingExtra {
    int line = 0;
    int column = 0;
  };

  bool read_timing(const std::string& key, const Row& row, int line, int column);
  void finish_timing();
  void finish_extras();

  model::Matrix& m_;
  RecordFields& fields_;
  std::set<std::string> seen_;
  std::vector<PendingTiming> timing_;
  std::vector<ExtraProperty> extras_;
  std::vector<PendingExtra> extra_places_;
};

}  // namespace cemv::formats::csv_records
