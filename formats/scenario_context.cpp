// What every part of reading a scenario shares (scenario_reader.hpp).
#include "formats/scenario_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/text.hpp"

namespace cemv::formats::scenario_detail {

using namespace cemv::model;

std::string json_type_name(const json& j) {
  if (j.is_boolean()) return "a boolean";
  if (j.is_number_integer() || j.is_number_unsigned()) return "an integer";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

ScenarioContext::ScenarioContext(const Matrix& matrix) : m(matrix), table(matrix) {
  for (const auto& t : table.tags()) input_names.push_back(t.name);
  for (const auto& e : m.effects) {
    if (e.function == EffectFunction::Comment) continue;
    for (std::size_t k = 0; k < e.tags.size(); ++k) {
      if (parse_internal_ref(e.tags[k].name)) continue;
      outputs.push_back({e.tags[k].name, e.id, static_cast<int>(k + 1)});
      output_names.push_back(e.tags[k].name);
    }
  }
  for (const auto& c : m.causes) {
    cause_names.push_back(c.name);
  }
  for (const auto& e : m.effects) effect_names.push_back(e.name);
}

void ScenarioContext::error(std::string where, std::string what) {
  issues.push_back({std::move(where), std::move(what)});
}

void ScenarioContext::check_keys(const json& obj, const std::string& path,
                std::initializer_list<const char*> allowed) {
  std::vector<std::string> names(allowed.begin(), allowed.end());
  for (const auto& [k, v] : obj.items()) {
    (void)v;
    if (std::find(names.begin(), names.end(), k) == names.end())
      error(join(path, k), "unknown key" + did_you_mean(k, names));
  }
}

std::string ScenarioContext::string_field(const json& j, const std::string& where) {
  if (!j.is_string()) {
    error(where, "must be a string, not " + json_type_name(j));
    return "";
  }
  return j.get<std::string>();
}

std::optional<bool> ScenarioContext::bool_field(const json& j, const std::string& where) {
  if (!j.is_boolean()) {
    error(where, "must be true or false, not " + json_type_name(j));
    return std::nullopt;
  }
  return j.get<bool>();
}

std::optional<std::int64_t> ScenarioContext::int_field(const json& j, const std::string& where) {
  if (j.is_number_unsigned()) {
    auto v = j.get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      error(where, "out of range");
      return std::nullopt;
    }
    return static_cast<std::int64_t>(v);
  }
  if (j.is_number_integer()) return j.get<std::int64_t>();
  error(where, "must be an integer, not " + json_type_name(j));
  return std::nullopt;
}

// A REAL (IEEE single precision, 6.3.1): finite and within float range.
std::optional<float> ScenarioContext::real_field(const json& j, const std::string& where) {
  if (!j.is_number()) {
    error(where, "must be a number, not " + json_type_name(j));
    return std::nullopt;
  }
  double d = j.get<double>();
  // Out of range is what rounds to an infinity as a float: the shortest
  // text of the largest float, 3.4028235e+38, is a little above it as a
  // double and must read back (the checker writes it in counterexamples).
  if (!std::isfinite(d) || std::isinf(static_cast<float>(d))) {
    error(where, "is outside the range of a REAL (32-bit float)");
    return std::nullopt;
  }
  return static_cast<float>(d);
}

// The value of an input (or simulated) tag: a boolean for Boolean tags, a
// number for analog ones.
std::optional<float> ScenarioContext::tag_value(const json& j, TagKind kind, const std::string& tag,
                               const std::string& where) {
  if (kind == TagKind::Bool) {
    if (!j.is_boolean()) {
      error(where, "tag " + in_quotes(tag) + " is Boolean: the value must be true or false, not " +
                       json_type_name(j));
      return std::nullopt;
    }
    return j.get<bool>() ? 1.0f : 0.0f;
  }
  if (!j.is_number()) {
    error(where, "tag " + in_quotes(tag) + " is analog: the value must be a number, not " +
                     json_type_name(j));
    return std::nullopt;
  }
  return real_field(j, where);
}

// A cause referenced by id (integer) or name (string, case-insensitive).
const Cause* ScenarioContext::cause_ref(const json& j, const std::string& where) {
  const Cause* c = nullptr;
  if (j.is_number_integer() || j.is_number_unsigned()) {
    auto id = int_field(j, where);
    if (id && *id >= 0 && *id <= std::numeric_limits<int>::max())
      c = m.find_cause(static_cast<int>(*id));
    if (!c) {
      error(where, "no cause with id " + j.dump());
      return nullptr;
    }
  } else if (j.is_string()) {
    std::string key = tag_key(j.get<std::string>());
    for (const auto& x : m.causes)
      if (tag_key(x.name) == key) c = &x;
    if (!c) {
      error(where, "no cause named " + in_quotes(j.get<std::string>()) +
                       did_you_mean(j.get<std::string>(), cause_names));
      return nullptr;
    }
  } else {
    error(where, "must be a cause id or name, not " + json_type_name(j));
    return nullptr;
  }
  if (c->function == CauseFunction::Comment) {
    error(where, "cause " + std::to_string(c->id) + " is comment-only and is not processed");
    return nullptr;
  }
  return c;
}

const Effect* ScenarioContext::effect_ref(const json& j, const std::string& where) {
  const Effect* e = nullptr;
  if (j.is_number_integer() || j.is_number_unsigned()) {
    auto id = int_field(j, where);
    if (id && *id >= 0 && *id <= std::numeric_limits<int>::max())
      e = m.find_effect(static_cast<int>(*id));
    if (!e) {
      error(where, "no effect with id " + j.dump());
      return nullptr;
    }
  } else if (j.is_string()) {
    std::string key = tag_key(j.get<std::string>());
    for (const auto& x : m.effects)
      if (tag_key(x.name) == key) e = &x;
    if (!e) {
      error(where, "no effect named " + in_quotes(j.get<std::string>()) +
                       did_you_mean(j.get<std::string>(), effect_names));
      return nullptr;
    }
  } else {
    error(where, "must be an effect id or name, not " + json_type_name(j));
    return nullptr;
  }
  if (e->function == EffectFunction::Comment) {
    error(where, "effect " + std::to_string(e->id) + " is comment-only and is not processed");
    return nullptr;
  }
  return e;
}

std::optional<ScenarioContext::SimulatedTag> ScenarioContext::simulatable_tag(const std::string& tag, const std::string& where) {
  tags_seen.insert(tag_key(tag));
  if (auto idx = table.find(tag)) return SimulatedTag{table.tags()[*idx].name, table.tags()[*idx].kind};
  auto out = std::find_if(outputs.begin(), outputs.end(),
                          [&](const OutputRef& o) { return tag_key(o.name) == tag_key(tag); });
  if (out != outputs.end()) return SimulatedTag{out->name, TagKind::Bool};
  std::vector<std::string> all = input_names;
  all.insert(all.end(), output_names.begin(), output_names.end());
  error(where, "unknown tag " + in_quotes(tag) + did_you_mean(tag, all));
  tags_unknown.insert(tag_key(tag));
  return std::nullopt;
}

}  // namespace cemv::formats::scenario_detail
