// `cemv record` (docs/acceptance.md): filled field checklists back into the
// matrix's acceptance status. A step is a deviation when any checklist
// records a deviation for it, ok when one records OK, open otherwise; an
// element (cause, effect, intersection) is a deviation when a step that
// witnesses one of its objectives is, accepted when every objective of it
// that the field suite witnesses is witnessed by an ok step, not-tested
// otherwise.
#include <cstdio>
#include <map>
#include <set>

#include "formats/diagnostics.hpp"
#include "testgen/field.hpp"

namespace cemv::testgen {

namespace {

formats::LoadIssue at_line(const std::string& file, int line, std::string what) {
  formats::LoadIssue i;
  i.file = file;
  i.line = static_cast<std::size_t>(line);
  i.what = std::move(what);
  return i;
}

// The element an objective is about: its intersection for `intersection.cI.eJ.*`.
std::string element_of(const Objective& o) {
  int c = 0, e = 0;
  if (std::sscanf(o.id.c_str(), "intersection.c%d.e%d.", &c, &e) == 2)
    return "intersection cause[" + std::to_string(c) + "]/effect[" + std::to_string(e) + "]";
  return model::to_string(o.element);
}

}  // namespace

formats::Acceptance record_acceptance(const model::Matrix& m, const FieldSuite& s,
                                      const std::vector<formats::FilledChecklist>& filled, const std::string& tool) {
  formats::Acceptance a;
  a.matrix = m.name;
  a.signature = s.signature;
  a.tool = tool;
  std::map<std::pair<std::string, int>, std::size_t> index;
  std::map<std::pair<std::string, int>, const FieldTestStep*> steps;
  for (const auto& t : s.tests)
    for (const auto& st : t.steps) {
      index[{t.id, st.number}] = a.steps.size();
      steps[{t.id, st.number}] = &st;
      formats::StepAcceptance sa;
      sa.test = t.id;
      sa.step = st.number;
      sa.phase = st.phase;
      sa.objectives = st.objectives;
      sa.objectives.insert(sa.objectives.end(), st.again.begin(), st.again.end());
      a.steps.push_back(std::move(sa));
    }
  std::vector<formats::LoadIssue> issues;
  for (const auto& c : filled) {
    a.checklists.push_back(c.file);
    if (c.signature != s.signature) {
      issues.push_back(at_line(c.file, c.signature_line,
                               "the checklist is for the matrix with signature " + c.signature + ", not " + m.name +
                                   " with signature " + s.signature + " (a checklist of another version)"));
      continue;
    }
    if (c.resolution != s.resolution)
      issues.push_back(at_line(c.file, 1, "the checklists differ in their resolution (record them one resolution at a time)"));
    for (const auto& r : c.rows) {
      auto it = index.find({r.test, r.step});
      if (it == index.end()) {
        issues.push_back(at_line(c.file, r.line, "the field suite of " + m.name + " has no step " + r.test + " / " +
                                                     std::to_string(r.step)));
        continue;
      }
      std::string want;
      for (const auto& x : steps.at({r.test, r.step})->actions) want += (want.empty() ? "" : "\n") + x;
      if (r.action != want) {
        issues.push_back(at_line(c.file, r.line, r.test + " step " + std::to_string(r.step) +
                                                     ": the action is not the one this matrix's field suite gives "
                                                     "(a checklist of another cemv version or edited): regenerate it"));
        continue;
      }
      if (r.result.empty()) continue;
      formats::StepAcceptance& sa = a.steps[it->second];
      sa.records.push_back({r.result, r.initials, r.date, c.file, r.line});
      if (r.result != "OK") sa.status = formats::StepStatus::Deviation;
      else if (sa.status == formats::StepStatus::Open) sa.status = formats::StepStatus::Ok;
    }
  }
  if (!issues.empty()) throw formats::LoadError(issues);

  // Elements: processed causes, effects, intersections.
  std::map<std::string, formats::ElementAcceptance> elements;
  std::vector<std::string> order;
  auto add = [&](formats::ElementKind kind, int cause, int effect, const std::string& name) {
    formats::ElementAcceptance e;
    e.kind = kind;
    e.cause = cause;
    e.effect = effect;
    e.name = name;
    order.push_back(e.key());
    elements[e.key()] = std::move(e);
  };
  for (const auto& c : m.causes)
    if (c.function != model::CauseFunction::Comment) add(formats::ElementKind::Cause, c.id, 0, c.name);
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment) add(formats::ElementKind::Effect, 0, e.id, e.name);
  for (const auto& i : m.intersections)
    if (model::is_processed(i.type) && elements.count("cause[" + std::to_string(i.cause) + "]") &&
        elements.count("effect[" + std::to_string(i.effect) + "]"))
      add(formats::ElementKind::Intersection, i.cause, i.effect, "");
  // Each objective's witnessing steps (first and again), each element's objectives and steps.
  std::map<std::string, std::set<std::size_t>> by_objective;
  for (const auto& t : s.tests)
    for (const auto& st : t.steps) {
      const std::size_t i = index.at({t.id, st.number});
      for (const auto& id : st.objectives) by_objective[id].insert(i);
      for (const auto& id : st.again) by_objective[id].insert(i);
    }
  std::map<std::string, std::set<std::size_t>> witnessing;
  std::map<std::string, int> objectives, shown;  // per element: field objectives, those an ok step witnesses
  for (const auto& o : s.objectives) {
    if (o.test < 0) continue;
    const std::string key = element_of(o.objective);
    const auto& at = by_objective[o.objective.id];
    witnessing[key].insert(at.begin(), at.end());
    ++objectives[key];
    for (std::size_t i : at)
      if (a.steps[i].status == formats::StepStatus::Ok) {
        ++shown[key];
        break;
      }
  }
  for (auto& [key, e] : elements) {
    for (std::size_t i : witnessing[key]) {
      const auto& sa = a.steps[i];
      if (sa.status == formats::StepStatus::Ok) ++e.steps_ok;
      else if (sa.status == formats::StepStatus::Open) ++e.steps_open;
      else {
        ++e.steps_deviation;
        for (const auto& r : sa.records)
          if (r.result != "OK")
            e.deviations.push_back(sa.test + " step " + std::to_string(sa.step) + ": " + r.result + " (" + r.initials +
                                   ", " + r.date + ")");
      }
    }
    e.status = e.steps_deviation                                ? formats::AcceptanceStatus::Deviation
               : objectives[key] > 0 && shown[key] == objectives[key] ? formats::AcceptanceStatus::Accepted
                                                                 : formats::AcceptanceStatus::NotTested;
  }
  for (const auto& k : order) a.elements.push_back(elements.at(k));
  return a;
}

}  // namespace cemv::testgen
