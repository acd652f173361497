// `cemv diff --format sarif`: the change as code-review annotations. Every
// structural change is a result at the line of its element in NEW (in OLD
// when it was removed), critical ones (the safety logic, 6.2.3) a warning,
// the others a note; every effect whose behaviour changed, or was not
// decided, a warning at its line, with the shortest distinguishing run.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "diff/print.hpp"
#include "diff/print_words.hpp"
#include "reports/sarif.hpp"

namespace cemv::diff {

namespace {

using json = nlohmann::ordered_json;
using checker::EquivalenceVerdict;

struct Rule {
  const char* id;
  const char* name;
  const char* text;
  const char* level;
};

const Rule kRules[] = {
    {"CEMV-DIFF-BEHAVIOUR", "EffectBehaviourChanged",
     "An effect behaves differently in the new version: some run of inputs and operator actions sets an "
     "output or status differently (shown by the shortest such run, replayed on both runtimes). Retest it.",
     "warning"},
    {"CEMV-DIFF-UNDECIDED", "EffectBehaviourUndecided",
     "Whether an effect behaves the same in both versions was not decided within the time limit: treat it as "
     "changed.",
     "warning"},
    {"CEMV-DIFF-CRITICAL", "SafetyLogicChanged",
     "A change of the safety logic (a field the runtime reads, manual 6.2.3): the effects in its cone are "
     "compared by behaviour.",
     "warning"},
    {"CEMV-DIFF-EDIT", "NonCriticalChange", "A change of texts or display only (names, descriptions, notes, units).",
     "note"},
};
enum RuleIndex { kBehaviour, kUndecided, kCritical, kEdit };

std::string element_of(ElementChange::Element e, int id, int effect) {
  switch (e) {
    case ElementChange::Element::Matrix: return "matrix";
    case ElementChange::Element::Cause: return "cause[" + std::to_string(id) + "]";
    case ElementChange::Element::Effect: return "effect[" + std::to_string(id) + "]";
    case ElementChange::Element::Intersection:
      return "intersection cause[" + std::to_string(id) + "]/effect[" + std::to_string(effect) + "]";
  }
  return "matrix";
}

// The location of an element: NEW's file at its line when NEW has it, else OLD's.
json location(const DiffReport& r, ElementChange::Element e, int old_id, int new_id, int old_effect,
              int new_effect) {
  const bool in_new = new_id != 0 || e == ElementChange::Element::Matrix;
  const std::string& file = in_new ? r.new_file : r.old_file;
  const std::string element = element_of(e, in_new ? new_id : old_id, in_new ? new_effect : old_effect);
  json physical;
  physical["artifactLocation"] = {{"uri", reports::uri_of_path(file)}};
  if (auto at = reports::MatrixLines(in_new ? r.new_text : r.old_text).find(element))
    physical["region"] = {{"startLine", at->first}, {"startColumn", at->second}};
  return {{"physicalLocation", std::move(physical)}};
}

json result(RuleIndex rule, const std::string& message, json loc, const std::string& fingerprint) {
  json j;
  j["ruleId"] = kRules[rule].id;
  j["ruleIndex"] = static_cast<int>(rule);
  j["level"] = kRules[rule].level;
  j["message"] = {{"text", message}};
  j["locations"] = json::array({std::move(loc)});
  j["partialFingerprints"] = {{"cemvChange/v1", fingerprint}};
  return j;
}

}  // namespace

std::string to_sarif(const DiffReport& r, const std::string& tool_version) {
  json results = json::array();
  for (const auto& c : r.structure.changes) {
    std::string message = std::string(c.critical() ? "Critical change: " : "Non-critical change: ") +
                          to_string(c.kind) + " " + c.label();
    if (c.kind == ChangeKind::Moved)
      message += " (number " + std::to_string(c.old_id) + " -> " + std::to_string(c.new_id) + ")";
    for (const auto& f : c.fields) message += "; " + field_line(f);
    results.push_back(result(c.critical() ? kCritical : kEdit, message + ".",
                             location(r, c.element, c.old_id, c.new_id, c.old_effect, c.new_effect),
                             r.new_m->name + "/" + to_string(c.kind) + "/" + c.label()));
  }
  for (const auto& e : r.behaviour.effects) {
    const bool undecided = e.result.verdict == EquivalenceVerdict::Unknown;
    if (!e.behaviour_changed()) continue;
    std::string message = effect_label(e) + ": " + behaviour_words(e);
    if (!e.result.method.empty()) message += " [" + e.result.method + "]";
    if (e.result.distinction) message += "; shortest difference: " + distinction_text(*e.result.distinction);
    if (std::string f = scenario_of(r, e.result.group); !f.empty()) message += "; scenario: " + f;
    results.push_back(result(undecided ? kUndecided : kBehaviour, message + ".",
                             location(r, ElementChange::Element::Effect, e.old_id, e.new_id, 0, 0),
                             r.new_m->name + "/behaviour/" + e.result.group));
  }

  json rules = json::array();
  for (const auto& rule : kRules)
    rules.push_back({{"id", rule.id},
                     {"name", rule.name},
                     {"shortDescription", {{"text", rule.text}}},
                     {"defaultConfiguration", {{"level", rule.level}}},
                     {"helpUri", reports::sarif_help_uri("change-acceptance.md")}});
  json driver = {{"name", "cemv"},
                 {"version", tool_version},
                 {"informationUri", reports::kSarifInformationUri},
                 {"rules", std::move(rules)}};
  json run;
  run["tool"] = {{"driver", std::move(driver)}};
  run["automationDetails"] = {{"id", "cemv-diff/" + r.new_m->name + "/"}};
  run["columnKind"] = "unicodeCodePoints";
  run["results"] = std::move(results);
  run["properties"] = {{"old", {{"file", r.old_file}, {"signature", r.old_signature}}},
                       {"new", {{"file", r.new_file}, {"signature", r.new_signature}}},
                       {"exit_code", r.exit_code()},
                       {"verdict", r.verdict()}};
  json log;
  log["$schema"] = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = json::array({std::move(run)});
  return log.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace cemv::diff
