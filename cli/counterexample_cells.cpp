#include "cli/counterexample_cells.hpp"

#include <algorithm>

#include "model/graph.hpp"
#include "model/validate.hpp"
#include "model/vocabulary.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "runtime/runtime.hpp"

namespace cemv::cli {

namespace {

// Scan cycles all replays of one counterexample may take together, and the
// cells tried: beyond either, no support is given (the property's elements
// stand in for it in SARIF).
constexpr std::size_t kReplayBudget = 500000;
constexpr std::size_t kMaxCells = 256;

const properties::Property* find_property(const properties::PropertyFile& f, const std::string& name) {
  for (const auto& p : f.properties)
    if (p.name == name) return &p;
  return nullptr;
}

// Whether `edited` reads the same input tags and shows the same observables
// as `m`, so that a run of `m` (tags by InputTable index) and the property
// (resolved against `m`) mean the same there.
bool same_interface(const model::Matrix& m, const model::Matrix& edited) {
  const model::InputTable a(m), b(edited);
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.tags()[i].name != b.tags()[i].name) return false;
  const auto oa = model::observables(m), ob = model::observables(edited);
  if (oa.size() != ob.size()) return false;
  for (std::size_t i = 0; i < oa.size(); ++i)
    if (oa[i].key != ob[i].key) return false;
  return true;
}

}  // namespace

std::optional<int> judged_cycle(const model::Matrix& m, const properties::PropertyFile& f,
                                const properties::Property& p, const std::vector<model::CycleInput>& inputs,
                                std::vector<std::vector<int>>* observables) {
  runtime::Runtime rt(m);
  properties::Trace trace;
  trace.reserve(inputs.size());
  for (const auto& in : inputs) {
    rt.step(in);
    properties::TraceCycle cycle{in, {}};
    rt.snapshot(cycle.observables);
    trace.push_back(std::move(cycle));
  }
  properties::Evaluation ev = properties::Evaluator(m).evaluate(p, f.assumptions, trace);
  if (observables) {
    observables->clear();
    for (auto& c : trace) observables->push_back(std::move(c.observables));
  }
  const bool found = p.kind == properties::PropertyKind::Reachable ? ev.holds : !ev.holds;
  if (!found || !ev.cycle) return std::nullopt;
  return static_cast<int>(*ev.cycle);
}

bool confirms(const model::Matrix& m, const properties::PropertyFile& f, const properties::Property& p,
              const checker::PropertyResult& r) {
  if (!r.trace || r.violation_cycle < 0) return false;
  std::vector<std::vector<int>> run;
  auto cycle = judged_cycle(m, f, p, r.trace->inputs, &run);
  return cycle && *cycle == r.violation_cycle && run == r.trace->observables;
}

std::vector<std::string> counterexample_cells(const model::Matrix& m, const properties::PropertyFile& f,
                                              const properties::Property& p, const checker::ConcreteTrace& trace) {
  if (p.kind == properties::PropertyKind::Reachable || trace.inputs.empty()) return {};
  const auto cone = model::DependencyGraph(m).feeders_of(properties::property_roots(p, f.assumptions, m));
  auto in_cone = [&](int effect) {
    return std::any_of(cone.begin(), cone.end(), [&](const model::Node& n) {
      return n.kind == model::Node::Kind::Effect && n.id == effect;
    });
  };
  std::vector<std::string> cells;
  std::size_t spent = 0, tried = 0;
  for (std::size_t i = 0; i < m.intersections.size(); ++i) {
    const model::Intersection& x = m.intersections[i];
    if (!in_cone(x.effect)) continue;
    spent += trace.inputs.size();
    if (spent > kReplayBudget || ++tried > kMaxCells) return {};
    model::Matrix edited = m;
    edited.intersections.erase(edited.intersections.begin() + static_cast<std::ptrdiff_t>(i));
    if (model::has_errors(model::validate(edited)) || !same_interface(m, edited)) continue;
    if (!judged_cycle(edited, f, p, trace.inputs))
      cells.push_back("intersection[" + std::to_string(x.cause) + "," + std::to_string(x.effect) + "]");
  }
  return cells;
}

void add_counterexample_cells(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                              checker::CheckResult& r) {
  for (auto& result : r.properties) {
    if (result.verdict != checker::PropertyVerdict::Falsified || !result.trace) continue;
    for (const auto& f : files) {
      if (f.file_name != result.file) continue;
      if (const properties::Property* p = find_property(f, result.name))
        result.counterexample_support = counterexample_cells(m, f, *p, *result.trace);
    }
  }
}

}  // namespace cemv::cli
