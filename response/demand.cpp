#include "response/demand.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "model/vocabulary.hpp"
#include "response/plant.hpp"

namespace cemv::response {

using model::Cause;

namespace {

// The causes a demand run trips: every trigger cause of a single-cause path;
// of an XooN path the X slowest, in degraded mode the degraded cause and the
// X - 1 slowest of the rest. Slowest: the longest on-delay first (the set
// whose response is latest); among equals a timed cause first (its pulse may
// end before the slower members' timers expire, and then the XooN never sees
// X active causes), then a cause whose bypass and inhibit no logic drives (a
// run in which a member is held off judges nothing from then on). With
// `pulses_first`, the timed causes come before all others, shortest pulse
// first: a pulse that ends before an on-delay member fires holds the XooN
// off for ever (big_matrix's 2oo7 into effect 77: a 0.2 s pulse beside a
// 0.9 s on-delay).
std::vector<int> demand_set(const model::Matrix& m, const Path& p, Mode mode, bool pulses_first, int bad) {
  if (p.causes.size() == 1) return p.causes;
  const bool degraded = mode == Mode::Degraded && !p.voted.empty();
  std::vector<int> out, rest;
  if (degraded) out.push_back(bad);
  for (int id : p.causes)
    if (!degraded || id != bad) rest.push_back(id);
  auto rank = [&](int id) {
    const Cause& c = *m.find_cause(id);
    const bool pulse = c.time.mode == model::TimeMode::Timed;
    return std::make_tuple(pulses_first && pulse ? static_cast<long long>(c.time.ms) - (1LL << 40) : 0LL,
                           c.time.mode == model::TimeMode::OnDelay ? -static_cast<long long>(c.time.ms) : 0LL,
                           pulse ? 0 : 1, held_by_logic(c) ? 1 : 0);
  };
  std::stable_sort(rest.begin(), rest.end(), [&](int a, int b) { return rank(a) < rank(b); });
  for (int id : rest)
    if (static_cast<int>(out.size()) < p.needed) out.push_back(id);
  return out;
}

// The voted trigger cause whose input the degraded demand runs put in bad
// quality first (0: none).
int first_voted(const Path& p) { return p.voted.empty() ? 0 : p.voted.front(); }

// A cause's input inside its limit: a discrete input at its healthy value, an
// analog one at `value` unless that is beyond the limit, else clear of the
// hysteresis band.
float healthy_value(const Cause& c, const model::CauseTag& t, float value) {
  if (c.input == model::InputKind::Analog && c.analog) {
    const bool high = c.analog->limit_type == model::LimitType::High;
    const float clear = std::max(1.0f, 2.0f * c.analog->hysteresis);
    if (high ? value >= c.analog->limit : value <= c.analog->limit)
      return high ? c.analog->limit - clear : c.analog->limit + clear;
    return value;
  }
  return t.ett ? 0.0f : 1.0f;
}

// `bad`: in degraded mode, the voted trigger cause with an input in bad
// quality.
// `also_tripped`: causes tripped in every cycle besides (rest_trips_released_by).
std::vector<model::CycleInput> demand_run(const model::Matrix& m, const Path& p, Mode mode, long long cycles,
                                          bool pulses_first, int bad,
                                          const std::vector<const Cause*>& also_tripped = {}) {
  const model::InputTable table(m);
  // The plant quiet: every cause's inputs inside their limits (scenario
  // defaults need not be: a de-energise-to-trip input defaults to 0), so that
  // nothing but the demand acts on the path's effect.
  model::CycleInput quiet = model::default_cycle_input(m);
  auto make_healthy = [&](const Cause& c) {
    for (const auto* t : external_tags(c))
      if (auto index = table.find(t->name)) quiet.tags[*index].value = healthy_value(c, *t, quiet.tags[*index].value);
  };
  for (const auto& c : m.causes) make_healthy(c);
  // Two causes may read one tag with limits no single value keeps both
  // inside (a high limit of -9 and a low limit of 132.5): then the causes
  // linked to the path's effects decide, so that those effects are quiet.
  const std::set<int> effects = effects_on(p);
  for (const auto& x : m.intersections)
    if (effects.count(x.effect))
      if (const Cause* c = m.find_cause(x.cause)) make_healthy(*c);
  // And last the causes of the elements that would hold a path cause off:
  // a path cause held off judges nothing, where another cause that reads
  // the same tag may still be quiet by its voting (big_matrix's `BSL_103A`:
  // cause 3 trips effect 64, which inhibits cause 86 of the path, at 0;
  // cause 5 of the path needs two of its three inputs).
  const Holders holders = holders_of(m, p);
  for (const auto& x : m.intersections)
    if (holders.effects.count(x.effect))
      if (const Cause* c = m.find_cause(x.cause); c && !std::count(p.causes.begin(), p.causes.end(), c->id))
        make_healthy(*c);
  for (int id : holders.causes)
    if (const Cause* c = m.find_cause(id); c && !std::count(p.causes.begin(), p.causes.end(), id)) make_healthy(*c);
  // An effect on the path that passes process data through shows the BPCS
  // value while it is not active (E.8): that value away from the active
  // state, so that the outputs respond only when the effect does. The
  // process value is P for a DTT tag and NOT P for an ETT one (E.9), so P = 1
  // puts every tag away from its safe value (0 DTT, 1 ETT), whatever its ett.
  for (const auto& n : p.elements) {
    if (n.kind != model::Node::Kind::Effect) continue;
    const model::Effect& e = *m.find_effect(n.id);
    if (!e.process_data || !e.process_data->pass_through || !e.process_data->tag) continue;
    if (auto index = table.find(*e.process_data->tag)) quiet.tags[*index].value = 1.0f;
  }
  // A cause's inputs beyond their limits (the first of them in bad quality
  // when `bad_first`).
  // Without a bad input, only as many inputs as the voting needs, those no
  // other cause reads first: a tag shared with another cause trips that one
  // too, and with it whatever it drives (big_matrix's cause 34 shares
  // FSL_105A with cause 5, whose effect 6 inhibits cause 57 of the same
  // XooN, and the run then judges nothing).
  std::map<std::string, int> readers;
  for (const auto& c : m.causes)
    for (const auto* t : external_tags(c)) ++readers[model::tag_key(t->name)];
  auto trip = [&](model::CycleInput& cycle, const Cause& c, bool bad_first) {
    auto tags = external_tags(c);
    if (!bad_first) {
      std::stable_sort(tags.begin(), tags.end(), [&](const auto* a, const auto* b) {
        return readers[model::tag_key(a->name)] < readers[model::tag_key(b->name)];
      });
      tags.resize(std::min(tags.size(), static_cast<std::size_t>(std::max(1, votes_needed(c)))));
    }
    for (std::size_t k = 0; k < tags.size(); ++k) {
      auto index = table.find(tags[k]->name);
      if (!index) continue;
      model::TagValue& v = cycle.tags[*index];
      v.bad_quality = bad_first && k == 0;
      // A bad input in `ignore` mode votes with the value delivered (C.3):
      // the worst case delivers its healthy value, which the quiet plant has.
      if (v.bad_quality && c.bad_quality == model::BadQuality::Ignore) continue;
      if (c.input == model::InputKind::Analog && c.analog)
        v.value = c.analog->limit;
      else
        v.value = tags[k]->ett ? 1.0f : 0.0f;
    }
  };
  for (const Cause* c : holds_released_by(m, p)) trip(quiet, *c, false);
  for (const Cause* c : also_tripped) trip(quiet, *c, false);
  // The demand: the trigger causes' inputs beyond their limits.
  model::CycleInput demand = quiet;
  for (int id : demand_set(m, p, mode, pulses_first, bad))
    trip(demand, *m.find_cause(id), mode == Mode::Degraded && !p.voted.empty() && id == bad);
  std::vector<model::CycleInput> run{quiet};
  run.resize(static_cast<std::size_t>(std::max(0LL, cycles)) + 2, demand);
  return run;
}

}  // namespace

std::vector<model::CycleInput> demand_run(const model::Matrix& m, const Path& p, Mode mode, long long cycles) {
  return demand_run(m, p, mode, cycles, false, first_voted(p));
}

namespace {

void hold_off(std::vector<model::CycleInput>& run, const std::set<std::size_t>& tags) {
  for (auto& cycle : run)
    for (std::size_t i : tags) cycle.tags[i].value = 1.0f;
}

}  // namespace

std::optional<std::vector<model::CycleInput>> demand_run_alone(const model::Matrix& m, const Path& p, Mode mode,
                                                               long long cycles) {
  const std::set<std::size_t> tags = hold_off_tags(m, p);
  if (tags.empty()) return std::nullopt;
  std::vector<model::CycleInput> run = demand_run(m, p, mode, cycles);
  hold_off(run, tags);
  return run;
}

std::optional<std::vector<model::CycleInput>> demand_run_pulses_first(const model::Matrix& m, const Path& p,
                                                                      Mode mode, long long cycles) {
  if (p.causes.size() < 2) return std::nullopt;
  bool pulse = false;
  for (int id : p.causes) pulse = pulse || m.find_cause(id)->time.mode == model::TimeMode::Timed;
  if (!pulse) return std::nullopt;
  // With the path alone where it can be (demand_run_alone): a run in which a
  // member is held off judges nothing.
  std::vector<model::CycleInput> run = demand_run(m, p, mode, cycles, true, first_voted(p));
  hold_off(run, hold_off_tags(m, p));
  return run;
}

namespace {

// demand_run_after_reset on the quiet plant and the demand of `base`.
std::optional<std::vector<model::CycleInput>> after_reset(const model::Matrix& m, const Path& p, long long cycles,
                                                          const std::vector<model::CycleInput>& base) {
  const std::set<int> effects = effects_on(p);
  const std::set<int> linked = linked_causes(m, p);
  long long settle = 0;
  for (int id : linked)
    if (const Cause* c = m.find_cause(id); c && c->time.mode != model::TimeMode::None)
      settle = std::max(settle, cycles_of(c->time.ms, m.cycle_ms));
  for (int id : effects) settle = std::max(settle, cycles_of(m.find_effect(id)->output_delay_ms, m.cycle_ms));
  settle += 1;
  constexpr long long kMaxSettle = 10000;
  if (settle > kMaxSettle) return std::nullopt;
  const model::CycleInput quiet = base.front(), demand = base.back();
  model::CycleInput reset = quiet;
  const model::InputTable table(m);
  // Commands in the fixed order (model::CommandOrder): acknowledgements by
  // cause, then resets by effect.
  for (int id : linked)
    if (const Cause* c = m.find_cause(id); c && !c->auto_ack) {
      model::Command ack;
      ack.op = model::CommandOp::AckCause;
      ack.cause = id;
      reset.commands.push_back(ack);
    }
  for (int id : effects) {
    const model::Effect& e = *m.find_effect(id);
    if (!e.reset_tag) {
      model::Command c;
      c.op = model::CommandOp::ResetEffect;
      c.effect = id;
      reset.commands.push_back(c);
    } else if (!model::parse_internal_ref(*e.reset_tag)) {
      if (auto index = table.find(*e.reset_tag)) reset.tags[*index].value = quiet.tags[*index].value != 0.0f ? 0.0f : 1.0f;
    }
  }
  // Commands count only with secure write enabled (M.3).
  if (m.secure_write && !reset.commands.empty())
    if (auto index = table.find(m.secure_write->enable_tag)) reset.tags[*index].value = 1.0f;
  std::vector<model::CycleInput> run(static_cast<std::size_t>(settle), quiet);
  run.push_back(reset);
  run.push_back(quiet);
  run.resize(run.size() + static_cast<std::size_t>(std::max(0LL, cycles)) + 1, demand);
  return run;
}

}  // namespace

std::optional<std::vector<model::CycleInput>> demand_run_after_reset(const model::Matrix& m, const Path& p,
                                                                     Mode mode, long long cycles) {
  return after_reset(m, p, cycles,
                     demand_run_alone(m, p, mode, cycles).value_or(demand_run(m, p, mode, cycles)));
}

std::optional<std::vector<model::CycleInput>> demand_run_settled(const model::Matrix& m, const Path& p, Mode mode,
                                                                 long long cycles) {
  const std::vector<const Cause*> released = rest_trips_released_by(m, p);
  if (released.empty()) return std::nullopt;
  std::vector<model::CycleInput> base = demand_run(m, p, mode, cycles, false, first_voted(p), released);
  hold_off(base, hold_off_tags(m, p));
  return after_reset(m, p, cycles, base);
}

std::vector<model::CycleInput> demand_run_at_start_up(const model::Matrix& m, const Path& p, Mode mode,
                                                      long long cycles) {
  std::vector<model::CycleInput> run = demand_run(m, p, mode, cycles);
  run.erase(run.begin());
  return run;
}

std::vector<std::vector<model::CycleInput>> demand_runs(const model::Matrix& m, const Path& p, Mode mode,
                                                        long long cycles) {
  std::vector<std::vector<model::CycleInput>> out{demand_run(m, p, mode, cycles)};
  if (auto pulses = demand_run_pulses_first(m, p, mode, cycles)) out.push_back(std::move(*pulses));
  if (auto alone = demand_run_alone(m, p, mode, cycles)) out.push_back(std::move(*alone));
  if (auto reset = demand_run_after_reset(m, p, mode, cycles)) out.push_back(std::move(*reset));
  if (auto settled = demand_run_settled(m, p, mode, cycles)) out.push_back(std::move(*settled));
  out.push_back(demand_run_at_start_up(m, p, mode, cycles));
  // The degraded figure of an XooN path is that of its slowest voted member
  // in bad quality: the demand with each of the others in turn (an `and`
  // whose bad input is ignored never trips, and its set never responds).
  if (mode == Mode::Degraded && p.causes.size() > 1)
    for (std::size_t i = 1; i < p.voted.size(); ++i) out.push_back(demand_run(m, p, mode, cycles, false, p.voted[i]));
  return out;
}

}  // namespace cemv::response
