// The field suite (docs/testgen.md, "Field suite"): one loop test per cause
// and per XooN group (field_loop.*), sorted by SIF group and cause; which
// objectives each step witnesses; every test replayed green.
#include "testgen/field.hpp"

#include <algorithm>
#include <map>
#include <cctype>
#include <set>

#include "checker/prover.hpp"
#include "checker/replay.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "properties/evaluator.hpp"
#include "testgen/field_loop.hpp"
#include "testgen/field_words.hpp"

namespace cemv::testgen {

using namespace detail;
using field_detail::LoopPlan;

std::size_t FieldSuite::witnessed() const {
  std::size_t n = 0;
  for (const auto& o : objectives) n += o.test >= 0;
  return n;
}

namespace {

bool external(const model::Cause& c) {
  for (const auto& t : c.tags)
    if (model::parse_internal_ref(t.name)) return false;
  return !c.tags.empty();
}

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.substr(0, 40);
}

// Why an objective the field tests do not witness stays automated.
std::string automated_reason(const Objective& o, bool witnessed_elsewhere) {
  const std::string& k = o.kind;
  if (o.id.find(".before") != std::string::npos || k == "timer")
    return "needs the cycle before or at a timer's expiry: sub-second resolution";
  if (k == "limit" || k == "hysteresis")
    return "needs the exact limit or hysteresis threshold and the next float: below a calibrator's resolution";
  if (k == "reference" || o.simulates) return "forces an output by simulation: not a field action";
  if (k == "bad-quality") return "the loop tests disconnect the first tag of a cause only";
  if (witnessed_elsewhere) return "reached only at a cycle no technician observes (between checkpoints)";
  return "no loop test (trip one cause, release, acknowledge, reset) reaches it: " + k +
         " needs a combination of causes, an operator maintenance command or timing beyond one loop";
}

bool field_kind(const Objective& o) {
  return !(o.id.find(".before") != std::string::npos || o.kind == "timer" || o.kind == "limit" ||
           o.kind == "hysteresis" || o.kind == "reference" || o.simulates);
}

// One loop per processed cause whose inputs are tags, one per XooN group (the
// first X causes of an effect's XooN cells), sorted by first SIF group (none
// last), then first cause, then size.
std::vector<LoopPlan> plan_loops(const model::Matrix& m, FieldSuite& s) {
  std::vector<LoopPlan> plans;
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    if (!external(c)) {
      s.untested.push_back(cause_name(m, c.id) + ": its inputs are internal references; it trips with the loops that "
                                                  "drive them");
      continue;
    }
    plans.push_back({c.sif.empty() ? 0 : c.sif.front(), {c.id}, 0, 0});
  }
  std::set<std::vector<int>> groups;
  for (const auto& e : m.effects) {
    std::vector<int> causes;
    int x = 0;
    for (const auto* i : m.intersections_of_effect(e.id))
      if (model::is_processed(i->type) && i->xoon && external(*m.find_cause(i->cause))) {
        causes.push_back(i->cause);
        x = *i->xoon;
      }
    if (x < 2 || static_cast<int>(causes.size()) < x) continue;
    causes.resize(static_cast<std::size_t>(x));
    if (!groups.insert(causes).second) continue;
    plans.push_back({e.sif.empty() ? 0 : e.sif.front(), causes, e.id, x});
  }
  auto rank = [](int sif) { return sif == 0 ? 1 << 30 : sif; };
  std::stable_sort(plans.begin(), plans.end(), [&](const LoopPlan& a, const LoopPlan& b) {
    return std::make_tuple(rank(a.sif), a.causes.front(), a.causes.size()) <
           std::make_tuple(rank(b.sif), b.causes.front(), b.causes.size());
  });
  return plans;
}

// F001, its title and its file name.
void name_test(const model::Matrix& m, const LoopPlan& p, std::size_t number, FieldTest& t) {
  char id[16];
  std::snprintf(id, sizeof id, "F%03zu", number);
  t.id = id;
  if (p.xoon_effect) {
    std::string list;
    for (int c : p.causes) list += (list.empty() ? "" : ", ") + std::to_string(c);
    t.title = std::string("XooN: causes ") + list + " together trip " + effect_name(m, p.xoon_effect) + " (" +
              std::to_string(p.xoon) + " needed)";
    t.file_name = t.id + "-xoon-effect-" + std::to_string(p.xoon_effect) + ".scenario.json";
  } else {
    const model::Cause& c = *m.find_cause(p.causes.front());
    t.title = "Cause " + std::to_string(c.id) + " " + c.name + (c.description.empty() ? "" : ": " + c.description);
    t.file_name = t.id + "-cause-" + std::to_string(c.id) + "-" + slug(c.name) + ".scenario.json";
  }
}

bool cancelled(const FieldOptions& o) { return o.cancel && o.cancel->cancelled(); }

// What a loop the time limit left unbuilt would have tested.
std::string unbuilt(const model::Matrix& m, const LoopPlan& p) {
  const std::string what = p.xoon_effect ? "XooN group of " + effect_name(m, p.xoon_effect)
                                         : cause_name(m, p.causes.front());
  return what + ": not built, the time limit (--total-timeout) ended the field suite first";
}

// Which objectives each step witnesses (the concrete evaluator on each
// test's run); an objective no step witnesses stays automated, with why.
void place_objectives(const model::Matrix& m, const FieldOptions& o, FieldSuite& s) {
  std::vector<Objective> all = derive_objectives(m);
  const properties::PropertyFile file = objectives_file(all);
  properties::Evaluator ev(m);
  for (auto& ob : all) s.objectives.push_back({std::move(ob), -1, 0, ""});
  std::vector<bool> elsewhere(s.objectives.size(), false);
  for (std::size_t ti = 0; ti < s.tests.size(); ++ti) {
    if (cancelled(o)) {
      s.interrupted = true;
      break;
    }
    FieldTest& t = s.tests[ti];
    const checker::ConcreteTrace run = checker::run_on_runtime(m, t.inputs);
    properties::Trace trace;
    for (std::size_t k = 0; k < run.inputs.size(); ++k) trace.push_back({run.inputs[k], run.observables[k]});
    for (std::size_t i = 0; i < s.objectives.size(); ++i) {
      FieldObjective& fo = s.objectives[i];
      if (!field_kind(fo.objective)) continue;
      auto e = ev.evaluate(file.properties[i], file.assumptions, trace);
      if (!e.holds || !e.cycle) continue;
      bool placed = false;
      for (auto& st : t.steps)
        if (*e.cycle >= st.first_cycle && *e.cycle <= st.last_cycle) {
          placed = true;
          if (fo.test >= 0) {
            st.again.push_back(fo.objective.id);
            continue;
          }
          fo.test = static_cast<int>(ti);
          fo.step = st.number;
          st.objectives.push_back(fo.objective.id);
        }
      if (!placed) elsewhere[i] = true;
    }
  }
  for (std::size_t i = 0; i < s.objectives.size(); ++i)
    if (s.objectives[i].test < 0)
      s.objectives[i].reason = s.interrupted ? "not decided: the time limit (--total-timeout) ended the field suite first"
                                             : automated_reason(s.objectives[i].objective, elsewhere[i]);
}

// Never an unchecked answer: every test as written replays green.
void replay_green(const model::Matrix& m, const FieldSuite& s) {
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& t : s.tests) texts.push_back({t.file_name, t.scenario_json});
  const ReplayResult replay = replay_texts(m, texts);
  for (const auto& t : replay.tests)
    if (!t.passed) {
      std::string why = t.load_error;
      for (const auto& st : t.steps)
        if (why.empty() && !st.failures.empty()) why = st.failures.front();
      throw checker::InternalError("field test " + t.name + " does not replay green: " + why);
    }
}

}  // namespace

FieldSuite generate_field_suite(const model::Matrix& m, const FieldOptions& o) {
  if (!(o.resolution > 0.0) || o.resolution > 1000.0) throw std::invalid_argument("--resolution must be in (0, 1000]");
  FieldSuite s;
  s.matrix_name = m.name;
  s.signature = formats::signature(m);
  s.resolution = o.resolution;
  for (const auto& p : plan_loops(m, s)) {
    if (s.interrupted || cancelled(o)) {
      s.interrupted = true;
      s.untested.push_back(unbuilt(m, p));
      continue;
    }
    FieldTest t = field_detail::build_loop(m, o, p);
    name_test(m, p, s.tests.size() + 1, t);
    s.field_s += t.field_s;
    s.tests.push_back(std::move(t));
  }
  place_objectives(m, o, s);
  replay_green(m, s);
  return s;
}

}  // namespace cemv::testgen
