// The matrix laid out for the scan cycle (runtime/scan_layout.hpp): what each
// block's configuration says, read from the matrix once.
#include "runtime/scan_layout.hpp"

#include <algorithm>
#include <stdexcept>

#include "model/graph.hpp"
#include "model/vocabulary.hpp"

namespace cemv::runtime {

namespace {

std::uint64_t seconds_to_cycles(std::uint32_t s, std::uint32_t cycle_ms) {
  return duration_cycles(static_cast<std::uint64_t>(s) * 1000u, cycle_ms);
}

int slot_of(const std::vector<int>& ids, int id) {
  auto it = std::lower_bound(ids.begin(), ids.end(), id);
  return it != ids.end() && *it == id ? static_cast<int>(it - ids.begin()) : -1;
}

class LayoutBuilder {
 public:
  LayoutBuilder(const model::Matrix& m, const model::InputTable& inputs) : matrix_(m), inputs_(inputs) {}
  ScanLayout build();

 private:
  TagSource resolve(const std::optional<std::string>& name) const;
  CauseConfig cause_config(const model::Cause& c) const;
  EffectConfig effect_config(const model::Effect& e) const;
  void evaluation_order();
  void first_out_groups();
  void simulation_targets();
  SimulationTarget& simulation_target(const std::string& key);

  const model::Matrix& matrix_;
  const model::InputTable& inputs_;
  ScanLayout out_;
  std::vector<int> effect_tag_counts_;  // slot -> number of output tags
};

ScanLayout LayoutBuilder::build() {
  if (matrix_.cycle_ms == 0) throw std::invalid_argument("runtime: cycle_ms must be > 0");
  for (const auto& c : matrix_.causes)
    if (c.function != model::CauseFunction::Comment) out_.cause_ids.push_back(c.id);
  std::sort(out_.cause_ids.begin(), out_.cause_ids.end());
  for (const auto& e : matrix_.effects)
    if (e.function != model::EffectFunction::Comment) out_.effect_ids.push_back(e.id);
  std::sort(out_.effect_ids.begin(), out_.effect_ids.end());
  for (int id : out_.effect_ids)
    effect_tag_counts_.push_back(
        static_cast<int>(std::min<std::size_t>(matrix_.find_effect(id)->tags.size(), model::kMaxEffectTags)));

  for (int id : out_.cause_ids) out_.causes.push_back(cause_config(*matrix_.find_cause(id)));
  for (int id : out_.effect_ids) out_.effects.push_back(effect_config(*matrix_.find_effect(id)));
  evaluation_order();
  first_out_groups();
  simulation_targets();
  if (matrix_.secure_write && !matrix_.secure_write->enable_tag.empty())
    out_.secure_write_enable = resolve(matrix_.secure_write->enable_tag);
  if (matrix_.group_deactivation)
    out_.group_deactivation = GroupDeactivationTags{resolve(matrix_.group_deactivation->enable_tag),
                                                    resolve(matrix_.group_deactivation->set_tag)};
  return std::move(out_);
}

// I.3: an internal reference names a processed cause/effect (or output tag);
// anything else it could name reads 0. An external tag is an InputTable index.
TagSource LayoutBuilder::resolve(const std::optional<std::string>& name) const {
  TagSource src;
  if (!name || name->empty()) return src;
  if (auto ref = model::parse_internal_ref(*name)) {
    if (ref->kind == model::InternalRef::Kind::Cause) {
      int slot = out_.cause_slot(ref->id);
      if (slot >= 0) src = {TagSource::Kind::CauseActive, slot, 0};
    } else {
      int slot = out_.effect_slot(ref->id);
      if (slot < 0) return src;
      if (ref->kind == model::InternalRef::Kind::Effect) {
        src = {TagSource::Kind::EffectActive, slot, 0};
      } else if (ref->tag >= 1 && ref->tag <= effect_tag_counts_[slot]) {
        src = {TagSource::Kind::EffectOutput, slot, ref->tag - 1};
      }
    }
    return src;
  }
  if (auto index = inputs_.find(*name)) src = {TagSource::Kind::Input, static_cast<int>(*index), 0};
  return src;
}


CauseConfig LayoutBuilder::cause_config(const model::Cause& c) const {
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
  cfg.time_cycles = duration_cycles(c.time.ms, matrix_.cycle_ms);
  cfg.has_ack_latch = !c.auto_ack && (c.time.mode == model::TimeMode::None ||
                                      c.time.mode == model::TimeMode::OnDelay);
  cfg.soft_bypass_allowed = c.soft_bypass.allowed;
  cfg.soft_bypass_timed = c.soft_bypass.max_s > 0;
  cfg.soft_bypass_cycles = seconds_to_cycles(c.soft_bypass.max_s, matrix_.cycle_ms);
  cfg.soft_bypass_prealarm = c.soft_bypass.prealarm_s > 0;
  cfg.soft_bypass_prealarm_cycles = seconds_to_cycles(c.soft_bypass.prealarm_s, matrix_.cycle_ms);
  cfg.has_bypass_tag = c.bypass_tag && !c.bypass_tag->empty();
  cfg.bypass_tag = resolve(c.bypass_tag);
  cfg.has_inhibit_tag = c.inhibit_tag && !c.inhibit_tag->empty();
  cfg.inhibit_tag = resolve(c.inhibit_tag);
  cfg.first_out_group = c.first_out_group;
  cfg.mutually_locked = c.mutually_locked_maintenance;
  return cfg;
}

EffectConfig LayoutBuilder::effect_config(const model::Effect& e) const {
  EffectConfig cfg;
  cfg.id = e.id;
  cfg.tag_count = static_cast<int>(std::min<std::size_t>(e.tags.size(), model::kMaxEffectTags));
  for (int j = 0; j < cfg.tag_count; ++j) {
    cfg.ett[j] = e.tags[j].ett;
    cfg.tag_key[j] = model::tag_key(e.tags[j].name);
  }
  // E.2: processed intersections only (M.4); the XooN assignment.
  for (const model::Intersection* x : matrix_.intersections_of_effect(e.id)) {
    if (!model::is_processed(x->type)) continue;
    int slot = out_.cause_slot(x->cause);
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
  cfg.output_delay_cycles = duration_cycles(e.output_delay_ms, matrix_.cycle_ms);
  cfg.soft_bypass_allowed = e.soft_bypass_allowed;
  cfg.has_bypass_tag = e.bypass_tag && !e.bypass_tag->empty();
  cfg.bypass_tag = resolve(e.bypass_tag);
  cfg.has_reset_tag = e.reset_tag && !e.reset_tag->empty();
  cfg.reset_tag = resolve(e.reset_tag);
  if (e.override_time) {
    cfg.has_override = true;
    cfg.override_cycles = seconds_to_cycles(e.override_time->max_s, matrix_.cycle_ms);
    cfg.override_prealarm = e.override_time->prealarm_s > 0;
    cfg.override_prealarm_cycles = seconds_to_cycles(e.override_time->prealarm_s, matrix_.cycle_ms);
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

// I.4: the one evaluation order, from the dependency graph.
void LayoutBuilder::evaluation_order() {
  model::DependencyGraph graph(matrix_);
  for (const model::Node& n : graph.evaluation_order()) {
    const bool is_cause = n.kind == model::Node::Kind::Cause;
    const int slot = is_cause ? out_.cause_slot(n.id) : out_.effect_slot(n.id);
    if (slot >= 0) out_.order.push_back({is_cause, slot});
  }
  if (out_.order.size() != out_.causes.size() + out_.effects.size())
    throw std::logic_error("runtime: the evaluation order does not cover every processed element");
}

// C.11: each group's causes in ascending id, the order first out is given in.
void LayoutBuilder::first_out_groups() {
  out_.first_out_groups.resize(model::kMaxFirstOutGroup + 1);
  for (std::size_t slot = 0; slot < out_.causes.size(); ++slot) {
    int g = out_.causes[slot].first_out_group;
    if (g >= 1 && g <= model::kMaxFirstOutGroup) out_.first_out_groups[g].push_back(static_cast<int>(slot));
  }
}

SimulationTarget& LayoutBuilder::simulation_target(const std::string& key) {
  for (auto& t : out_.simulation_targets)
    if (t.key == key) return t;
  out_.simulation_targets.push_back(SimulationTarget{key, -1, true, {}, {}});
  return out_.simulation_targets.back();
}

// O.8: the simulatable tags: external cause input tags, output tags.
void LayoutBuilder::simulation_targets() {
  for (std::size_t slot = 0; slot < out_.causes.size(); ++slot) {
    const CauseConfig& cfg = out_.causes[slot];
    for (int i = 0; i < cfg.tag_count; ++i) {
      if (cfg.input_index[i] < 0) continue;
      SimulationTarget& t = simulation_target(cfg.tag_key[i]);
      t.input_index = cfg.input_index[i];
      t.readers.emplace_back(static_cast<int>(slot), i);
      if (!matrix_.find_cause(out_.cause_ids[slot])->tags[i].simulation_allowed) t.allowed = false;
    }
  }
  for (std::size_t slot = 0; slot < out_.effects.size(); ++slot) {
    const EffectConfig& cfg = out_.effects[slot];
    for (int j = 0; j < cfg.tag_count; ++j) {
      SimulationTarget& t = simulation_target(cfg.tag_key[j]);
      t.outputs.emplace_back(static_cast<int>(slot), j);
      if (!matrix_.find_effect(out_.effect_ids[slot])->tags[j].simulation_allowed) t.allowed = false;
    }
  }
}

}  // namespace

int ScanLayout::cause_slot(int id) const { return slot_of(cause_ids, id); }
int ScanLayout::effect_slot(int id) const { return slot_of(effect_ids, id); }

ScanLayout lay_out(const model::Matrix& m, const model::InputTable& inputs) {
  return LayoutBuilder(m, inputs).build();
}

}  // namespace cemv::runtime
