#include "cli/explain_trace.hpp"

#include <map>
#include <stdexcept>

#include "model/text.hpp"
#include "model/vocabulary.hpp"
#include "properties/print.hpp"
#include "runtime/runtime.hpp"

namespace cemv::cli {

namespace {

std::string value_text(const model::Observable& o, int v) {
  if (o.type == model::FieldType::Voting) return model::to_string(static_cast<model::Voting>(v));
  return std::to_string(v);
}

std::string input_text(const model::InputTag& t, const model::TagValue& v) {
  std::string s = t.kind == model::TagKind::Analog ? model::float_text(v.value) : (v.value != 0.0f ? "1" : "0");
  return v.bad_quality ? s + " (bad quality)" : s;
}

}  // namespace

std::vector<checker::StepNote> explain_trace(const model::Matrix& m, const checker::ConcreteTrace& t,
                                             const std::vector<std::string>& observables,
                                             const std::vector<std::size_t>& inputs) {
  const auto all = model::observables(m);
  std::map<std::size_t, bool> wanted;  // observable index -> read by the property
  for (const auto& key : observables)
    for (std::size_t i = 0; i < all.size(); ++i)
      if (all[i].key == key) wanted[i] = true;
  runtime::Runtime rt(m);
  const model::InputTable& table = rt.inputs();
  rt.explain(true);
  std::vector<checker::StepNote> steps;
  std::vector<int> snapshot;
  for (std::size_t k = 0; k < t.inputs.size(); ++k) {
    const model::CycleInput& in = t.inputs[k];
    const int cycle = static_cast<int>(k) + 1;
    for (std::size_t i : inputs) {
      if (i >= table.size()) continue;
      const model::TagValue now = in.tags[i];
      const model::TagValue was = k == 0 ? model::TagValue{} : t.inputs[k - 1].tags[i];
      if (k > 0 && now.value == was.value && now.bad_quality == was.bad_quality) continue;
      if (k == 0 && now.value == 0.0f && !now.bad_quality) continue;
      steps.push_back({cycle, table.tags()[i].name, k == 0 ? "" : input_text(table.tags()[i], was),
                       input_text(table.tags()[i], now), "an input of the run (the plant or the operator's switch)"});
    }
    rt.step(in);
    rt.snapshot(snapshot);
    if (k < t.observables.size() && snapshot != t.observables[k])
      throw std::logic_error("the runtime does not reproduce the trace in cycle " + std::to_string(cycle) +
                             " when it runs it again with explanations");
    for (const auto& e : rt.explanations())
      if (wanted.count(e.observable))
        steps.push_back({cycle, all[e.observable].key, value_text(all[e.observable], e.before),
                         value_text(all[e.observable], e.after), e.why});
  }
  return steps;
}

void explain_results(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                     checker::CheckResult& r) {
  for (auto& p : r.properties) {
    if (!p.trace) continue;
    for (const auto& f : files) {
      if (f.file_name != p.file) continue;  // names are unique across the files (check_distinct_names)
      for (const auto& prop : f.properties) {
        if (prop.name != p.name) continue;
        const properties::Signals s = properties::signals_of(prop, f.assumptions);
        p.explanation = explain_trace(m, *p.trace, s.observables, s.inputs);
      }
    }
  }
}

}  // namespace cemv::cli
