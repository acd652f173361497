// One loop test of the field suite (docs/testgen.md, "Field suite"): the
// initial conditions, the inhibit and bypass switches, the trip tag by tag,
// the restore (release, acknowledge, reset, clear first out), a channel fault,
// then the scenario as cemv-scenario/1 and the test's time in the field.
#include <algorithm>
#include <cctype>
#include <optional>

#include "formats/scenario_writer.hpp"
#include "model/text.hpp"
#include "testgen/field_loop.hpp"
#include "testgen/field_words.hpp"

namespace cemv::testgen::field_detail {

using namespace detail;

namespace {

// The tags a trip needs, in order (the voting of 3.4 / 6.3.1).
std::size_t tags_to_trip(const model::Cause& c) {
  switch (c.function) {
    case model::CauseFunction::And: return c.tags.size();
    case model::CauseFunction::TwoOoThree: return 2;
    default: return 1;
  }
}

model::Command command(model::CommandOp op, int cause, int effect, int group = 0) {
  model::Command c;
  c.op = op;
  c.cause = cause;
  c.effect = effect;
  c.group = group;
  return c;
}

// The effects a plan's causes drive (an XooN group test: its own effect and
// the causes' other links).
std::set<int> effects_of(const model::Matrix& m, const LoopPlan& p) {
  std::set<int> effects;
  for (int id : p.causes)
    for (const auto* i : m.intersections_of_cause(id))
      if (model::is_processed(i->type) && (!p.xoon_effect || i->effect == p.xoon_effect || !i->xoon))
        effects.insert(i->effect);
  return effects;
}

// How long the loop may take to settle: the causes' longest time function
// plus the matrix's longest output delay.
std::uint64_t settle_ms(const model::Matrix& m, const LoopPlan& p) {
  std::uint64_t cause_ms = 0, delay = 0;
  for (int id : p.causes) cause_ms = std::max<std::uint64_t>(cause_ms, m.find_cause(id)->time.ms);
  for (const auto& e : m.effects) delay = std::max<std::uint64_t>(delay, e.output_delay_ms);
  return cause_ms + delay;
}

// Writes one loop test; the order of the methods in write() is the order of
// the steps.
class LoopWriter {
 public:
  LoopWriter(const model::Matrix& m, const FieldOptions& o, const LoopPlan& p)
      : m_(m), o_(o), p_(p), r_(o.resolution), effects_(effects_of(m, p)), b_(m, settle_ms(m, p)) {
    t_.sif = p.sif;
    t_.causes = p.causes;
    t_.effects.assign(effects_.begin(), effects_.end());
  }

  FieldTest write() {
    set_initial_conditions();
    if (single()) test_switches();
    trip();
    release();
    rest_ = b_.run()[t_.steps.front().last_cycle];
    unlatch("Restore");
    if (single()) test_channel_fault();
    expect_initial_conditions_again();
    write_scenario();
    estimate_field_time();
    return std::move(t_);
  }

 private:
  bool single() const { return p_.causes.size() == 1; }
  std::size_t input(const std::string& tag) const { return *b_.table().find(tag); }
  // A switch the technician sets: an input of the matrix, not an internal
  // reference (I.3), which follows the element it names.
  std::optional<std::size_t> field_switch(const std::optional<std::string>& tag) const {
    if (!tag || tag->empty()) return std::nullopt;
    return b_.table().find(*tag);
  }
  bool differs(std::size_t i) const { return b_.state()[i] != rest_[i]; }
  void add(const std::string& phase, std::vector<std::string> actions, std::vector<Segment> segs) {
    t_.steps.push_back(b_.step(phase, std::move(actions), std::move(segs)));
  }

  std::string trip_words(const model::Cause& c, const model::CauseTag& tag, const model::TagValue& v) const {
    std::string what = "Set " + tag.name + " to " + tag_value_words(c, tag, v, r_);
    if (c.analog && c.input == model::InputKind::Analog)
      what += std::string(" (trip: limit ") + model::float_text(c.analog->limit) + ", " +
              (c.analog->limit_type == model::LimitType::High ? "high" : "low") + ", hysteresis " +
              model::float_text(c.analog->hysteresis) + ")";
    else
      what += " (trip)";
    return what;
  }
  std::string healthy_words(const model::Cause& c, const model::CauseTag& tag, const model::TagValue& v) const {
    return "Set " + tag.name + " back to " + tag_value_words(c, tag, v, r_) + " (healthy)";
  }

  // An operator command on the Viewer as the segments of one step: with secure
  // write configured (M.3) its enable tag is switched on for the command and
  // off again; an enable given by an internal reference is not switched.
  std::vector<Segment> viewer_command(const model::Command& c, std::string& action) const {
    if (!m_.secure_write) return {Segment{{}, {c}, 0}};
    const std::string& tag = m_.secure_write->enable_tag;
    const auto idx = b_.table().find(tag);
    if (!idx) {
      action += " (secure write follows " + tag + ")";
      return {Segment{{}, {c}, 0}};
    }
    model::TagValue on, off;
    on.value = 1.0f;
    std::string lower = action;
    if (!lower.empty()) lower[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(lower[0])));
    action = "Switch " + tag + " on (secure write enable); " + lower + "; switch " + tag + " off";
    return {Segment{{{*idx, on}}, {c}, (1000 + m_.cycle_ms - 1) / m_.cycle_ms}, Segment{{{*idx, off}}, {}, 0}};
  }

  // Every input the test touches at its healthy value, every other cause healthy.
  void set_initial_conditions() {
    std::vector<std::string> init;
    Segment healthy;
    for (int id : p_.causes) {
      const model::Cause& c = *m_.find_cause(id);
      for (const auto& tag : c.tags) {
        const auto idx = b_.table().find(tag.name);
        if (!idx) continue;
        const model::TagValue v = cause_tag_value(c, tag, false, r_);
        healthy.set.push_back({*idx, v});
        init.push_back(tag.name + " at " + tag_value_words(c, tag, v, r_) +
                       (single() ? " (healthy)" : " (healthy; input of " + cause_name(m_, id) + ")"));
      }
      if (c.inhibit_tag) init.push_back(*c.inhibit_tag + switch_words(c.inhibit_tag, "inhibit"));
      if (c.bypass_tag) init.push_back(*c.bypass_tag + switch_words(c.bypass_tag, "bypass"));
    }
    for (int id : t_.effects) {
      const model::Effect& e = *m_.find_effect(id);
      if (!e.reset_tag) continue;
      init.push_back(*e.reset_tag + (field_switch(e.reset_tag) ? " released (reset button of effect "
                                                               : " off (internal reference: the reset of effect ") +
                     std::to_string(id) + ")");
    }
    std::set<std::size_t> touched;
    for (const auto& [i, v] : healthy.set) touched.insert(i);
    for (const auto& c : m_.causes) {
      if (c.function == model::CauseFunction::Comment) continue;
      for (const auto& tag : c.tags) {
        const auto idx = b_.table().find(tag.name);
        if (!idx || !touched.insert(*idx).second) continue;
        healthy.set.push_back({*idx, cause_tag_value(c, tag, false, r_)});
      }
    }
    init.push_back("Every other cause of the matrix healthy (not tripped, no prewarning)");
    init.push_back("No bypass, inhibit, override or simulation active; every effect of the test reset");
    FieldTestStep first = b_.step("Initial conditions", init, {healthy}, true);
    expect_initial_state(first);
    t_.steps.push_back(std::move(first));
  }
  std::string switch_words(const std::optional<std::string>& tag, const std::string& kind) const {
    return field_switch(tag) ? " off (" + kind + " switch)" : " off (internal reference: the " + kind + ")";
  }

  // The outputs of the test's effects and every Viewer indication that is on.
  void expect_initial_state(FieldTestStep& first) const {
    const auto& s = b_.state();
    std::vector<std::string> on;
    for (std::size_t i : b_.shown()) {
      const auto& ob = b_.all()[i];
      if (ob.field == "tag" && effects_.count(ob.id)) first.expected.push_back(observation_words(m_, ob, s[i]));
      else if (ob.field != "tag" && s[i]) on.push_back(observation_words(m_, ob, s[i]));
    }
    if (on.empty()) first.expected.push_back("Viewer: no indication ON");
    first.expected.insert(first.expected.end(), on.begin(), on.end());
  }

  // A single cause's inhibit and bypass switches (C.8): on, the trip, no
  // effect acts; off again. A switch given by an internal reference is not
  // one the technician sets.
  void test_switches() {
    const model::Cause& c = *m_.find_cause(p_.causes.front());
    test_switch(c, c.inhibit_tag, "inhibit");
    test_switch(c, c.bypass_tag, "bypass");
  }
  void test_switch(const model::Cause& c, const std::optional<std::string>& sw, const std::string& kind) {
    const auto idx = field_switch(sw);
    if (!idx) return;
    const std::size_t need = std::min(tags_to_trip(c), c.tags.size());
    model::TagValue on, off;
    on.value = 1.0f;
    const std::string phase = "Test with the " + kind;
    add(phase, {"Switch " + *sw + " on (" + kind + " of " + cause_name(m_, c.id) + ")"}, {Segment{{{*idx, on}}, {}, 0}});
    Segment trip, back;
    std::vector<std::string> acts, backs;
    for (std::size_t k = 0; k < need; ++k) {
      const auto tv = cause_tag_value(c, c.tags[k], true, r_), hv = cause_tag_value(c, c.tags[k], false, r_);
      trip.set.push_back({input(c.tags[k].name), tv});
      back.set.push_back({input(c.tags[k].name), hv});
      acts.push_back(trip_words(c, c.tags[k], tv) + " and hold it");
      backs.push_back(healthy_words(c, c.tags[k], hv));
    }
    add(phase, acts, {trip});
    add(phase, backs, {back});
    add(phase, {"Switch " + *sw + " off"}, {Segment{{{*idx, off}}, {}, 0}});
  }

  // The trip, tag by tag (an analog cause's prewarning first).
  void trip() {
    for (int id : p_.causes) {
      const model::Cause& c = *m_.find_cause(id);
      const std::size_t need = std::min(tags_to_trip(c), c.tags.size());
      for (std::size_t k = 0; k < need; ++k) {
        const model::CauseTag& tag = c.tags[k];
        if (k == 0) show_prewarning(c, tag);
        const model::TagValue v = cause_tag_value(c, tag, true, r_);
        add("Test", {trip_words(c, tag, v) + " and hold it"}, {Segment{{{input(tag.name), v}}, {}, 0}});
        tripped_.push_back({id, &tag});
      }
      if (single()) rotate_voting(c, need);
    }
  }
  void show_prewarning(const model::Cause& c, const model::CauseTag& tag) {
    if (c.input != model::InputKind::Analog || !c.analog) return;
    const AnalogValues a = analog_values(*c.analog, r_);
    if (!a.prewarning) return;
    model::TagValue v;
    v.value = static_cast<float>(*a.prewarning);
    add("Test",
        {"Set " + tag.name + " to " + tag_value_words(c, tag, v, r_) + " (prewarning " +
         model::float_text(*c.analog->prewarning) + ", limit " + model::float_text(c.analog->limit) + ")"},
        {Segment{{{input(tag.name), v}}, {}, 0}});
  }
  // Every further transmitter of a single cause's voting in turn: the last
  // one tripped goes back, the next one takes its place (the trip request
  // goes off and on again on the Viewer).
  void rotate_voting(const model::Cause& c, std::size_t need) {
    for (std::size_t k = need; k < c.tags.size(); ++k) {
      const model::CauseTag& last = *tripped_.back().second;
      const auto hv = cause_tag_value(c, last, false, r_);
      add("Test", {healthy_words(c, last, hv)}, {Segment{{{input(last.name), hv}}, {}, 0}});
      tripped_.pop_back();
      const model::CauseTag& tag = c.tags[k];
      const auto tv = cause_tag_value(c, tag, true, r_);
      add("Test", {trip_words(c, tag, tv) + " and hold it"}, {Segment{{{input(tag.name), tv}}, {}, 0}});
      tripped_.push_back({c.id, &tag});
    }
  }

  // Restore: every tripped tag back to healthy.
  void release() {
    Segment release;
    std::vector<std::string> acts;
    for (const auto& [id, tag] : tripped_) {
      const model::Cause& c = *m_.find_cause(id);
      const model::TagValue v = cause_tag_value(c, *tag, false, r_);
      release.set.push_back({input(tag->name), v});
      acts.push_back(healthy_words(c, *tag, v));
    }
    add("Restore", acts, {release});
  }

  // Acknowledge, reset, clear first out: back to the initial conditions.
  void unlatch(const std::string& phase) {
    acknowledge(phase);
    reset(phase);
    clear_first_out(phase);
  }
  void acknowledge(const std::string& phase) {
    for (int id : p_.causes) {
      const model::Cause& c = *m_.find_cause(id);
      if (c.auto_ack) continue;
      if (!b_.state()[b_.index(model::observable_key(model::Node{model::Node::Kind::Cause, id}, "ack_required"))])
        continue;
      std::string a = "On the Viewer, acknowledge " + cause_name(m_, id);
      auto segs = viewer_command(command(model::CommandOp::AckCause, id, 0), a);
      add(phase, {a}, segs);
    }
  }
  // A reset given by an internal reference follows its element: no field
  // action resets the effect, and what stays latched is said at the end.
  void reset(const std::string& phase) {
    for (int id : t_.effects) {
      const model::Effect& e = *m_.find_effect(id);
      const model::Node n{model::Node::Kind::Effect, id};
      if (!differs(b_.index(model::observable_key(n, "active"))) && !differs(b_.index(model::observable_key(n, "latched"))))
        continue;
      if (const auto idx = field_switch(e.reset_tag)) {
        model::TagValue on, off;
        on.value = 1.0f;
        add(phase, {"Press " + *e.reset_tag + " (reset of " + effect_name(m_, id) + ") for 1 s, release it"},
            {Segment{{{*idx, on}}, {}, (1000 + m_.cycle_ms - 1) / m_.cycle_ms}, Segment{{{*idx, off}}, {}, 0}});
      } else if (!e.reset_tag) {
        std::string a = "On the Viewer, reset " + effect_name(m_, id);
        auto segs = viewer_command(command(model::CommandOp::ResetEffect, 0, id), a);
        add(phase, {a}, segs);
      }
    }
  }
  void clear_first_out(const std::string& phase) {
    std::set<int> groups;
    for (const auto& c : m_.causes)
      if (c.first_out_group > 0 &&
          differs(b_.index(model::observable_key(model::Node{model::Node::Kind::Cause, c.id}, "first_out"))))
        groups.insert(c.first_out_group);
    for (int g : groups) {
      std::string a = "On the Viewer, clear the first-out display of group " + std::to_string(g);
      auto segs = viewer_command(command(model::CommandOp::ClearFirstOut, 0, 0, g), a);
      add(phase, {a}, segs);
    }
  }

  // A channel fault of a single cause's first tag (6.1.6: the F-channel
  // driver's bad quality, the wire disconnected): what the cause's bad
  // quality mode makes of it, then reconnected and restored.
  void test_channel_fault() {
    const model::Cause& c = *m_.find_cause(p_.causes.front());
    const model::CauseTag& tag = c.tags.front();
    const std::size_t idx = input(tag.name);
    model::TagValue bad = cause_tag_value(c, tag, false, r_), good = bad;
    bad.bad_quality = true;
    const std::string phase = "Test with a channel fault";
    add(phase, {"Disconnect " + tag.name + " at the terminal (wire break: bad quality; " +
                model::to_string(c.bad_quality) + " configured)"},
        {Segment{{{idx, bad}}, {}, 0}});
    add(phase, {"Reconnect " + tag.name + " (" + tag_value_words(c, tag, good, r_) + ", good quality)"},
        {Segment{{{idx, good}}, {}, 0}});
    unlatch(phase);
  }

  void expect_initial_conditions_again() {
    std::vector<std::string> left;
    for (std::size_t i : b_.shown())
      if (differs(i)) left.push_back(observation_words(m_, b_.all()[i], b_.state()[i]));
    if (left.empty()) t_.steps.back().expected.push_back("The loop is back at its initial conditions (step 1)");
    else
      for (const auto& l : left) t_.steps.back().expected.push_back("Not as in step 1: " + l);
  }

  // The scenario: every technician observable at every checkpoint, every
  // input stated in the first step, each field step a step of its own.
  void write_scenario() {
    formats::ScenarioRun run;
    run.matrix = o_.matrix_ref;
    run.first_step_states_every_input = true;
    run.durations = formats::Durations::Milliseconds;
    const auto& in = b_.inputs();
    run.cycles = in;
    std::map<std::size_t, int> field_step;  // first cycle -> step number
    for (std::size_t s = 0; s < t_.steps.size(); ++s) {
      t_.steps[s].number = static_cast<int>(s + 1);
      field_step[t_.steps[s].first_cycle] = t_.steps[s].number;
    }
    for (std::size_t k = 0; k < in.size();) {
      formats::WrittenStep st;
      if (auto fs = field_step.find(k); fs != field_step.end()) st.description = "step " + std::to_string(fs->second);
      const std::size_t n = same_inputs_from(k, field_step);
      st.cycles = n;
      const std::size_t last = k + n - 1;
      if (b_.checkpoints().count(last)) {
        std::vector<formats::ExpectedValue> e;
        for (std::size_t i : b_.shown()) e.push_back({b_.all()[i].key, model::FieldType::Bool, b_.run()[last][i] != 0});
        st.expect = std::move(e);
      }
      run.steps.push_back(std::move(st));
      k += n;
    }
    t_.scenario_json = formats::scenario_text(m_, run);
    t_.inputs = in;
    t_.cycles = in.size();
  }
  // How many cycles from k hold the same inputs, without a command, up to
  // the next checkpoint or field step.
  std::size_t same_inputs_from(std::size_t k, const std::map<std::size_t, int>& field_step) const {
    const auto& in = b_.inputs();
    std::size_t n = 1;
    while (k + n < in.size() && !b_.checkpoints().count(k + n - 1) && !field_step.count(k + n) &&
           in[k + n].commands.empty()) {
      bool same = true;
      for (std::size_t i = 0; i < b_.table().size() && same; ++i)
        same = in[k + n].tags[i].value == in[k].tags[i].value && in[k + n].tags[i].bad_quality == in[k].tags[i].bad_quality;
      if (!same) break;
      ++n;
    }
    return n;
  }

  void estimate_field_time() {
    for (auto& s : t_.steps)
      t_.field_s += 30 * s.actions.size() * (s.phase == "Initial conditions" ? 0 : 1) + s.hold_ms / 1000 +
                    10 * s.expected.size();
    t_.field_s += 120;  // connecting and disconnecting the calibrator, the permit
  }

  const model::Matrix& m_;
  const FieldOptions& o_;
  const LoopPlan& p_;
  const double r_;
  const std::set<int> effects_;
  LoopBuilder b_;
  FieldTest t_;
  std::vector<std::pair<int, const model::CauseTag*>> tripped_;
  std::vector<int> rest_;  // the observables at the end of the initial conditions
};

}  // namespace

FieldTest build_loop(const model::Matrix& m, const FieldOptions& o, const LoopPlan& p) {
  return LoopWriter(m, o, p).write();
}

}  // namespace cemv::testgen::field_detail
