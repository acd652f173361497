// Random runs of both runtimes side by side (checker/equivalence_falsifier.hpp).
#include "checker/equivalence_falsifier.hpp"

#include <algorithm>

#include "checker/context_pool.hpp"
#include "checker/random_runs.hpp"
#include "checker/replay.hpp"
#include "encoder/encode.hpp"
#include "runtime/runtime.hpp"

namespace cemv::checker {

using model::Node;

std::optional<int> RandomFalsifier::find(GroupEquivalence& out) const {
  const model::Matrix& a_ = q_.a;
  const model::Matrix& b_ = q_.b;
  const std::vector<Node>& ra = q_.ra;
  const std::vector<Node>& rb = q_.rb;
  const std::vector<KeyInfo>& keys_ = q_.keys;
  if (keys_.empty()) return std::nullopt;
  std::vector<std::string> tags;
  std::vector<model::Command> commands;
  {
    PooledContext ctx;
    for (const auto& [m, roots] : {std::make_pair(&a_, &ra), std::make_pair(&b_, &rb)}) {
      std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, *m, *roots);
      for (std::size_t i = 0; i < enc->tag_value.size(); ++i)
        if (enc->tag_value[i] || enc->tag_bad[i]) tags.push_back(enc->inputs.tags()[i].name);
      for (const auto& c : enc->commands) commands.push_back(c.command());
    }
  }
  RunSpace space = run_space(a_, &b_, tags, commands);
  if (commands.empty()) space.commands.clear();  // no command reaches the cones
  RandomRuns gen(std::move(space), 0x5eedULL);
  const model::CycleInput start_a = model::default_cycle_input(a_);
  model::CycleInput start_b = model::default_cycle_input(b_);
  {
    const model::InputTable ta(a_), tb(b_);
    for (std::size_t i = 0; i < tb.size(); ++i)
      if (auto j = ta.find(tb.tags()[i].name)) start_b.tags[i] = start_a.tags[*j];
  }
  // The slices, started from the whole matrices' values (a tag's value at
  // rest depends on every cause that reads it, in the cone or not).
  const model::Matrix sa = ra.empty() ? a_ : cone_matrix(a_, ra, false);
  const model::Matrix sb = rb.empty() ? b_ : cone_matrix(b_, rb, false);
  auto start_of = [](const model::Matrix& slice, const model::Matrix& whole, const model::CycleInput& start) {
    model::CycleInput s = model::default_cycle_input(slice);
    const model::InputTable ts(slice), tw(whole);
    for (std::size_t i = 0; i < ts.size(); ++i)
      if (auto j = tw.find(ts.tags()[i].name)) s.tags[i] = start.tags[*j];
    return s;
  };
  const model::CycleInput slice_start_a = start_of(sa, a_, start_a), slice_start_b = start_of(sb, b_, start_b);
  std::vector<std::pair<std::size_t, std::size_t>> slice_index;  // per key, in observables(sa), (sb)
  {
    const auto oa = model::observables(sa), ob = model::observables(sb);
    auto at = [](const std::vector<model::Observable>& obs, const std::string& key) -> std::optional<std::size_t> {
      for (std::size_t i = 0; i < obs.size(); ++i)
        if (obs[i].key == key) return i;
      return std::nullopt;
    };
    for (const auto& k : keys_) {
      auto x = at(oa, k.key), y = at(ob, k.key);
      if (!x || !y) return std::nullopt;  // not in a slice: the provers decide
      slice_index.emplace_back(*x, *y);
    }
  }
  auto differs = [&](const Run& run) -> long {
    const auto in_a = expand(sa, run, slice_start_a), in_b = expand(sb, run, slice_start_b);
    runtime::Runtime x(sa), y(sb);
    // Only the group's keys are read each cycle: runs of 400,000 cycles.
    for (std::size_t c = 0; c < in_a.size(); ++c) {
      x.step(in_a[c]);
      y.step(in_b[c]);
      for (const auto& [i, j] : slice_index)
        if (x.observable(i) != y.observable(j)) return static_cast<long>(c);
    }
    return -1;
  };
  constexpr int kRuns = 300;
  constexpr std::size_t kSegments = 10;
  // A budget of simulated cycles, not of time: the same runs everywhere.
  std::size_t simulated = 0;
  for (int r = 0; r < kRuns && simulated < q_.random_cycles; ++r) {
    if (q_.limits.interrupted()) throw Interrupted{};
    // Every sixteenth run may hold an input for hours of cycles (a soft
    // bypass timeout of 8 h moved by a second); the others stay short.
    Run run = gen.next(kSegments, r % 16 == 15 ? 400000 : 5000);
    simulated += run_cycles(run);
    if (differs(run) < 0) continue;
    run = minimise_run(std::move(run), differs);
    const long c = differs(run);
    if (c < 0) continue;
    // The run on the whole matrices: the difference must be there, in the
    // same cycle (the slice is exact for the group's observables,
    // docs/encoding.md); a run that is not is left to the provers.
    ConcreteTrace ta = run_on_runtime(a_, expand(a_, run, start_a));
    ConcreteTrace tb = run_on_runtime(b_, expand(b_, run, start_b));
    const std::size_t cycle = static_cast<std::size_t>(c);
    bool earlier = false;
    for (std::size_t k = 0; k < cycle && !earlier; ++k)
      for (const auto& key : keys_) earlier |= ta.observables[k][key.index_a] != tb.observables[k][key.index_b];
    if (earlier) continue;
    for (const auto& k : keys_) {
      if (ta.observables[cycle][k.index_a] == tb.observables[cycle][k.index_b]) continue;
      out.verdict = EquivalenceVerdict::Differs;
      out.rest_on(EquivalenceBasis::Simulation);
      out.distinction = make_distinction(k, cycle, std::move(ta), std::move(tb));
      return static_cast<int>(cycle);
    }
  }
  return std::nullopt;
}

}  // namespace cemv::checker
