// The field suite (docs/testgen.md, "Field suite"). Each test is built on the
// reference runtime one field step at a time: the step's action is applied,
// the runtime runs until nothing changes any more (bounded by the loop's time
// functions and output delays), and the step holds one second beyond the last
// change, rounded up to half seconds. What the technician is told to observe
// is what the runtime shows at the step's checkpoints; a timed observation
// is checked one cycle either side of its time (the tolerance printed).
#include "testgen/field.hpp"

#include <algorithm>
#include <map>
#include <set>


#include "formats/scenario_writer.hpp"
#include "checker/prover.hpp"
#include "checker/replay.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "model/text.hpp"
#include "properties/evaluator.hpp"
#include "testgen/field_words.hpp"

namespace cemv::testgen {

using namespace detail;

std::size_t FieldSuite::witnessed() const {
  std::size_t n = 0;
  for (const auto& o : objectives) n += o.test >= 0;
  return n;
}

namespace {

struct Segment {
  std::vector<std::pair<std::size_t, model::TagValue>> set;  // input index, value
  std::vector<model::Command> commands;
  std::size_t cycles = 0;  // 0: the step's last segment, held until the loop settles
};

// One loop test under construction.
class LoopBuilder {
 public:
  LoopBuilder(const model::Matrix& m, const FieldOptions& o, std::uint64_t settle_ms)
      : m_(m), o_(o), table_(m), all_(model::observables(m)), shown_(technician_observables(m)) {
    for (std::size_t i = 0; i < all_.size(); ++i) index_[all_[i].key] = i;
    for (const auto& s : shown_) shown_index_.push_back(index_.at(s.key));
    current_ = model::default_cycle_input(m);
    second_ = (1000 + m.cycle_ms - 1) / m.cycle_ms;
    bound_ = (settle_ms + 3000 + m.cycle_ms - 1) / m.cycle_ms;
  }

  const model::InputTable& table() const { return table_; }
  const std::vector<model::Observable>& all() const { return all_; }
  const std::vector<std::size_t>& shown() const { return shown_index_; }
  const std::vector<std::vector<int>>& run() const { return obs_; }
  const std::vector<model::CycleInput>& inputs() const { return inputs_; }
  const std::set<std::size_t>& checkpoints() const { return checkpoints_; }
  std::size_t index(const std::string& key) const { return index_.at(key); }
  const std::vector<int>& state() const { return obs_.back(); }

  // Applies the segments and holds; returns the step with its observations.
  FieldTestStep step(const std::string& phase, std::vector<std::string> actions, std::vector<Segment> segs,
                     bool initial = false) {
    const std::size_t start = inputs_.size();
    std::vector<model::CycleInput> tail;
    std::size_t fixed = 0;
    for (std::size_t s = 0; s < segs.size(); ++s) {
      for (const auto& [i, v] : segs[s].set) current_.tags[i] = v;
      const bool last = s + 1 == segs.size();
      const std::size_t n = last ? bound_ : segs[s].cycles;
      for (std::size_t k = 0; k < n; ++k) {
        model::CycleInput in = current_;
        if (k == 0) in.commands = segs[s].commands;
        tail.push_back(std::move(in));
      }
      if (!last) fixed += n;
    }
    std::vector<model::CycleInput> all_in = inputs_;
    all_in.insert(all_in.end(), tail.begin(), tail.end());
    checker::ConcreteTrace t = checker::run_on_runtime(m_, all_in);
    std::size_t last_change = 0;
    for (std::size_t k = std::max<std::size_t>(start, 1); k < all_in.size(); ++k)
      if (t.observables[k] != t.observables[k - 1]) last_change = k - start;
    const std::size_t half = std::max<std::size_t>(1, (500 + m_.cycle_ms - 1) / m_.cycle_ms);
    std::size_t len = std::max(last_change + 1 + second_, fixed + second_);
    len = (len + half - 1) / half * half;
    if (len > all_in.size() - start) len = all_in.size() - start;
    all_in.resize(start + len);
    t.observables.resize(start + len);
    inputs_ = std::move(all_in);
    obs_ = std::move(t.observables);

    FieldTestStep st;
    st.phase = phase;
    st.actions = std::move(actions);
    st.hold_ms = static_cast<std::uint64_t>(len) * m_.cycle_ms;
    st.first_cycle = start;
    st.last_cycle = start + len - 1;
    checkpoints_.insert(st.last_cycle);
    if (initial) return st;
    const std::vector<int>& before = obs_[start - 1];
    const std::vector<int>& after = obs_[st.last_cycle];
    // Outputs one a line; Viewer indications grouped by element, state and time.
    // Per time of change (0: within 1 s, else the cycle), the outputs one a
    // line and the Viewer's indications grouped by element and state.
    struct Group {
      std::vector<std::string> outputs;
      std::vector<std::pair<std::string, std::vector<std::string>>> viewer;  // "cause 1 X|ON" -> fields
    };
    std::map<std::size_t, Group> groups;
    std::vector<std::string> pulses;
    for (std::size_t i : shown_index_) {
      if (before[i] == after[i]) {
        // A pulse the technician can see: on at once, off again after a second or more (a timed cause).
        std::vector<std::size_t> at;
        for (std::size_t k = start; k <= st.last_cycle; ++k)
          if (obs_[k][i] != obs_[k - 1][i]) at.push_back(k - start);
        if (at.size() != 2 || at[0] >= second_ || at[1] < second_) continue;
        checkpoints_.insert(start + second_ - 1);
        checkpoints_.insert(start + at[1] - 2);
        checkpoints_.insert(start + at[1] + 1);
        const model::Observable& ob = all_[i];
        const int during = obs_[start + at[0]][i];
        const std::string again = " " + seconds_text(at[1] * m_.cycle_ms) + " (±" + seconds_text(m_.cycle_ms) +
                                  ") after the action";
        if (ob.field == "tag")
          pulses.push_back(observation_words(m_, ob, during) + " at once, " + observation_words(m_, ob, after[i]) +
                           " again" + again);
        else
          pulses.push_back("Viewer, " + viewer_element(m_, ob) + ": " + viewer_field(ob) + (during ? " ON" : " OFF") +
                           " at once, " + (after[i] ? "ON" : "OFF") + " again" + again);
        continue;
      }
      std::size_t d = 0;
      for (std::size_t k = start; k <= st.last_cycle; ++k)
        if (obs_[k][i] != obs_[k - 1][i]) d = k - start;
      if (d >= second_) {
        if (d >= 2) checkpoints_.insert(start + d - 2);
        checkpoints_.insert(start + d + 1);
      } else {
        checkpoints_.insert(std::min(start + second_ - 1, st.last_cycle));
        d = 0;
      }
      Group& g = groups[d];
      const model::Observable& ob = all_[i];
      if (ob.field == "tag") {
        g.outputs.push_back(observation_words(m_, ob, after[i]));
        continue;
      }
      const std::string key = viewer_element(m_, ob) + (after[i] ? "|ON" : "|OFF");
      auto it = std::find_if(g.viewer.begin(), g.viewer.end(), [&](const auto& v) { return v.first == key; });
      if (it == g.viewer.end()) g.viewer.push_back({key, {viewer_field(ob)}});
      else it->second.push_back(viewer_field(ob));
    }
    const bool timed = groups.size() > 1 || (groups.size() == 1 && groups.begin()->first > 0);
    for (const auto& [d, g] : groups) {
      if (timed)
        st.expected.push_back(d == 0 ? "At once (within 1 s):"
                                     : "After " + seconds_text(d * m_.cycle_ms) + " (±" + seconds_text(m_.cycle_ms) +
                                           "):");
      const std::string indent = timed ? "- " : "";
      for (const auto& o : g.outputs) st.expected.push_back(indent + o);
      for (const auto& [key, fields] : g.viewer) {
        const std::size_t bar = key.find('|');
        std::string list;
        for (std::size_t f = 0; f < fields.size(); ++f)
          list += (f == 0 ? "" : f + 1 == fields.size() ? " and " : ", ") + fields[f];
        st.expected.push_back(indent + "Viewer, " + key.substr(0, bar) + ": " + list + " " + key.substr(bar + 1));
      }
    }
    st.expected.insert(st.expected.end(), pulses.begin(), pulses.end());
    if (st.expected.empty()) st.expected.push_back("No output and no Viewer indication changes");
    return st;
  }

 private:
  const model::Matrix& m_;
  const FieldOptions& o_;
  model::InputTable table_;
  std::vector<model::Observable> all_;
  std::vector<model::Observable> shown_;
  std::vector<std::size_t> shown_index_;
  std::map<std::string, std::size_t> index_;
  model::CycleInput current_;
  std::vector<model::CycleInput> inputs_;
  std::vector<std::vector<int>> obs_;
  std::set<std::size_t> checkpoints_;
  std::size_t second_ = 10, bound_ = 30;
};

bool external(const model::Cause& c) {
  for (const auto& t : c.tags)
    if (model::parse_internal_ref(t.name)) return false;
  return !c.tags.empty();
}

// The tags a trip needs, in order (the voting of 3.4 / 6.3.1).
std::size_t tags_to_trip(const model::Cause& c) {
  switch (c.function) {
    case model::CauseFunction::And: return c.tags.size();
    case model::CauseFunction::TwoOoThree: return 2;
    default: return 1;
  }
}

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.substr(0, 40);
}

struct LoopPlan {
  int sif = 0;
  std::vector<int> causes;
  int xoon_effect = 0;  // an XooN group test: the effect, else 0
  int xoon = 0;
};

model::Command command(model::CommandOp op, int cause, int effect, int group = 0) {
  model::Command c;
  c.op = op;
  c.cause = cause;
  c.effect = effect;
  c.group = group;
  return c;
}

// An operator command on the Viewer as the segments of one step: with secure
// write configured (M.3) its enable tag is switched on for the command and
// off again.
std::vector<Segment> viewer_command(const model::Matrix& m, const LoopBuilder& b, const model::Command& c,
                                    std::string& action) {
  if (!m.secure_write) return {Segment{{}, {c}, 0}};
  const std::size_t idx = *b.table().find(m.secure_write->enable_tag);
  model::TagValue on, off;
  on.value = 1.0f;
  const std::string& tag = m.secure_write->enable_tag;
  std::string lower = action;
  if (!lower.empty()) lower[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(lower[0])));
  action = "Switch " + tag + " on (secure write enable); " + lower + "; switch " + tag + " off";
  return {Segment{{{idx, on}}, {c}, (1000 + m.cycle_ms - 1) / m.cycle_ms}, Segment{{{idx, off}}, {}, 0}};
}

FieldTest build_loop(const model::Matrix& m, const FieldOptions& o, const LoopPlan& p) {
  const double r = o.resolution;
  std::set<int> effects;
  std::uint64_t settle = 0, cause_ms = 0;
  for (int id : p.causes) {
    cause_ms = std::max<std::uint64_t>(cause_ms, m.find_cause(id)->time.ms);
    for (const auto* i : m.intersections_of_cause(id))
      if (model::is_processed(i->type) && (!p.xoon_effect || i->effect == p.xoon_effect || !i->xoon))
        effects.insert(i->effect);
  }
  std::uint64_t delay = 0;
  for (const auto& e : m.effects) delay = std::max<std::uint64_t>(delay, e.output_delay_ms);
  settle = cause_ms + delay;
  LoopBuilder b(m, o, settle);
  FieldTest t;
  t.sif = p.sif;
  t.causes = p.causes;
  t.effects.assign(effects.begin(), effects.end());

  // Initial conditions: every input the test touches at its healthy value.
  std::vector<std::string> init;
  Segment healthy;
  for (int id : p.causes) {
    const model::Cause& c = *m.find_cause(id);
    for (const auto& tag : c.tags) {
      const auto idx = b.table().find(tag.name);
      if (!idx) continue;
      const model::TagValue v = cause_tag_value(c, tag, false, r);
      healthy.set.push_back({*idx, v});
      init.push_back(tag.name + " at " + tag_value_words(c, tag, v, r) +
                     (p.causes.size() > 1 ? " (healthy; input of " + cause_name(m, id) + ")" : " (healthy)"));
    }
    if (c.inhibit_tag) init.push_back(*c.inhibit_tag + " off (inhibit switch)");
    if (c.bypass_tag) init.push_back(*c.bypass_tag + " off (bypass switch)");
  }
  for (int id : t.effects) {
    const model::Effect& e = *m.find_effect(id);
    if (e.reset_tag) init.push_back(*e.reset_tag + " released (reset button of effect " + std::to_string(id) + ")");
  }
  std::set<std::size_t> touched;
  for (const auto& [i, v] : healthy.set) touched.insert(i);
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    for (const auto& tag : c.tags) {
      const auto idx = b.table().find(tag.name);
      if (!idx || !touched.insert(*idx).second) continue;
      healthy.set.push_back({*idx, cause_tag_value(c, tag, false, r)});
    }
  }
  init.push_back("Every other cause of the matrix healthy (not tripped, no prewarning)");
  init.push_back("No bypass, inhibit, override or simulation active; every effect of the test reset");
  FieldTestStep first = b.step("Initial conditions", init, {healthy}, true);
  {
    const auto& s = b.state();
    std::vector<std::string> on;
    for (std::size_t i : b.shown()) {
      const auto& ob = b.all()[i];
      if (ob.field == "tag" && effects.count(ob.id)) first.expected.push_back(observation_words(m, ob, s[i]));
      else if (ob.field != "tag" && s[i]) on.push_back(observation_words(m, ob, s[i]));
    }
    if (on.empty()) first.expected.push_back("Viewer: no indication ON");
    first.expected.insert(first.expected.end(), on.begin(), on.end());
  }
  t.steps.push_back(std::move(first));

  auto trip_words = [&](const model::Cause& c, const model::CauseTag& tag, const model::TagValue& v) {
    std::string what = "Set " + tag.name + " to " + tag_value_words(c, tag, v, r);
    if (c.analog && c.input == model::InputKind::Analog)
      what += std::string(" (trip: limit ") + model::float_text(c.analog->limit) + ", " +
              (c.analog->limit_type == model::LimitType::High ? "high" : "low") + ", hysteresis " +
              model::float_text(c.analog->hysteresis) + ")";
    else
      what += " (trip)";
    return what;
  };
  auto healthy_words = [&](const model::Cause& c, const model::CauseTag& tag, const model::TagValue& v) {
    return "Set " + tag.name + " back to " + tag_value_words(c, tag, v, r) + " (healthy)";
  };

  // A single cause's inhibit and bypass switches (C.8): on, the trip, no effect acts; off again.
  if (p.causes.size() == 1) {
    const model::Cause& c = *m.find_cause(p.causes.front());
    const std::size_t need = std::min(tags_to_trip(c), c.tags.size());
    for (const auto* sw : {c.inhibit_tag ? &*c.inhibit_tag : nullptr, c.bypass_tag ? &*c.bypass_tag : nullptr}) {
      if (!sw) continue;
      const std::string kind = sw == (c.inhibit_tag ? &*c.inhibit_tag : nullptr) ? "inhibit" : "bypass";
      const std::size_t idx = *b.table().find(*sw);
      model::TagValue on, off;
      on.value = 1.0f;
      const std::string phase = "Test with the " + kind;
      t.steps.push_back(b.step(phase, {"Switch " + *sw + " on (" + kind + " of " + cause_name(m, c.id) + ")"},
                               {Segment{{{idx, on}}, {}, 0}}));
      Segment trip, back;
      std::vector<std::string> acts, backs;
      for (std::size_t k = 0; k < need; ++k) {
        const auto tv = cause_tag_value(c, c.tags[k], true, r), hv = cause_tag_value(c, c.tags[k], false, r);
        trip.set.push_back({*b.table().find(c.tags[k].name), tv});
        back.set.push_back({*b.table().find(c.tags[k].name), hv});
        acts.push_back(trip_words(c, c.tags[k], tv) + " and hold it");
        backs.push_back(healthy_words(c, c.tags[k], hv));
      }
      t.steps.push_back(b.step(phase, acts, {trip}));
      t.steps.push_back(b.step(phase, backs, {back}));
      t.steps.push_back(b.step(phase, {"Switch " + *sw + " off"}, {Segment{{{idx, off}}, {}, 0}}));
    }
  }

  // The trip, tag by tag.
  std::vector<std::pair<int, const model::CauseTag*>> tripped;
  for (int id : p.causes) {
    const model::Cause& c = *m.find_cause(id);
    const std::size_t need = std::min(tags_to_trip(c), c.tags.size());
    for (std::size_t k = 0; k < need; ++k) {
      const model::CauseTag& tag = c.tags[k];
      const std::size_t idx = *b.table().find(tag.name);
      if (k == 0 && c.input == model::InputKind::Analog && c.analog) {
        const AnalogValues a = analog_values(*c.analog, r);
        if (a.prewarning) {
          model::TagValue v;
          v.value = static_cast<float>(*a.prewarning);
          t.steps.push_back(b.step("Test",
                                   {"Set " + tag.name + " to " + tag_value_words(c, tag, v, r) + " (prewarning " +
                                    model::float_text(*c.analog->prewarning) + ", limit " +
                                    model::float_text(c.analog->limit) + ")"},
                                   {Segment{{{idx, v}}, {}, 0}}));
        }
      }
      const model::TagValue v = cause_tag_value(c, tag, true, r);
      t.steps.push_back(b.step("Test", {trip_words(c, tag, v) + " and hold it"}, {Segment{{{idx, v}}, {}, 0}}));
      tripped.push_back({id, &tag});
    }
    // Every further transmitter of a single cause's voting in turn: the last
    // one tripped goes back, the next one takes its place (the trip request
    // goes off and on again on the Viewer).
    if (p.causes.size() != 1) continue;
    for (std::size_t k = need; k < c.tags.size(); ++k) {
      const model::CauseTag& last = *tripped.back().second;
      const auto hv = cause_tag_value(c, last, false, r);
      t.steps.push_back(b.step("Test", {healthy_words(c, last, hv)}, {Segment{{{*b.table().find(last.name), hv}}, {}, 0}}));
      tripped.pop_back();
      const model::CauseTag& tag = c.tags[k];
      const auto tv = cause_tag_value(c, tag, true, r);
      t.steps.push_back(b.step("Test", {trip_words(c, tag, tv) + " and hold it"},
                               {Segment{{{*b.table().find(tag.name), tv}}, {}, 0}}));
      tripped.push_back({id, &tag});
    }
  }

  // Restore: release, acknowledge, reset, clear first out.
  {
    Segment release;
    std::vector<std::string> acts;
    for (const auto& [id, tag] : tripped) {
      const model::Cause& c = *m.find_cause(id);
      const model::TagValue v = cause_tag_value(c, *tag, false, r);
      release.set.push_back({*b.table().find(tag->name), v});
      acts.push_back(healthy_words(c, *tag, v));
    }
    t.steps.push_back(b.step("Restore", acts, {release}));
  }
  const std::vector<int> rest = b.run()[t.steps.front().last_cycle];
  auto differs = [&](std::size_t i) { return b.state()[i] != rest[i]; };
  // Acknowledge, reset, clear first out: back to the initial conditions.
  auto unlatch = [&](const std::string& phase) {
    for (int id : p.causes) {
      const model::Cause& c = *m.find_cause(id);
      if (c.auto_ack) continue;
      if (!b.state()[b.index(model::observable_key(model::Node{model::Node::Kind::Cause, id}, "ack_required"))]) continue;
      std::string a = "On the Viewer, acknowledge " + cause_name(m, id);
      auto segs = viewer_command(m, b, command(model::CommandOp::AckCause, id, 0), a);
      t.steps.push_back(b.step(phase, {a}, segs));
    }
    for (int id : t.effects) {
      const model::Effect& e = *m.find_effect(id);
      const model::Node n{model::Node::Kind::Effect, id};
      if (!differs(b.index(model::observable_key(n, "active"))) && !differs(b.index(model::observable_key(n, "latched"))))
        continue;
      if (e.reset_tag) {
        const std::size_t idx = *b.table().find(*e.reset_tag);
        model::TagValue on, off;
        on.value = 1.0f;
        t.steps.push_back(b.step(phase,
                                 {"Press " + *e.reset_tag + " (reset of " + effect_name(m, id) + ") for 1 s, release it"},
                                 {Segment{{{idx, on}}, {}, (1000 + m.cycle_ms - 1) / m.cycle_ms}, Segment{{{idx, off}}, {}, 0}}));
      } else {
        std::string a = "On the Viewer, reset " + effect_name(m, id);
        auto segs = viewer_command(m, b, command(model::CommandOp::ResetEffect, 0, id), a);
        t.steps.push_back(b.step(phase, {a}, segs));
      }
    }
    std::set<int> groups;
    for (const auto& c : m.causes)
      if (c.first_out_group > 0 && differs(b.index(model::observable_key(model::Node{model::Node::Kind::Cause, c.id}, "first_out"))))
        groups.insert(c.first_out_group);
    for (int g : groups) {
      std::string a = "On the Viewer, clear the first-out display of group " + std::to_string(g);
      auto segs = viewer_command(m, b, command(model::CommandOp::ClearFirstOut, 0, 0, g), a);
      t.steps.push_back(b.step(phase, {a}, segs));
    }
  };
  unlatch("Restore");

  // A channel fault of a single cause's first tag (6.1.6: the F-channel
  // driver's bad quality, the wire disconnected): what the cause's bad
  // quality mode makes of it, then reconnected and restored.
  if (p.causes.size() == 1) {
    const model::Cause& c = *m.find_cause(p.causes.front());
    const model::CauseTag& tag = c.tags.front();
    const std::size_t idx = *b.table().find(tag.name);
    model::TagValue bad = cause_tag_value(c, tag, false, r), good = bad;
    bad.bad_quality = true;
    const std::string phase = "Test with a channel fault";
    t.steps.push_back(b.step(phase, {"Disconnect " + tag.name + " at the terminal (wire break: bad quality; " +
                                     model::to_string(c.bad_quality) + " configured)"},
                             {Segment{{{idx, bad}}, {}, 0}}));
    t.steps.push_back(b.step(phase, {"Reconnect " + tag.name + " (" + tag_value_words(c, tag, good, r) + ", good quality)"},
                             {Segment{{{idx, good}}, {}, 0}}));
    unlatch(phase);
  }
  std::vector<std::string> left;
  for (std::size_t i : b.shown())
    if (differs(i)) left.push_back(observation_words(m, b.all()[i], b.state()[i]));
  if (left.empty()) t.steps.back().expected.push_back("The loop is back at its initial conditions (step 1)");
  else
    for (const auto& l : left) t.steps.back().expected.push_back("Not as in step 1: " + l);

  // The scenario: every technician observable at every checkpoint, every
  // input stated in the first step, each field step a step of its own.
  formats::ScenarioRun run;
  run.matrix = o.matrix_ref;
  run.first_step_states_every_input = true;
  run.durations = formats::Durations::Milliseconds;
  const auto& in = b.inputs();
  run.cycles = in;
  std::map<std::size_t, int> field_step;  // first cycle -> step number
  for (std::size_t s = 0; s < t.steps.size(); ++s) {
    t.steps[s].number = static_cast<int>(s + 1);
    field_step[t.steps[s].first_cycle] = t.steps[s].number;
  }
  for (std::size_t k = 0; k < in.size();) {
    formats::WrittenStep st;
    if (auto fs = field_step.find(k); fs != field_step.end()) st.description = "step " + std::to_string(fs->second);
    std::size_t n = 1;
    while (k + n < in.size() && !b.checkpoints().count(k + n - 1) && !field_step.count(k + n) &&
           in[k + n].commands.empty()) {
      bool same = true;
      for (std::size_t i = 0; i < b.table().size() && same; ++i)
        same = in[k + n].tags[i].value == in[k].tags[i].value && in[k + n].tags[i].bad_quality == in[k].tags[i].bad_quality;
      if (!same) break;
      ++n;
    }
    st.cycles = n;
    const std::size_t last = k + n - 1;
    if (b.checkpoints().count(last)) {
      std::vector<formats::ExpectedValue> e;
      for (std::size_t i : b.shown()) e.push_back({b.all()[i].key, model::FieldType::Bool, b.run()[last][i] != 0});
      st.expect = std::move(e);
    }
    run.steps.push_back(std::move(st));
    k += n;
  }
  t.scenario_json = formats::scenario_text(m, run);
  t.inputs = in;
  t.cycles = in.size();
  for (auto& s : t.steps) {
    t.field_s += 30 * s.actions.size() * (s.phase == "Initial conditions" ? 0 : 1) + s.hold_ms / 1000 +
                 10 * s.expected.size();
  }
  t.field_s += 120;  // connecting and disconnecting the calibrator, the permit
  return t;
}

// Why an objective the field tests do not witness stays automated.
std::string automated_reason(const Objective& o, bool witnessed_elsewhere) {
  const std::string& k = o.kind;
  if (o.id.find(".before") != std::string::npos || k == "timer")
    return "needs the cycle before or at a timer's expiry: sub-second resolution";
  if (k == "limit" || k == "hysteresis")
    return "needs the exact limit or hysteresis threshold and the next float: below a calibrator's resolution";
  if (k == "reference" || o.simulates) return "forces an output by simulation: not a field action";
  if (k == "bad-quality") return "the loop tests disconnect the first tag of a cause only";
  if (witnessed_elsewhere) return "reached only at a cycle no technician observes (between checkpoints)";
  return "no loop test (trip one cause, release, acknowledge, reset) reaches it: " + k +
         " needs a combination of causes, an operator maintenance command or timing beyond one loop";
}

bool field_kind(const Objective& o) {
  return !(o.id.find(".before") != std::string::npos || o.kind == "timer" || o.kind == "limit" ||
           o.kind == "hysteresis" || o.kind == "reference" || o.simulates);
}

}  // namespace

FieldSuite generate_field_suite(const model::Matrix& m, const FieldOptions& o) {
  if (!(o.resolution > 0.0) || o.resolution > 1000.0) throw std::invalid_argument("--resolution must be in (0, 1000]");
  FieldSuite s;
  s.matrix_name = m.name;
  s.signature = formats::signature(m);
  s.resolution = o.resolution;
  std::vector<LoopPlan> plans;
  for (const auto& c : m.causes) {
    if (c.function == model::CauseFunction::Comment) continue;
    if (!external(c)) {
      s.untested.push_back(cause_name(m, c.id) + ": its inputs are internal references; it trips with the loops that "
                                                  "drive them");
      continue;
    }
    plans.push_back({c.sif.empty() ? 0 : c.sif.front(), {c.id}, 0, 0});
  }
  std::set<std::vector<int>> groups;
  for (const auto& e : m.effects) {
    std::vector<int> causes;
    int x = 0;
    for (const auto* i : m.intersections_of_effect(e.id))
      if (model::is_processed(i->type) && i->xoon && external(*m.find_cause(i->cause))) {
        causes.push_back(i->cause);
        x = *i->xoon;
      }
    if (x < 2 || static_cast<int>(causes.size()) < x) continue;
    causes.resize(static_cast<std::size_t>(x));
    if (!groups.insert(causes).second) continue;
    plans.push_back({e.sif.empty() ? 0 : e.sif.front(), causes, e.id, x});
  }
  auto rank = [](int sif) { return sif == 0 ? 1 << 30 : sif; };
  std::stable_sort(plans.begin(), plans.end(), [&](const LoopPlan& a, const LoopPlan& b) {
    return std::make_tuple(rank(a.sif), a.causes.front(), a.causes.size()) <
           std::make_tuple(rank(b.sif), b.causes.front(), b.causes.size());
  });
  for (const auto& p : plans) {
    FieldTest t = build_loop(m, o, p);
    char id[16];
    std::snprintf(id, sizeof id, "F%03zu", s.tests.size() + 1);
    t.id = id;
    if (p.xoon_effect) {
      std::string list;
      for (int c : p.causes) list += (list.empty() ? "" : ", ") + std::to_string(c);
      t.title = std::string("XooN: causes ") + list + " together trip " + effect_name(m, p.xoon_effect) + " (" +
                std::to_string(p.xoon) + " needed)";
      t.file_name = t.id + "-xoon-effect-" + std::to_string(p.xoon_effect) + ".scenario.json";
    } else {
      const model::Cause& c = *m.find_cause(p.causes.front());
      t.title = "Cause " + std::to_string(c.id) + " " + c.name + (c.description.empty() ? "" : ": " + c.description);
      t.file_name = t.id + "-cause-" + std::to_string(c.id) + "-" + slug(c.name) + ".scenario.json";
    }
    s.field_s += t.field_s;
    s.tests.push_back(std::move(t));
  }

  // Which objectives each step witnesses (the concrete evaluator on the run).
  std::vector<Objective> all = derive_objectives(m);
  const properties::PropertyFile file = objectives_file(all);
  properties::Evaluator ev(m);
  for (auto& ob : all) s.objectives.push_back({std::move(ob), -1, 0, ""});
  std::vector<bool> elsewhere(s.objectives.size(), false);
  for (std::size_t ti = 0; ti < s.tests.size(); ++ti) {
    FieldTest& t = s.tests[ti];
    const checker::ConcreteTrace run = checker::run_on_runtime(m, t.inputs);
    properties::Trace trace;
    for (std::size_t k = 0; k < run.inputs.size(); ++k) trace.push_back({run.inputs[k], run.observables[k]});
    for (std::size_t i = 0; i < s.objectives.size(); ++i) {
      FieldObjective& fo = s.objectives[i];
      if (!field_kind(fo.objective)) continue;
      auto e = ev.evaluate(file.properties[i], file.assumptions, trace);
      if (!e.holds || !e.cycle) continue;
      bool placed = false;
      for (auto& st : t.steps)
        if (*e.cycle >= st.first_cycle && *e.cycle <= st.last_cycle) {
          placed = true;
          if (fo.test >= 0) {
            st.again.push_back(fo.objective.id);
            continue;
          }
          fo.test = static_cast<int>(ti);
          fo.step = st.number;
          st.objectives.push_back(fo.objective.id);
        }
      if (!placed) elsewhere[i] = true;
    }
  }
  for (std::size_t i = 0; i < s.objectives.size(); ++i)
    if (s.objectives[i].test < 0) s.objectives[i].reason = automated_reason(s.objectives[i].objective, elsewhere[i]);

  // Never an unchecked answer: every test as written replays green.
  std::vector<std::pair<std::string, std::string>> texts;
  for (const auto& t : s.tests) texts.push_back({t.file_name, t.scenario_json});
  const ReplayResult replay = replay_texts(m, texts);
  for (const auto& t : replay.tests)
    if (!t.passed) {
      std::string why = t.load_error;
      for (const auto& st : t.steps)
        if (why.empty() && !st.failures.empty()) why = st.failures.front();
      throw checker::InternalError("field test " + t.name + " does not replay green: " + why);
    }
  return s;
}

}  // namespace cemv::testgen
