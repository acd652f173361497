#include "cli/check_gate.hpp"

#include <nlohmann/json.hpp>

#include "cli/matrix_input.hpp"
#include "formats/diagnostics.hpp"
#include "reports/check_report.hpp"

namespace cemv::cli {

namespace {

using checker::PropertyVerdict;

bool is_verdict_word(const std::string& w) {
  for (auto v : {PropertyVerdict::Proved, PropertyVerdict::Falsified, PropertyVerdict::Reachable,
                 PropertyVerdict::Unreachable, PropertyVerdict::Vacuous, PropertyVerdict::Unknown})
    if (w == checker::to_string(v)) return true;
  return false;
}

[[noreturn]] void refuse(const std::string& file, std::string_view text, const std::string& where,
                         const std::string& what) {
  std::vector<formats::LoadIssue> issues{{where, what}};
  formats::locate_issues(text, file, issues);
  throw formats::LoadError(std::move(issues));
}

}  // namespace

CheckGate::CheckGate(bool expect, const std::string& baseline_file,
                     const std::vector<properties::PropertyFile>& files)
    : expect_(expect), baseline_file_(baseline_file) {
  if (expect_)
    for (const auto& f : files)
      for (const auto& p : f.properties)
        if (!p.expect.empty()) expected_[{f.file_name == "<standard>" ? "" : f.file_name, p.name}] = {p.expect, "# expect:"};
  if (baseline_file_.empty()) return;

  // A previous run's cemv-result/1 (docs/checker.md): its verdicts, by
  // property file and name. Only what the gate reads is checked.
  const std::string name = input_name(baseline_file_);
  const std::string text = read_input(baseline_file_);
  std::vector<formats::LoadIssue> issues;
  auto json = formats::parse_guarded_json(text, name, issues, {256, "result", 5});
  if (!json) throw formats::LoadError(std::move(issues));
  const auto& root = *json;
  if (!root.is_object() || !root.contains("format") || root["format"] != "cemv-result/1")
    refuse(name, text, "", "not a cemv-result/1 file (the baseline is the JSON result of an earlier "
                           "`cemv check --format json`)");
  if (!root.contains("properties") || !root["properties"].is_array())
    refuse(name, text, "properties", "expected an array of properties");
  const std::string from = "baseline " + name;
  std::size_t index = 0;
  for (const auto& p : root["properties"]) {
    const std::string where = formats::element_path("properties", index++);
    if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("verdict") ||
        !p["verdict"].is_string() || !p.contains("file") || !(p["file"].is_string() || p["file"].is_null()))
      refuse(name, text, where, "expected an object with name, file and verdict (cemv-result/1)");
    const std::string verdict = p["verdict"];
    if (!is_verdict_word(verdict))
      refuse(name, text, formats::member_path(where, "verdict"), "'" + verdict + "' is not a verdict");
    // Unknown is no verdict: such a property is held to the other expectations.
    if (verdict == "unknown") continue;
    Key key{p["file"].is_null() ? "" : p["file"].get<std::string>(), p["name"].get<std::string>()};
    expected_[key] = {verdict, from};
  }
}

void CheckGate::annotate(checker::CheckResult& r) const {
  if (!active()) return;
  for (auto& p : r.properties) {
    auto it = expected_.find({reports::is_standard(p) ? "" : p.file, p.name});
    p.expected = it == expected_.end() ? "" : it->second.verdict;
    p.expected_from = it == expected_.end() ? "" : it->second.from;
  }
}

int CheckGate::exit_code(const checker::CheckResult& r) const {
  std::vector<PropertyVerdict> verdicts;
  for (const auto& p : r.properties) verdicts.push_back(p.verdict);
  if (!active()) return checker::exit_code(verdicts);
  bool undecided = false;
  for (const auto& p : r.properties) {
    if (reports::as_expected(p)) continue;
    if (p.verdict != PropertyVerdict::Unknown) return 1;
    undecided = true;
  }
  return undecided ? 3 : 0;
}

std::string CheckGate::summary(const checker::CheckResult& r) const {
  if (!active()) return "";
  std::string option = expect_ && !baseline_file_.empty() ? "--expect --baseline"
                       : expect_                          ? "--expect"
                                                          : "--baseline";
  std::size_t as_expected = 0, negative = 0;
  std::string unexpected;
  for (const auto& p : r.properties) {
    if (reports::as_expected(p)) {
      ++as_expected;
      negative += reports::is_failure(p.verdict);
      continue;
    }
    unexpected += std::string(unexpected.empty() ? "" : ", ") + p.name + " (" + reports::verdict_name(p.verdict) +
                  ", expected " + (p.expected.empty() ? "proved or reachable" : p.expected) + ")";
  }
  std::string line = "cemv check " + option + ": ";
  const std::string total = std::to_string(r.properties.size());
  if (unexpected.empty())
    line += total + " of " + total + " properties as expected";
  else
    line += std::to_string(r.properties.size() - as_expected) + " of " + total + " properties not as expected: " +
            unexpected;
  if (negative) line += " (" + std::to_string(negative) + " known finding" + (negative == 1 ? "" : "s") + " expected)";
  return line + "\n";
}

}  // namespace cemv::cli
