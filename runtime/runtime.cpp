// The scan cycle of a whole matrix (docs/semantics.md section M) and the
// operator commands (section O). The per-element logic lives in
// cause_block.cpp and effect_block.cpp.
#include "runtime/runtime.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string>

#include "model/graph.hpp"
#include "model/vocabulary.hpp"
#include "runtime/cause_block.hpp"
#include "runtime/effect_block.hpp"
#include "runtime/explain_rules.hpp"
#include "runtime/signals.hpp"

namespace cemv::runtime {

namespace {

// Case-insensitive comparison of a tag name with a key made by model::tag_key,
// without allocating (commands are handled inside step()).
bool same_tag(std::string_view key, std::string_view name) {
  if (key.size() != name.size()) return false;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (key[i] != static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])))) return false;
  return true;
}

std::uint64_t seconds_to_cycles(std::uint32_t s, std::uint32_t cycle_ms) {
  return duration_cycles(static_cast<std::uint64_t>(s) * 1000u, cycle_ms);
}

// One evaluation step of the cycle: a cause or an effect slot.
struct Step {
  bool is_cause = true;
  int slot = 0;
};

// A compiled observable: which block, which field.
struct CompiledObservable {
  bool is_cause = true;
  int slot = 0;
  int field = 0;   // CauseField / EffectField, or -1 for an output tag
  int tag = 0;     // 0-based output tag
};

// A tag an operator may simulate (O.8): a cause input tag and/or an output tag.
struct SimulationTarget {
  std::string key;
  int input_index = -1;                          // cause input tag
  bool allowed = true;                           // no reader or writer forbids it (O.8)
  std::vector<std::pair<int, int>> readers;      // (cause slot, position) reading it
  std::vector<std::pair<int, int>> outputs;      // (effect slot, position) writing it
};

}  // namespace

struct Runtime::Impl {
  model::Matrix matrix;
  model::InputTable inputs;
  std::vector<int> cause_ids;   // slot -> id (ascending)
  std::vector<int> effect_ids;
  std::vector<int> effect_tag_counts;  // slot -> number of output tags
  std::vector<CauseBlock> causes;
  std::vector<EffectBlock> effects;
  std::vector<Step> order;      // the dependency graph's evaluation order (I.4)
  std::vector<std::vector<int>> first_out_groups;  // group -> cause slots by id (C.11)
  std::vector<SimulationTarget> simulation_targets;
  std::vector<CompiledObservable> observables;
  Signals signals;

  bool has_secure_write = false;
  TagSource secure_write_enable;
  bool has_group_deactivation = false;
  TagSource gdm_enable;
  TagSource gdm_set;
  bool gdm_set_before = false;

  std::uint64_t cycle = 0;
  int refused = 0;
  bool group_deactivated = false;  // M.2 fired in the last cycle

  // Explanations (explain.hpp), only while explaining.
  bool explaining = false;
  std::vector<int> before;
  std::vector<std::uint8_t> accepted;  // per command of the cycle
  std::vector<Explanation> explanations;
  void explain_cycle(const model::CycleInput& in);

  explicit Impl(const model::Matrix& m);
  int cause_slot(int id) const;
  int effect_slot(int id) const;
  TagSource resolve(const std::optional<std::string>& name) const;
  CauseConfig cause_config(const model::Cause& c) const;
  EffectConfig effect_config(const model::Effect& e) const;
  bool compile(const model::Observable& o, CompiledObservable& out) const;
  int read(const CompiledObservable& c) const;

  void step(const model::CycleInput& in);
  void group_deactivation();
  bool apply(const model::Command& c);
  bool simulate(const model::Command& c);
  bool stop_simulation(const model::Command& c);
  bool another_tag_in_maintenance(int cause_slot, int position) const;
  bool another_output_simulated(int effect_slot, int position) const;
  void end_simulation(SimulationTarget& t);
};

int Runtime::Impl::cause_slot(int id) const {
  auto it = std::lower_bound(cause_ids.begin(), cause_ids.end(), id);
  return it != cause_ids.end() && *it == id ? static_cast<int>(it - cause_ids.begin()) : -1;
}

int Runtime::Impl::effect_slot(int id) const {
  auto it = std::lower_bound(effect_ids.begin(), effect_ids.end(), id);
  return it != effect_ids.end() && *it == id ? static_cast<int>(it - effect_ids.begin()) : -1;
}

// I.3: an internal reference names a processed cause/effect (or output tag);
// anything else it could name reads 0. An external tag is an InputTable index.
TagSource Runtime::Impl::resolve(const std::optional<std::string>& name) const {
  TagSource src;
  if (!name || name->empty()) return src;
  if (auto ref = model::parse_internal_ref(*name)) {
    if (ref->kind == model::InternalRef::Kind::Cause) {
      int slot = cause_slot(ref->id);
      if (slot >= 0) src = {TagSource::Kind::CauseActive, slot, 0};
    } else {
      int slot = effect_slot(ref->id);
      if (slot < 0) return src;
      if (ref->kind == model::InternalRef::Kind::Effect) {
        src = {TagSource::Kind::EffectActive, slot, 0};
      } else if (ref->tag >= 1 && ref->tag <= effect_tag_counts[slot]) {
        src = {TagSource::Kind::EffectOutput, slot, ref->tag - 1};
      }
    }
    return src;
  }
  if (auto index = inputs.find(*name)) src = {TagSource::Kind::Input, static_cast<int>(*index), 0};
  return src;
}


CauseConfig Runtime::Impl::cause_config(const model::Cause& c) const {
  CauseConfig cfg;
  cfg.id = c.id;
  cfg.tag_count = static_cast<int>(std::min<std::size_t>(c.tags.size(), model::kMaxCauseTags));
  for (int i = 0; i < cfg.tag_count; ++i) {
    const model::CauseTag& t = c.tags[i];
    cfg.tag_source[i] = resolve(t.name);
    cfg.input_index[i] = cfg.tag_source[i].kind == TagSource::Kind::Input ? cfg.tag_source[i].index : -1;
    cfg.tag_key[i] = model::tag_key(t.name);
    cfg.ett[i] = t.ett;
    cfg.tag_soft_bypass_allowed[i] = t.soft_bypass_allowed;
  }
  // C.4 configured logic.
  switch (c.function) {
    case model::CauseFunction::And: cfg.configured_x = cfg.tag_count; break;
    case model::CauseFunction::TwoOoThree: cfg.configured_x = 2; break;
    default: cfg.configured_x = 1; break;
  }
  cfg.analog = c.input == model::InputKind::Analog && c.analog.has_value();
  if (cfg.analog) {
    const model::AnalogParams& a = *c.analog;
    cfg.limit_type = a.limit_type;
    cfg.limit = a.limit;
    // C.4: the relaxed threshold computed once, in single precision.
    cfg.relaxed_threshold =
        a.limit_type == model::LimitType::High ? a.limit - a.hysteresis : a.limit + a.hysteresis;
    // C.5: a prewarning at or beyond the limit in the trip direction is disabled.
    if (a.prewarning) {
      cfg.prewarning = *a.prewarning;
      cfg.prewarning_enabled = a.limit_type == model::LimitType::High ? *a.prewarning < a.limit
                                                                      : *a.prewarning > a.limit;
    }
    cfg.delta_enabled = a.delta > 0.0f && cfg.tag_count >= 2;
    cfg.delta = a.delta;
    cfg.delta_clear = a.delta - a.hysteresis;
  }
  cfg.bad_quality = c.bad_quality;
  cfg.time_mode = c.time.mode;
  cfg.time_cycles = duration_cycles(c.time.ms, matrix.cycle_ms);
  cfg.has_ack_latch = !c.auto_ack && (c.time.mode == model::TimeMode::None ||
                                      c.time.mode == model::TimeMode::OnDelay);
  cfg.soft_bypass_allowed = c.soft_bypass.allowed;
  cfg.soft_bypass_timed = c.soft_bypass.max_s > 0;
  cfg.soft_bypass_cycles = seconds_to_cycles(c.soft_bypass.max_s, matrix.cycle_ms);
  cfg.soft_bypass_prealarm = c.soft_bypass.prealarm_s > 0;
  cfg.soft_bypass_prealarm_cycles = seconds_to_cycles(c.soft_bypass.prealarm_s, matrix.cycle_ms);
  cfg.has_bypass_tag = c.bypass_tag && !c.bypass_tag->empty();
  cfg.bypass_tag = resolve(c.bypass_tag);
  cfg.has_inhibit_tag = c.inhibit_tag && !c.inhibit_tag->empty();
  cfg.inhibit_tag = resolve(c.inhibit_tag);
  cfg.first_out_group = c.first_out_group;
  cfg.mutually_locked = c.mutually_locked_maintenance;
  return cfg;
}

EffectConfig Runtime::Impl::effect_config(const model::Effect& e) const {
  EffectConfig cfg;
  cfg.id = e.id;
  cfg.tag_count = static_cast<int>(std::min<std::size_t>(e.tags.size(), model::kMaxEffectTags));
  for (int j = 0; j < cfg.tag_count; ++j) {
    cfg.ett[j] = e.tags[j].ett;
    cfg.tag_key[j] = model::tag_key(e.tags[j].name);
  }
  // E.2: processed intersections only (M.4); the XooN assignment.
  for (const model::Intersection* x : matrix.intersections_of_effect(e.id)) {
    if (!model::is_processed(x->type)) continue;
    int slot = cause_slot(x->cause);
    if (slot < 0) continue;  // comment-only or missing cause
    EffectLink link{slot, x->type, x->xoon.has_value()};
    if (x->xoon) {
      cfg.xoon_x = cfg.has_xoon ? std::min(cfg.xoon_x, *x->xoon) : *x->xoon;
      if (!cfg.has_xoon) cfg.xoon_type = x->type;  // E.2: the lowest cause id decides
      cfg.has_xoon = true;
    }
    if (x->type == model::IntersectionType::S || x->type == model::IntersectionType::R)
      cfg.has_reset_or_stored = true;
    if (x->type == model::IntersectionType::V || x->type == model::IntersectionType::R)
      cfg.has_overridable = true;
    cfg.links.push_back(link);
  }
  cfg.output_delay_cycles = duration_cycles(e.output_delay_ms, matrix.cycle_ms);
  cfg.soft_bypass_allowed = e.soft_bypass_allowed;
  cfg.has_bypass_tag = e.bypass_tag && !e.bypass_tag->empty();
  cfg.bypass_tag = resolve(e.bypass_tag);
  cfg.has_reset_tag = e.reset_tag && !e.reset_tag->empty();
  cfg.reset_tag = resolve(e.reset_tag);
  if (e.override_time) {
    cfg.has_override = true;
    cfg.override_cycles = seconds_to_cycles(e.override_time->max_s, matrix.cycle_ms);
    cfg.override_prealarm = e.override_time->prealarm_s > 0;
    cfg.override_prealarm_cycles = seconds_to_cycles(e.override_time->prealarm_s, matrix.cycle_ms);
  }
  if (e.process_data && e.process_data->tag && !e.process_data->tag->empty()) {
    const model::ProcessData& pd = *e.process_data;
    cfg.process_tag = resolve(pd.tag);
    cfg.pass_through = pd.pass_through;
    cfg.mask = pd.mask_tag && !pd.mask_tag->empty();  // E.8: a mask needs a process tag
    cfg.mask_tag = resolve(pd.mask_tag);
  }
  cfg.mutually_locked = e.mutually_locked_maintenance;
  return cfg;
}

Runtime::Impl::Impl(const model::Matrix& m) : matrix(m), inputs(m) {
  if (matrix.cycle_ms == 0) throw std::invalid_argument("runtime: cycle_ms must be > 0");
  for (const auto& c : matrix.causes)
    if (c.function != model::CauseFunction::Comment) cause_ids.push_back(c.id);
  for (const auto& e : matrix.effects)
    if (e.function != model::EffectFunction::Comment) {
      effect_ids.push_back(e.id);
      effect_tag_counts.push_back(
          static_cast<int>(std::min<std::size_t>(e.tags.size(), model::kMaxEffectTags)));
    }
  std::sort(cause_ids.begin(), cause_ids.end());
  std::sort(effect_ids.begin(), effect_ids.end());

  for (int id : cause_ids) causes.emplace_back(cause_config(*matrix.find_cause(id)));
  for (int id : effect_ids) effects.emplace_back(effect_config(*matrix.find_effect(id)));

  // I.4: the one evaluation order, from the dependency graph.
  model::DependencyGraph graph(matrix);
  for (const model::Node& n : graph.evaluation_order()) {
    if (n.kind == model::Node::Kind::Cause) {
      int slot = cause_slot(n.id);
      if (slot >= 0) order.push_back({true, slot});
    } else {
      int slot = effect_slot(n.id);
      if (slot >= 0) order.push_back({false, slot});
    }
  }
  if (order.size() != causes.size() + effects.size())
    throw std::logic_error("runtime: the evaluation order does not cover every processed element");

  first_out_groups.resize(model::kMaxFirstOutGroup + 1);
  for (std::size_t slot = 0; slot < causes.size(); ++slot) {
    int g = causes[slot].config().first_out_group;
    if (g >= 1 && g <= model::kMaxFirstOutGroup) first_out_groups[g].push_back(static_cast<int>(slot));
  }

  // O.8: the simulatable tags: external cause input tags, output tags.
  auto target = [&](const std::string& key) -> SimulationTarget& {
    for (auto& t : simulation_targets)
      if (t.key == key) return t;
    simulation_targets.push_back(SimulationTarget{key, -1, true, {}, {}});
    return simulation_targets.back();
  };
  for (std::size_t slot = 0; slot < causes.size(); ++slot) {
    const CauseConfig& cfg = causes[slot].config();
    for (int i = 0; i < cfg.tag_count; ++i) {
      if (cfg.input_index[i] < 0) continue;
      SimulationTarget& t = target(cfg.tag_key[i]);
      t.input_index = cfg.input_index[i];
      t.readers.emplace_back(static_cast<int>(slot), i);
      if (!matrix.find_cause(cause_ids[slot])->tags[i].simulation_allowed) t.allowed = false;
    }
  }
  for (std::size_t slot = 0; slot < effects.size(); ++slot) {
    const EffectConfig& cfg = effects[slot].config();
    for (int j = 0; j < cfg.tag_count; ++j) {
      SimulationTarget& t = target(cfg.tag_key[j]);
      t.outputs.emplace_back(static_cast<int>(slot), j);
      if (!matrix.find_effect(effect_ids[slot])->tags[j].simulation_allowed) t.allowed = false;
    }
  }

  if (matrix.secure_write && !matrix.secure_write->enable_tag.empty()) {
    has_secure_write = true;
    secure_write_enable = resolve(matrix.secure_write->enable_tag);
  }
  if (matrix.group_deactivation) {
    has_group_deactivation = true;
    gdm_enable = resolve(matrix.group_deactivation->enable_tag);
    gdm_set = resolve(matrix.group_deactivation->set_tag);
  }

  signals.input_simulated.assign(inputs.size(), 0);
  signals.input_simulated_value.assign(inputs.size(), 0.0f);
  signals.cause_active.assign(causes.size(), 0);
  signals.effect_active.assign(effects.size(), 0);
  signals.effect_output.assign(effects.size(), {});

  for (const model::Observable& o : model::observables(matrix)) {
    CompiledObservable c;
    if (!compile(o, c)) throw std::logic_error("runtime: unknown observable " + o.key);
    observables.push_back(c);
  }
}

bool Runtime::Impl::compile(const model::Observable& o, CompiledObservable& out) const {
  out.is_cause = o.kind == model::Node::Kind::Cause;
  out.slot = out.is_cause ? cause_slot(o.id) : effect_slot(o.id);
  if (out.slot < 0) return false;
  if (out.is_cause) {
    CauseField f;
    if (!cause_field_from_name(o.field, f)) return false;
    out.field = static_cast<int>(f);
    return true;
  }
  if (o.field == "tag") {
    out.field = -1;
    out.tag = o.tag - 1;
    return out.tag >= 0 && out.tag < effects[out.slot].config().tag_count;
  }
  EffectField f;
  if (!effect_field_from_name(o.field, f)) return false;
  out.field = static_cast<int>(f);
  return true;
}

int Runtime::Impl::read(const CompiledObservable& c) const {
  if (c.is_cause) return causes[c.slot].field(static_cast<CauseField>(c.field));
  if (c.field < 0) return effects[c.slot].output(c.tag);
  return effects[c.slot].field(static_cast<EffectField>(c.field));
}

// ---- the cycle (M.1) --------------------------------------------------------

void Runtime::Impl::step(const model::CycleInput& in) {
  if (in.tags.size() != inputs.size())
    throw std::invalid_argument("runtime: the cycle input has " + std::to_string(in.tags.size()) +
                                " tag values, the matrix reads " + std::to_string(inputs.size()));
  ++cycle;
  const std::uint64_t k = cycle;
  signals.input = &in;
  refused = 0;
  group_deactivated = false;
  if (explaining) {
    before.resize(observables.size());
    for (std::size_t i = 0; i < observables.size(); ++i) before[i] = read(observables[i]);
    accepted.clear();
  }

  // Phase 1: group deactivation (M.2).
  if (has_group_deactivation) {
    const bool enable = signals.read_bool(gdm_enable);
    const bool set = signals.read_bool(gdm_set);
    const bool edge = k > 1 && set && !gdm_set_before;
    gdm_set_before = set;
    group_deactivated = enable && edge;
    if (group_deactivated) group_deactivation();
  }

  // Phase 2: operator commands, in order, gated by secure write (M.3).
  const bool secure_write_open = !has_secure_write || signals.read_bool(secure_write_enable);
  for (const model::Command& c : in.commands) {
    const bool ok = secure_write_open && apply(c);
    if (!ok) ++refused;
    if (explaining) accepted.push_back(ok);
  }

  // Phase 3: every cause and effect in the evaluation order (I.4).
  for (const Step& s : order) {
    if (s.is_cause) {
      causes[s.slot].evaluate(signals, k);
      signals.cause_active[s.slot] = causes[s.slot].active();
    } else {
      effects[s.slot].evaluate(signals, s.slot, k);
    }
  }

  // Phase 4: first out (C.11): the lowest id among those that became active.
  for (int g = 1; g <= model::kMaxFirstOutGroup; ++g) {
    const std::vector<int>& group = first_out_groups[g];
    bool held = false;
    for (int slot : group)
      if (causes[slot].field(CauseField::FirstOut)) held = true;
    if (held) continue;
    for (int slot : group)
      if (causes[slot].became_active()) {
        causes[slot].give_first_out();
        break;
      }
  }
  if (explaining) explain_cycle(in);
  signals.input = nullptr;
}

// Every observable that changed in this cycle, with the rule that changed it
// (explain_rules.cpp reads what each block recorded in its facts).
void Runtime::Impl::explain_cycle(const model::CycleInput& in) {
  explanations.clear();
  const CycleView view{matrix, in, accepted, group_deactivated, cause_ids, effect_ids, causes, effects};
  for (std::size_t i = 0; i < observables.size(); ++i) {
    const CompiledObservable& o = observables[i];
    const int after = read(o);
    if (after == before[i]) {
      // An override that ended and was started again in the same cycle keeps
      // its value but is a new override: worth saying (E.3 steps 1 and 2).
      if (!o.is_cause && o.field == static_cast<int>(EffectField::OverrideActive) && after) {
        const EffectFacts& f = effects[static_cast<std::size_t>(o.slot)].facts();
        if (f.override_started && (f.end_timeout || f.end_new_cause || f.end_no_request))
          explanations.push_back({i, before[i], after, why_effect(view, o.slot, o.field, 0, 1, 0) +
                                                           "; in the same cycle a new override started (E.3 step 2)"});
      }
      continue;
    }
    std::string why = o.is_cause ? why_cause(view, o.slot, static_cast<CauseField>(o.field), before[i], after)
                                 : why_effect(view, o.slot, o.field, o.tag, before[i], after);
    explanations.push_back({i, before[i], after, std::move(why)});
  }
}

void Runtime::Impl::group_deactivation() {
  for (auto& c : causes) c.end_maintenance();
  for (auto& e : effects) e.end_maintenance();
  std::fill(signals.input_simulated.begin(), signals.input_simulated.end(), 0);
}

// ---- operator commands (section O) --------------------------------------------

bool Runtime::Impl::another_tag_in_maintenance(int cause, int position) const {
  const CauseBlock& block = causes[cause];
  const CauseConfig& cfg = block.config();
  for (int j = 0; j < cfg.tag_count; ++j) {
    if (j == position || cfg.tag_key[j] == cfg.tag_key[position]) continue;
    if (block.tag_soft_bypassed(j)) return true;
    if (cfg.input_index[j] >= 0 && signals.input_simulated[cfg.input_index[j]]) return true;
  }
  return false;
}

bool Runtime::Impl::another_output_simulated(int effect, int position) const {
  const EffectBlock& block = effects[effect];
  const EffectConfig& cfg = block.config();
  for (int j = 0; j < cfg.tag_count; ++j) {
    if (j == position || cfg.tag_key[j] == cfg.tag_key[position]) continue;
    if (block.output_simulated(j)) return true;
  }
  return false;
}

void Runtime::Impl::end_simulation(SimulationTarget& t) {
  if (t.input_index >= 0) signals.input_simulated[t.input_index] = 0;
  for (auto [slot, j] : t.outputs) effects[slot].stop_output_simulation(j);
}

bool Runtime::Impl::simulate(const model::Command& c) {
  for (SimulationTarget& t : simulation_targets) {
    if (!same_tag(t.key, c.tag_name)) continue;
    if (!t.allowed) return false;  // simulation of this tag is not allowed (O.8)
    // Mutual lock (O.8).
    for (auto [slot, i] : t.readers)
      if (causes[slot].config().mutually_locked && another_tag_in_maintenance(slot, i)) return false;
    for (auto [slot, j] : t.outputs)
      if (effects[slot].config().mutually_locked && another_output_simulated(slot, j)) return false;
    if (t.input_index >= 0) {
      signals.input_simulated[t.input_index] = 1;
      signals.input_simulated_value[t.input_index] = c.value;
    }
    for (auto [slot, j] : t.outputs) effects[slot].simulate_output(j, c.value != 0.0f);
    return true;
  }
  return false;
}

bool Runtime::Impl::stop_simulation(const model::Command& c) {
  if (c.tag_name.empty()) {
    for (SimulationTarget& t : simulation_targets) end_simulation(t);
    return true;
  }
  for (SimulationTarget& t : simulation_targets)
    if (same_tag(t.key, c.tag_name)) {
      end_simulation(t);
      return true;
    }
  return false;
}

// Applies one command; false when it is refused (section O).
bool Runtime::Impl::apply(const model::Command& c) {
  using Op = model::CommandOp;
  switch (c.op) {
    case Op::AckCause: {  // O.1
      int slot = cause_slot(c.cause);
      if (slot < 0 || !causes[slot].config().has_ack_latch) return false;
      causes[slot].request_ack();
      return true;
    }
    case Op::ResetEffect: {  // O.2
      int slot = effect_slot(c.effect);
      if (slot < 0) return false;
      const EffectConfig& cfg = effects[slot].config();
      if (cfg.has_reset_tag || !cfg.has_reset_or_stored) return false;
      effects[slot].request_reset();
      return true;
    }
    case Op::OverrideEffect:
    case Op::StopOverride: {  // O.3
      int slot = effect_slot(c.effect);
      if (slot < 0) return false;
      const EffectConfig& cfg = effects[slot].config();
      if (cfg.has_reset_tag || !cfg.has_overridable) return false;
      effects[slot].request_toggle();
      return true;
    }
    case Op::SoftBypassCause: {  // O.5
      int slot = cause_slot(c.cause);
      if (slot < 0 || !causes[slot].config().soft_bypass_allowed) return false;
      causes[slot].set_soft_bypass(c.on, cycle);
      return true;
    }
    case Op::SoftBypassTag: {  // O.6
      int slot = cause_slot(c.cause);
      if (slot < 0) return false;
      const CauseConfig& cfg = causes[slot].config();
      const int position = c.tag - 1;
      if (position < 0 || position >= cfg.tag_count || !cfg.tag_soft_bypass_allowed[position])
        return false;
      if (c.on && cfg.mutually_locked && another_tag_in_maintenance(slot, position)) return false;
      causes[slot].set_tag_soft_bypass(position, c.on);
      return true;
    }
    case Op::SoftBypassEffect: {  // O.7
      int slot = effect_slot(c.effect);
      if (slot < 0 || !effects[slot].config().soft_bypass_allowed) return false;
      effects[slot].set_soft_bypass(c.on);
      return true;
    }
    case Op::SimulateTag: return simulate(c);           // O.8
    case Op::StopSimulation: return stop_simulation(c);  // O.8
    case Op::ClearFirstOut: {  // O.9
      if (c.group < 1 || c.group > model::kMaxFirstOutGroup) return false;
      for (int slot : first_out_groups[c.group]) causes[slot].clear_first_out();
      return true;
    }
    case Op::ClearAlarms: {  // O.10
      int cs = c.cause != 0 ? cause_slot(c.cause) : -1;
      int es = c.effect != 0 ? effect_slot(c.effect) : -1;
      if ((c.cause != 0 && cs < 0) || (c.effect != 0 && es < 0) || (cs < 0 && es < 0)) return false;
      if (cs >= 0) causes[cs].clear_alarms();
      if (es >= 0) effects[es].clear_alarms();
      return true;
    }
  }
  return false;
}

// ---- public API ------------------------------------------------------------------

Runtime::Runtime(const model::Matrix& m) : impl_(std::make_unique<Impl>(m)) {}
Runtime::~Runtime() = default;
Runtime::Runtime(Runtime&&) noexcept = default;
Runtime& Runtime::operator=(Runtime&&) noexcept = default;
Runtime::Runtime(const Runtime& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Runtime& Runtime::operator=(const Runtime& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}

const model::Matrix& Runtime::matrix() const { return impl_->matrix; }
const model::InputTable& Runtime::inputs() const { return impl_->inputs; }

// S.1: the scenario format's defaults. They are a convention of the input
// format, not scan-cycle semantics, so the runtime uses the model's one definition.
model::CycleInput Runtime::default_input() const { return model::default_cycle_input(impl_->matrix); }

void Runtime::step(const model::CycleInput& in) { impl_->step(in); }
std::uint64_t Runtime::cycles_run() const { return impl_->cycle; }

int Runtime::value(const model::Observable& o) const {
  CompiledObservable c;
  if (!impl_->compile(o, c)) throw std::invalid_argument("runtime: unknown observable " + o.key);
  return impl_->read(c);
}

void Runtime::snapshot(std::vector<int>& out) const {
  out.resize(impl_->observables.size());
  for (std::size_t i = 0; i < impl_->observables.size(); ++i) out[i] = impl_->read(impl_->observables[i]);
}

std::optional<bool> Runtime::output(std::string_view tag) const {
  for (std::size_t slot = 0; slot < impl_->effects.size(); ++slot) {
    const EffectConfig& cfg = impl_->effects[slot].config();
    for (int j = 0; j < cfg.tag_count; ++j)
      if (same_tag(cfg.tag_key[j], tag)) return impl_->effects[slot].output(j);
  }
  return std::nullopt;
}

int Runtime::commands_refused() const { return impl_->refused; }

void Runtime::explain(bool on) {
  impl_->explaining = on;
  impl_->explanations.clear();
}

const std::vector<Explanation>& Runtime::explanations() const { return impl_->explanations; }

}  // namespace cemv::runtime
