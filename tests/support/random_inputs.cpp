#include "tests/support/random_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tests/support/random_matrix.hpp"

namespace cemv::testsupport {

namespace {

using namespace cemv::model;

enum class Behaviour {
  CauseInput,  // tripped / non-tripped values, quality
  Hold,        // bypass, inhibit, mask, process value, enables: long holds
  Pulse,       // reset and group-deactivation set tags: rising edges
};

struct TagPlan {
  TagKind kind = TagKind::Bool;
  Behaviour behaviour = Behaviour::Hold;
  float normal = 0.0f;              // non-tripped default (docs/semantics.md S.1)
  float active_bias = 0.2f;         // Hold: probability of TRUE
  std::vector<float> candidates;    // analog: thresholds and their neighbours
  float lo = 0.0f, hi = 0.0f;       // analog: range of random values
  // State while generating.
  TagValue now;
  int hold = 0;
};

bool has_role(const InputTag& t, TagRole r) {
  return std::find(t.roles.begin(), t.roles.end(), r) != t.roles.end();
}

void add_with_neighbours(std::vector<float>& out, float v) {
  out.push_back(v);
  out.push_back(std::nextafter(v, -std::numeric_limits<float>::infinity()));
  out.push_back(std::nextafter(v, std::numeric_limits<float>::infinity()));
}

// The value a scenario starts an analog input at (docs/semantics.md S.1), computed
// as the scenario format and the runtime do: in double, rounded to float once.
float non_tripped(const AnalogParams& a) {
  const double limit = a.limit, hysteresis = a.hysteresis;
  return static_cast<float>(a.limit_type == LimitType::High ? limit - hysteresis - 1.0 : limit + hysteresis + 1.0);
}

std::vector<TagPlan> plan_tags(const Matrix& m, const InputTable& table) {
  std::vector<TagPlan> plans(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) {
    const InputTag& t = table.tags()[i];
    TagPlan& p = plans[i];
    p.kind = t.kind;
    if (has_role(t, TagRole::CauseInput)) p.behaviour = Behaviour::CauseInput;
    else if (has_role(t, TagRole::EffectReset) || has_role(t, TagRole::GroupDeactivationSet))
      p.behaviour = Behaviour::Pulse;
    if (has_role(t, TagRole::SecureWriteEnable)) p.active_bias = 0.85f;
    if (has_role(t, TagRole::GroupDeactivationEnable) || has_role(t, TagRole::ProcessValue) ||
        has_role(t, TagRole::Mask))
      p.active_bias = 0.5f;
  }
  // Cause input tags: the first reader fixes the default, every reader adds its
  // thresholds.
  std::vector<bool> seen(table.size(), false);
  for (const auto& c : m.causes) {
    if (c.function == CauseFunction::Comment) continue;
    for (const auto& ct : c.tags) {
      auto idx = table.find(ct.name);
      if (!idx) continue;  // internal reference
      TagPlan& p = plans[*idx];
      if (c.analog && p.kind == TagKind::Analog) {
        const AnalogParams& a = *c.analog;
        if (!seen[*idx]) {
          p.normal = non_tripped(a);
          p.lo = p.hi = a.limit;
        }
        float h = a.hysteresis, d = a.delta;
        for (float v : {a.limit, a.limit - h, a.limit + h, non_tripped(a)}) add_with_neighbours(p.candidates, v);
        if (a.prewarning) add_with_neighbours(p.candidates, *a.prewarning);
        if (d > 0)
          for (float v : {a.limit - d, a.limit + d, a.limit - (d - h), a.limit + (d - h)})
            add_with_neighbours(p.candidates, v);
        for (float v : p.candidates) {
          p.lo = std::min(p.lo, v);
          p.hi = std::max(p.hi, v);
        }
      } else if (!seen[*idx]) {
        p.normal = ct.ett ? 0.0f : 1.0f;  // DTT is healthy TRUE, ETT healthy FALSE (6.3.4)
      }
      seen[*idx] = true;
    }
  }
  for (auto& p : plans) {
    p.now.value = p.normal;
    p.now.bad_quality = false;
  }
  return plans;
}

float random_analog(Rng& rng, const TagPlan& p) {
  int r = rng.uniform(0, 99);
  if (r < 70 && !p.candidates.empty()) return rng.pick(p.candidates);
  if (r < 90) {
    // Clamped so that a hand-written matrix with huge limits cannot overflow int.
    int lo = static_cast<int>(std::floor(std::clamp(p.lo, -1.0e6f, 1.0e6f))) - 20;
    int hi = static_cast<int>(std::ceil(std::clamp(p.hi, -1.0e6f, 1.0e6f))) + 20;
    return static_cast<float>(rng.uniform(lo * 4, hi * 4)) / 4.0f;
  }
  // Values that are not short decimals, to exercise exact float handling.
  return static_cast<float>(rng.uniform(-1000000, 2000000)) / 7.0f;
}

int random_hold(Rng& rng) { return rng.chance(0.85) ? rng.uniform(1, 12) : rng.uniform(13, 60); }

void next_value(Rng& rng, TagPlan& p) {
  switch (p.behaviour) {
    case Behaviour::CauseInput:
      if (p.kind == TagKind::Analog) {
        p.now.value = random_analog(rng, p);
      } else {
        // Mostly healthy, tripped for a while now and then.
        p.now.value = rng.chance(0.35) ? 1.0f - p.normal : p.normal;
      }
      p.now.bad_quality = rng.chance(0.08);
      p.hold = random_hold(rng);
      break;
    case Behaviour::Hold:
      p.now.value = rng.chance(p.active_bias) ? 1.0f : 0.0f;
      p.hold = random_hold(rng);
      break;
    case Behaviour::Pulse:
      if (p.now.value != 0.0f) {
        p.now.value = 0.0f;
        p.hold = rng.uniform(3, 40);
      } else {
        p.now.value = 1.0f;
        p.hold = rng.uniform(1, 3);
      }
      break;
  }
}

struct Targets {
  std::vector<int> causes, all_causes, effects, all_effects, groups;
  std::vector<const Cause*> delta_causes;
  std::vector<std::string> outputs;
  int max_cause = 0, max_effect = 0;
};

Targets targets_of(const Matrix& m) {
  Targets t;
  for (const auto& c : m.causes) {
    t.all_causes.push_back(c.id);
    t.max_cause = std::max(t.max_cause, c.id);
    if (c.function == CauseFunction::Comment) continue;
    t.causes.push_back(c.id);
    if (c.first_out_group && std::find(t.groups.begin(), t.groups.end(), c.first_out_group) == t.groups.end())
      t.groups.push_back(c.first_out_group);
    if (c.analog && c.analog->delta > 0 && c.tags.size() >= 2) t.delta_causes.push_back(&c);
  }
  for (const auto& e : m.effects) {
    t.all_effects.push_back(e.id);
    t.max_effect = std::max(t.max_effect, e.id);
    if (e.function == EffectFunction::Comment) continue;
    t.effects.push_back(e.id);
    for (const auto& tag : e.tags) t.outputs.push_back(tag.name);
  }
  if (t.groups.empty()) t.groups.push_back(1);
  return t;
}

// Mostly a processed element, sometimes one the runtime must refuse: a comment
// element, id 0 or an id past the last.
int pick_id(Rng& rng, const std::vector<int>& valid, const std::vector<int>& all, int max_id) {
  int r = rng.uniform(0, 99);
  if (r < 88 && !valid.empty()) return rng.pick(valid);
  if (r < 94 && !all.empty()) return rng.pick(all);
  return r < 97 ? 0 : max_id + rng.uniform(1, 5);
}

Command random_command(Rng& rng, const Matrix& m, const InputTable& table, const std::vector<TagPlan>& plans,
                       const Targets& t) {
  Command c;
  c.op = static_cast<CommandOp>(rng.uniform(0, static_cast<int>(CommandOp::ClearAlarms)));
  auto cause = [&] { return pick_id(rng, t.causes, t.all_causes, t.max_cause); };
  auto effect = [&] { return pick_id(rng, t.effects, t.all_effects, t.max_effect); };
  switch (c.op) {
    case CommandOp::AckCause:
      c.cause = cause();
      break;
    case CommandOp::ResetEffect:
    case CommandOp::OverrideEffect:
    case CommandOp::StopOverride:
      c.effect = effect();
      break;
    case CommandOp::SoftBypassCause:
      c.cause = cause();
      c.on = rng.chance(0.6);
      break;
    case CommandOp::SoftBypassTag: {
      c.cause = cause();
      const Cause* cc = m.find_cause(c.cause);
      int ntags = cc ? static_cast<int>(cc->tags.size()) : 1;
      c.tag = rng.chance(0.92) ? rng.uniform(1, std::max(1, ntags)) : rng.uniform(0, 4);
      c.on = rng.chance(0.6);
      break;
    }
    case CommandOp::SoftBypassEffect:
      c.effect = effect();
      c.on = rng.chance(0.6);
      break;
    case CommandOp::SimulateTag: {
      int r = rng.uniform(0, 99);
      if (r < 70 && table.size() > 0) {
        std::size_t i = static_cast<std::size_t>(rng.uniform(0, static_cast<int>(table.size()) - 1));
        c.tag_name = table.tags()[i].name;
        c.value = plans[i].kind == TagKind::Analog ? random_analog(rng, plans[i]) : (rng.chance(0.5) ? 1.0f : 0.0f);
      } else if (r < 92 && !t.outputs.empty()) {
        c.tag_name = rng.pick(t.outputs);
        c.value = rng.chance(0.5) ? 1.0f : 0.0f;
      } else {
        c.tag_name = "NO_SUCH_TAG";
        c.value = 1.0f;
      }
      break;
    }
    case CommandOp::StopSimulation:
      if (rng.chance(0.5) && table.size() > 0)
        c.tag_name = table.tags()[static_cast<std::size_t>(rng.uniform(0, static_cast<int>(table.size()) - 1))].name;
      break;
    case CommandOp::ClearFirstOut:
      c.group = rng.chance(0.9) ? rng.pick(t.groups) : rng.uniform(0, 16);
      break;
    case CommandOp::ClearAlarms:
      if (rng.chance(0.5)) c.cause = cause();
      else c.effect = effect();
      break;
  }
  return c;
}

std::uint64_t scramble(std::uint64_t seed) {
  Rng r(seed ^ 0x696E70757473ull /* "inputs" */);
  return r.next();
}

}  // namespace

CycleInput default_inputs(const Matrix& m) {
  InputTable table(m);
  auto plans = plan_tags(m, table);
  CycleInput in;
  for (const auto& p : plans) in.tags.push_back(p.now);
  return in;
}

std::vector<CycleInput> random_inputs(const Matrix& m, std::uint64_t seed, int cycles) {
  Rng rng(scramble(seed));
  InputTable table(m);
  auto plans = plan_tags(m, table);
  Targets targets = targets_of(m);
  for (auto& p : plans) p.hold = rng.uniform(1, 8);  // start calm, then diverge

  std::vector<CycleInput> frames;
  frames.reserve(static_cast<std::size_t>(std::max(cycles, 0)));
  for (int k = 0; k < cycles; ++k) {
    if (k > 0) {
      for (auto& p : plans)
        if (--p.hold <= 0) next_value(rng, p);
      // Now and then all tags of a cause with a discrepancy alarm move together,
      // about `delta` apart (6.3.5): exactly delta, just under, delta - hysteresis.
      if (!targets.delta_causes.empty() && rng.chance(0.05)) {
        const Cause* c = rng.pick(targets.delta_causes);
        const AnalogParams& a = *c->analog;
        float base = rng.chance(0.5) ? a.limit : non_tripped(a);
        std::vector<float> offsets = {0.0f, a.delta, a.delta - a.hysteresis,
                                      std::nextafter(a.delta, 0.0f), -a.delta};
        int hold = random_hold(rng);
        for (const auto& ct : c->tags) {
          auto idx = table.find(ct.name);
          if (!idx) continue;
          plans[*idx].now.value = base + rng.pick(offsets);
          plans[*idx].now.bad_quality = false;
          plans[*idx].hold = hold;
        }
      }
    }
    CycleInput in;
    in.tags.reserve(plans.size());
    for (const auto& p : plans) in.tags.push_back(p.now);
    if (k > 0 && rng.chance(0.25)) {
      in.commands.push_back(random_command(rng, m, table, plans, targets));
      if (rng.chance(0.15)) in.commands.push_back(random_command(rng, m, table, plans, targets));
    }
    frames.push_back(std::move(in));
  }
  return frames;
}

}  // namespace cemv::testsupport
