// See validation_report.hpp. Deterministic: no times, files in the order given,
// findings in validate()'s order.
#include "reports/validation_report.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "reports/sarif.hpp"
#include "reports/xml_text.hpp"

namespace cemv::reports {

namespace {

using nlohmann::ordered_json;
using model::Diagnostic;
using model::Severity;

// The rule a file that cannot be loaded is reported under (JUnit, SARIF).
constexpr const char* kLoadRule = "E-LOAD";
constexpr const char* kLoadMeaning =
    "the file could not be read or is not a well-formed cemv-matrix/1 file (docs/format.md)";

bool counts_as_error(const Diagnostic& d, const ValidationOptions& o) {
  return d.severity == Severity::Error || o.warnings_as_errors;
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// The single-file text report of earlier versions (tests pin it).
std::string text_block(const ValidatedFile& f, const ValidationOptions& o) {
  std::ostringstream out;
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : f.diagnostics) {
    (d.severity == Severity::Error ? errors : warnings)++;
    if (o.quiet && !counts_as_error(d, o)) continue;
    out << std::left << std::setw(7) << model::to_string(d.severity) << " " << d.rule << "  " << d.element
        << "  [" << d.section << "]  " << d.message << "\n";
  }
  if (o.quiet) return out.str();
  out << errors << " errors, " << warnings << " warnings\n";
  out << "signature: " << f.signature << "\n";
  return out.str();
}

ordered_json diagnostics_json(const ValidatedFile& f, bool positions) {
  ordered_json diagnostics = ordered_json::array();
  for (std::size_t i = 0; i < f.diagnostics.size(); ++i) {
    const Diagnostic& d = f.diagnostics[i];
    ordered_json j{{"severity", model::to_string(d.severity)},
                   {"rule", d.rule},
                   {"element", d.element},
                   {"section", d.section},
                   {"message", d.message}};
    if (positions && i < f.positions.size() && f.positions[i].first > 0) {
      j["line"] = f.positions[i].first;
      j["column"] = f.positions[i].second;
    }
    diagnostics.push_back(std::move(j));
  }
  return diagnostics;
}

std::pair<std::size_t, std::size_t> count(const ValidatedFile& f) {
  std::size_t errors = 0, warnings = 0;
  for (const auto& d : f.diagnostics) (d.severity == Severity::Error ? errors : warnings)++;
  return {errors, warnings};
}

std::string json_one(const ValidatedFile& f) {
  auto [errors, warnings] = count(f);
  ordered_json j;
  j["format"] = "cemv-validation/1";
  j["matrix"] = f.matrix_name;
  j["signature"] = f.signature;
  j["errors"] = errors;
  j["warnings"] = warnings;
  j["diagnostics"] = diagnostics_json(f, false);
  return j.dump(2) + "\n";
}

std::string json_many(const std::vector<ValidatedFile>& files, const ValidationSummary& s) {
  ordered_json list = ordered_json::array();
  for (const auto& f : files) {
    ordered_json j;
    j["file"] = f.file;
    if (!f.loaded) {
      j["unreadable"] = true;
      j["load_errors"] = f.load_errors;
    } else {
      auto [errors, warnings] = count(f);
      j["matrix"] = f.matrix_name;
      j["signature"] = f.signature;
      j["errors"] = errors;
      j["warnings"] = warnings;
      j["diagnostics"] = diagnostics_json(f, true);
    }
    list.push_back(std::move(j));
  }
  ordered_json j;
  j["format"] = "cemv-validation-files/1";
  j["files"] = std::move(list);
  j["summary"] = {{"files", s.files},           {"clean", s.clean},   {"with_errors", s.with_errors},
                  {"unreadable", s.unreadable}, {"errors", s.errors}, {"warnings", s.warnings}};
  return j.dump(2) + "\n";
}

std::pair<std::size_t, std::size_t> position_of(const ValidatedFile& f, std::size_t i) {
  std::pair<std::size_t, std::size_t> p{0, 0};
  if (i < f.positions.size()) p = f.positions[i];
  if (p.first == 0) p = {1, 1};  // an element the file does not show: the file's start
  return p;
}

// FILE:LINE:COLUMN: error|warning: [RULE] element: message
std::string gcc_lines(const std::vector<ValidatedFile>& files, const ValidationOptions& o) {
  std::string out;
  for (const auto& f : files) {
    for (std::size_t i = 0; i < f.diagnostics.size(); ++i) {
      const Diagnostic& d = f.diagnostics[i];
      if (o.quiet && !counts_as_error(d, o)) continue;
      auto [line, column] = position_of(f, i);
      // Under --warnings-as-errors a warning is reported as an error (as
      // compilers do with -Werror); its rule id still says W-.
      out += f.file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
             (counts_as_error(d, o) ? "error" : "warning") + ": [" + d.rule + "] " + d.element + ": " + d.message +
             "\n";
    }
  }
  return out;
}

std::string attr(std::string_view s) { return xml_escape(s, true); }
std::string text(std::string_view s) { return xml_escape(s, false); }

// One <testsuite> per file, one <testcase> per rule of the catalogue (and
// E-LOAD for a file that cannot be read): a rule fails when it has findings
// that count as errors; a rule with warnings only passes and lists them.
std::string junit(const std::vector<ValidatedFile>& files, const ValidationSummary& s,
                  const ValidationOptions& o) {
  const auto& rules = model::validation_rules();
  std::ostringstream suites;
  std::size_t total_tests = 0, total_failures = 0, total_errors = 0;
  for (const auto& f : files) {
    std::ostringstream cases;
    std::size_t tests = 0, failures = 0, errors = 0;
    if (!f.loaded) {
      std::string lines;
      for (const auto& l : f.load_errors) lines += l + "\n";
      cases << "    <testcase classname=\"" << attr(f.file) << "\" name=\"" << kLoadRule << "\">\n"
            << "      <error message=\"" << attr(f.load_errors.empty() ? kLoadMeaning : f.load_errors.front())
            << "\" type=\"" << kLoadRule << "\">" << text(lines) << "</error>\n"
            << "    </testcase>\n";
      tests = 1;
      errors = 1;
    } else {
      for (const auto& rule : rules) {
        std::string failing, passing;
        std::size_t n_failing = 0;
        for (std::size_t i = 0; i < f.diagnostics.size(); ++i) {
          const Diagnostic& d = f.diagnostics[i];
          if (d.rule != rule.id) continue;
          auto [line, column] = position_of(f, i);
          std::string l = f.file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                          model::to_string(d.severity) + ": " + d.element + ": " + d.message + "\n";
          if (counts_as_error(d, o)) {
            failing += l;
            ++n_failing;
          } else {
            passing += l;
          }
        }
        ++tests;
        cases << "    <testcase classname=\"" << attr(f.file) << "\" name=\"" << attr(rule.id) << "\"";
        if (n_failing == 0 && passing.empty()) {
          cases << "/>\n";
          continue;
        }
        cases << ">\n";
        if (n_failing > 0) {
          ++failures;
          cases << "      <failure message=\"" << attr(plural(n_failing, "finding") + ": " + rule.meaning + " (" +
                                                     rule.section + ")")
                << "\" type=\"" << attr(rule.id) << "\">" << text(failing) << "</failure>\n";
        }
        if (!passing.empty()) cases << "      <system-out>" << text(passing) << "</system-out>\n";
        cases << "    </testcase>\n";
      }
    }
    total_tests += tests;
    total_failures += failures;
    total_errors += errors;
    suites << "  <testsuite name=\"" << attr(f.file) << "\" tests=\"" << tests << "\" failures=\"" << failures
           << "\" errors=\"" << errors << "\" skipped=\"0\">\n"
           << cases.str() << "  </testsuite>\n";
  }
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"cemv validate\" tests=\"" << total_tests << "\" failures=\"" << total_failures
      << "\" errors=\"" << total_errors << "\">\n"
      << suites.str() << "</testsuites>\n";
  (void)s;
  return out.str();
}

// A finding's place in SARIF: the file, the line and column.
ordered_json sarif_location(const std::string& file, std::size_t line, std::size_t column) {
  ordered_json physical;
  physical["artifactLocation"] = {{"uri", uri_of_path(file)}};
  physical["region"] = {{"startLine", line}, {"startColumn", column}};
  return ordered_json{{"physicalLocation", physical}};
}

// SARIF 2.1.0: one run; the rules are the validation catalogue (id, manual
// section, meaning) plus E-LOAD; one result per finding, located at its
// element's line in its file.
std::string sarif(const std::vector<ValidatedFile>& files, const ValidationOptions& o) {
  const auto& catalogue = model::validation_rules();
  ordered_json rules = ordered_json::array();
  auto add_rule = [&](const std::string& id, const std::string& section, const std::string& meaning,
                      const char* level) {
    ordered_json r;
    r["id"] = id;
    r["shortDescription"] = {{"text", meaning}};
    r["fullDescription"] = {{"text", section.empty() ? meaning : meaning + " (manual section " + section + ")"}};
    r["help"] = {{"text", "Rule " + id + (section.empty() ? "" : " of manual section " + section) + ": " + meaning +
                              ". docs/validation.md lists every rule."}};
    r["helpUri"] = sarif_help_uri("validation.md");
    r["defaultConfiguration"] = {{"level", level}};
    r["properties"] = {{"section", section}};
    rules.push_back(std::move(r));
  };
  for (const auto& rule : catalogue)
    add_rule(rule.id, rule.section, rule.meaning, rule.severity == Severity::Error ? "error" : "warning");
  add_rule(kLoadRule, "", kLoadMeaning, "error");
  auto rule_index = [&](const std::string& id) -> std::size_t {
    for (std::size_t i = 0; i < catalogue.size(); ++i)
      if (id == catalogue[i].id) return i;
    return catalogue.size();
  };

  ordered_json results = ordered_json::array();
  ordered_json artifacts = ordered_json::array();
  for (const auto& f : files) {
    artifacts.push_back({{"location", {{"uri", uri_of_path(f.file)}}}});
    if (!f.loaded) {
      ordered_json r;
      r["ruleId"] = kLoadRule;
      r["ruleIndex"] = catalogue.size();
      r["level"] = "error";
      std::string message;
      for (const auto& l : f.load_errors) message += (message.empty() ? "" : "\n") + l;
      r["message"] = {{"text", message.empty() ? std::string(kLoadMeaning) : message}};
      r["locations"] = ordered_json::array({sarif_location(f.file, 1, 1)});
      results.push_back(std::move(r));
      continue;
    }
    for (std::size_t i = 0; i < f.diagnostics.size(); ++i) {
      const Diagnostic& d = f.diagnostics[i];
      auto [line, column] = position_of(f, i);
      ordered_json r;
      r["ruleId"] = d.rule;
      r["ruleIndex"] = rule_index(d.rule);
      r["level"] = counts_as_error(d, o) ? "error" : "warning";
      r["message"] = {{"text", d.element + ": " + d.message + " (" + d.section + ")"}};
      r["locations"] = ordered_json::array({sarif_location(f.file, line, column)});
      r["partialFingerprints"] = {{"cemvFinding/v1", f.matrix_name + "/" + d.rule + "/" + d.element}};
      results.push_back(std::move(r));
    }
  }
  ordered_json driver;
  driver["name"] = "cemv";
  driver["version"] = o.tool_version;
  driver["informationUri"] = kSarifInformationUri;
  driver["rules"] = std::move(rules);
  ordered_json run;
  run["tool"] = {{"driver", std::move(driver)}};
  run["artifacts"] = std::move(artifacts);
  run["results"] = std::move(results);
  ordered_json log;
  log["$schema"] = "https://json.schemastore.org/sarif-2.1.0.json";
  log["version"] = "2.1.0";
  log["runs"] = ordered_json::array({std::move(run)});
  return log.dump(2) + "\n";
}

}  // namespace

std::optional<ValidationFormat> validation_format_from_string(const std::string& name) {
  if (name == "text") return ValidationFormat::Text;
  if (name == "json") return ValidationFormat::Json;
  if (name == "gcc") return ValidationFormat::Gcc;
  if (name == "junit") return ValidationFormat::Junit;
  if (name == "sarif") return ValidationFormat::Sarif;
  return std::nullopt;
}

ValidationSummary summarize(const std::vector<ValidatedFile>& files, const ValidationOptions& o) {
  ValidationSummary s;
  s.files = files.size();
  for (const auto& f : files) {
    int code = 0;
    if (!f.loaded) {
      ++s.unreadable;
      code = 2;
    } else {
      bool bad = false;
      for (const auto& d : f.diagnostics) {
        (d.severity == Severity::Error ? s.errors : s.warnings)++;
        bad = bad || counts_as_error(d, o);
      }
      (bad ? s.with_errors : s.clean)++;
      code = bad ? 1 : 0;
    }
    s.exit_code = std::max(s.exit_code, code);
  }
  return s;
}

std::string summary_line(const ValidationSummary& s) {
  // No singular forms, as in the single-file summary: scripts match one pattern.
  std::string line = std::to_string(s.files) + " files: " + std::to_string(s.clean) + " clean, " +
                     std::to_string(s.with_errors) + " with errors";
  if (s.unreadable > 0) line += ", " + std::to_string(s.unreadable) + " unreadable";
  return line + "; " + std::to_string(s.errors) + " errors, " + std::to_string(s.warnings) + " warnings";
}

std::string validation_report(const std::vector<ValidatedFile>& files, ValidationFormat format,
                              const ValidationOptions& options) {
  const ValidationSummary s = summarize(files, options);
  const bool one = files.size() == 1;
  switch (format) {
    case ValidationFormat::Text: {
      if (one) return files.front().loaded ? text_block(files.front(), options) : "";
      std::string out;
      for (const auto& f : files) {
        if (!f.loaded) continue;
        if (!options.quiet) out += "== " + f.file + "\n";
        out += text_block(f, options);
      }
      if (!options.quiet) out += summary_line(s) + "\n";
      return out;
    }
    case ValidationFormat::Json:
      if (one && files.front().loaded) return json_one(files.front());
      return json_many(files, s);
    case ValidationFormat::Gcc: {
      std::string out = gcc_lines(files, options);
      if (!options.quiet) out += summary_line(s) + "\n";
      return out;
    }
    case ValidationFormat::Junit: return junit(files, s, options);
    case ValidationFormat::Sarif: return sarif(files, options);
  }
  return "";
}

}  // namespace cemv::reports
