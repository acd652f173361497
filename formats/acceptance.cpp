#include "formats/acceptance.hpp"

#include <cctype>
#include <cstdlib>
#include <map>

#include <nlohmann/json.hpp>

#include "formats/csv_rfc4180.hpp"
#include "formats/diagnostics.hpp"

namespace cemv::formats {

namespace {

LoadIssue at_line(const std::string& file, int line, std::string what) {
  LoadIssue i;
  i.file = file;
  i.line = static_cast<std::size_t>(line);
  i.what = std::move(what);
  return i;
}

bool iso_date(const std::string& d) {
  if (d.size() != 10 || d[4] != '-' || d[7] != '-') return false;
  for (std::size_t i : {0, 1, 2, 3, 5, 6, 8, 9})
    if (!std::isdigit(static_cast<unsigned char>(d[i]))) return false;
  const int month = std::atoi(d.substr(5, 2).c_str()), day = std::atoi(d.substr(8, 2).c_str());
  return month >= 1 && month <= 12 && day >= 1 && day <= 31;
}

std::string trim(std::string s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  std::size_t b = 0;
  while (b < s.size() && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
  return s.substr(b);
}

}  // namespace

const char* to_string(StepStatus s) {
  switch (s) {
    case StepStatus::Ok: return "ok";
    case StepStatus::Deviation: return "deviation";
    case StepStatus::Open: return "open";
  }
  return "open";
}

const char* to_string(AcceptanceStatus s) {
  switch (s) {
    case AcceptanceStatus::Accepted: return "accepted";
    case AcceptanceStatus::Deviation: return "deviation";
    case AcceptanceStatus::NotTested: return "not-tested";
  }
  return "not-tested";
}

const char* to_string(ElementKind k) {
  switch (k) {
    case ElementKind::Cause: return "cause";
    case ElementKind::Effect: return "effect";
    case ElementKind::Intersection: return "intersection";
  }
  return "cause";
}

std::string ElementAcceptance::key() const {
  switch (kind) {
    case ElementKind::Cause: return "cause[" + std::to_string(cause) + "]";
    case ElementKind::Effect: return "effect[" + std::to_string(effect) + "]";
    case ElementKind::Intersection:
      return "intersection cause[" + std::to_string(cause) + "]/effect[" + std::to_string(effect) + "]";
  }
  return "";
}

FilledChecklist read_filled_checklist(std::string_view text, const std::string& file) {
  FilledChecklist c;
  c.file = file;
  std::vector<CsvRecord> records;
  try {
    records = parse_csv(text, ',', true, file);
  } catch (const LoadError& e) {
    throw e.in_file(file);
  }
  std::vector<LoadIssue> issues;
  std::map<std::string, std::size_t> column;
  bool format = false;
  for (const auto& r : records) {
    if (r.fields.empty() || (r.fields.size() == 1 && trim(r.fields[0].text).empty())) continue;
    const std::string first = trim(r.fields[0].text);
    auto field = [&](std::size_t i) { return i < r.fields.size() ? trim(r.fields[i].text) : std::string(); };
    if (!first.empty() && first[0] == '#') {
      const std::string key = trim(first.substr(1));
      if (key == "format") {
        if (field(1) != kFieldChecklistFormat)
          issues.push_back(at_line(file, r.line, "not a field checklist: the format is \"" + field(1) + "\", expected " +
                                                     kFieldChecklistFormat));
        format = true;
      } else if (key == "matrix") {
        c.matrix = field(1);
      } else if (key == "signature") {
        c.signature = field(1);
        c.signature_line = r.line;
      } else if (key == "resolution") {
        char* end = nullptr;
        const std::string v = field(1);
        c.resolution = std::strtod(v.c_str(), &end);
        if (v.empty() || *end != '\0' || !(c.resolution > 0.0))
          issues.push_back(at_line(file, r.line, "the resolution \"" + v + "\" is not a positive number"));
      }
      continue;
    }
    if (!format) {
      issues.push_back(at_line(file, r.line, std::string("not a field checklist: no \"# format,") +
                                                 kFieldChecklistFormat + "\" line before the steps"));
      break;
    }
    if (column.empty()) {
      for (std::size_t i = 0; i < r.fields.size(); ++i) column[trim(r.fields[i].text)] = i;
      for (const char* need : {"test", "step", "action", "result", "initials", "date"})
        if (!column.count(need)) issues.push_back(at_line(file, r.line, std::string("the header has no column \"") + need + "\""));
      if (!issues.empty()) break;
      continue;
    }
    FilledRow row;
    row.line = r.line;
    row.test = field(column["test"]);
    const std::string step = field(column["step"]);
    char* end = nullptr;
    const long n = std::strtol(step.c_str(), &end, 10);
    if (row.test.empty() || step.empty() || *end != '\0' || n < 1 || n > 100000) {
      issues.push_back(at_line(file, r.line, "a row needs a test and a step number (test \"" + row.test + "\", step \"" +
                                                 step + "\")"));
      continue;
    }
    row.step = static_cast<int>(n);
    row.action = r.fields.size() > column["action"] ? r.fields[column["action"]].text : "";
    row.result = field(column["result"]);
    row.initials = field(column["initials"]);
    row.date = field(column["date"]);
    if (!row.result.empty() && (row.initials.empty() || row.date.empty()))
      issues.push_back(at_line(file, r.line, row.test + " step " + step + ": a result needs initials and a date"));
    else if (!row.date.empty() && !iso_date(row.date))
      issues.push_back(at_line(file, r.line, row.test + " step " + step + ": the date \"" + row.date +
                                                 "\" is not YYYY-MM-DD"));
    else if (row.result.empty() && (!row.initials.empty() || !row.date.empty()))
      issues.push_back(at_line(file, r.line, row.test + " step " + step +
                                                 ": initials or a date without a result (write OK or the deviation)"));
    c.rows.push_back(std::move(row));
    if (issues.size() >= kMaxIssues) break;
  }
  if (issues.empty() && !format)
    issues.push_back(at_line(file, 1, std::string("not a field checklist: no \"# format,") + kFieldChecklistFormat + "\" line"));
  if (issues.empty() && c.signature.empty())
    issues.push_back(at_line(file, 1, "the checklist carries no \"# signature\" line"));
  if (!issues.empty()) throw LoadError(issues);
  return c;
}

std::string acceptance_json(const Acceptance& a) {
  using nlohmann::ordered_json;
  ordered_json doc;
  doc["format"] = kAcceptanceFormat;
  doc["matrix"] = a.matrix;
  doc["signature"] = a.signature;
  doc["tool"] = a.tool;
  doc["checklists"] = a.checklists;
  std::map<std::string, int> steps, elements;
  for (const auto& s : a.steps) steps[to_string(s.status)]++;
  for (const auto& e : a.elements) elements[to_string(e.status)]++;
  doc["summary"] = {{"steps", a.steps.size()},
                    {"ok", steps["ok"]},
                    {"deviation", steps["deviation"]},
                    {"open", steps["open"]},
                    {"elements", a.elements.size()},
                    {"accepted", elements["accepted"]},
                    {"deviations", elements["deviation"]},
                    {"not_tested", elements["not-tested"]}};
  ordered_json js = ordered_json::array();
  for (const auto& s : a.steps) {
    ordered_json j;
    j["test"] = s.test;
    j["step"] = s.step;
    j["phase"] = s.phase;
    j["status"] = to_string(s.status);
    ordered_json rs = ordered_json::array();
    for (const auto& r : s.records)
      rs.push_back({{"result", r.result}, {"initials", r.initials}, {"date", r.date}, {"file", r.file}, {"line", r.line}});
    j["records"] = rs;
    j["objectives"] = s.objectives;
    js.push_back(j);
  }
  doc["steps"] = js;
  ordered_json je = ordered_json::array();
  for (const auto& e : a.elements) {
    ordered_json j;
    j["element"] = e.key();
    j["kind"] = to_string(e.kind);
    if (e.kind != ElementKind::Effect) j["cause"] = e.cause;
    if (e.kind != ElementKind::Cause) j["effect"] = e.effect;
    if (!e.name.empty()) j["name"] = e.name;
    j["status"] = to_string(e.status);
    j["steps_ok"] = e.steps_ok;
    j["steps_deviation"] = e.steps_deviation;
    j["steps_open"] = e.steps_open;
    if (!e.deviations.empty()) j["deviations"] = e.deviations;
    if (!e.carried_over.empty()) j["carried_over"] = e.carried_over;
    je.push_back(j);
  }
  doc["elements"] = je;
  return doc.dump(1) + "\n";
}

Acceptance read_acceptance(std::string_view text, const std::string& file) {
  std::vector<LoadIssue> issues;
  JsonLimits limits;
  limits.document = "acceptance record";
  limits.max_members = 4096;
  auto doc = parse_guarded_json(text, file, issues, limits);
  if (!doc) throw LoadError(issues);
  auto fail = [&](const std::string& where, const std::string& what) {
    std::vector<LoadIssue> v{{where, what}};
    locate_issues(text, file, v);
    throw LoadError(v);
  };
  if (!doc->is_object() || !doc->contains("format") || (*doc)["format"] != kAcceptanceFormat)
    fail("format", std::string("not an acceptance record: expected \"format\": \"") + kAcceptanceFormat + "\"");
  Acceptance a;
  try {
    a.matrix = doc->value("matrix", "");
    a.signature = doc->value("signature", "");
    a.tool = doc->value("tool", "");
    if (doc->contains("checklists")) a.checklists = (*doc)["checklists"].get<std::vector<std::string>>();
    const auto& els = doc->at("elements");
    for (std::size_t i = 0; i < els.size(); ++i) {
      const auto& j = els[i];
      ElementAcceptance e;
      const std::string kind = j.at("kind").get<std::string>(), status = j.at("status").get<std::string>();
      if (kind == "cause") e.kind = ElementKind::Cause;
      else if (kind == "effect") e.kind = ElementKind::Effect;
      else if (kind == "intersection") e.kind = ElementKind::Intersection;
      else fail(element_path("elements", i) + ".kind", "unknown kind \"" + kind + "\" (cause, effect, intersection)");
      if (status == "accepted") e.status = AcceptanceStatus::Accepted;
      else if (status == "deviation") e.status = AcceptanceStatus::Deviation;
      else if (status == "not-tested") e.status = AcceptanceStatus::NotTested;
      else fail(element_path("elements", i) + ".status", "unknown status \"" + status + "\" (accepted, deviation, not-tested)");
      e.cause = j.value("cause", 0);
      e.effect = j.value("effect", 0);
      e.name = j.value("name", "");
      e.steps_ok = j.value("steps_ok", 0);
      e.steps_deviation = j.value("steps_deviation", 0);
      e.steps_open = j.value("steps_open", 0);
      if (j.contains("deviations")) e.deviations = j["deviations"].get<std::vector<std::string>>();
      e.carried_over = j.value("carried_over", "");
      a.elements.push_back(std::move(e));
    }
    if (doc->contains("steps"))
      for (const auto& j : (*doc)["steps"]) {
        StepAcceptance s;
        s.test = j.at("test").get<std::string>();
        s.step = j.at("step").get<int>();
        s.phase = j.value("phase", "");
        const std::string st = j.value("status", "open");
        s.status = st == "ok" ? StepStatus::Ok : st == "deviation" ? StepStatus::Deviation : StepStatus::Open;
        if (j.contains("records"))
          for (const auto& r : j["records"])
            s.records.push_back({r.value("result", ""), r.value("initials", ""), r.value("date", ""), r.value("file", ""),
                                 r.value("line", 0)});
        if (j.contains("objectives")) s.objectives = j["objectives"].get<std::vector<std::string>>();
        a.steps.push_back(std::move(s));
      }
  } catch (const nlohmann::json::exception& e) {
    fail("elements", std::string("malformed acceptance record: ") + e.what());
  }
  return a;
}

}  // namespace cemv::formats
