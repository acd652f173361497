#include "defeats/ask.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "checker/check.hpp"
#include "formats/diagnostics.hpp"
#include "properties/parser.hpp"
#include "response/property.hpp"

namespace cemv::defeats {

std::string set_name(const PathDefeats& pd, const std::vector<int>& s) {
  std::string n = "defeat." + pd.path.key() + ".";
  if (s.empty()) return n + "none";
  n += "a";
  for (std::size_t i = 0; i < s.size(); ++i) n += (i ? "_" : "") + std::to_string(s[i] + 1);
  return n;
}

namespace {

properties::PropertyFile parse_question(const model::Matrix& m, const PathDefeats& pd, const std::vector<int>& s,
                                        const std::string& property) {
  std::vector<std::string> excluded;
  for (std::size_t i = 0; i < pd.actions.size(); ++i)
    if (!std::binary_search(s.begin(), s.end(), static_cast<int>(i)))
      excluded.push_back(pd.actions[i].excluded_term());
  const std::string text = response::requirement_property_text(m, pd.path, *pd.requirement, property, excluded);
  try {
    return properties::parse_properties(text, m, "cemv-defeats:" + property);
  } catch (const formats::LoadError& e) {
    std::string what;
    for (const auto& i : e.issues()) what += "\n" + i.str();
    throw std::logic_error("cemv defeats wrote a property the parser refuses:" + what + "\n" + text);
  }
}

}  // namespace

Question ask_checker(const model::Matrix& m, const PathDefeats& pd, const std::vector<int>& s,
                     const std::string& property, bool group, bool write, const std::vector<Run>& demand_runs,
                     const AskOptions& o) {
  Question q;
  q.actions = s;
  q.property = property;
  const properties::PropertyFile file = parse_question(m, pd, s, property);
  checker::CheckOptions options;
  options.property_timeout_s = o.timeout_s;
  options.cancel = o.cancel;
  options.jobs = 1;
  options.out_dir = write ? o.out_dir : "";
  options.support = false;
  options.budgets.engine = o.work;
  // The demand with the set's actions taken: most defeats shown by one run
  // of the runtime; the runs also witness that a demand can occur (vacuity).
  options.directed_runs = defeat_runs(m, pd.path, pd.actions, s, demand_runs);
  options.localize_to = pd.path.elements;
  // A question no directed run falsifies usually holds: the engines of a
  // proof first, as cemv response asks for a bound it expects to hold
  // (invariants+induction, k-induction, BMC; PDR and BMC on a wide cone);
  // left open, the whole portfolio. A group gets the proof engines alone,
  // within a quarter of the budget: a group not proved is split anyway.
  options.engines = {checker::Method::InvariantsInduction, checker::Method::KInduction, checker::Method::Bmc};
  options.engines_when_wide = {checker::Method::Pdr, checker::Method::Bmc};
  if (group) {
    options.engines.pop_back();
    options.engines_when_wide.pop_back();
    options.budgets.engine = o.work / 4;
  }
  checker::CheckResult r = checker::check_properties(m, {file}, options);
  if (r.properties.at(0).verdict == checker::PropertyVerdict::Unknown && !group &&
      !(o.cancel && o.cancel->cancelled())) {
    options.engines.clear();
    options.engines_when_wide.clear();
    options.localize_to.clear();
    r = checker::check_properties(m, {file}, options);
  }
  const checker::PropertyResult& pr = r.properties.at(0);
  q.verdict = pr.verdict;
  q.method = pr.method;
  q.reason = pr.reason;
  q.work = pr.work;
  q.violation_cycle = pr.violation_cycle;
  if (!pr.scenario_file.empty()) q.scenario = std::filesystem::path(pr.scenario_file).filename().string();
  if (!write) q.scenario.clear();
  return q;
}

void finish_path(PathDefeats& pd, bool complete, std::string reason, bool cancelled) {
  if (cancelled) {
    complete = false;
    if (reason.empty()) reason = checker::to_string(checker::UnknownReason::TimeLimit);
  }
  pd.status = complete ? PathStatus::Complete : PathStatus::Unknown;
  pd.reason = std::move(reason);
  std::stable_sort(pd.sets.begin(), pd.sets.end(), [](const DefeatSet& a, const DefeatSet& b) {
    return a.actions.size() != b.actions.size() ? a.actions.size() < b.actions.size() : a.actions < b.actions;
  });
  for (const auto& d : pd.sets)
    if (d.set_class == SetClass::Indirect) {
      pd.distance = static_cast<int>(d.actions.size());
      break;
    }
}

}  // namespace cemv::defeats
