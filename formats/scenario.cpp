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
#include "formats/scenario_reader.hpp"
#include "model/text.hpp"

namespace cemv::formats {

using namespace cemv::model;

namespace {

using namespace scenario_detail;

// ---- the parser ------------------------------------------------------------

class Parser : public ScenarioContext {
 public:
  using ScenarioContext::ScenarioContext;

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
        std::uint64_t width = std::max<std::uint64_t>(1, table.size());
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
    if (issues.empty()) return;
    // A scenario whose tags are mostly unknown is most likely the scenario of
    // another matrix: one line says so before the list of unknown tags.
    if (tags_seen.size() >= 3 && 2 * tags_unknown.size() > tags_seen.size()) {
      const std::string n = std::to_string(tags_seen.size());
      std::string what = tags_unknown.size() == tags_seen.size()
                             ? "none of the scenario's " + n + " tags is in matrix " + m.name
                             : std::to_string(tags_unknown.size()) + " of the scenario's " + n +
                                   " tags are not in matrix " + m.name;
      issues.insert(issues.begin(), LoadIssue{"", what + "; is it the scenario of another matrix?"});
    }
    throw LoadError(issues);
  }

 private:
  std::vector<InputSetting> parse_inputs(const json& j, const std::string& path) {
    std::vector<InputSetting> out;
    if (!j.is_object()) {
      error(path, "must be an object of tag names, not " + json_type_name(j));
      return out;
    }
    for (const auto& [name, v] : j.items()) {
      std::string where = join(path, name);
      auto idx = table.find(name);
      tags_seen.insert(tag_key(name));
      if (!idx) {
        std::string hint = did_you_mean(name, input_names);
        // The key by value: clang before 16 cannot capture a structured binding.
        bool is_output = std::any_of(outputs.begin(), outputs.end(), [&, key = tag_key(name)](const OutputRef& o) {
          return tag_key(o.name) == key;
        });
        if (is_output)
          error(path, in_quotes(name) +
                          " is an output tag; outputs cannot be set as inputs (use the "
                          "simulate_tag command to force one)");
        else
          error(path, "unknown tag " + in_quotes(name) + hint);
        if (!is_output) tags_unknown.insert(tag_key(name));
        continue;
      }
      if (std::any_of(out.begin(), out.end(), [&](const InputSetting& s) { return s.tag == *idx; })) {
        error(where, "tag " + in_quotes(table.tags()[*idx].name) + " is set twice");
        continue;
      }
      const InputTag& tag = table.tags()[*idx];
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
          if (auto c = read_command(*this, cs[i], path + ".commands[" + std::to_string(i) + "]"))
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
        std::uint64_t cycle = m.cycle_ms == 0 ? 1 : m.cycle_ms;
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
          if (auto x = read_expectation(*this, k, v, join(path, "expect"))) st.expect.push_back(*x);
      }
    }
    return st;
  }
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
