#include "testgen/explore.hpp"

#include <algorithm>

#include "checker/random_runs.hpp"
#include "encoder/encode.hpp"
#include "properties/evaluator.hpp"
#include "runtime/runtime.hpp"

namespace cemv::testgen::detail {

namespace {

// The tags and commands of the goal's cone: what a run may change. Outside
// the cone nothing the objective reads moves.
checker::RunSpace cone_space(const model::Matrix& m, const Goal& g) {
  z3::context ctx;
  std::shared_ptr<encoder::Encoding> enc = encoder::encode(ctx, m, g.roots);
  std::vector<std::string> tags;
  for (std::size_t i = 0; i < enc->tag_value.size(); ++i)
    if (enc->tag_value[i] || enc->tag_bad[i]) tags.push_back(enc->inputs.tags()[i].name);
  std::vector<model::Command> commands;
  for (const auto& c : enc->commands) commands.push_back(c.command());
  checker::RunSpace s = checker::run_space(m, nullptr, tags, commands);
  // A cone without a command of its own: runs only change inputs.
  if (commands.empty()) s.commands.clear();
  return s;
}

class Judge {
 public:
  Judge(const model::Matrix& m, const Goal& g, const std::vector<model::CycleInput>& prefix)
      : m_(m), g_(g), prefix_(prefix), eval_(m) {
    runtime::Runtime rt(m);
    std::vector<int> obs;
    for (const auto& in : prefix) {
      rt.step(in);
      rt.snapshot(obs);
      trace_.push_back({in, obs});
    }
    start_ = prefix.empty() ? model::default_cycle_input(m) : prefix.back();
    start_.commands.clear();
  }

  // The cycle after the prefix where the run witnesses the goal, or -1.
  long witness(const checker::Run& run) {
    const std::vector<model::CycleInput> cycles = checker::expand(m_, run, start_);
    runtime::Runtime rt(m_);
    for (const auto& in : prefix_) rt.step(in);
    // The run's cycles are judged after the prefix's and dropped again: the
    // prefix (hours of a soft bypass: 576,000 cycles) is held once, not
    // copied for every run.
    const std::size_t base = trace_.size();
    std::vector<int> obs;
    for (const auto& in : cycles) {
      rt.step(in);
      rt.snapshot(obs);
      trace_.push_back({in, obs});
    }
    const auto e = eval_.evaluate(*g_.property, g_.file->assumptions, trace_);
    trace_.erase(trace_.begin() + static_cast<long>(base), trace_.end());
    if (!e.holds || !e.cycle || *e.cycle < prefix_.size()) return -1;
    return static_cast<long>(*e.cycle - prefix_.size());
  }

  const model::CycleInput& start() const { return start_; }

 private:
  const model::Matrix& m_;
  const Goal& g_;
  const std::vector<model::CycleInput>& prefix_;
  properties::Evaluator eval_;
  properties::Trace trace_;
  model::CycleInput start_;
};

}  // namespace

SearchResult explore(const model::Matrix& m, const Goal& g, const std::vector<model::CycleInput>& prefix,
                     std::uint64_t seed, int runs, std::size_t segments) {
  SearchResult out;
  checker::RandomRuns gen(cone_space(m, g), seed);
  Judge judge(m, g, prefix);
  // Long enough for the objective's timers, not for hours of soft bypass
  // (accelerated BMC's macro steps reach those).
  const std::size_t max_cycles = std::max<std::size_t>(400, 4 * static_cast<std::size_t>(std::max(0, g.horizon)));
  // Each run replays the prefix first: a long test gets fewer runs, so that
  // one objective costs at most ~1,000,000 simulated cycles, and fewer on a
  // large matrix, whose cycle costs more: 16,000,000 element-cycles (the
  // examples, up to 16 causes and effects, keep their 1,000,000; the
  // 128 x 128 benchmark matrix gets 62,500, where a million took minutes).
  // A budget in work, not in seconds, keeps the runs independent of load.
  const std::size_t elements = std::max<std::size_t>(16, m.causes.size() + m.effects.size());
  const std::size_t budget = std::min<std::size_t>(1000000, 16000000 / elements);
  const std::size_t per_run = prefix.size() + max_cycles;
  runs = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(0, runs)),
                                                std::max<std::size_t>(20, budget / per_run)));
  for (int r = 0; r < runs; ++r) {
    checker::Run run = gen.next(segments, max_cycles);
    if (judge.witness(run) < 0) continue;
    run = checker::minimise_run(std::move(run), [&](const checker::Run& x) { return judge.witness(x); });
    const long w = judge.witness(run);
    if (w < 0) break;  // cannot happen: minimise_run keeps a witness
    out.cycles = checker::expand(m, run, judge.start());
    out.cycles.resize(static_cast<std::size_t>(w) + 1);
    out.kind = SearchResult::Kind::Found;
    out.method = "simulation";
    return out;
  }
  out.reason = "no witness in " + std::to_string(runs) + " random runs";
  return out;
}

}  // namespace cemv::testgen::detail
