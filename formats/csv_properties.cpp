// The property records of cemv-csv/1 (docs/csv.md): the matrix's own keys, the
// timing keys of docs/response-time.md (watchdog_ms,
// sif_group.N.process_safety_time_ms, cause.ID.sensor_ms,
// effect.ID.actuator_ms) as property rows, so the record layout's columns stay
// as they were, and the extras of formats/matrix_extras.hpp.
#include <charconv>

#include "formats/csv_records.hpp"

namespace cemv::formats::csv_records {

using namespace csv_text;
using model::in_quotes;

namespace {

// Sets a time of the element with `id`; false when the matrix has none.
template <typename Element>
bool set_time(std::vector<Element>& elements, int id, std::uint32_t Element::*time, std::uint32_t ms) {
  bool found = false;
  for (auto& x : elements)
    if (x.id == id) x.*time = ms, found = true;
  return found;
}

}  // namespace

void PropertyRecords::read(const Row& row) {
  auto key_field = fields_.cell(row, "key");
  const std::string key = std::string(trim(key_field.text));
  const std::string value = fields_.text(row, "value");
  if (!seen_.insert(key).second) {
    fields_.error(key_field.line, key_field.column, "property " + in_quotes(key) + " repeated");
    return;
  }
  if (key == "format") {
    if (value != model::kMatrixFormat)
      fields_.error(key_field.line, key_field.column + 1,
                    "format: " + in_quotes(value) + " is not " + in_quotes(model::kMatrixFormat));
  } else if (key == "name") {
    m_.name = value;
  } else if (key == "title") {
    m_.title = value;
  } else if (key == "cycle_ms") {
    m_.cycle_ms = fields_.u32_value(row, "value", 100);
  } else if (key == "secure_write.enable_tag") {
    m_.secure_write = model::SecureWrite{value};
  } else if (key == "group_deactivation.enable_tag") {
    if (!m_.group_deactivation) m_.group_deactivation.emplace();
    m_.group_deactivation->enable_tag = value;
  } else if (key == "group_deactivation.set_tag") {
    if (!m_.group_deactivation) m_.group_deactivation.emplace();
    m_.group_deactivation->set_tag = value;
  } else if (read_timing(key, row, key_field.line, key_field.column)) {
  } else if (is_extra_property(key)) {
    extras_.push_back({key, value});
    extra_places_.push_back({key_field.line, key_field.column});
  } else {
    fields_.error(key_field.line, key_field.column,
                  "unknown property " + in_quotes(key) +
                      " (expected format, name, title, cycle_ms, secure_write.enable_tag, "
                      "group_deactivation.enable_tag, group_deactivation.set_tag, watchdog_ms, "
                      "sif_group.N.process_safety_time_ms, cause.ID.sensor_ms, effect.ID.actuator_ms, "
                      "tag.NAME.description, cause.ID.tag.N.simulation_allowed, "
                      "effect.ID.tag.N.simulation_allowed, provenance.import.K, provenance.parameters.K)");
  }
}

bool PropertyRecords::read_timing(const std::string& key, const Row& row, int line, int column) {
  if (key == "watchdog_ms") {
    std::uint32_t ms = fields_.u32_value(row, "value", 0);
    if (ms == 0) fields_.error(line, column, "watchdog_ms must be positive");
    else m_.watchdog_ms = ms;
    return true;
  }
  struct Spelling {
    TimingKey key;
    std::string_view prefix;
    std::string_view suffix;
  };
  static constexpr Spelling kSpellings[] = {
      {TimingKey::ProcessSafetyTime, "sif_group.", ".process_safety_time_ms"},
      {TimingKey::SensorTime, "cause.", ".sensor_ms"},
      {TimingKey::ActuatorTime, "effect.", ".actuator_ms"},
  };
  for (const auto& s : kSpellings) {
    if (key.size() <= s.prefix.size() + s.suffix.size() || key.compare(0, s.prefix.size(), s.prefix) != 0 ||
        key.compare(key.size() - s.suffix.size(), s.suffix.size(), s.suffix) != 0)
      continue;
    const std::string number = key.substr(s.prefix.size(), key.size() - s.prefix.size() - s.suffix.size());
    int id = 0;
    auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), id);
    if (ec != std::errc{} || end != number.data() + number.size()) return false;
    timing_.push_back({s.key, id, fields_.u32_value(row, "value", 0), line, column});
    return true;
  }
  return false;
}

void PropertyRecords::finish() {
  finish_timing();
  finish_extras();
}

void PropertyRecords::finish_timing() {
  for (const auto& t : timing_) {
    switch (t.key) {
      case TimingKey::ProcessSafetyTime:
        if (!m_.sif_groups.count(t.id))
          fields_.error(t.line, t.column, "SIF group " + std::to_string(t.id) + " is not defined");
        else if (t.ms == 0) fields_.error(t.line, t.column, "a process safety time must be positive");
        else m_.process_safety_time_ms[t.id] = t.ms;
        break;
      case TimingKey::SensorTime:
        if (!set_time(m_.causes, t.id, &model::Cause::sensor_ms, t.ms))
          fields_.error(t.line, t.column, "no cause " + std::to_string(t.id));
        break;
      case TimingKey::ActuatorTime:
        if (!set_time(m_.effects, t.id, &model::Effect::actuator_ms, t.ms))
          fields_.error(t.line, t.column, "no effect " + std::to_string(t.id));
        break;
    }
  }
}

void PropertyRecords::finish_extras() {
  for (const auto& [row, why] : apply_extra_properties(m_, extras_))
    fields_.error(extra_places_[row].line, extra_places_[row].column, why);
}

}  // namespace cemv::formats::csv_records
