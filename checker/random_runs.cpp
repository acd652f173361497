#include "checker/random_runs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace cemv::checker {

std::vector<float> analog_test_values(const model::Matrix& m, const model::InputTag& tag, float hold) {
  std::vector<float> v{hold, model::default_tag_value(m, tag).value, 0.0f};
  const float inf = std::numeric_limits<float>::infinity();
  for (const auto& c : m.causes) {
    if (c.input != model::InputKind::Analog || !c.analog) continue;
    bool reads = false;
    for (const auto& t : c.tags) reads |= model::tag_key(t.name) == model::tag_key(tag.name);
    if (!reads) continue;
    const auto& a = *c.analog;
    const bool high = a.limit_type == model::LimitType::High;
    const float safe = high ? -inf : inf;
    const float thr = high ? a.limit - a.hysteresis : a.limit + a.hysteresis;
    const float margin = std::max(1.0f, a.hysteresis);
    v.push_back(a.limit);
    v.push_back(std::nextafter(a.limit, safe));
    v.push_back(thr);
    v.push_back(std::nextafter(thr, safe));
    v.push_back(high ? a.limit + 2 * margin : a.limit - 2 * margin);
    v.push_back(high ? thr - margin : thr + margin);
    if (a.prewarning) {
      v.push_back(*a.prewarning);
      v.push_back(std::nextafter(*a.prewarning, safe));
    }
    if (a.delta > 0.0f) {
      v.push_back(a.limit + a.delta);
      v.push_back(a.limit - a.delta);
    }
  }
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

namespace {

// Cycles of each duration the matrix configures (docs/semantics.md C.6, C.8,
// E.3, E.7), and one either side: a run then stops at an expiry, one cycle
// before or one after it.
void add_durations(const model::Matrix& m, std::set<std::size_t>& holds) {
  const std::uint64_t cycle = std::max<std::uint32_t>(1, m.cycle_ms);
  auto add_ms = [&](std::uint64_t ms) {
    if (ms == 0) return;
    const std::uint64_t lo = ms / cycle, hi = (ms + cycle - 1) / cycle;
    for (std::uint64_t n : {lo, hi})
      for (std::uint64_t d : {n - 1, n, n + 1})
        if (d >= 1 && n >= 1) holds.insert(static_cast<std::size_t>(d));
  };
  auto add_timeout = [&](std::uint32_t max_s, std::uint32_t prealarm_s) {
    add_ms(std::uint64_t{max_s} * 1000);
    add_ms(std::uint64_t{prealarm_s} * 1000);
    if (max_s > prealarm_s) add_ms(std::uint64_t{max_s - prealarm_s} * 1000);
  };
  for (const auto& c : m.causes) {
    add_ms(c.time.ms);
    add_timeout(c.soft_bypass.max_s, c.soft_bypass.prealarm_s);
  }
  for (const auto& e : m.effects) {
    add_ms(e.output_delay_ms);
    if (e.override_time) add_timeout(e.override_time->max_s, e.override_time->prealarm_s);
  }
}

void add_space(const model::Matrix& m, const std::vector<std::string>& only, std::vector<RunSpace::Tag>& tags) {
  const model::InputTable table(m);
  for (const auto& t : table.tags()) {
    if (!only.empty() && std::none_of(only.begin(), only.end(), [&](const std::string& n) {
          return model::tag_key(n) == model::tag_key(t.name);
        }))
      continue;
    auto it = std::find_if(tags.begin(), tags.end(),
                           [&](const RunSpace::Tag& x) { return model::tag_key(x.name) == model::tag_key(t.name); });
    std::vector<float> values =
        t.kind == model::TagKind::Analog ? analog_test_values(m, t, model::default_tag_value(m, t).value)
                                         : std::vector<float>{0.0f, 1.0f};
    if (it == tags.end()) {
      tags.push_back({t.name, std::move(values)});
      continue;
    }
    it->values.insert(it->values.end(), values.begin(), values.end());
    std::sort(it->values.begin(), it->values.end());
    it->values.erase(std::unique(it->values.begin(), it->values.end()), it->values.end());
  }
}

// Every command an operator can give on `m`, simulation aside (O.1-O.10).
std::vector<model::Command> all_commands(const model::Matrix& m) {
  using model::CommandOp;
  std::vector<model::Command> out;
  auto add = [&](CommandOp op, int cause, int effect, int tag, int group, bool on) {
    model::Command c;
    c.op = op;
    c.cause = cause;
    c.effect = effect;
    c.tag = tag;
    c.group = group;
    c.on = on;
    out.push_back(c);
  };
  std::set<int> groups;
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    add(CommandOp::AckCause, c.id, 0, 0, 0, true);
    add(CommandOp::ClearAlarms, c.id, 0, 0, 0, true);
    for (bool on : {true, false}) {
      add(CommandOp::SoftBypassCause, c.id, 0, 0, 0, on);
      for (std::size_t t = 0; t < c.tags.size(); ++t)
        add(CommandOp::SoftBypassTag, c.id, 0, static_cast<int>(t + 1), 0, on);
    }
    if (c.first_out_group) groups.insert(c.first_out_group);
  }
  for (const auto& e : m.effects) {
    if (e.function == model::EffectFunction::Comment) continue;
    for (auto op : {CommandOp::ResetEffect, CommandOp::OverrideEffect, CommandOp::StopOverride, CommandOp::ClearAlarms})
      add(op, 0, e.id, 0, 0, true);
    for (bool on : {true, false}) add(CommandOp::SoftBypassEffect, 0, e.id, 0, 0, on);
  }
  for (int g : groups) add(CommandOp::ClearFirstOut, 0, 0, 0, g, true);
  return out;
}

}  // namespace

namespace {

// The changes that trip cause `c`: every tag it votes with beyond its limit
// (C.3: a DTT tag at FALSE, an ETT tag at TRUE; an analog tag past its limit
// by twice the hysteresis), in good quality; empty when one of its tags is
// not among `have` (a reference trips with its element, not with a value).
std::vector<RunSegment::Change> trip_of(const model::Cause& c, const std::set<std::string>& have) {
  std::vector<RunSegment::Change> trip;
  for (const auto& t : c.tags) {
    if (model::parse_internal_ref(t.name)) continue;
    if (!have.count(model::tag_key(t.name))) return {};
    float value = t.ett ? 1.0f : 0.0f;
    if (c.input == model::InputKind::Analog && c.analog) {
      const auto& a = *c.analog;
      const float margin = std::max(1.0f, a.hysteresis);
      value = a.limit_type == model::LimitType::High ? a.limit + 2 * margin : a.limit - 2 * margin;
    }
    trip.push_back({t.name, {value, false}});
  }
  return trip;
}

}  // namespace

std::vector<RunSegment::Change> cause_trip(const model::Cause& c, const std::vector<std::string>& tags) {
  std::set<std::string> have;
  for (const auto& t : tags) have.insert(model::tag_key(t));
  return trip_of(c, have);
}

std::vector<std::vector<RunSegment::Change>> cause_trips(const model::Matrix& m, const std::vector<std::string>& tags) {
  std::set<std::string> have;
  for (const auto& t : tags) have.insert(model::tag_key(t));
  std::map<int, std::vector<RunSegment::Change>> by_cause;
  std::vector<std::vector<RunSegment::Change>> out;
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    std::vector<RunSegment::Change> trip = trip_of(c, have);
    if (trip.empty()) continue;
    by_cause[c.id] = trip;
    out.push_back(std::move(trip));
  }
  // Every cause of an effect's XooN assignment at once: X of them active
  // together, which trips of one cause at a time seldom reach.
  for (const auto& e : m.effects) {
    std::vector<RunSegment::Change> all;
    std::size_t causes = 0;
    bool complete = true;
    for (const auto* i : m.intersections_of_effect(e.id)) {
      if (!i->xoon) continue;
      auto it = by_cause.find(i->cause);
      if (it == by_cause.end()) {
        complete = false;
        break;
      }
      all.insert(all.end(), it->second.begin(), it->second.end());
      ++causes;
    }
    if (complete && causes >= 2) out.push_back(std::move(all));
  }
  return out;
}

std::vector<std::vector<RunSegment::Change>> rests_of(const model::Matrix& m,
                                                      const std::vector<std::vector<RunSegment::Change>>& trips) {
  const model::InputTable table(m);
  const model::CycleInput defaults = model::default_cycle_input(m);
  std::vector<std::vector<RunSegment::Change>> out;
  for (const auto& trip : trips) {
    std::vector<RunSegment::Change> rest;
    for (const auto& c : trip)
      if (auto i = table.find(c.tag)) rest.push_back({c.tag, {defaults.tags[*i].value, false}});
    out.push_back(std::move(rest));
  }
  return out;
}

RunSpace run_space(const model::Matrix& m, const model::Matrix* other, const std::vector<std::string>& tags,
                   const std::vector<model::Command>& commands) {
  RunSpace s;
  add_space(m, tags, s.tags);
  if (other) add_space(*other, tags, s.tags);
  for (const auto& c : commands)
    if (c.op != model::CommandOp::SimulateTag && c.op != model::CommandOp::StopSimulation) s.commands.push_back(c);
  if (commands.empty()) s.commands = all_commands(m);
  std::set<std::size_t> holds{1, 2, 3};
  add_durations(m, holds);
  if (other) add_durations(*other, holds);
  s.holds.assign(holds.begin(), holds.end());
  return s;
}

std::uint64_t RandomRuns::draw(std::uint64_t n) {
  // xorshift64*: fixed on every platform.
  state_ ^= state_ >> 12;
  state_ ^= state_ << 25;
  state_ ^= state_ >> 27;
  const std::uint64_t x = state_ * 0x2545F4914F6CDD1DULL;
  return n ? (x >> 11) % n : 0;
}

Run RandomRuns::next(std::size_t segments, std::size_t max_cycles) {
  Run run;
  std::size_t left = max_cycles;
  for (std::size_t s = 0; s < segments && left > 0; ++s) {
    RunSegment seg;
    if (!space_.trips.empty() && draw(3) == 0) {
      const std::size_t k = draw(space_.trips.size());
      const bool rest = k < space_.rests.size() && draw(2) == 0;
      seg.changes = rest ? space_.rests[k] : space_.trips[k];
      const std::size_t fitting = static_cast<std::size_t>(
          std::upper_bound(space_.holds.begin(), space_.holds.end(), left) - space_.holds.begin());
      seg.cycles = fitting == 0 ? left : space_.holds[fitting - 1];
      left -= seg.cycles;
      run.push_back(std::move(seg));
      continue;
    }
    const bool command = !space_.commands.empty() && (space_.tags.empty() || draw(3) == 0);
    const std::size_t changes = space_.tags.empty() ? 0 : (command ? draw(2) : 1 + draw(2));
    for (std::size_t c = 0; c < changes; ++c) {
      const auto& t = space_.tags[draw(space_.tags.size())];
      RunSegment::Change ch{t.name, {t.values[draw(t.values.size())], draw(6) == 0}};
      seg.changes.push_back(ch);
    }
    if (command) seg.commands.push_back(space_.commands[draw(space_.commands.size())]);
    // Half of the segments last a cycle or a few, the others a configured
    // duration.
    const std::size_t fitting = static_cast<std::size_t>(
        std::upper_bound(space_.holds.begin(), space_.holds.end(), left) - space_.holds.begin());
    seg.cycles = draw(2) == 0 || fitting == 0 ? 1 + draw(3) : space_.holds[draw(fitting)];
    seg.cycles = std::min(seg.cycles, left);
    left -= seg.cycles;
    run.push_back(std::move(seg));
  }
  return run;
}

void for_each_cycle(const model::Matrix& m, const Run& run, const model::CycleInput& start,
                    const std::function<bool(const model::CycleInput&)>& each) {
  const model::InputTable table(m);
  const model::CommandOrder order(m);
  model::CycleInput held = start;
  held.commands.clear();
  for (const auto& seg : run) {
    for (const auto& ch : seg.changes)
      if (auto i = table.find(ch.tag)) {
        held.tags[*i] = ch.value;
        if (table.tags()[*i].kind == model::TagKind::Bool) held.tags[*i].value = ch.value.value != 0.0f ? 1.0f : 0.0f;
      }
    model::CycleInput first = held;
    for (const auto& c : seg.commands)
      if ((c.cause == 0 || m.find_cause(c.cause)) && (c.effect == 0 || m.find_effect(c.effect)))
        first.commands.push_back(c);
    first.commands = order.canonical(first.commands);
    if (!each(first)) return;
    for (std::size_t k = 1; k < seg.cycles; ++k)
      if (!each(held)) return;
  }
}

std::vector<model::CycleInput> expand(const model::Matrix& m, const Run& run, const model::CycleInput& start) {
  std::vector<model::CycleInput> out;
  out.reserve(run_cycles(run));
  for_each_cycle(m, run, start, [&](const model::CycleInput& in) {
    out.push_back(in);
    return true;
  });
  return out;
}

std::size_t run_cycles(const Run& run) {
  std::size_t n = 0;
  for (const auto& s : run) n += s.cycles;
  return n;
}

namespace {

// The run up to and including cycle `cycle`.
Run cut(Run run, std::size_t cycle) {
  std::size_t at = 0;
  for (std::size_t s = 0; s < run.size(); ++s) {
    if (cycle < at + run[s].cycles) {
      run[s].cycles = cycle - at + 1;
      run.resize(s + 1);
      return run;
    }
    at += run[s].cycles;
  }
  return run;
}

}  // namespace

Run minimise_run(Run run, const std::function<long(const Run&)>& keep) {
  long c = keep(run);
  if (c < 0) return run;
  run = cut(std::move(run), static_cast<std::size_t>(c));
  for (std::size_t s = run.size(); s-- > 0;) {
    if (run.size() <= 1) break;
    if (s >= run.size()) continue;
    Run shorter = run;
    shorter.erase(shorter.begin() + static_cast<long>(s));
    if (long k = keep(shorter); k >= 0) run = cut(std::move(shorter), static_cast<std::size_t>(k));
  }
  for (std::size_t s = 0; s < run.size(); ++s) {
    if (run[s].cycles <= 1) continue;
    Run shorter = run;
    shorter[s].cycles = 1;
    if (long k = keep(shorter); k >= 0) run = cut(std::move(shorter), static_cast<std::size_t>(k));
  }
  return run;
}

}  // namespace cemv::checker
