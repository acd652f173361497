// Reading cemv-scenario/1 against a matrix (scenario.cpp): what every part of
// the reading shares (the matrix's names, the typed reads of fields, the
// problems found so far), and the readers of commands and expectations.
// Internal to formats/.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/diagnostics.hpp"
#include "formats/scenario.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"

namespace cemv::formats::scenario_detail {

using nlohmann::json;

// "a boolean", "an integer", ... for messages.
std::string json_type_name(const json& j);
// The path of member `key` of the object at `path`.
std::string join(const std::string& path, const std::string& key);

// The matrix a scenario is read against, the problems found so far and the
// typed reads every part of the reading uses; each read records why a value
// was not accepted and returns nothing.
class ScenarioContext {
 public:
  explicit ScenarioContext(const model::Matrix& matrix);

  void error(std::string where, std::string what);
  void check_keys(const json& obj, const std::string& path, std::initializer_list<const char*> allowed);
  std::string string_field(const json& j, const std::string& where);
  std::optional<bool> bool_field(const json& j, const std::string& where);
  std::optional<std::int64_t> int_field(const json& j, const std::string& where);
  // A REAL (IEEE single precision, 6.3.1): finite and within float range.
  std::optional<float> real_field(const json& j, const std::string& where);
  // The value of an input (or simulated) tag: a boolean for Boolean tags, a
  // number for analog ones.
  std::optional<float> tag_value(const json& j, model::TagKind kind, const std::string& tag, const std::string& where);
  // A cause or an effect referenced by id (integer) or name (string,
  // case-insensitive); comment-only elements are refused.
  const model::Cause* cause_ref(const json& j, const std::string& where);
  const model::Effect* effect_ref(const json& j, const std::string& where);
  // A simulatable tag by name (O.8): an input tag of the matrix, else one of
  // its output tags; nullopt (and an error naming the closest tags) otherwise.
  struct SimulatedTag {
    std::string name;
    model::TagKind kind = model::TagKind::Bool;
  };
  std::optional<SimulatedTag> simulatable_tag(const std::string& tag, const std::string& where);

  struct OutputRef {
    std::string name;
    int effect;
    int k;
  };
  const model::Matrix& m;
  model::InputTable table;
  std::vector<std::string> input_names;
  std::vector<OutputRef> outputs;
  std::vector<std::string> output_names;
  std::vector<std::string> cause_names;
  std::vector<std::string> effect_names;
  std::vector<LoadIssue> issues;
  // Tag names the scenario uses (inputs, simulated tags, output expectations)
  // and those of them the matrix does not know, by tag_key.
  std::set<std::string> tags_seen;
  std::set<std::string> tags_unknown;
};

// docs/scenario.md "Commands (10.7)": one command, its arguments checked
// against the matrix (scenario_commands.cpp).
std::optional<model::Command> read_command(ScenarioContext& cx, const json& j, const std::string& path);

// docs/scenario.md "Expectations": KEY -> VALUE, where the key names a status
// field (cause[..].FIELD, effect[..].FIELD, effect[..].tag[k]) or an output
// tag (scenario_expectations.cpp).
std::optional<Expectation> read_expectation(ScenarioContext& cx, const std::string& key, const json& v,
                                            const std::string& path);

}  // namespace cemv::formats::scenario_detail
