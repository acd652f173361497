// A loop test's run on the reference runtime, step by step, and what the
// technician is told to observe: what the runtime shows at the step's
// checkpoints; a timed observation is checked one cycle either side of its
// time (the tolerance printed).
#include <algorithm>

#include "checker/replay.hpp"
#include "testgen/field_loop.hpp"
#include "testgen/field_words.hpp"

namespace cemv::testgen::field_detail {

using namespace detail;

LoopBuilder::LoopBuilder(const model::Matrix& m, std::uint64_t settle_ms)
    : m_(m), table_(m), all_(model::observables(m)), shown_(technician_observables(m)) {
  for (std::size_t i = 0; i < all_.size(); ++i) index_[all_[i].key] = i;
  for (const auto& s : shown_) shown_index_.push_back(index_.at(s.key));
  current_ = model::default_cycle_input(m);
  second_ = (1000 + m.cycle_ms - 1) / m.cycle_ms;
  bound_ = (settle_ms + 3000 + m.cycle_ms - 1) / m.cycle_ms;
}

FieldTestStep LoopBuilder::step(const std::string& phase, std::vector<std::string> actions, std::vector<Segment> segs,
                                bool initial) {
  const std::size_t start = inputs_.size();
  const std::size_t len = run_and_settle(segs);
  FieldTestStep st;
  st.phase = phase;
  st.actions = std::move(actions);
  st.hold_ms = static_cast<std::uint64_t>(len) * m_.cycle_ms;
  st.first_cycle = start;
  st.last_cycle = start + len - 1;
  checkpoints_.insert(st.last_cycle);
  if (!initial) describe_changes(st);
  return st;
}

// Runs the segments, the last one held up to the bound, and keeps the run up
// to one second past the last change (at least one second past the fixed
// segments), in half seconds; returns the step's length in cycles.
std::size_t LoopBuilder::run_and_settle(const std::vector<Segment>& segs) {
  const std::size_t start = inputs_.size();
  std::vector<model::CycleInput> all_in = inputs_;
  std::size_t fixed = 0;
  for (std::size_t s = 0; s < segs.size(); ++s) {
    for (const auto& [i, v] : segs[s].set) current_.tags[i] = v;
    const bool last = s + 1 == segs.size();
    const std::size_t n = last ? bound_ : segs[s].cycles;
    for (std::size_t k = 0; k < n; ++k) {
      model::CycleInput in = current_;
      if (k == 0) in.commands = segs[s].commands;
      all_in.push_back(std::move(in));
    }
    if (!last) fixed += n;
  }
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
  return len;
}

// An indication the technician sees pulse: on at once, off again after a
// second or more (a timed cause). False when observable i does not pulse.
bool LoopBuilder::describe_pulse(std::size_t i, const FieldTestStep& st, std::vector<std::string>& pulses) {
  const std::size_t start = st.first_cycle;
  std::vector<std::size_t> at;
  for (std::size_t k = start; k <= st.last_cycle; ++k)
    if (obs_[k][i] != obs_[k - 1][i]) at.push_back(k - start);
  if (at.size() != 2 || at[0] >= second_ || at[1] < second_) return false;
  checkpoints_.insert(start + second_ - 1);
  checkpoints_.insert(start + at[1] - 2);
  checkpoints_.insert(start + at[1] + 1);
  const model::Observable& ob = all_[i];
  const int during = obs_[start + at[0]][i];
  const int after = obs_[st.last_cycle][i];
  const std::string again =
      " " + seconds_text(at[1] * m_.cycle_ms) + " (±" + seconds_text(m_.cycle_ms) + ") after the action";
  if (ob.field == "tag")
    pulses.push_back(observation_words(m_, ob, during) + " at once, " + observation_words(m_, ob, after) + " again" +
                     again);
  else
    pulses.push_back("Viewer, " + viewer_element(m_, ob) + ": " + viewer_field(ob) + (during ? " ON" : " OFF") +
                     " at once, " + (after ? "ON" : "OFF") + " again" + again);
  return true;
}

// When observable i last changed in the step (0: within its first second),
// with the checkpoints either side of that time.
std::size_t LoopBuilder::change_time(std::size_t i, const FieldTestStep& st) {
  const std::size_t start = st.first_cycle;
  std::size_t d = 0;
  for (std::size_t k = start; k <= st.last_cycle; ++k)
    if (obs_[k][i] != obs_[k - 1][i]) d = k - start;
  if (d >= second_) {
    if (d >= 2) checkpoints_.insert(start + d - 2);
    checkpoints_.insert(start + d + 1);
    return d;
  }
  checkpoints_.insert(std::min(start + second_ - 1, st.last_cycle));
  return 0;
}

// Per time of change (0: within 1 s, else the cycle), the outputs one a line
// and the Viewer's indications grouped by element and state; pulses last.
void LoopBuilder::describe_changes(FieldTestStep& st) {
  struct Group {
    std::vector<std::string> outputs;
    std::vector<std::pair<std::string, std::vector<std::string>>> viewer;  // "cause 1 X|ON" -> fields
  };
  std::map<std::size_t, Group> groups;
  std::vector<std::string> pulses;
  const std::vector<int>& before = obs_[st.first_cycle - 1];
  const std::vector<int>& after = obs_[st.last_cycle];
  for (std::size_t i : shown_index_) {
    if (before[i] == after[i]) {
      describe_pulse(i, st, pulses);
      continue;
    }
    Group& g = groups[change_time(i, st)];
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
}

}  // namespace cemv::testgen::field_detail
