#include "testgen/scenario_writer.hpp"

#include <map>
#include <set>

#include "formats/scenario_writer.hpp"
#include "model/text.hpp"
#include "runtime/runtime.hpp"
#include "testgen/phrases.hpp"

namespace cemv::testgen::detail {

std::size_t count_steps(const std::vector<model::CycleInput>& inputs, const std::vector<std::size_t>& checkpoints) {
  return formats::step_lengths(inputs, checkpoints).size();
}

std::vector<model::Observable> field_observables(const model::Matrix& m) {
  std::vector<model::Observable> out;
  for (const auto& o : model::observables(m)) {
    bool keep = false;
    if (o.kind == model::Node::Kind::Cause) {
      const model::Cause& c = *m.find_cause(o.id);
      const bool latch = !c.auto_ack && (c.time.mode == model::TimeMode::None || c.time.mode == model::TimeMode::OnDelay);
      const bool analog = c.input == model::InputKind::Analog && c.analog;
      keep = o.field == "active" || o.field == "trip_requested" || (o.field == "ack_required" && latch) ||
             (o.field == "first_out" && c.first_out_group > 0) ||
             (o.field == "prewarning" && analog && c.analog->prewarning) ||
             (o.field == "delta_alarm" && analog && c.analog->delta > 0.0f && c.tags.size() >= 2) ||
             (o.field == "bypassed" && (c.bypass_tag || c.soft_bypass.allowed)) ||
             (o.field == "inhibited" && c.inhibit_tag) ||
             ((o.field == "bypass_timeout" || o.field == "bypass_prealarm") && c.soft_bypass.allowed && c.soft_bypass.max_s > 0);
    } else {
      const model::Effect& e = *m.find_effect(o.id);
      keep = o.field == "active" || o.field == "tag" || o.field == "latched" ||
             ((o.field == "override_active" || o.field == "override_failed_timeout" ||
               o.field == "override_failed_cause" || o.field == "override_prealarm") && e.override_time) ||
             (o.field == "bypassed" && (e.bypass_tag || e.soft_bypass_allowed)) ||
             (o.field == "output_delay_running" && e.output_delay_ms > 0);
    }
    if (keep) out.push_back(o);
  }
  return out;
}

std::map<std::size_t, std::vector<int>> snapshots_at(const model::Matrix& m, const std::vector<model::CycleInput>& inputs,
                                                     const std::vector<std::size_t>& cycles) {
  std::map<std::size_t, std::vector<int>> out;
  for (std::size_t c : cycles) out[c];
  runtime::Runtime rt(m);
  for (std::size_t k = 0; k < inputs.size() && !out.empty() && k <= out.rbegin()->first; ++k) {
    rt.step(inputs[k]);
    if (auto it = out.find(k); it != out.end()) rt.snapshot(it->second);
  }
  return out;
}

std::string test_scenario_json(const model::Matrix& m, const std::string& matrix_ref, const std::string& description,
                               const std::vector<model::CycleInput>& inputs,
                               const std::map<std::size_t, std::vector<int>>& snapshots,
                               const std::vector<Checkpoint>& checkpoints, std::size_t& steps,
                               std::vector<FieldStep>& field) {
  const model::InputTable table(m);
  const auto all = model::observables(m);
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < all.size(); ++i) index[all[i].key] = i;
  // Output tags by name where the name is one output (6.1.4: case-insensitive).
  std::map<std::string, int> writers;
  for (const auto& e : m.effects)
    if (e.function != model::EffectFunction::Comment)
      for (const auto& t : e.tags) ++writers[model::tag_key(t.name)];
  auto key_of = [&](const model::Observable& o) {
    if (o.field != "tag") return o.key;
    const auto& name = m.find_effect(o.id)->tags[static_cast<std::size_t>(o.tag - 1)].name;
    return writers[model::tag_key(name)] == 1 && !table.find(name) ? name : o.key;
  };
  const auto shown = field_observables(m);
  std::map<std::size_t, const Checkpoint*> at;
  std::vector<std::size_t> at_cycles;
  for (const auto& c : checkpoints) {
    at[c.cycle] = &c;
    at_cycles.push_back(c.cycle);
  }

  formats::ScenarioRun run;
  run.matrix = matrix_ref;
  run.description = description;
  run.cycles = inputs;
  run.durations = formats::Durations::Milliseconds;
  std::vector<model::TagValue> current = model::default_cycle_input(m).tags;
  std::vector<int> seen(all.size(), 0);  // what the previous checkpoint showed (start-up: all 0)
  field.clear();
  std::size_t k = 0;
  for (std::size_t n : formats::step_lengths(inputs, at_cycles)) {
    const model::CycleInput& in = inputs[k];
    formats::WrittenStep step;
    step.cycles = n;
    FieldStep fs;
    for (std::size_t i = 0; i < table.size(); ++i)
      if (current[i].value != in.tags[i].value || current[i].bad_quality != in.tags[i].bad_quality)
        fs.actions.push_back(phrase_input(m, table.tags()[i], current[i], in.tags[i]));
    for (const auto& c : in.commands) fs.actions.push_back(phrase_command(m, c));
    current = in.tags;
    const std::size_t last = k + n - 1;
    fs.ms = static_cast<std::uint64_t>(n) * m.cycle_ms;
    if (auto cp = at.find(last); cp != at.end()) {
      const std::vector<int>& after = snapshots.at(last);
      std::set<std::string> phrased;
      auto say = [&](std::size_t i) {
        if (phrased.insert(all[i].key).second) fs.expected.push_back(phrase_observation(m, all[i], after[i]));
      };
      for (const auto& key : cp->second->observe)
        if (index.count(key)) say(index.at(key));
      for (const auto& o : shown) {
        std::size_t i = index.at(o.key);
        if (after[i] != seen[i]) say(i);
      }
      seen = after;
      std::string d;
      for (const auto& x : cp->second->descriptions) d += (d.empty() ? "" : "; ") + x;
      fs.covers = d;
      step.description = d;
      std::vector<formats::ExpectedValue> e;
      std::set<std::string> done;
      auto put = [&](const model::Observable& o) {
        if (done.insert(o.key).second) e.push_back({key_of(o), o.type, after[index.at(o.key)]});
      };
      for (const auto& key : cp->second->observe)
        if (index.count(key)) put(all[index.at(key)]);
      for (const auto& o : shown) put(o);
      step.expect = std::move(e);
    }
    run.steps.push_back(std::move(step));
    field.push_back(std::move(fs));
    k += n;
  }
  steps = run.steps.size();
  return formats::scenario_text(m, run);
}

}  // namespace cemv::testgen::detail
