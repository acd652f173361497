// One loop test of the field suite (docs/testgen.md, "Field suite"), built on
// the reference runtime one field step at a time: the step's action is
// applied, the runtime runs until nothing changes any more (bounded by the
// loop's time functions and output delays), and the step holds one second
// beyond the last change, rounded up to half seconds. Internal to testgen/.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "testgen/field.hpp"

namespace cemv::testgen::field_detail {

// Inputs set together, commands issued in the segment's first cycle.
struct Segment {
  std::vector<std::pair<std::size_t, model::TagValue>> set;  // input index, value
  std::vector<model::Command> commands;
  std::size_t cycles = 0;  // 0: the step's last segment, held until the loop settles
};

// What one loop test trips: a cause, or the causes of an XooN group.
struct LoopPlan {
  int sif = 0;
  std::vector<int> causes;
  int xoon_effect = 0;  // an XooN group test: the effect, else 0
  int xoon = 0;
};

// One loop test under construction: the run so far and its checkpoints.
class LoopBuilder {
 public:
  LoopBuilder(const model::Matrix& m, std::uint64_t settle_ms);

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
                     bool initial = false);

 private:
  std::size_t run_and_settle(const std::vector<Segment>& segs);
  void describe_changes(FieldTestStep& st);
  bool describe_pulse(std::size_t i, const FieldTestStep& st, std::vector<std::string>& pulses);
  std::size_t change_time(std::size_t i, const FieldTestStep& st);

  const model::Matrix& m_;
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

// The loop test of a plan, with its scenario and its time in the field.
FieldTest build_loop(const model::Matrix& m, const FieldOptions& o, const LoopPlan& p);

}  // namespace cemv::testgen::field_detail
