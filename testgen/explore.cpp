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

// Judges runs after the prefix cycle by cycle (properties::StreamEvaluator):
// the runtime and the evaluator are stepped through the prefix once and
// copied for every run, so neither the prefix (hours of a soft bypass:
// 576,000 cycles) nor a run (up to 4 x a timer's horizon) is ever held as a
// trace, and a run is judged only up to its witness. Only the run that
// becomes a test is expanded (explore below), and it is judged again on its
// whole trace when it is adopted (testgen/generate.cpp).
class Judge {
 public:
  Judge(const model::Matrix& m, const Goal& g, const std::vector<model::CycleInput>& prefix)
      : m_(m), rt_(m), eval_(m, *g.property, g.file->assumptions), prefix_cycles_(prefix.size()) {
    rt_.snapshot(obs_);  // sized; each cycle then copies only what the evaluator reads
    for (const auto& in : prefix) {
      rt_.step(in);
      read(rt_);
      eval_.step(in, obs_);
    }
    start_ = prefix.empty() ? model::default_cycle_input(m) : prefix.back();
    start_.commands.clear();
  }

  // The cycle after the prefix where the run witnesses the goal, or -1.
  long witness(const checker::Run& run) {
    // Decided within the prefix: a witness there, or an assumption failed.
    if (eval_.final()) return -1;
    runtime::Runtime rt = rt_;
    properties::StreamEvaluator ev = eval_;
    checker::for_each_cycle(m_, run, start_, [&](const model::CycleInput& in) {
      rt.step(in);
      read(rt);
      ev.step(in, obs_);
      return !ev.final();
    });
    const properties::Evaluation& e = ev.result();
    if (!e.holds || !e.cycle || *e.cycle < prefix_cycles_) return -1;
    return static_cast<long>(*e.cycle - prefix_cycles_);
  }

  const model::CycleInput& start() const { return start_; }

 private:
  // A run of an 8 h soft bypass is 576,000 cycles: the few observables the
  // objective reads, not the matrix's hundreds.
  void read(const runtime::Runtime& rt) {
    for (std::size_t i : eval_.observables_read()) obs_[i] = rt.observable(i);
  }

  const model::Matrix& m_;
  runtime::Runtime rt_;                // after the prefix
  properties::StreamEvaluator eval_;   // after the prefix
  std::size_t prefix_cycles_;
  std::vector<int> obs_;
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
    out.cycles.reserve(static_cast<std::size_t>(w) + 1);
    checker::for_each_cycle(m, run, judge.start(), [&](const model::CycleInput& in) {
      out.cycles.push_back(in);
      return out.cycles.size() <= static_cast<std::size_t>(w);
    });
    out.kind = SearchResult::Kind::Found;
    out.method = "simulation";
    return out;
  }
  out.reason = "no witness in " + std::to_string(runs) + " random runs";
  return out;
}

}  // namespace cemv::testgen::detail
