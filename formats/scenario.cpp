// cemv-scenario/1: parsing against a matrix, defaults, expansion into cycles.
// The format is a contract; docs/scenario.md describes it field by field.
#include "formats/scenario.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "formats/matrix_json.hpp"
#include "model/text.hpp"

namespace cemv::formats {

using namespace cemv::model;

namespace {

using nlohmann::json;

// ---- small helpers ---------------------------------------------------------

std::string json_type_name(const json& j) {
  if (j.is_boolean()) return "a boolean";
  if (j.is_number_integer() || j.is_number_unsigned()) return "an integer";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}

// ---- the parser ------------------------------------------------------------

class Parser {
 public:
  Parser(const Matrix& m) : m_(m), table_(m) {
    for (const auto& t : table_.tags()) input_names_.push_back(t.name);
    for (const auto& e : m_.effects) {
      if (e.function == EffectFunction::Comment) continue;
      for (std::size_t k = 0; k < e.tags.size(); ++k) {
        if (parse_internal_ref(e.tags[k].name)) continue;
        outputs_.push_back({e.tags[k].name, e.id, static_cast<int>(k + 1)});
        output_names_.push_back(e.tags[k].name);
      }
    }
    for (const auto& c : m_.causes) {
      cause_names_.push_back(c.name);
    }
    for (const auto& e : m_.effects) effect_names_.push_back(e.name);
  }

  Scenario parse(const json& root) {
    Scenario sc;
    if (!root.is_object()) {
      error("", "a scenario is a JSON object, not " + json_type_name(root));
      finish();
    }
    check_keys(root, "", {"format", "matrix", "description", "initial", "steps"});
    if (!root.contains("format")) {
      error("format", "missing; expected \"" + std::string(kScenarioFormat) + "\"");
    } else if (!root["format"].is_string() ||
               root["format"].get<std::string>() != kScenarioFormat) {
      error("format", "expected \"" + std::string(kScenarioFormat) + "\", got " +
                          root["format"].dump());
    }
    if (root.contains("matrix")) {
      sc.matrix = string_field(root["matrix"], "matrix");
      if (root["matrix"].is_string() && sc.matrix.empty())
        error("matrix", "empty; the path of the cemv-matrix/1 file, relative to the scenario file");
    }
    if (root.contains("description")) sc.description = string_field(root["description"], "description");
    if (root.contains("initial")) sc.initial = parse_inputs(root["initial"], "initial");
    if (!root.contains("steps")) {
      error("steps", "missing; a scenario has at least one step");
    } else if (!root["steps"].is_array()) {
      error("steps", "must be an array, not " + json_type_name(root["steps"]));
    } else if (root["steps"].empty()) {
      error("steps", "empty; a scenario has at least one step");
    } else {
      std::uint64_t total = 0;
      const auto& steps = root["steps"];
      for (std::size_t i = 0; i < steps.size(); ++i) {
        sc.steps.push_back(parse_step(steps[i], "steps[" + std::to_string(i) + "]"));
        total += sc.steps.back().cycles;
        if (total > kMaxScenarioCycles) {
          error("steps[" + std::to_string(i) + "]",
                "the scenario exceeds " + std::to_string(kMaxScenarioCycles) + " cycles in total");
          break;
        }
        std::uint64_t width = std::max<std::uint64_t>(1, table_.size());
        if (total * width > kMaxScenarioTagValues) {
          error("steps[" + std::to_string(i) + "]",
                "the scenario is too long for this matrix: " + std::to_string(total) + " cycles x " +
                    std::to_string(width) + " input tags exceed " +
                    std::to_string(kMaxScenarioTagValues) + " input values");
          break;
        }
      }
    }
    finish();
    return sc;
  }

  void finish() {
    if (issues_.empty()) return;
    // A scenario whose tags are mostly unknown is most likely the scenario of
    // another matrix: one line says so before the list of unknown tags.
    if (tags_seen_.size() >= 3 && 2 * tags_unknown_.size() > tags_seen_.size()) {
      const std::string n = std::to_string(tags_seen_.size());
      std::string what = tags_unknown_.size() == tags_seen_.size()
                             ? "none of the scenario's " + n + " tags is in matrix " + m_.name
                             : std::to_string(tags_unknown_.size()) + " of the scenario's " + n +
                                   " tags are not in matrix " + m_.name;
      issues_.insert(issues_.begin(), LoadIssue{"", what + "; is it the scenario of another matrix?"});
    }
    throw LoadError(issues_);
  }

 private:
  struct OutputRef {
    std::string name;
    int effect;
    int k;
  };

  void error(std::string where, std::string what) {
    issues_.push_back({std::move(where), std::move(what)});
  }

  static std::string join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

  void check_keys(const json& obj, const std::string& path,
                  std::initializer_list<const char*> allowed) {
    std::vector<std::string> names(allowed.begin(), allowed.end());
    for (const auto& [k, v] : obj.items()) {
      (void)v;
      if (std::find(names.begin(), names.end(), k) == names.end())
        error(join(path, k), "unknown key" + did_you_mean(k, names));
    }
  }

  std::string string_field(const json& j, const std::string& where) {
    if (!j.is_string()) {
      error(where, "must be a string, not " + json_type_name(j));
      return "";
    }
    return j.get<std::string>();
  }

  std::optional<bool> bool_field(const json& j, const std::string& where) {
    if (!j.is_boolean()) {
      error(where, "must be true or false, not " + json_type_name(j));
      return std::nullopt;
    }
    return j.get<bool>();
  }

  std::optional<std::int64_t> int_field(const json& j, const std::string& where) {
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
  std::optional<float> real_field(const json& j, const std::string& where) {
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
  std::optional<float> tag_value(const json& j, TagKind kind, const std::string& tag,
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

  std::vector<InputSetting> parse_inputs(const json& j, const std::string& path) {
    std::vector<InputSetting> out;
    if (!j.is_object()) {
      error(path, "must be an object of tag names, not " + json_type_name(j));
      return out;
    }
    for (const auto& [name, v] : j.items()) {
      std::string where = join(path, name);
      auto idx = table_.find(name);
      tags_seen_.insert(tag_key(name));
      if (!idx) {
        std::string hint = did_you_mean(name, input_names_);
        // The key by value: clang before 16 cannot capture a structured binding.
        bool is_output = std::any_of(outputs_.begin(), outputs_.end(), [&, key = tag_key(name)](const OutputRef& o) {
          return tag_key(o.name) == key;
        });
        if (is_output)
          error(path, in_quotes(name) +
                          " is an output tag; outputs cannot be set as inputs (use the "
                          "simulate_tag command to force one)");
        else
          error(path, "unknown tag " + in_quotes(name) + hint);
        if (!is_output) tags_unknown_.insert(tag_key(name));
        continue;
      }
      if (std::any_of(out.begin(), out.end(), [&](const InputSetting& s) { return s.tag == *idx; })) {
        error(where, "tag " + in_quotes(table_.tags()[*idx].name) + " is set twice");
        continue;
      }
      const InputTag& tag = table_.tags()[*idx];
      InputSetting s;
      s.tag = *idx;
      if (v.is_object()) {
        check_keys(v, where, {"value", "quality"});
        if (!v.contains("value") && !v.contains("quality"))
          error(where, "needs \"value\", \"quality\" or both");
        if (v.contains("value")) s.value = tag_value(v["value"], tag.kind, tag.name, join(where, "value"));
        if (v.contains("quality")) {
          const json& q = v["quality"];
          if (q.is_string() && q.get<std::string>() == "good")
            s.bad_quality = false;
          else if (q.is_string() && q.get<std::string>() == "bad")
            s.bad_quality = true;
          else
            error(join(where, "quality"), "must be \"good\" or \"bad\", not " + q.dump());
        }
      } else {
        s.value = tag_value(v, tag.kind, tag.name, where);
        s.bad_quality = false;
      }
      out.push_back(s);
    }
    return out;
  }

  // A cause referenced by id (integer) or name (string, case-insensitive).
  const Cause* cause_ref(const json& j, const std::string& where) {
    const Cause* c = nullptr;
    if (j.is_number_integer() || j.is_number_unsigned()) {
      auto id = int_field(j, where);
      if (id && *id >= 0 && *id <= std::numeric_limits<int>::max())
        c = m_.find_cause(static_cast<int>(*id));
      if (!c) {
        error(where, "no cause with id " + j.dump());
        return nullptr;
      }
    } else if (j.is_string()) {
      std::string key = tag_key(j.get<std::string>());
      for (const auto& x : m_.causes)
        if (tag_key(x.name) == key) c = &x;
      if (!c) {
        error(where, "no cause named " + in_quotes(j.get<std::string>()) +
                         did_you_mean(j.get<std::string>(), cause_names_));
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

  const Effect* effect_ref(const json& j, const std::string& where) {
    const Effect* e = nullptr;
    if (j.is_number_integer() || j.is_number_unsigned()) {
      auto id = int_field(j, where);
      if (id && *id >= 0 && *id <= std::numeric_limits<int>::max())
        e = m_.find_effect(static_cast<int>(*id));
      if (!e) {
        error(where, "no effect with id " + j.dump());
        return nullptr;
      }
    } else if (j.is_string()) {
      std::string key = tag_key(j.get<std::string>());
      for (const auto& x : m_.effects)
        if (tag_key(x.name) == key) e = &x;
      if (!e) {
        error(where, "no effect named " + in_quotes(j.get<std::string>()) +
                         did_you_mean(j.get<std::string>(), effect_names_));
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

  // docs/scenario.md "Commands (10.7)": one command, its arguments checked
  // against the matrix. Each argument kind has its own reader below.
  std::optional<Command> parse_command(const json& j, const std::string& path) {
    if (!j.is_object()) {
      error(path, "a command is an object, not " + json_type_name(j));
      return std::nullopt;
    }
    auto op = parse_op(j, path);
    if (!op) return std::nullopt;
    const std::string name = j["op"].get<std::string>();
    Command cmd;
    cmd.op = *op;
    std::size_t before = issues_.size();
    CommandArgs args{*this, j, path, name, cmd};
    switch (*op) {
      case CommandOp::AckCause:
        check_keys(j, path, {"op", "cause"});
        args.cause();
        break;
      case CommandOp::ResetEffect:
      case CommandOp::OverrideEffect:
      case CommandOp::StopOverride:
        check_keys(j, path, {"op", "effect"});
        args.effect();
        break;
      case CommandOp::SoftBypassCause:
        check_keys(j, path, {"op", "cause", "on"});
        args.cause();
        args.on();
        break;
      case CommandOp::SoftBypassTag:
        check_keys(j, path, {"op", "cause", "tag", "on"});
        args.tag_index(args.cause());
        args.on();
        break;
      case CommandOp::SoftBypassEffect:
        check_keys(j, path, {"op", "effect", "on"});
        args.effect();
        args.on();
        break;
      case CommandOp::SimulateTag:
        check_keys(j, path, {"op", "tag", "value"});
        args.simulated_tag_and_value();
        break;
      case CommandOp::StopSimulation:
        check_keys(j, path, {"op", "tag"});
        args.stopped_tag();
        break;
      case CommandOp::ClearFirstOut:
        check_keys(j, path, {"op", "group"});
        args.group();
        break;
      case CommandOp::ClearAlarms:
        check_keys(j, path, {"op", "cause", "effect"});
        args.cause_or_effect();
        break;
    }
    if (issues_.size() != before) return std::nullopt;
    return cmd;
  }

  // The "op" of a command: a known command name.
  std::optional<CommandOp> parse_op(const json& j, const std::string& path) {
    if (!j.contains("op") || !j["op"].is_string()) {
      error(join(path, "op"), "missing or not a string; a command names its \"op\"");
      return std::nullopt;
    }
    std::string name = j["op"].get<std::string>();
    auto op = command_op_from_string(name);
    if (!op) {
      std::vector<std::string> ops;
      for (int i = 0; i <= static_cast<int>(CommandOp::ClearAlarms); ++i)
        ops.push_back(to_string(static_cast<CommandOp>(i)));
      error(join(path, "op"), "unknown command " + in_quotes(name) + did_you_mean(name, ops));
    }
    return op;
  }

  // A simulatable tag by name (O.8): an input tag of the matrix, else one of its
  // output tags; nullopt (and an error naming the closest tags) otherwise.
  struct SimulatedTag {
    std::string name;
    TagKind kind = TagKind::Bool;
  };
  std::optional<SimulatedTag> simulatable_tag(const std::string& tag, const std::string& where) {
    tags_seen_.insert(tag_key(tag));
    if (auto idx = table_.find(tag)) return SimulatedTag{table_.tags()[*idx].name, table_.tags()[*idx].kind};
    auto out = std::find_if(outputs_.begin(), outputs_.end(),
                            [&](const OutputRef& o) { return tag_key(o.name) == tag_key(tag); });
    if (out != outputs_.end()) return SimulatedTag{out->name, TagKind::Bool};
    std::vector<std::string> all = input_names_;
    all.insert(all.end(), output_names_.begin(), output_names_.end());
    error(where, "unknown tag " + in_quotes(tag) + did_you_mean(tag, all));
    tags_unknown_.insert(tag_key(tag));
    return std::nullopt;
  }

  // The arguments of one command, each read into `cmd` with its own checks.
  struct CommandArgs {
    Parser& p;
    const json& j;
    const std::string& path;
    const std::string& name;
    Command& cmd;

    const json* need(const char* key) {
      if (!j.contains(key)) {
        p.error(path, "command " + in_quotes(name) + " needs \"" + key + "\"");
        return nullptr;
      }
      return &j[key];
    }
    const Cause* cause() {
      const json* v = need("cause");
      if (!v) return nullptr;
      const Cause* c = p.cause_ref(*v, join(path, "cause"));
      if (c) cmd.cause = c->id;
      return c;
    }
    void effect() {
      const json* v = need("effect");
      if (!v) return;
      if (const Effect* e = p.effect_ref(*v, join(path, "effect"))) cmd.effect = e->id;
    }
    void on() {
      const json* v = need("on");
      if (!v) return;
      if (auto b = p.bool_field(*v, join(path, "on"))) cmd.on = *b;
    }
    // soft_bypass_tag (O.6): the position of an input tag of cause `c`, 1-3.
    void tag_index(const Cause* c) {
      const json* t = need("tag");
      if (!t) return;
      auto k = p.int_field(*t, join(path, "tag"));
      if (!k || !c) return;
      if (*k < 1 || *k > static_cast<std::int64_t>(c->tags.size()))
        p.error(join(path, "tag"), "cause " + std::to_string(c->id) + " has " + std::to_string(c->tags.size()) +
                                       " input tag(s); the tag index is 1-" + std::to_string(c->tags.size()));
      else
        cmd.tag = static_cast<int>(*k);
    }
    // simulate_tag (O.8): the tag, and a value of its kind.
    void simulated_tag_and_value() {
      const json* t = need("tag");
      const json* v = need("value");
      if (!t) return;
      std::string tag = p.string_field(*t, join(path, "tag"));
      if (tag.empty()) return;
      auto sim = p.simulatable_tag(tag, join(path, "tag"));
      if (!sim) return;
      cmd.tag_name = sim->name;
      if (v)
        if (auto x = p.tag_value(*v, sim->kind, sim->name, join(path, "value"))) cmd.value = *x;
    }
    // stop_simulation (O.8): one tag, or (without "tag") every simulation.
    void stopped_tag() {
      if (!j.contains("tag")) return;
      std::string tag = p.string_field(j["tag"], join(path, "tag"));
      if (!j["tag"].is_string()) return;
      if (auto sim = p.simulatable_tag(tag, join(path, "tag"))) cmd.tag_name = sim->name;
    }
    // clear_first_out (O.9): a first-out group.
    void group() {
      const json* g = need("group");
      if (!g) return;
      auto v = p.int_field(*g, join(path, "group"));
      if (v && (*v < 1 || *v > kMaxFirstOutGroup))
        p.error(join(path, "group"), "first-out groups are 1-" + std::to_string(kMaxFirstOutGroup));
      else if (v)
        cmd.group = static_cast<int>(*v);
    }
    // clear_alarms (O.10): exactly one of a cause and an effect.
    void cause_or_effect() {
      if (j.contains("cause") == j.contains("effect")) {
        p.error(path, "command 'clear_alarms' needs exactly one of \"cause\" and \"effect\"");
      } else if (j.contains("cause")) {
        if (const Cause* c = p.cause_ref(j["cause"], join(path, "cause"))) cmd.cause = c->id;
      } else {
        if (const Effect* e = p.effect_ref(j["effect"], join(path, "effect"))) cmd.effect = e->id;
      }
    }
  };


  // "cause[ID or NAME].FIELD", "effect[..].FIELD", "effect[..].tag[k]" or an
  // output tag name.
  // docs/scenario.md "Expectations": KEY -> VALUE, where the key names a status
  // field (cause[..].FIELD, effect[..].FIELD, effect[..].tag[k]) or an output tag.
  std::optional<Expectation> parse_expectation(const std::string& key, const json& v,
                                               const std::string& path) {
    Expectation x;
    x.key = key;
    x.where = join(path, key);
    const bool status = key.starts_with("cause[") || key.starts_with("effect[");
    auto target = status ? status_target(key, x.where) : output_target(key, x.where);
    if (!target) return std::nullopt;
    x.target = *target;
    x.type = target->observable.type;
    auto expected = expected_value(x.type, v, x.where);
    if (!expected) return std::nullopt;
    x.expected = *expected;
    return x;
  }

  // cause[ID or NAME].FIELD or effect[ID or NAME].FIELD.
  std::optional<ExpectTarget> status_target(const std::string& key, const std::string& where) {
    const bool is_cause = key.starts_with("cause[");
    std::size_t open = key.find('[');
    std::size_t close = key.find(']', open);
    if (close == std::string::npos || close + 1 >= key.size() || key[close + 1] != '.') {
      error(where, "malformed key; expected " + std::string(is_cause ? "cause" : "effect") +
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
      const Cause* c = cause_ref(ref_json, where);
      if (!c) return std::nullopt;
      o = cause_field(*c, field, where);
    } else {
      const Effect* e = effect_ref(ref_json, where);
      if (!e) return std::nullopt;
      o = effect_field(*e, field, where);
    }
    if (!o) return std::nullopt;
    ExpectTarget t;
    t.kind = ExpectTarget::Kind::Status;
    t.observable = *o;
    return t;
  }

  // A status field of a cause (C.9).
  std::optional<Observable> cause_field(const Cause& c, const std::string& field, const std::string& where) {
    const auto& fields = cause_fields();
    auto f = std::find_if(fields.begin(), fields.end(), [&](const FieldInfo& fi) { return field == fi.name; });
    if (f == fields.end()) {
      std::vector<std::string> names;
      for (const auto& fi : fields) names.push_back(fi.name);
      error(where, "unknown cause field " + in_quotes(field) + did_you_mean(field, names));
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
  std::optional<Observable> effect_field(const Effect& e, const std::string& field, const std::string& where) {
    Observable o;
    o.kind = Node::Kind::Effect;
    o.id = e.id;
    if (field.starts_with("tag[") && field.ends_with("]")) {
      std::string digits = field.substr(4, field.size() - 5);
      bool ok = !digits.empty() && digits.size() <= 2 &&
                std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
      int k = ok ? std::stoi(digits) : 0;
      if (k < 1 || k > static_cast<int>(e.tags.size())) {
        error(where, "effect " + std::to_string(e.id) + " has " + std::to_string(e.tags.size()) +
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
      error(where, "unknown effect field " + in_quotes(field) + did_you_mean(field, names));
      return std::nullopt;
    }
    o.field = f->name;
    o.type = f->type;
    o.key = observable_key({o.kind, o.id}, o.field);
    return o;
  }

  // An output tag by name: the value the matrix writes to it (E.9).
  std::optional<ExpectTarget> output_target(const std::string& key, const std::string& where) {
    auto out = std::find_if(outputs_.begin(), outputs_.end(),
                            [&](const OutputRef& o) { return tag_key(o.name) == tag_key(key); });
    tags_seen_.insert(tag_key(key));
    if (out == outputs_.end()) {
      std::string hint = did_you_mean(key, output_names_);
      if (!table_.find(key)) tags_unknown_.insert(tag_key(key));
      if (table_.find(key))
        error(where, in_quotes(key) + " is an input tag; expectations name output tags, "
                                      "cause[..].FIELD or effect[..].FIELD");
      else
        error(where, "unknown expectation key " + in_quotes(key) +
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
  std::optional<int> expected_value(FieldType type, const json& v, const std::string& where) {
    switch (type) {
      case FieldType::Bool:
        if (!v.is_boolean()) {
          error(where, "expects true or false, not " + json_type_name(v));
          return std::nullopt;
        }
        return v.get<bool>() ? 1 : 0;
      case FieldType::Int: {
        if (!v.is_number_integer() && !v.is_number_unsigned()) {
          error(where, "expects an integer, not " + json_type_name(v));
          return std::nullopt;
        }
        auto n = v.get<std::int64_t>();
        if (n < 0 || n > 1000) {
          error(where, "expects a count, not " + v.dump());
          return std::nullopt;
        }
        return static_cast<int>(n);
      }
      case FieldType::Voting: {
        auto s = v.is_string() ? voting_from_string(v.get<std::string>()) : std::nullopt;
        if (!s) {
          error(where, "expects a voting: \"1oo1\", \"1oo2\", \"2oo2\", \"1oo3\", \"2oo3\", "
                       "\"3oo3\" or \"bypass\", not " + v.dump());
          return std::nullopt;
        }
        return static_cast<int>(*s);
      }
    }
    return std::nullopt;
  }


  ScenarioStep parse_step(const json& j, const std::string& path) {
    ScenarioStep st;
    if (!j.is_object()) {
      error(path, "a step is an object, not " + json_type_name(j));
      return st;
    }
    check_keys(j, path, {"description", "inputs", "commands", "cycles", "ms", "expect"});
    if (j.contains("description")) st.description = string_field(j["description"], join(path, "description"));
    if (j.contains("inputs")) st.inputs = parse_inputs(j["inputs"], join(path, "inputs"));
    if (j.contains("commands")) {
      const json& cs = j["commands"];
      if (!cs.is_array()) {
        error(join(path, "commands"), "must be an array, not " + json_type_name(cs));
      } else {
        for (std::size_t i = 0; i < cs.size(); ++i)
          if (auto c = parse_command(cs[i], path + ".commands[" + std::to_string(i) + "]"))
            st.commands.push_back(*c);
      }
    }
    if (j.contains("cycles") && j.contains("ms")) {
      error(path, "give either \"cycles\" or \"ms\", not both");
    } else if (j.contains("cycles")) {
      auto n = int_field(j["cycles"], join(path, "cycles"));
      if (n && (*n < 1 || static_cast<std::uint64_t>(*n) > kMaxScenarioCycles))
        error(join(path, "cycles"), "must be 1-" + std::to_string(kMaxScenarioCycles) + ", not " +
                                        std::to_string(*n));
      else if (n)
        st.cycles = static_cast<std::uint64_t>(*n);
    } else if (j.contains("ms")) {
      auto n = int_field(j["ms"], join(path, "ms"));
      if (n) {
        std::uint64_t cycle = m_.cycle_ms == 0 ? 1 : m_.cycle_ms;
        if (*n < 1)
          error(join(path, "ms"), "must be positive, not " + std::to_string(*n));
        else if (static_cast<std::uint64_t>(*n) % cycle != 0)
          error(join(path, "ms"), std::to_string(*n) + " is not a multiple of cycle_ms (" +
                                      std::to_string(cycle) + ")");
        else if (static_cast<std::uint64_t>(*n) / cycle > kMaxScenarioCycles)
          error(join(path, "ms"), "exceeds " + std::to_string(kMaxScenarioCycles) + " cycles");
        else
          st.cycles = static_cast<std::uint64_t>(*n) / cycle;
      }
    }
    if (j.contains("expect")) {
      const json& ex = j["expect"];
      if (!ex.is_object()) {
        error(join(path, "expect"), "must be an object, not " + json_type_name(ex));
      } else {
        for (const auto& [k, v] : ex.items())
          if (auto x = parse_expectation(k, v, join(path, "expect"))) st.expect.push_back(*x);
      }
    }
    return st;
  }

  const Matrix& m_;
  InputTable table_;
  std::vector<std::string> input_names_;
  std::vector<OutputRef> outputs_;
  std::vector<std::string> output_names_;
  std::vector<std::string> cause_names_;
  std::vector<std::string> effect_names_;
  std::vector<LoadIssue> issues_;
  // Tag names the scenario uses (inputs, simulated tags, output expectations)
  // and those of them the matrix does not know, by tag_key.
  std::set<std::string> tags_seen_;
  std::set<std::string> tags_unknown_;
};

}  // namespace

std::string expectation_value_text(FieldType type, int value) {
  switch (type) {
    case FieldType::Bool: return value ? "true" : "false";
    case FieldType::Int: return std::to_string(value);
    case FieldType::Voting: return to_string(static_cast<Voting>(value));
  }
  return std::to_string(value);
}

namespace {

// The limits of the guarded parser for a scenario: an `inputs` object sets up
// to every input tag of a matrix (3 per cause, 3.4) and an `expect` object may
// name every status field, so objects are allowed many more members than in a
// matrix; the nesting a scenario needs is 6 (steps, a step, commands, a
// command, and an input's {"value", "quality"}).
constexpr JsonLimits kScenarioLimits{4096, "scenario", 6};

// The JSON text of a scenario as a DOM through the guarded parser of every
// format (diagnostics.hpp): size and depth guards, NaN, Infinity and numbers
// that overflow a double, repeated keys, each placed at FILE:LINE:COL.
json parse_scenario_json(std::string_view json_text, const std::string& source_name) {
  if (json_text.size() > kMaxFileBytes)
    throw LoadError({{source_name, "file larger than " + std::to_string(kMaxFileBytes) + " bytes", source_name}});
  if (json_text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw LoadError({{source_name, "file is empty (expected a cemv-scenario/1 JSON object)", source_name}});
  std::vector<LoadIssue> issues;
  auto parsed = parse_guarded_json(json_text, source_name, issues, kScenarioLimits);
  if (!parsed || !issues.empty()) {
    // The scenario's syntax errors say so (docs/scenario.md).
    for (auto& i : issues)
      if (i.what.rfind("syntax error", 0) == 0) i.what = "JSON " + i.what;
    throw LoadError(std::move(issues));
  }
  // The parser below reads keys in sorted order (its messages and the order of
  // a step's expectations have always been so).
  return json(*parsed);
}

}  // namespace

Scenario parse_scenario(std::string_view json_text, const Matrix& m, const std::string& source_name) {
  json root = parse_scenario_json(json_text, source_name);
  Parser p(m);
  try {
    return p.parse(root);
  } catch (const LoadError& e) {
    std::vector<LoadIssue> issues = e.issues();
    locate_issues(json_text, source_name, issues);
    throw LoadError(std::move(issues));
  }
}

Scenario load_scenario(const std::filesystem::path& file, const Matrix& m) {
  return parse_scenario(read_text_file(file), m, file.string());
}

std::optional<std::string> scenario_matrix_key(std::string_view json_text, const std::string& source_name) {
  json root = parse_scenario_json(json_text, source_name);
  if (!root.is_object() || !root.contains("matrix")) return std::nullopt;
  const json& j = root["matrix"];
  if (!j.is_string() || j.get<std::string>().empty()) {
    std::vector<LoadIssue> issues{{"matrix",
                                   "must be a non-empty string, the path of the cemv-matrix/1 file relative "
                                   "to the scenario file"}};
    locate_issues(json_text, source_name, issues);
    throw LoadError(std::move(issues));
  }
  return j.get<std::string>();
}

std::optional<std::filesystem::path> scenario_matrix_path(const std::filesystem::path& scenario_file) {
  auto key = scenario_matrix_key(read_text_file(scenario_file), scenario_file.string());
  if (!key) return std::nullopt;
  return scenario_file.parent_path() / *key;
}

std::filesystem::path resolve_inner_path(const std::string& path, const std::filesystem::path& base,
                                         const std::filesystem::path& root, bool trust,
                                         std::string_view source_text, const std::string& source_name,
                                         const std::string& key_name) {
  namespace fs = std::filesystem;
  const fs::path written(path);
  const fs::path resolved = written.is_absolute() ? written : base / written;
  if (trust) return resolved;
  auto refuse = [&](const std::string& why) {
    std::vector<LoadIssue> issues{{key_name, why + "; a path inside an input file must lead to a file inside " +
                                                 "the working folder (give the file on the command line, or " +
                                                 "--trust-paths to follow it)"}};
    locate_issues(source_text, source_name, issues);
    throw LoadError(std::move(issues));
  };
  if (written.is_absolute()) refuse("is an absolute path");
  // Symbolic links followed: a link inside the folder to a file outside it
  // leads outside it.
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(fs::absolute(resolved, ec), ec);
  const fs::path top = fs::weakly_canonical(fs::absolute(root, ec), ec);
  if (ec) refuse("cannot be resolved");
  if (std::mismatch(top.begin(), top.end(), target.begin(), target.end()).first != top.end())
    refuse("leads outside the working folder");
  return resolved;
}

ExpandedScenario expand_scenario(const Scenario& sc, const Matrix& m) {
  ExpandedScenario out;
  CycleInput current = default_cycle_input(m);
  auto apply = [&](const std::vector<InputSetting>& settings) {
    for (const auto& s : settings) {
      if (s.tag >= current.tags.size()) continue;
      if (s.value) current.tags[s.tag].value = *s.value;
      if (s.bad_quality) current.tags[s.tag].bad_quality = *s.bad_quality;
    }
  };
  apply(sc.initial);
  for (std::size_t i = 0; i < sc.steps.size(); ++i) {
    const ScenarioStep& st = sc.steps[i];
    apply(st.inputs);
    for (std::uint64_t c = 0; c < st.cycles; ++c) {
      CycleInput in;
      in.tags = current.tags;
      if (c == 0) in.commands = st.commands;
      out.cycles.push_back(std::move(in));
      out.step_of_cycle.push_back(i);
    }
    out.checks.push_back({i, out.cycles.size() - 1, &st.expect});
  }
  return out;
}

std::string ExpectationOutcome::failure_text(std::uint32_t cycle_ms) const {
  const Expectation& x = *expectation;
  return "FAIL steps[" + std::to_string(step) + "] (cycle " + std::to_string(cycle + 1) + ", t = " +
         std::to_string(static_cast<std::uint64_t>(cycle) * cycle_ms) + " ms): " + x.key + " expected " +
         expectation_value_text(x.type, x.expected) + ", actual " +
         (actual ? expectation_value_text(x.type, *actual) : std::string("unknown"));
}

std::vector<ExpectationOutcome> ExpectationChecker::after_cycle(std::size_t cycle, const Actual& actual) {
  std::vector<ExpectationOutcome> out;
  while (next_check_ < ex_.checks.size() && ex_.checks[next_check_].cycle == cycle) {
    const auto& check = ex_.checks[next_check_];
    for (const auto& x : *check.expect) {
      ExpectationOutcome o{check.step, cycle, &x, actual(x.target), false};
      if (o.actual && x.type == FieldType::Bool) *o.actual = *o.actual != 0;
      o.ok = o.actual && *o.actual == x.expected;
      ++checked_;
      if (!o.ok) ++failed_;
      out.push_back(o);
    }
    ++next_check_;
  }
  return out;
}

}  // namespace cemv::formats
