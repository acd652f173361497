// SARIF 2.1.0 (OASIS), for code-scanning views such as GitHub's: one run, one
// rule per kind of finding, one result per property that did not pass, located
// at the property's line in its file and naming the matrix element it is
// about, in the message and as a logical location. Properties that passed are
// not findings and produce no result. No times, so the log is the same on
// every run.
#include "reports/check_sarif.hpp"

#include <iterator>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/sarif.hpp"

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

// A passing verdict where a gate expected another (cemv check --expect,
// --baseline): the seeded defect or the known finding is gone.
const Rule kNotAsExpected = {PropertyVerdict::Proved, "CEMV-NOT-AS-EXPECTED", "VerdictNotAsExpected",
                             "A property did not get the verdict it is expected to get.",
                             "The property passed, but its `# expect:` comment or the baseline result "
                             "(cemv check --expect, --baseline) says it should not: the expectation is out "
                             "of date, or the defect it records is no longer found.",
                             "error"};

// The rule of a property's result; nullptr when it passed as expected.
const Rule* rule_for(const PropertyResult& p) {
  for (const auto& r : kRules)
    if (r.verdict == p.verdict) return &r;
  return as_expected(p) ? nullptr : &kNotAsExpected;
}

ordered_json matrix_location(const std::string& uri, std::pair<std::size_t, std::size_t> at) {
  ordered_json physical;
  physical["artifactLocation"] = {{"uri", uri}};
  physical["region"] = {{"startLine", at.first}, {"startColumn", at.second}};
  return physical;
}

ordered_json result_json(const checker::CheckResult& r, const CheckReportInputs& in,
                         const PropertyResult& p, const Rule& rule, std::size_t rule_index) {
  std::vector<std::string> elements = property_elements(p);
  std::string about;
  for (const auto& e : elements) about += (about.empty() ? "" : ", ") + e;
  std::string message = "Property '" + p.name + "' " + outcome_text(p) +
                        (p.expected.empty() ? ""
                         : as_expected(p)   ? " (as expected)"
                                            : ", expected " + p.expected + " (" + p.expected_from + ")") +
                        "; it concerns " +
                        (about.empty() ? "the whole" : about + " of") + " matrix " +
                        r.matrix_name + ".";
  if (!p.scenario_file.empty()) message += " Counterexample scenario: " + p.scenario_file + ".";
  if (!p.diagram_file.empty()) message += " Timing diagram: " + p.diagram_file + ".";
  if (!p.vcd_file.empty()) message += " Waveforms (VCD): " + p.vcd_file + ".";

  const MatrixLines lines(in.matrix_text);
  const std::string matrix_uri = uri_of_path(in.matrix_file);
  ordered_json physical;
  // Standard properties are derived from the matrix: they live in its file,
  // at the line of the element they are about.
  physical["artifactLocation"] = {{"uri", is_standard(p) ? matrix_uri : uri_of_path(p.file)}};
  if (p.line > 0)
    physical["region"] = {{"startLine", p.line}, {"startColumn", p.column > 0 ? p.column : 1}};
  else if (is_standard(p) && !elements.empty())
    if (auto at = lines.find(elements.front())) physical = matrix_location(matrix_uri, *at);
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
  // A counterexample's cells at their lines in the matrix file, which is what
  // a change under review touches (the elements the property reads when no
  // single cell carries the run).
  if (p.verdict == PropertyVerdict::Falsified) {
    ordered_json related = ordered_json::array();
    const bool cells = !p.counterexample_support.empty();
    for (const auto& e : cells ? p.counterexample_support : elements)
      if (auto at = lines.find(e))
        related.push_back({{"id", related.size()},
                           {"physicalLocation", matrix_location(matrix_uri, *at)},
                           {"message", {{"text", e + (cells ? ": a cell of the counterexample (deleting it, the "
                                                              "run satisfies the property)"
                                                            : ": an element the property reads")}}}});
    if (!related.empty()) j["relatedLocations"] = std::move(related);
  }
  // Stable identity of a finding across commits: the property, not its line.
  j["partialFingerprints"] = {{"cemvProperty/v1", r.matrix_name + "/" + p.file + "/" + p.name}};
  // A negative verdict the gate expects: suppressed, with where the
  // expectation is recorded (`# expect:` in the file, or the baseline).
  if (!p.expected.empty() && as_expected(p))
    j["suppressions"] = ordered_json::array(
        {{{"kind", p.expected_from.rfind("baseline", 0) == 0 ? "external" : "inSource"},
          {"status", "accepted"},
          {"justification", "expected " + p.expected + " (" + p.expected_from + ")"}}});
  j["properties"] = {{"verdict", verdict_name(p.verdict)}, {"property", p.name}, {"kind", p.kind}};
  if (!p.expected.empty()) j["properties"]["expected"] = p.expected;
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
  std::vector<const Rule*> all_rules;
  for (const auto& rule : kRules) all_rules.push_back(&rule);
  all_rules.push_back(&kNotAsExpected);
  for (const Rule* rule_ptr : all_rules) {
    const Rule& rule = *rule_ptr;
    ordered_json d;
    d["id"] = rule.id;
    d["name"] = rule.name;
    d["shortDescription"] = {{"text", rule.short_text}};
    d["fullDescription"] = {{"text", rule.full_text}};
    d["defaultConfiguration"] = {{"level", rule.level}};
    d["helpUri"] = sarif_help_uri("checker.md");
    rules.push_back(std::move(d));
  }
  ordered_json driver;
  driver["name"] = "cemv";
  driver["version"] = r.tool_version;
  driver["informationUri"] = kSarifInformationUri;
  driver["rules"] = std::move(rules);

  ordered_json results = ordered_json::array();
  for (const auto& p : r.properties) {
    const Rule* rule = rule_for(p);
    std::size_t index = rule == &kNotAsExpected ? std::size(kRules) : static_cast<std::size_t>(rule - kRules);
    if (rule) results.push_back(result_json(r, in, p, *rule, index));
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
