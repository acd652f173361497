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

using StepKey = std::pair<std::string, int>;  // test id, step number

// The acceptance status of one matrix version from its filled checklists:
// the steps first, then the elements they witness.
class AcceptanceRecorder {
 public:
  AcceptanceRecorder(const model::Matrix& m, const FieldSuite& s, const std::string& tool) : m_(m), s_(s) {
    a_.matrix = m.name;
    a_.signature = s.signature;
    a_.tool = tool;
  }

  formats::Acceptance record(const std::vector<formats::FilledChecklist>& filled) {
    list_steps();
    std::vector<formats::LoadIssue> issues;
    for (const auto& c : filled) read_checklist(c, issues);
    if (!issues.empty()) throw formats::LoadError(issues);
    list_elements();
    judge_elements();
    return std::move(a_);
  }

 private:
  // Every step of the field suite, open, with the objectives it witnesses.
  void list_steps() {
    for (const auto& t : s_.tests)
      for (const auto& st : t.steps) {
        index_[{t.id, st.number}] = a_.steps.size();
        steps_[{t.id, st.number}] = &st;
        formats::StepAcceptance sa;
        sa.test = t.id;
        sa.step = st.number;
        sa.phase = st.phase;
        sa.objectives = st.objectives;
        sa.objectives.insert(sa.objectives.end(), st.again.begin(), st.again.end());
        a_.steps.push_back(std::move(sa));
      }
  }

  // One filled checklist: of this version, its rows the suite's steps with
  // their actions unchanged; each result recorded on its step.
  void read_checklist(const formats::FilledChecklist& c, std::vector<formats::LoadIssue>& issues) {
    a_.checklists.push_back(c.file);
    if (c.signature != s_.signature) {
      issues.push_back(at_line(c.file, c.signature_line,
                               "the checklist is for the matrix with signature " + c.signature + ", not " + m_.name +
                                   " with signature " + s_.signature + " (a checklist of another version)"));
      return;
    }
    if (c.resolution != s_.resolution)
      issues.push_back(at_line(c.file, 1, "the checklists differ in their resolution (record them one resolution at a time)"));
    for (const auto& r : c.rows) {
      auto it = index_.find({r.test, r.step});
      if (it == index_.end()) {
        issues.push_back(at_line(c.file, r.line, "the field suite of " + m_.name + " has no step " + r.test + " / " +
                                                     std::to_string(r.step)));
        continue;
      }
      std::string want;
      for (const auto& x : steps_.at({r.test, r.step})->actions) want += (want.empty() ? "" : "\n") + x;
      if (r.action != want) {
        issues.push_back(at_line(c.file, r.line, r.test + " step " + std::to_string(r.step) +
                                                     ": the action is not the one this matrix's field suite gives "
                                                     "(a checklist of another cemv version or edited): regenerate it"));
        continue;
      }
      if (r.result.empty()) continue;
      formats::StepAcceptance& sa = a_.steps[it->second];
      sa.records.push_back({r.result, r.initials, r.date, c.file, r.line});
      if (r.result != "OK") sa.status = formats::StepStatus::Deviation;
      else if (sa.status == formats::StepStatus::Open) sa.status = formats::StepStatus::Ok;
    }
  }

  // Elements: processed causes, effects, intersections, in the matrix's order.
  void list_elements() {
    auto add = [&](formats::ElementKind kind, int cause, int effect, const std::string& name) {
      formats::ElementAcceptance e;
      e.kind = kind;
      e.cause = cause;
      e.effect = effect;
      e.name = name;
      order_.push_back(e.key());
      elements_[e.key()] = std::move(e);
    };
    for (const auto& c : m_.causes)
      if (c.function != model::CauseFunction::Comment) add(formats::ElementKind::Cause, c.id, 0, c.name);
    for (const auto& e : m_.effects)
      if (e.function != model::EffectFunction::Comment) add(formats::ElementKind::Effect, 0, e.id, e.name);
    for (const auto& i : m_.intersections)
      if (model::is_processed(i.type) && elements_.count("cause[" + std::to_string(i.cause) + "]") &&
          elements_.count("effect[" + std::to_string(i.effect) + "]"))
        add(formats::ElementKind::Intersection, i.cause, i.effect, "");
  }

  // Each objective's witnessing steps (first and again).
  std::map<std::string, std::set<std::size_t>> steps_by_objective() const {
    std::map<std::string, std::set<std::size_t>> by_objective;
    for (const auto& t : s_.tests)
      for (const auto& st : t.steps) {
        const std::size_t i = index_.at({t.id, st.number});
        for (const auto& id : st.objectives) by_objective[id].insert(i);
        for (const auto& id : st.again) by_objective[id].insert(i);
      }
    return by_objective;
  }

  // A deviation when a witnessing step is one; accepted when an ok step
  // witnesses every field objective of the element; not tested otherwise.
  void judge_elements() {
    const auto by_objective = steps_by_objective();
    std::map<std::string, std::set<std::size_t>> witnessing;
    std::map<std::string, int> objectives, shown;  // per element: field objectives, those an ok step witnesses
    for (const auto& o : s_.objectives) {
      if (o.test < 0) continue;
      const std::string key = element_of(o.objective);
      const auto found = by_objective.find(o.objective.id);
      const std::set<std::size_t> none;
      const auto& at = found == by_objective.end() ? none : found->second;
      witnessing[key].insert(at.begin(), at.end());
      ++objectives[key];
      for (std::size_t i : at)
        if (a_.steps[i].status == formats::StepStatus::Ok) {
          ++shown[key];
          break;
        }
    }
    for (auto& [key, e] : elements_) {
      count_steps(e, witnessing[key]);
      e.status = e.steps_deviation                                  ? formats::AcceptanceStatus::Deviation
                 : objectives[key] > 0 && shown[key] == objectives[key] ? formats::AcceptanceStatus::Accepted
                                                                   : formats::AcceptanceStatus::NotTested;
    }
    for (const auto& k : order_) a_.elements.push_back(elements_.at(k));
  }

  void count_steps(formats::ElementAcceptance& e, const std::set<std::size_t>& witnessing) const {
    for (std::size_t i : witnessing) {
      const auto& sa = a_.steps[i];
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
  }

  const model::Matrix& m_;
  const FieldSuite& s_;
  formats::Acceptance a_;
  std::map<StepKey, std::size_t> index_;
  std::map<StepKey, const FieldTestStep*> steps_;
  std::map<std::string, formats::ElementAcceptance> elements_;
  std::vector<std::string> order_;
};

}  // namespace

formats::Acceptance record_acceptance(const model::Matrix& m, const FieldSuite& s,
                                      const std::vector<formats::FilledChecklist>& filled, const std::string& tool) {
  return AcceptanceRecorder(m, s, tool).record(filled);
}

}  // namespace cemv::testgen
