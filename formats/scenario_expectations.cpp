// cemv-scenario/1 expectations (docs/scenario.md "Expectations"): the key a
// status field or an output tag of the matrix, the value of its type.
#include "formats/scenario_reader.hpp"

#include <algorithm>
#include <string>

#include "model/text.hpp"

namespace cemv::formats::scenario_detail {

using namespace cemv::model;

namespace {

// A status field of a cause (C.9).
std::optional<Observable> cause_field(ScenarioContext& cx, const Cause& c, const std::string& field, const std::string& where) {
  const auto& fields = cause_fields();
  auto f = std::find_if(fields.begin(), fields.end(), [&](const FieldInfo& fi) { return field == fi.name; });
  if (f == fields.end()) {
    std::vector<std::string> names;
    for (const auto& fi : fields) names.push_back(fi.name);
    cx.error(where, "unknown cause field " + in_quotes(field) + did_you_mean(field, names));
    return std::nullopt;
  }
  Observable o;
  o.kind = Node::Kind::Cause;
  o.id = c.id;
  o.field = f->name;
  o.type = f->type;
  o.key = observable_key({o.kind, o.id}, o.field);
  return o;
}

// A status field of an effect (E.11), or tag[k], the value of its output k (E.9).
std::optional<Observable> effect_field(ScenarioContext& cx, const Effect& e, const std::string& field, const std::string& where) {
  Observable o;
  o.kind = Node::Kind::Effect;
  o.id = e.id;
  if (field.starts_with("tag[") && field.ends_with("]")) {
    std::string digits = field.substr(4, field.size() - 5);
    bool ok = !digits.empty() && digits.size() <= 2 &&
              std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    int k = ok ? std::stoi(digits) : 0;
    if (k < 1 || k > static_cast<int>(e.tags.size())) {
      cx.error(where, "effect " + std::to_string(e.id) + " has " + std::to_string(e.tags.size()) +
                       " output tag(s); tag[k] takes k = 1-" + std::to_string(e.tags.size()));
      return std::nullopt;
    }
    o.field = "tag";
    o.tag = k;
    o.type = FieldType::Bool;
    o.key = observable_key({o.kind, o.id}, o.field, k);
    return o;
  }
  const auto& fields = effect_fields();
  auto f = std::find_if(fields.begin(), fields.end(), [&](const FieldInfo& fi) { return field == fi.name; });
  if (f == fields.end()) {
    std::vector<std::string> names;
    for (const auto& fi : fields) names.push_back(fi.name);
    names.push_back("tag[1]");
    cx.error(where, "unknown effect field " + in_quotes(field) + did_you_mean(field, names));
    return std::nullopt;
  }
  o.field = f->name;
  o.type = f->type;
  o.key = observable_key({o.kind, o.id}, o.field);
  return o;
}

// cause[ID or NAME].FIELD or effect[ID or NAME].FIELD.
std::optional<ExpectTarget> status_target(ScenarioContext& cx, const std::string& key, const std::string& where) {
  const bool is_cause = key.starts_with("cause[");
  std::size_t open = key.find('[');
  std::size_t close = key.find(']', open);
  if (close == std::string::npos || close + 1 >= key.size() || key[close + 1] != '.') {
    cx.error(where, "malformed key; expected " + std::string(is_cause ? "cause" : "effect") +
                     "[ID or NAME].FIELD");
    return std::nullopt;
  }
  std::string ref = key.substr(open + 1, close - open - 1);
  std::string field = key.substr(close + 2);
  bool numeric = !ref.empty() && ref.size() <= 9 &&
                 std::all_of(ref.begin(), ref.end(), [](char c) { return c >= '0' && c <= '9'; });
  json ref_json = numeric ? json(std::stoi(ref)) : json(ref);
  std::optional<Observable> o;
  if (is_cause) {
    const Cause* c = cx.cause_ref(ref_json, where);
    if (!c) return std::nullopt;
    o = cause_field(cx, *c, field, where);
  } else {
    const Effect* e = cx.effect_ref(ref_json, where);
    if (!e) return std::nullopt;
    o = effect_field(cx, *e, field, where);
  }
  if (!o) return std::nullopt;
  ExpectTarget t;
  t.kind = ExpectTarget::Kind::Status;
  t.observable = *o;
  return t;
}

// An output tag by name: the value the matrix writes to it (E.9).
std::optional<ExpectTarget> output_target(ScenarioContext& cx, const std::string& key, const std::string& where) {
  auto out = std::find_if(cx.outputs.begin(), cx.outputs.end(),
                          [&](const ScenarioContext::OutputRef& o) { return tag_key(o.name) == tag_key(key); });
  cx.tags_seen.insert(tag_key(key));
  if (out == cx.outputs.end()) {
    std::string hint = did_you_mean(key, cx.output_names);
    if (!cx.table.find(key)) cx.tags_unknown.insert(tag_key(key));
    if (cx.table.find(key))
      cx.error(where, in_quotes(key) + " is an input tag; expectations name output tags, "
                                    "cause[..].FIELD or effect[..].FIELD");
    else
      cx.error(where, "unknown expectation key " + in_quotes(key) +
                       ": not an output tag, nor cause[..].FIELD / effect[..].FIELD" + hint);
    return std::nullopt;
  }
  ExpectTarget t;
  t.kind = ExpectTarget::Kind::OutputTag;
  t.output_tag = out->name;
  Observable& o = t.observable;
  o.kind = Node::Kind::Effect;
  o.id = out->effect;
  o.field = "tag";
  o.tag = out->k;
  o.type = FieldType::Bool;
  o.key = observable_key({o.kind, o.id}, o.field, o.tag);
  return t;
}

// The expected value, written as the field's type is (docs/scenario.md).
std::optional<int> expected_value(ScenarioContext& cx, FieldType type, const json& v, const std::string& where) {
  switch (type) {
    case FieldType::Bool:
      if (!v.is_boolean()) {
        cx.error(where, "expects true or false, not " + json_type_name(v));
        return std::nullopt;
      }
      return v.get<bool>() ? 1 : 0;
    case FieldType::Int: {
      if (!v.is_number_integer() && !v.is_number_unsigned()) {
        cx.error(where, "expects an integer, not " + json_type_name(v));
        return std::nullopt;
      }
      auto n = v.get<std::int64_t>();
      if (n < 0 || n > 1000) {
        cx.error(where, "expects a count, not " + v.dump());
        return std::nullopt;
      }
      return static_cast<int>(n);
    }
    case FieldType::Voting: {
      auto s = v.is_string() ? voting_from_string(v.get<std::string>()) : std::nullopt;
      if (!s) {
        cx.error(where, "expects a voting: \"1oo1\", \"1oo2\", \"2oo2\", \"1oo3\", \"2oo3\", "
                     "\"3oo3\" or \"bypass\", not " + v.dump());
        return std::nullopt;
      }
      return static_cast<int>(*s);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Expectation> read_expectation(ScenarioContext& cx, const std::string& key, const json& v,
                                            const std::string& path) {
  Expectation x;
  x.key = key;
  x.where = join(path, key);
  const bool status = key.starts_with("cause[") || key.starts_with("effect[");
  auto target = status ? status_target(cx, key, x.where) : output_target(cx, key, x.where);
  if (!target) return std::nullopt;
  x.target = *target;
  x.type = target->observable.type;
  auto expected = expected_value(cx, x.type, v, x.where);
  if (!expected) return std::nullopt;
  x.expected = *expected;
  return x;
}

}  // namespace cemv::formats::scenario_detail
