// cemv-plc-map/1: reading and writing (docs/plc.md "Map and relations").
#include "formats/plc_map.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "formats/located_issues.hpp"
#include "model/text.hpp"

namespace cemv::formats {

namespace {

using nlohmann::ordered_json;

constexpr JsonLimits kMapLimits{4096, "map", 4};
constexpr std::size_t kMaxName = 128;          // IEC identifiers are shorter in every PLC we know
constexpr std::uint32_t kMaxScanMs = 86400000;  // one day

std::string json_type(const ordered_json& j) {
  if (j.is_string()) return "a string";
  if (j.is_number()) return "a number";
  if (j.is_boolean()) return "a boolean";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

std::string list(const std::set<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

class MapParser {
 public:
  PlcMap parse(const ordered_json& root) {
    PlcMap out;
    if (!root.is_object()) {
      error("", "a PLC map is a JSON object, not " + json_type(root));
      return out;
    }
    keys(root, "", {"format", "pou", "scan_ms", "inputs", "outputs", "commands", "program_inputs"});
    if (!root.contains("format") || root["format"] != kPlcMapFormat)
      error("format", std::string("expected \"") + kPlcMapFormat + "\"" +
                          (root.contains("format") ? ", got " + root["format"].dump() : ""));
    if (root.contains("pou")) out.pou = name(root["pou"], "pou");
    if (root.contains("scan_ms")) out.scan_ms = scan_ms(root["scan_ms"]);
    each(root, "inputs", [&](const ordered_json& e, const std::string& p) { out.inputs.push_back(input(e, p)); });
    each(root, "outputs", [&](const ordered_json& e, const std::string& p) { out.outputs.push_back(output(e, p)); });
    each(root, "commands", [&](const ordered_json& e, const std::string& p) { out.commands.push_back(command(e, p)); });
    each(root, "program_inputs",
         [&](const ordered_json& e, const std::string& p) { out.program_inputs.push_back(program_input(e, p)); });
    return out;
  }

  std::vector<LoadIssue> issues;

 private:
  void error(const std::string& path, std::string what) { issues.push_back({path, std::move(what)}); }

  void keys(const ordered_json& j, const std::string& path, const std::set<std::string>& allowed) {
    for (const auto& [key, value] : j.items())
      if (!allowed.count(key)) error(member_path(path, key), "unknown key; expected one of " + list(allowed));
  }

  template <class F>
  void each(const ordered_json& root, const char* key, F&& f) {
    if (!root.contains(key)) return;
    const ordered_json& a = root[key];
    if (!a.is_array()) {
      error(key, "must be an array, not " + json_type(a));
      return;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string p = element_path(key, i);
      if (!a[i].is_object()) error(p, "must be an object, not " + json_type(a[i]));
      else f(a[i], p);
    }
  }

  std::string name(const ordered_json& j, const std::string& path) {
    if (!j.is_string() || j.get<std::string>().empty() || j.get<std::string>().size() > kMaxName) {
      error(path, "must be a non-empty name of at most " + std::to_string(kMaxName) + " bytes, not " +
                      (j.is_string() ? model::in_quotes(j.get<std::string>()) : json_type(j)));
      return "";
    }
    return j.get<std::string>();
  }

  std::string required_name(const ordered_json& e, const std::string& path, const char* key) {
    if (!e.contains(key)) {
      error(path, std::string("missing \"") + key + "\"");
      return "";
    }
    return name(e[key], member_path(path, key));
  }

  int id(const ordered_json& j, const std::string& path, int max) {
    if (!j.is_number_integer() || j.get<long long>() < 1 || j.get<long long>() > max) {
      error(path, "must be a whole number 1.." + std::to_string(max) + ", not " + j.dump());
      return 0;
    }
    return j.get<int>();
  }

  std::optional<std::uint32_t> scan_ms(const ordered_json& j) {
    if (!j.is_number_integer() || j.get<long long>() < 1 || j.get<long long>() > kMaxScanMs) {
      error("scan_ms", "must be a whole number of milliseconds 1.." + std::to_string(kMaxScanMs) + ", not " + j.dump());
      return std::nullopt;
    }
    return j.get<std::uint32_t>();
  }

  PlcInputBinding input(const ordered_json& e, const std::string& p) {
    keys(e, p, {"tag", "variable", "value", "bad_quality"});
    PlcInputBinding b;
    b.tag = required_name(e, p, "tag");
    if (e.contains("variable")) b.variable = name(e["variable"], member_path(p, "variable"));
    if (e.contains("value")) {
      const ordered_json& v = e["value"];
      if (v.is_boolean()) b.value = v.get<bool>() ? 1.0 : 0.0;
      else if (v.is_number() && std::isfinite(v.get<double>())) b.value = v.get<double>();
      else error(member_path(p, "value"), "must be a number or a boolean, not " + json_type(v));
    }
    if (e.contains("variable") == e.contains("value"))
      error(p, "give the tag either a \"variable\" or the \"value\" it is held at");
    if (e.contains("bad_quality")) {
      const ordered_json& q = e["bad_quality"];
      if (q.is_boolean() && !q.get<bool>()) b.good_quality = true;
      else b.bad_quality = name(q, member_path(p, "bad_quality"));
      if (e.contains("value")) error(member_path(p, "bad_quality"), "a tag held at a value has good quality");
    }
    return b;
  }

  PlcOutputBinding output(const ordered_json& e, const std::string& p) {
    keys(e, p, {"tag", "effect", "variable"});
    PlcOutputBinding b;
    b.tag = required_name(e, p, "tag");
    if (e.contains("effect")) b.effect = id(e["effect"], member_path(p, "effect"), 1 << 20);
    b.variable = required_name(e, p, "variable");
    return b;
  }

  PlcCommandBinding command(const ordered_json& e, const std::string& p) {
    keys(e, p, {"command", "cause", "effect", "tag", "tag_name", "on", "variable", "unused"});
    PlcCommandBinding b;
    if (!e.contains("command") || !e["command"].is_string()) {
      error(p, "missing \"command\" (an operator command of docs/semantics.md O.1-O.8)");
    } else if (auto op = model::command_op_from_string(e["command"].get<std::string>())) {
      b.op = *op;
    } else {
      error(member_path(p, "command"), "unknown command " + model::in_quotes(e["command"].get<std::string>()));
    }
    if (e.contains("cause")) b.cause = id(e["cause"], member_path(p, "cause"), 1 << 20);
    if (e.contains("effect")) b.effect = id(e["effect"], member_path(p, "effect"), 1 << 20);
    if (e.contains("tag")) b.tag = id(e["tag"], member_path(p, "tag"), 3);
    if (e.contains("tag_name")) b.tag_name = name(e["tag_name"], member_path(p, "tag_name"));
    if (e.contains("on")) {
      if (e["on"].is_boolean()) b.on = e["on"].get<bool>();
      else error(member_path(p, "on"), "must be true or false, not " + json_type(e["on"]));
    }
    const bool unused = e.contains("unused");
    if (unused && e["unused"] != true) error(member_path(p, "unused"), "can only be true");
    if (e.contains("variable")) b.variable = name(e["variable"], member_path(p, "variable"));
    if (unused == e.contains("variable"))
      error(p, "give the command either the \"variable\" that issues it or \"unused\": true");
    return b;
  }

  PlcProgramInput program_input(const ordered_json& e, const std::string& p) {
    keys(e, p, {"variable", "value"});
    PlcProgramInput b;
    b.variable = required_name(e, p, "variable");
    if (!e.contains("value")) error(p, "missing \"value\" (the value the input is held at)");
    else if (e["value"].is_boolean()) b.value = e["value"].get<bool>() ? 1.0 : 0.0;
    else if (e["value"].is_number() && std::isfinite(e["value"].get<double>())) b.value = e["value"].get<double>();
    else error(member_path(p, "value"), "must be a number or a boolean, not " + json_type(e["value"]));
    return b;
  }
};

ordered_json value_json(double v) {
  if (v == std::floor(v) && std::fabs(v) < 9e15) return static_cast<long long>(v);
  return v;
}

}  // namespace

PlcMap parse_plc_map(std::string_view json_text, const std::string& source_name) {
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-plc-map/1 JSON object)", source_name}});
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(json_text, source_name, issues, kMapLimits);
  if (!parsed || !issues.empty()) throw LoadError(std::move(issues));
  MapParser parser;
  PlcMap map = parser.parse(*parsed);
  if (!parser.issues.empty()) throw_in_text_order(json_text, source_name, std::move(parser.issues));
  return map;
}

std::string plc_map_json(const PlcMap& map) {
  ordered_json j;
  j["format"] = kPlcMapFormat;
  if (!map.pou.empty()) j["pou"] = map.pou;
  if (map.scan_ms) j["scan_ms"] = *map.scan_ms;
  j["inputs"] = ordered_json::array();
  for (const auto& b : map.inputs) {
    ordered_json e;
    e["tag"] = b.tag;
    if (!b.variable.empty()) e["variable"] = b.variable;
    else if (b.value) e["value"] = value_json(*b.value);
    if (!b.bad_quality.empty()) e["bad_quality"] = b.bad_quality;
    else if (b.good_quality) e["bad_quality"] = false;
    j["inputs"].push_back(std::move(e));
  }
  j["outputs"] = ordered_json::array();
  for (const auto& b : map.outputs) {
    ordered_json e;
    e["tag"] = b.tag;
    if (b.effect) e["effect"] = b.effect;
    e["variable"] = b.variable;
    j["outputs"].push_back(std::move(e));
  }
  j["commands"] = ordered_json::array();
  for (const auto& b : map.commands) {
    ordered_json e;
    e["command"] = model::to_string(b.op);
    if (b.cause) e["cause"] = b.cause;
    if (b.effect) e["effect"] = b.effect;
    if (b.tag) e["tag"] = b.tag;
    if (!b.tag_name.empty()) e["tag_name"] = b.tag_name;
    if (b.on) e["on"] = *b.on;
    if (b.variable.empty()) e["unused"] = true;
    else e["variable"] = b.variable;
    j["commands"].push_back(std::move(e));
  }
  if (!map.program_inputs.empty()) {
    j["program_inputs"] = ordered_json::array();
    for (const auto& b : map.program_inputs) j["program_inputs"].push_back({{"variable", b.variable}, {"value", value_json(b.value)}});
  }
  const auto replace = ordered_json::error_handler_t::replace;
  return j.dump(2, ' ', false, replace) + "\n";
}

}  // namespace cemv::formats
