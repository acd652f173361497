// SARIF 2.1.0 (OASIS), for code-scanning views such as GitHub's: one run, one
// rule per kind of finding, one result per property that did not pass, located
// at the property's line in its file and naming the matrix element it is
// about, in the message and as a logical location. Properties that passed are
// not findings and produce no result. No times, so the log is the same on
// every run.
#include "reports/check_sarif.hpp"

#include <nlohmann/json.hpp>

#ifndef CEMV_HOME_URI
#define CEMV_HOME_URI "https://cemv.invalid/"
#endif

namespace cemv::reports {

namespace {

using nlohmann::ordered_json;
using checker::PropertyResult;
using checker::PropertyVerdict;

struct Rule {
  PropertyVerdict verdict;
  const char* id;
  const char* name;
  const char* short_text;
  const char* full_text;
  const char* level;
};

const Rule kRules[] = {
    {PropertyVerdict::Falsified, "CEMV-FALSIFIED", "PropertyFalsified",
     "A safety property of the matrix is violated.",
     "The checker found a run of the matrix that violates the property. The run was replayed on "
     "the reference runtime and is saved as a cemv-scenario/1 file: `cemv simulate MATRIX "
     "SCENARIO` shows it cycle by cycle.",
     "error"},
    {PropertyVerdict::Unreachable, "CEMV-UNREACHABLE", "CoverUnreachable",
     "A reachable property has no witness: the logic it describes is dead.",
     "No run of the matrix makes the property's condition true, which was proved. The cause, "
     "effect or state it names can never occur.",
     "error"},
    {PropertyVerdict::Vacuous, "CEMV-VACUOUS", "PropertyVacuous",
     "A property holds only vacuously.",
     "The property's assumptions cannot hold together, or the antecedent of its implication or "
     "the trigger of its response can never occur, so proving it says nothing.",
     "error"},
    {PropertyVerdict::Unknown, "CEMV-UNKNOWN", "PropertyUndecided",
     "A property was not decided.",
     "The checker reached a time limit or a bound before it could prove or refute the property.",
     "warning"},
};

const Rule* rule_for(PropertyVerdict v) {
  for (const auto& r : kRules)
    if (r.verdict == v) return &r;
  return nullptr;
}

// A relative path as a URI reference: percent-encode what a path may hold but
// a URI may not (RFC 3986 section 2).
std::string uri_of_path(const std::string& path) {
  static const char* hex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (plain) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  return out;
}

ordered_json result_json(const checker::CheckResult& r, const CheckReportInputs& in,
                         const PropertyResult& p, const Rule& rule, std::size_t rule_index) {
  std::vector<std::string> elements = property_elements(p);
  std::string about;
  for (const auto& e : elements) about += (about.empty() ? "" : ", ") + e;
  std::string message = "Property '" + p.name + "' " + outcome_text(p) + "; it concerns " +
                        (about.empty() ? "the whole" : about + " of") + " matrix " +
                        r.matrix_name + ".";
  if (!p.scenario_file.empty()) message += " Counterexample scenario: " + p.scenario_file + ".";
  if (!p.diagram_file.empty()) message += " Timing diagram: " + p.diagram_file + ".";
  if (!p.vcd_file.empty()) message += " Waveforms (VCD): " + p.vcd_file + ".";

  ordered_json physical;
  // Standard properties are derived from the matrix: they live in its file.
  physical["artifactLocation"] = {{"uri", uri_of_path(p.file.empty() ? in.matrix_file : p.file)}};
  if (p.line > 0)
    physical["region"] = {{"startLine", p.line}, {"startColumn", p.column > 0 ? p.column : 1}};
  ordered_json logical = ordered_json::array();
  for (const auto& e : elements.empty() ? std::vector<std::string>{r.matrix_name} : elements)
    logical.push_back({{"name", e},
                       {"fullyQualifiedName", r.matrix_name + "/" + e},
                       {"kind", elements.empty() ? "module" : "object"}});
  ordered_json location;
  location["physicalLocation"] = physical;
  location["logicalLocations"] = logical;

  ordered_json j;
  j["ruleId"] = rule.id;
  j["ruleIndex"] = rule_index;
  j["level"] = rule.level;
  j["message"] = {{"text", message}};
  j["locations"] = ordered_json::array({location});
  // Stable identity of a finding across commits: the property, not its line.
  j["partialFingerprints"] = {{"cemvProperty/v1", r.matrix_name + "/" + p.file + "/" + p.name}};
  j["properties"] = {{"verdict", verdict_name(p.verdict)}, {"property", p.name}, {"kind", p.kind}};
  // The files of the run beside the finding, as SARIF result attachments.
  ordered_json attachments = ordered_json::array();
  auto attach = [&](const std::string& file, const char* what) {
    if (!file.empty())
      attachments.push_back({{"description", {{"text", what}}}, {"artifactLocation", {{"uri", uri_of_path(file)}}}});
  };
  attach(p.scenario_file, "the run as a cemv-scenario/1 file (cemv simulate MATRIX SCENARIO replays it)");
  attach(p.diagram_file, "the run as a timing diagram (SVG)");
  attach(p.vcd_file, "the run as a value change dump (VCD, IEEE 1364) for waveform viewers");
  if (!attachments.empty()) j["attachments"] = std::move(attachments);
  return j;
}

// "2/3" -> "shard-2-of-3": a slash would end the category (SARIF 3.17.4).
std::string shard_label(const std::string& shard) {
  if (shard.empty()) return "all";
  std::string s = "shard-" + shard;
  if (auto slash = s.find('/'); slash != std::string::npos) s.replace(slash, 1, "-of-");
  return s;
}

}  // namespace

std::string check_sarif(const checker::CheckResult& r, const CheckReportInputs& in) {
  ordered_json rules = ordered_json::array();
  for (const auto& rule : kRules) {
    ordered_json d;
    d["id"] = rule.id;
    d["name"] = rule.name;
    d["shortDescription"] = {{"text", rule.short_text}};
    d["fullDescription"] = {{"text", rule.full_text}};
    d["defaultConfiguration"] = {{"level", rule.level}};
    d["helpUri"] = std::string(CEMV_HOME_URI) + "docs/checker.md";
    rules.push_back(std::move(d));
  }
  ordered_json driver;
  driver["name"] = "cemv";
  driver["version"] = r.tool_version;
  driver["informationUri"] = CEMV_HOME_URI;
  driver["rules"] = std::move(rules);

  ordered_json results = ordered_json::array();
  for (const auto& p : r.properties) {
    const Rule* rule = rule_for(p.verdict);
    if (rule) results.push_back(result_json(r, in, p, *rule, static_cast<std::size_t>(rule - kRules)));
  }

  ordered_json run;
  run["tool"] = {{"driver", std::move(driver)}};
  // One category per shard, so that the uploads of a sharded run do not
  // replace each other in a code-scanning view.
  run["automationDetails"] = {
      {"id", "cemv-check/" + r.matrix_name + "/" +
                 shard_label(r.shard) + "/"}};
  run["columnKind"] = "unicodeCodePoints";
  run["results"] = std::move(results);
  run["properties"] = {{"matrix", r.matrix_name},
                       {"signature", r.matrix_signature},
                       {"interrupted", r.interrupted}};

  ordered_json log;
  log["$schema"] = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = ordered_json::array({run});
  return log.dump(2, ' ', false, ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace cemv::reports
