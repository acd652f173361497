#include "testgen/scenario_writer.hpp"

#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "checker/counterexample.hpp"
#include "formats/scenario.hpp"
#include "model/text.hpp"
#include "testgen/phrases.hpp"

namespace cemv::testgen::detail {

namespace {

using nlohmann::ordered_json;

ordered_json number(float v) { return ordered_json::parse(model::float_text(v)); }

ordered_json value_json(model::FieldType type, int v) {
  switch (type) {
    case model::FieldType::Bool: return v != 0;
    case model::FieldType::Int: return v;
    case model::FieldType::Voting: return model::to_string(static_cast<model::Voting>(v));
  }
  return v;
}

bool same_tags(const std::vector<model::TagValue>& a, const std::vector<model::TagValue>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].value != b[i].value || a[i].bad_quality != b[i].bad_quality) return false;
  return true;
}

}  // namespace

bool starts_step(const std::vector<model::CycleInput>& inputs, std::size_t k, bool after_checkpoint) {
  return k == 0 || after_checkpoint || !inputs[k].commands.empty() || !same_tags(inputs[k].tags, inputs[k - 1].tags);
}

std::size_t count_steps(const std::vector<model::CycleInput>& inputs, const std::vector<std::size_t>& checkpoints) {
  const std::set<std::size_t> at(checkpoints.begin(), checkpoints.end());
  std::size_t steps = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k) steps += starts_step(inputs, k, k > 0 && at.count(k - 1));
  return steps;
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

std::string test_scenario_json(const model::Matrix& m, const std::string& matrix_ref, const std::string& description,
                               const std::vector<model::CycleInput>& inputs,
                               const std::vector<std::vector<int>>& observables,
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
  for (const auto& c : checkpoints) at[c.cycle] = &c;

  ordered_json doc;
  doc["format"] = formats::kScenarioFormat;
  if (!matrix_ref.empty()) doc["matrix"] = matrix_ref;
  doc["description"] = description;
  ordered_json jsteps = ordered_json::array();
  std::vector<model::TagValue> current = model::default_cycle_input(m).tags;
  std::vector<int> seen(all.size(), 0);  // what the previous checkpoint showed (start-up: all 0)
  field.clear();
  for (std::size_t k = 0; k < inputs.size();) {
    const model::CycleInput& in = inputs[k];
    ordered_json step;
    FieldStep fs;
    for (std::size_t i = 0; i < table.size(); ++i)
      if (current[i].value != in.tags[i].value || current[i].bad_quality != in.tags[i].bad_quality)
        fs.actions.push_back(phrase_input(m, table.tags()[i], current[i], in.tags[i]));
    for (const auto& c : in.commands) fs.actions.push_back(phrase_command(m, c));
    ordered_json changed = ordered_json::object();
    for (std::size_t i = 0; i < table.size(); ++i) {
      const bool vc = current[i].value != in.tags[i].value, qc = current[i].bad_quality != in.tags[i].bad_quality;
      if (!vc && !qc) continue;
      const auto& tag = table.tags()[i];
      ordered_json v = tag.kind == model::TagKind::Bool ? ordered_json(in.tags[i].value != 0.0f) : number(in.tags[i].value);
      if (qc || in.tags[i].bad_quality) {
        ordered_json o;
        o["value"] = v;
        o["quality"] = in.tags[i].bad_quality ? "bad" : "good";
        v = o;
      }
      changed[tag.name] = v;
    }
    current = in.tags;
    std::size_t n = 1;
    while (k + n < inputs.size() && !starts_step(inputs, k + n, at.count(k + n - 1) > 0)) ++n;
    const std::size_t last = k + n - 1;
    auto cp = at.find(last);
    if (cp != at.end()) step["description"] = cp->second->descriptions.empty() ? "" : cp->second->descriptions.front();
    if (!changed.empty()) step["inputs"] = changed;
    if (!in.commands.empty()) {
      ordered_json cmds = ordered_json::array();
      for (const auto& c : in.commands) cmds.push_back(ordered_json::parse(checker::command_text(m, c)));
      step["commands"] = cmds;
    }
    step["ms"] = static_cast<std::uint64_t>(n) * m.cycle_ms;
    fs.ms = static_cast<std::uint64_t>(n) * m.cycle_ms;
    if (cp != at.end()) {
      std::set<std::string> phrased;
      auto say = [&](std::size_t i) {
        if (phrased.insert(all[i].key).second) fs.expected.push_back(phrase_observation(m, all[i], observables[last][i]));
      };
      for (const auto& key : cp->second->observe)
        if (index.count(key)) say(index.at(key));
      for (const auto& o : shown) {
        std::size_t i = index.at(o.key);
        if (observables[last][i] != seen[i]) say(i);
      }
      seen = observables[last];
      for (const auto& d : cp->second->descriptions) fs.covers += (fs.covers.empty() ? "" : "; ") + d;
      ordered_json e = ordered_json::object();
      std::set<std::string> done;
      auto put = [&](const model::Observable& o) {
        if (!done.insert(o.key).second) return;
        e[key_of(o)] = value_json(o.type, observables[last][index.at(o.key)]);
      };
      for (const auto& key : cp->second->observe)
        if (index.count(key)) put(all[index.at(key)]);
      for (const auto& o : shown) put(o);
      step["expect"] = e;
      if (cp->second->descriptions.size() > 1) {
        std::string d;
        for (const auto& s : cp->second->descriptions) d += (d.empty() ? "" : "; ") + s;
        step["description"] = d;
      }
    }
    jsteps.push_back(step);
    field.push_back(std::move(fs));
    k += n;
  }
  doc["steps"] = jsteps;
  steps = jsteps.size();
  return doc.dump(1) + "\n";
}

}  // namespace cemv::testgen::detail
