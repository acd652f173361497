#include "defeats/runs.hpp"

#include <optional>
#include <set>
#include <string>

namespace cemv::defeats {

namespace {

// The first cycle whose inputs differ from the cycle before: where the
// demand begins (0 when the run starts with it).
std::size_t demand_start(const Run& run) {
  for (std::size_t i = 1; i < run.size(); ++i)
    for (std::size_t t = 0; t < run[i].tags.size(); ++t)
      if (run[i].tags[t].value != run[i - 1].tags[t].value) return i;
  return 0;
}

float unsafe_value(const model::Matrix& m, const Action& a) {
  const model::Effect& e = *m.find_effect(a.effect);
  for (const auto& t : e.tags)
    if (model::tag_key(t.name) == model::tag_key(a.tag)) return t.ett ? 0.0f : 1.0f;
  return 1.0f;
}

// The run with the demand moved onto the tags the set touches: for each
// voted trigger cause, the tags beyond the limit at the end of the run are
// replaced by the touched ones first, then the untouched ones, as many as
// before. Nullopt when it moves nothing.
std::optional<Run> moved_demand(const model::Matrix& m, const model::InputTable& table, const response::Path& p,
                                const std::vector<Action>& actions, const std::vector<int>& set, Run run) {
  if (run.empty()) return std::nullopt;
  std::set<std::string> touched;
  for (int i : set)
    if (actions[i].kind == ActionKind::SoftBypassTag || actions[i].kind == ActionKind::SimulateInput ||
        actions[i].kind == ActionKind::BadQuality)
      touched.insert(model::tag_key(actions[i].tag));
  const std::size_t start = demand_start(run);
  bool moved = false;
  for (int id : p.causes) {
    const model::Cause& c = *m.find_cause(id);
    std::vector<std::size_t> tags;  // input indices of the external tags, in the cause's order
    std::vector<bool> ett;
    for (const auto* t : response::external_tags(c))
      if (auto i = table.find(t->name)) {
        tags.push_back(*i);
        ett.push_back(t->ett);
      }
    if (tags.size() < 2) continue;
    const auto& last = run.back().tags;
    std::size_t beyond = 0;
    std::optional<float> analog_value;
    for (std::size_t k = 0; k < tags.size(); ++k)
      if (last[tags[k]].value != run[0].tags[tags[k]].value) {
        ++beyond;
        analog_value = last[tags[k]].value;
      }
    std::vector<std::size_t> order;  // touched first
    for (std::size_t k = 0; k < tags.size(); ++k)
      if (touched.count(model::tag_key(table.tags()[tags[k]].name))) order.push_back(k);
    if (order.empty() || beyond == 0) continue;
    for (std::size_t k = 0; k < tags.size(); ++k)
      if (!touched.count(model::tag_key(table.tags()[tags[k]].name))) order.push_back(k);
    for (std::size_t r = 0; r < order.size(); ++r) {
      const std::size_t k = order[r];
      const float quiet = run[0].tags[tags[k]].value;
      const float trip = c.input == model::InputKind::Analog ? *analog_value : (ett[k] ? 1.0f : 0.0f);
      for (std::size_t cycle = start; cycle < run.size(); ++cycle)
        if (run[cycle].tags[tags[k]].value != run[0].tags[tags[k]].value || r < beyond)
          run[cycle].tags[tags[k]].value = r < beyond ? trip : quiet;
      moved = true;
    }
  }
  if (!moved) return std::nullopt;
  return run;
}

}  // namespace

std::vector<Run> defeat_runs(const model::Matrix& m, const response::Path& p, const std::vector<Action>& actions,
                             const std::vector<int>& set, const std::vector<Run>& demand_runs) {
  if (set.empty()) return demand_runs;
  const model::InputTable table(m);
  const model::CommandOrder order(m);
  std::vector<Run> bases;
  for (const Run& run : demand_runs) {
    bases.push_back(run);
    if (auto moved = moved_demand(m, table, p, actions, set, run)) bases.push_back(std::move(*moved));
  }
  std::vector<Run> out;
  for (Run run : bases) {
    if (run.empty()) continue;
    const std::size_t start = demand_start(run);
    std::vector<model::Command> first;
    auto each_cycle_from = [&](std::size_t from, const std::string& tag, auto&& f) {
      if (auto i = table.find(tag))
        for (std::size_t c = from; c < run.size(); ++c) f(run[c].tags[*i], run[0].tags[*i]);
    };
    for (int index : set) {
      const Action& a = actions[index];
      model::Command cmd;
      switch (a.kind) {
        case ActionKind::SoftBypassCause:
          cmd.op = model::CommandOp::SoftBypassCause;
          cmd.cause = a.cause;
          first.push_back(cmd);
          break;
        case ActionKind::SoftBypassTag:
          cmd.op = model::CommandOp::SoftBypassTag;
          cmd.cause = a.cause;
          cmd.tag = a.tag_index;
          first.push_back(cmd);
          break;
        case ActionKind::SoftBypassEffect:
          cmd.op = model::CommandOp::SoftBypassEffect;
          cmd.effect = a.effect;
          first.push_back(cmd);
          break;
        case ActionKind::CauseBypassTag:
        case ActionKind::CauseInhibitTag:
        case ActionKind::EffectBypassTag:
        case ActionKind::MaskTag:
          each_cycle_from(0, a.tag, [](model::TagValue& v, const model::TagValue&) { v.value = 1.0f; });
          break;
        case ActionKind::SimulateInput:
        case ActionKind::SimulateOutput: {
          cmd.op = model::CommandOp::SimulateTag;
          cmd.tag_name = a.tag;
          cmd.value = a.kind == ActionKind::SimulateOutput ? unsafe_value(m, a) : 0.0f;
          if (a.kind == ActionKind::SimulateInput)
            if (auto i = table.find(a.tag)) cmd.value = run[0].tags[*i].value;
          first.push_back(cmd);
          break;
        }
        case ActionKind::BadQuality:
          each_cycle_from(start, a.tag, [](model::TagValue& v, const model::TagValue& quiet) {
            v.bad_quality = true;
            v.value = quiet.value;
          });
          break;
        case ActionKind::Override: break;
      }
    }
    if (!first.empty()) {
      first.insert(first.end(), run[0].commands.begin(), run[0].commands.end());
      run[0].commands = order.canonical(first);
      if (m.secure_write)
        if (auto i = table.find(m.secure_write->enable_tag)) run[0].tags[*i].value = 1.0f;
    }
    out.push_back(std::move(run));
  }
  return out;
}

}  // namespace cemv::defeats
