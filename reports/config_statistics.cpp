// The counts of the configuration report's size-and-usage section.
#include "reports/config_document.hpp"

#include "model/text.hpp"
#include "model/vocabulary.hpp"

namespace cemv::reports::config {

using namespace cemv::model;

Statistics statistics(const Matrix& m) {
  Statistics s;
  for (auto t : {IntersectionType::N, IntersectionType::S, IntersectionType::V, IntersectionType::R,
                 IntersectionType::X, IntersectionType::Note})
    s.by_type[to_string(t)] = 0;
  for (auto f : {CauseFunction::Normal, CauseFunction::And, CauseFunction::Or,
                 CauseFunction::TwoOoThree, CauseFunction::Comment})
    s.by_function[to_string(f)] = 0;
  for (auto k : {InputKind::Discrete, InputKind::Analog}) s.by_input[to_string(k)] = 0;
  for (auto t : {TimeMode::None, TimeMode::OnDelay, TimeMode::OffDelay, TimeMode::Timed})
    s.by_time[to_string(t)] = 0;
  for (auto b : {BadQuality::Ignore, BadQuality::Trip, BadQuality::Degrade})
    s.by_bad_quality[to_string(b)] = 0;
  for (auto f : {EffectFunction::Normal, EffectFunction::Comment}) s.by_effect_function[to_string(f)] = 0;

  auto count_ref = [&](const std::string& name) {
    if (parse_internal_ref(name)) ++s.internal_refs;
  };
  for (const auto& c : m.causes) {
    ++s.by_function[to_string(c.function)];
    ++s.by_input[to_string(c.input)];
    ++s.by_time[to_string(c.time.mode)];
    ++s.by_bad_quality[to_string(c.bad_quality)];
    s.cause_tags += static_cast<int>(c.tags.size());
    for (const auto& t : c.tags) count_ref(t.name);
    if (c.bypass_tag) ++s.bypass_tags;
    if (c.inhibit_tag) ++s.inhibit_tags;
    if (c.first_out_group) s.first_out_groups.insert(c.first_out_group);
    s.sif_used.insert(c.sif.begin(), c.sif.end());
  }
  for (const auto& e : m.effects) {
    ++s.by_effect_function[to_string(e.function)];
    s.effect_tags += static_cast<int>(e.tags.size());
    if (e.reset_tag) ++s.reset_tags;
    if (e.bypass_tag) ++s.effect_bypass_tags;
    s.sif_used.insert(e.sif.begin(), e.sif.end());
    bool xoon = false;
    for (const auto* x : m.intersections_of_effect(e.id)) xoon = xoon || x->xoon.has_value();
    if (xoon) ++s.xoon_effects;
  }
  for (const auto& x : m.intersections) {
    ++s.by_type[to_string(x.type)];
    if (!x.note.empty()) ++s.noted_intersections;
  }
  s.external_inputs = InputTable(m).size();
  return s;
}

}  // namespace cemv::reports::config
