// The suite (docs/testgen.md, "Synthesis and minimisation"). Per SIF group,
// objectives are taken in catalogue order; each is first tried as an
// extension of the group's open test (BMC from the state the test leaves),
// else searched from start-up (a new test), else proved unreachable, else
// left undecided. After every change to a test, the runtime replays it and
// the concrete property evaluator marks every objective of the group it
// witnesses as covered, so an objective covered by an earlier test is never
// searched again. Groups are independent, so --jobs searches them in parallel
// and the result does not depend on the number of jobs.
#include <algorithm>
#include <chrono>
#include <functional>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "checker/engines/accelerated_bmc.hpp"
#include "checker/prover.hpp"
#include "checker/work_queue.hpp"
#include "checker/replay.hpp"
#include "formats/matrix_json.hpp"
#include "formats/scenario.hpp"
#include "properties/evaluator.hpp"
#include "properties/monitor.hpp"
#include "runtime/runtime.hpp"
#include "testgen/explore.hpp"
#include "testgen/scenario_writer.hpp"
#include "testgen/search.hpp"
#include "testgen/sweep.hpp"
#include "testgen/testgen.hpp"

namespace cemv::testgen {

namespace {

using detail::Goal;
using detail::SearchResult;

struct Draft {
  int sif = 0;
  std::vector<model::CycleInput> inputs;
  std::vector<model::Node> roots;
  std::vector<std::pair<std::size_t, std::size_t>> witnesses;  // (cycle, objective index)
  bool simulates = false;  // some cycle forces a tag (simulate_tag): only `simulates` objectives follow
};

bool forces(const std::vector<model::CycleInput>& inputs) {
  for (const auto& in : inputs)
    for (const auto& c : in.commands)
      if (c.op == model::CommandOp::SimulateTag) return true;
  return false;
}

std::vector<model::Node> merge(std::vector<model::Node> a, const std::vector<model::Node>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end()), a.end());
  return a;
}

// A test's inputs and what extends them, allocated once at their size (a
// vector grown by insert may keep twice the capacity of an 8 h test).
std::vector<model::CycleInput> joined(const std::vector<model::CycleInput>& test, std::vector<model::CycleInput> more) {
  std::vector<model::CycleInput> all;
  all.reserve(test.size() + more.size());
  all.insert(all.end(), test.begin(), test.end());
  all.insert(all.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
  return all;
}

// Cycles a sweep adds to a test at most (testgen/sweep.hpp); objectives
// whose witness needs half of them or more (timers) are searched alone.
constexpr int kSweepDepth = 16;

class GroupRun {
 public:
  GroupRun(const model::Matrix& m, const TestgenOptions& o, const properties::PropertyFile& file,
           std::vector<ObjectiveResult>& results, const std::vector<std::size_t>& members, std::mutex& report)
      : m_(m), options_(o), file_(file), results_(results), members_(members), report_(report), search_(m, o) {}

  // The group's tests; when the run's cancel token or wall clock ends it,
  // the tests made so far (each already replayed green), every objective
  // not yet decided left undecided ("time limit").
  std::vector<Draft> run() {
    try {
      decide_all();
    } catch (const checker::Interrupted&) {
      if (open_ && drafts_.back().witnesses.empty()) drafts_.pop_back();
      for (std::size_t i : members_) {
        ObjectiveResult& res = results_[i];
        if (res.status != ObjectiveStatus::Undecided || !res.reason.empty()) continue;
        res.reason = checker::to_string(checker::UnknownReason::TimeLimit);
      }
    }
    return std::move(drafts_);
  }

 private:
  void decide_all() {
    sweep_all(false);
    sweep_all(true);
    for (std::size_t i : members_) {
      if (results_[i].status == ObjectiveStatus::Covered) continue;
      const properties::Property& p = file_.properties[i];
      t0_ = std::chrono::steady_clock::now();
      Goal g{&file_, &p, roots_of(i), results_[i].objective.horizon};
      // What the sweep could not reach within its depth waits for a timer
      // in its cone, most likely: accelerated BMC (macro steps) goes first.
      if (swept_.count(i)) g.horizon = std::max(g.horizon, timer_horizon(g.roots));
      // A `reference` objective is infeasible wherever no forcing interrupts
      // the reference: proved first, so that no search budget is spent on it.
      if (results_[i].objective.simulates && proved(i, g)) continue;
      if (room(i) && extend(i, g)) continue;
      SearchResult r = search_.find(g, {}, options_.objective_work);
      if (r.kind == SearchResult::Kind::Found && !fits(r.cycles.size())) {
        ObjectiveResult& res = results_[i];
        res.status = ObjectiveStatus::Undecided;
        res.reason = "its shortest witness found has " + std::to_string(r.cycles.size()) +
                     " cycles, more than a test may have (TestgenOptions::max_test_cycles and the scenario limits)";
        announce(res);
        continue;
      }
      if (r.kind == SearchResult::Kind::Found && start(i, g, r)) continue;
      if (r.kind == SearchResult::Kind::Found) {
        // A slice over-approximates what lies outside its cone
        // (docs/encoding.md "Slices"): the whole matrix is exact.
        Goal full = g;
        full.roots.clear();
        SearchResult again = search_.find(full, {}, options_.objective_work);
        if (again.kind == SearchResult::Kind::Found && start(i, full, again)) continue;
        throw checker::InternalError("the runtime does not reproduce the witness of objective " +
                                     results_[i].objective.id);
      }
      if (simulate(i, g)) continue;
      SearchResult proof = results_[i].objective.simulates ? SearchResult{} : search_.prove_unreachable(g);
      ObjectiveResult& res = results_[i];
      if (proof.kind == SearchResult::Kind::Infeasible) {
        res.status = ObjectiveStatus::Infeasible;
        res.method = proof.method;
        res.reason = proof.reason;
      } else {
        res.status = ObjectiveStatus::Undecided;
        res.reason = "search: " + r.reason + "; proof: " + (proof.reason.empty() ? "not found first" : proof.reason);
      }
      announce(res);
    }
  }

  // The group's objectives of short horizon on one incremental BMC a
  // question (testgen/sweep.hpp): the open test is extended by the shortest
  // run that reaches any of them, with every other one the same run can
  // reach as well, again and again; when none is within reach of its end, a
  // new test starts from start-up. With `held`, the same for the objectives
  // that wait for a timer (a long horizon, or not reached by the first
  // sweep), on macro steps of held inputs. What no sweep reaches is taken
  // one objective at a time below (any float, simulation, proof).
  void sweep_all(bool held) {
    std::set<std::size_t> left_out;  // reached by a sweep but not witnessed on the runtime
    for (;;) {
      std::vector<std::size_t> pending;
      int horizon = 0;
      for (std::size_t i : members_) {
        const ObjectiveResult& r = results_[i];
        if (r.status != ObjectiveStatus::Undecided || !r.reason.empty() || r.objective.simulates || left_out.count(i))
          continue;
        const bool long_horizon = r.objective.horizon >= kSweepDepth / 2;
        const bool wanted = held ? long_horizon || swept_.count(i) > 0 : !long_horizon;
        if (!wanted) continue;
        pending.push_back(i);
        if (!held) swept_.insert(i);
        horizon = std::max({horizon, r.objective.horizon, held ? timer_horizon(roots_of(i)) : 0});
      }
      if (pending.empty()) return;
      t0_ = std::chrono::steady_clock::now();
      detail::SweepQuestion q;
      q.file = &file_;
      q.held = held;
      q.max_depth = held ? checker::AcceleratedBmc::kMaxMacroSteps : kSweepDepth;
      // Held inputs may be held far longer than a timer needs (any length
      // satisfies a saturated one): a test holds them at most as long as
      // one objective's search would (testgen/search.cpp).
      const std::int64_t longest = std::min<std::int64_t>(
          checker::kMaxTraceCycles, std::max(2 * horizon, horizon + options_.max_depth));
      // A question that reaches nothing spends all of its budget: a few
      // objectives left get a small one, many a whole objective's.
      q.budget = std::min<checker::Work>(options_.objective_work,
                                         pending.size() * std::max<checker::Work>(1, options_.objective_work / 32));
      for (std::size_t i : pending) {
        q.targets.push_back(&file_.properties[i]);
        q.roots = merge(std::move(q.roots), roots_of(i));
      }
      const std::string method = held ? "accelerated-bmc" : "bmc";
      if (room(pending.front())) {
        Draft& d = drafts_.back();
        q.prefix = &d.inputs;
        q.roots = merge(std::move(q.roots), d.roots);
        q.max_cycles = std::min<std::int64_t>(longest, static_cast<std::int64_t>(options_.max_test_cycles) -
                                                           static_cast<std::int64_t>(d.inputs.size()));
        detail::SweepAnswer a = q.max_cycles > 0 ? detail::sweep(m_, options_, q) : detail::SweepAnswer{};
        if (!a.cycles.empty()) {
          const std::size_t target = pending[a.reached.front()];
          std::vector<model::CycleInput> all = joined(d.inputs, std::move(a.cycles));
          if (adopt(d, std::move(all), target, method)) {
            d.roots = q.roots;
            continue;
          }
        }
        q.prefix = nullptr;
      }
      q.max_cycles = longest;
      detail::SweepAnswer a = detail::sweep(m_, options_, q);
      if (a.cycles.empty()) return;
      const std::size_t target = pending[a.reached.front()];
      SearchResult r;
      r.kind = SearchResult::Kind::Found;
      r.cycles = std::move(a.cycles);
      r.method = method;
      Goal g{&file_, &file_.properties[target], q.roots, results_[target].objective.horizon};
      if (!start(target, g, r)) left_out.insert(target);
    }
  }

  // The longest on-delay of the causes in a cone, in cycles, and one more.
  int timer_horizon(const std::vector<model::Node>& roots) const {
    int h = 0;
    for (const auto& n : roots) {
      const model::Cause* c = n.kind == model::Node::Kind::Cause ? m_.find_cause(n.id) : nullptr;
      if (c && c->time.mode == model::TimeMode::OnDelay)
        h = std::max(h, static_cast<int>((c->time.ms + m_.cycle_ms - 1) / m_.cycle_ms) + 1);
    }
    return h;
  }

  const std::vector<model::Node>& roots_of(std::size_t i) {
    auto it = roots_.find(i);
    if (it == roots_.end())
      it = roots_.emplace(i, properties::property_roots(file_.properties[i], file_.assumptions, m_)).first;
    return it->second;
  }

  bool proved(std::size_t i, const Goal& g) {
    SearchResult proof = search_.prove_unreachable(g);
    if (proof.kind != SearchResult::Kind::Infeasible) return false;
    ObjectiveResult& res = results_[i];
    res.status = ObjectiveStatus::Infeasible;
    res.method = proof.method;
    res.reason = proof.reason;
    announce(res);
    return true;
  }

  // The open test may be extended while it is shorter than the step limit
  // (docs/testgen.md, "Synthesis and minimisation"): steps are what a field
  // engineer performs, so a hold of 8 hours counts as one step, not as 288,000
  // cycles, and the soft-bypass checkpoints of a cause follow each other in
  // one test. The cycle limit only bounds the memory of a replay.
  bool room(std::size_t i) const {
    if (!open_) return false;
    const Draft& d = drafts_.back();
    // After a forced output only objectives that may force follow: the others
    // assume no simulation, and their witnesses must not lean on one.
    if (d.simulates && !results_[i].objective.simulates) return false;
    if (!fits(d.inputs.size() + 1)) return false;
    std::vector<std::size_t> checkpoints;
    for (const auto& w : d.witnesses) checkpoints.push_back(w.first);
    return detail::count_steps(d.inputs, checkpoints) < options_.max_test_steps;
  }

  // A test must load as a scenario (formats/scenario.hpp: at most
  // kMaxScenarioCycles cycles and kMaxScenarioTagValues input values) and stay
  // within the cycle limit, which bounds the memory of generating it (a few
  // KB per cycle: inputs, observables and the evaluator's trace).
  bool fits(std::size_t cycles) const {
    const std::size_t width = std::max<std::size_t>(1, model::InputTable(m_).size());
    return cycles <= options_.max_test_cycles && cycles <= formats::kMaxScenarioCycles &&
           cycles <= formats::kMaxScenarioTagValues / width;
  }

  // A long witness of accelerated BMC holds its inputs through each macro
  // step, operator commands included: the same command issued in every cycle
  // of a stretch, one checklist step per cycle. The run without the repeats
  // is adopted when it still witnesses the objective.
  bool adopt(Draft& d, std::vector<model::CycleInput> inputs, std::size_t target, const std::string& method) {
    bool repeats = false;
    for (std::size_t k = inputs.size(); k-- > 1 && !repeats;)
      repeats = !inputs[k].commands.empty() && same_commands(inputs[k].commands, inputs[k - 1].commands);
    if (repeats) {
      // A copy only then: an 8 h test's inputs are 576,000 cycles.
      std::vector<model::CycleInput> once = inputs;
      for (std::size_t k = once.size(); k-- > 1;)
        if (!once[k].commands.empty() && same_commands(inputs[k].commands, inputs[k - 1].commands))
          once[k].commands.clear();
      if (adopt_run(d, std::move(once), target, method)) return true;
    }
    return adopt_run(d, std::move(inputs), target, method);
  }

  static bool same_commands(const std::vector<model::Command>& a, const std::vector<model::Command>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].op != b[i].op || a[i].cause != b[i].cause || a[i].effect != b[i].effect || a[i].tag != b[i].tag ||
          a[i].group != b[i].group || a[i].on != b[i].on || a[i].tag_name != b[i].tag_name || a[i].value != b[i].value)
        return false;
    return true;
  }

  // Replays `inputs` and marks what they witness; false when `target` is not
  // witnessed. The run is judged as the runtime steps it, each objective of
  // the group still open by the concrete evaluator streamed cycle by cycle
  // (properties::StreamEvaluator): a test keeps its inputs only, never a
  // trace, so what generating it holds is its inputs (an 8 h test: 576,000
  // cycles), not their observables as well.
  bool adopt_run(Draft& d, std::vector<model::CycleInput> inputs, std::size_t target, const std::string& method) {
    if (!fits(inputs.size())) return false;
    std::vector<std::size_t> open;
    std::vector<properties::StreamEvaluator> judges;
    for (std::size_t i : members_) {
      const ObjectiveStatus st = results_[i].status;
      if (i != target && (st == ObjectiveStatus::Covered || st == ObjectiveStatus::Infeasible)) continue;
      open.push_back(i);
      judges.emplace_back(m_, file_.properties[i], file_.assumptions);
    }
    // Each cycle copies only the observables the open objectives read.
    std::vector<std::size_t> read;
    for (const auto& j : judges) read.insert(read.end(), j.observables_read().begin(), j.observables_read().end());
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
    runtime::Runtime rt(m_);
    std::vector<int> obs;
    rt.snapshot(obs);
    for (const auto& in : inputs) {
      rt.step(in);
      for (std::size_t i : read) obs[i] = rt.observable(i);
      bool all_final = true;
      for (auto& j : judges)
        if (!j.final()) {
          j.step(in, obs);
          all_final = all_final && j.final();
        }
      if (all_final) break;
    }
    auto witness = [&](std::size_t k) -> std::optional<std::size_t> {
      const properties::Evaluation& e = judges[k].result();
      if (e.holds && e.cycle) return *e.cycle;
      return std::nullopt;
    };
    const std::size_t t = static_cast<std::size_t>(std::find(open.begin(), open.end(), target) - open.begin());
    if (!witness(t)) return false;
    d.simulates = forces(inputs);
    d.inputs = std::move(inputs);
    for (std::size_t k = 0; k < open.size(); ++k) {
      const std::size_t i = open[k];
      ObjectiveResult& r = results_[i];
      if (r.status == ObjectiveStatus::Covered || r.status == ObjectiveStatus::Infeasible) continue;
      auto c = witness(k);
      if (!c) continue;
      r.status = ObjectiveStatus::Covered;
      r.test = -1;  // numbered when the suite is assembled
      r.cycle = static_cast<int>(*c);
      r.method = i == target ? method : "replay";
      r.reason.clear();
      d.witnesses.push_back({*c, i});
      announce(r);
    }
    return true;
  }

  bool extend(std::size_t i, const Goal& g) {
    Draft& d = drafts_.back();
    Goal eg = g;
    eg.roots = merge(d.roots, g.roots);
    SearchResult r = search_.find(eg, d.inputs, options_.objective_work / 2);
    if (r.kind != SearchResult::Kind::Found) return false;
    std::vector<model::CycleInput> all = joined(d.inputs, std::move(r.cycles));
    if (!adopt(d, std::move(all), i, r.method)) return false;
    d.roots = eg.roots;
    return true;
  }

  // BMC did not reach the objective within its budget: seeded random runs on
  // the runtime look for a witness, first continuing the open test, then
  // from start-up (testgen/explore.hpp); BMC then finds the run's last
  // cycles from the state a few cycles before its witness, shortest first.
  bool simulate(std::size_t i, const Goal& g) {
    std::uint64_t seed = 1469598103934665603ULL;  // FNV-1a of the objective id: fixed runs
    for (char c : results_[i].objective.id) seed = (seed ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
    if (room(i)) {
      Draft& d = drafts_.back();
      SearchResult r = detail::explore(m_, g, d.inputs, seed);
      if (r.kind == SearchResult::Kind::Found &&
          complete(g, d.inputs, r, [&](std::vector<model::CycleInput> cycles, const std::string& method) {
            return adopt(d, joined(d.inputs, std::move(cycles)), i, method);
          }))
        return true;
    }
    SearchResult r = detail::explore(m_, g, {}, seed + 1);
    if (r.kind != SearchResult::Kind::Found) return false;
    return complete(g, {}, r, [&](std::vector<model::CycleInput> cycles, const std::string& method) {
      SearchResult s;
      s.kind = SearchResult::Kind::Found;
      s.cycles = std::move(cycles);
      s.method = method;
      return start(i, g, s);
    });
  }

  // Offers `take` the simulated run with its last cycles found again by BMC
  // from the state shortly before the witness, then the simulated run
  // itself, until it takes one. One candidate at a time: a run of an 8 h
  // test is 576,000 cycles of inputs.
  bool complete(const Goal& g, const std::vector<model::CycleInput>& prefix, SearchResult& r,
                const std::function<bool(std::vector<model::CycleInput>, const std::string&)>& take) {
    constexpr std::size_t kTail = 3;
    const std::size_t keep = r.cycles.size() > kTail ? r.cycles.size() - kTail : 0;
    if (!prefix.empty() || keep > 0) {
      SearchResult b;
      {
        std::vector<model::CycleInput> head;
        head.reserve(prefix.size() + keep);
        head = prefix;
        head.insert(head.end(), r.cycles.begin(), r.cycles.begin() + static_cast<long>(keep));
        b = search_.find(g, head, options_.objective_work / 4);
      }
      if (b.kind == SearchResult::Kind::Found) {
        std::vector<model::CycleInput> cycles;
        cycles.reserve(keep + b.cycles.size());
        cycles.assign(r.cycles.begin(), r.cycles.begin() + static_cast<long>(keep));
        cycles.insert(cycles.end(), b.cycles.begin(), b.cycles.end());
        if (take(std::move(cycles), "simulation+" + b.method)) return true;
      }
    }
    return take(std::move(r.cycles), "simulation");
  }

  bool start(std::size_t i, const Goal& g, const SearchResult& r) {
    Draft d;
    d.sif = results_[i].objective.sif;
    d.roots = g.roots;
    drafts_.push_back(std::move(d));
    open_ = true;
    if (adopt(drafts_.back(), r.cycles, i, r.method)) return true;
    drafts_.pop_back();
    return false;
  }

  void announce(ObjectiveResult& r) {
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (!options_.on_decided) return;
    std::lock_guard<std::mutex> lock(report_);
    options_.on_decided(r);
  }

  const model::Matrix& m_;
  const TestgenOptions& options_;
  const properties::PropertyFile& file_;
  std::vector<ObjectiveResult>& results_;
  const std::vector<std::size_t>& members_;
  std::mutex& report_;
  detail::Searcher search_;
  std::vector<Draft> drafts_;
  std::map<std::size_t, std::vector<model::Node>> roots_;  // each objective's cone
  std::set<std::size_t> swept_;                            // asked of a sweep
  bool open_ = false;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (std::isalnum(static_cast<unsigned char>(c))) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.substr(0, 40);
}

// SIF groups in ascending order, objectives without a group last.
int group_rank(int sif) { return sif == 0 ? 1 << 30 : sif; }

}  // namespace

TestSuite generate_tests(const model::Matrix& m, const TestgenOptions& options) {
  TestSuite suite;
  suite.matrix_name = m.name;
  suite.signature = formats::signature(m);
  std::vector<Objective> all = derive_objectives(m);
  std::vector<Objective> chosen;
  for (auto& o : all)
    if ((!options.sif || o.sif == *options.sif) && (!options.elements || options.elements->count(o.element)))
      chosen.push_back(std::move(o));
  const properties::PropertyFile file = objectives_file(chosen);
  for (auto& o : chosen) {
    ObjectiveResult r;
    r.objective = std::move(o);
    suite.objectives.push_back(std::move(r));
  }

  std::map<int, std::vector<std::size_t>> groups;  // by rank
  for (std::size_t i = 0; i < suite.objectives.size(); ++i)
    groups[group_rank(suite.objectives[i].objective.sif)].push_back(i);
  std::vector<const std::vector<std::size_t>*> order;
  for (const auto& [rank, members] : groups) order.push_back(&members);
  std::vector<std::vector<Draft>> drafts(order.size());
  std::mutex report;
  checker::CancelToken own;
  TestgenOptions mine = options;
  if (!mine.cancel) mine.cancel = &own;
  checker::WorkQueue queue(options.jobs, *mine.cancel);
  queue.run(order.size(), [&](std::size_t g) {
    drafts[g] = GroupRun(m, mine, file, suite.objectives, *order[g], report).run();
  });
  // The cancel token (--total-timeout) ended the run first: the groups it
  // did not reach are undecided, the suite holds the tests made before.
  if (mine.cancel->cancelled())
    for (auto& r : suite.objectives)
      if (r.status == ObjectiveStatus::Undecided && r.reason.empty())
        r.reason = checker::to_string(checker::UnknownReason::TimeLimit);

  // The given tests first (C001, ...), each checked at its last cycle.
  for (const GivenTest& g : options.given) {
    if (g.inputs.empty()) continue;
    Test t;
    char id[16];
    std::snprintf(id, sizeof id, "C%03zu", suite.tests.size() + 1);
    t.id = id;
    t.sif = g.sif;
    t.description = t.id + ": " + g.description;
    t.file_name = t.id + "-" + slug(g.name) + ".scenario.json";
    const std::size_t last = g.inputs.size() - 1;
    std::vector<detail::Checkpoint> cps{{last, {g.description}, {g.key}}};
    t.checkpoints = {last};
    t.inputs = g.inputs;
    t.scenario_json = detail::test_scenario_json(m, options.matrix_ref, t.description, g.inputs,
                                                 detail::snapshots_at(m, g.inputs, t.checkpoints), cps, t.steps,
                                                 t.field_steps);
    suite.total_steps += t.steps;
    suite.total_cycles += t.inputs.size();
    suite.tests.push_back(std::move(t));
  }
  const std::size_t given = suite.tests.size();

  // Assemble: tests in group order, then creation order; objective results
  // point at the final test numbers.
  std::map<std::pair<std::size_t, int>, int> number;  // (group, draft) -> test index
  for (std::size_t g = 0; g < order.size(); ++g)
    for (std::size_t d = 0; d < drafts[g].size(); ++d) {
      Draft& dr = drafts[g][d];
      if (dr.witnesses.empty()) continue;
      const int index = static_cast<int>(suite.tests.size());
      number[{g, static_cast<int>(d)}] = index;
      std::sort(dr.witnesses.begin(), dr.witnesses.end());
      Test t;
      char id[16];
      std::snprintf(id, sizeof id, "T%03zu", static_cast<std::size_t>(index) + 1 - given);
      t.id = id;
      t.sif = dr.sif;
      const Objective& first = suite.objectives[dr.witnesses.front().second].objective;
      const auto sif_name = m.sif_groups.find(dr.sif);
      t.description = std::string(id) + (dr.sif ? " (SIF " + std::to_string(dr.sif) +
                                                      (sif_name != m.sif_groups.end() ? " " + sif_name->second : "") + ")"
                                                : "") + ": " + first.text;
      t.file_name = t.id + "-" + slug(first.id) + ".scenario.json";
      std::vector<detail::Checkpoint> cps;
      for (const auto& [cycle, oi] : dr.witnesses) {
        ObjectiveResult& r = suite.objectives[oi];
        r.test = index;
        if (cps.empty() || cps.back().cycle != cycle) cps.push_back({cycle, {}, {}});
        cps.back().descriptions.push_back(r.objective.id + ": " + r.objective.text);
        for (const auto& k : r.objective.observe) cps.back().observe.push_back(k);
        t.objectives.push_back(r.objective.id);
      }
      for (const auto& c : cps) t.checkpoints.push_back(c.cycle);
      t.scenario_json = detail::test_scenario_json(m, options.matrix_ref, t.description, dr.inputs,
                                                   detail::snapshots_at(m, dr.inputs, t.checkpoints), cps, t.steps,
                                                   t.field_steps);
      t.inputs = std::move(dr.inputs);
      suite.total_steps += t.steps;
      suite.total_cycles += t.inputs.size();
      suite.tests.push_back(std::move(t));
    }
  for (const auto& r : suite.objectives) {
    suite.covered += r.status == ObjectiveStatus::Covered;
    suite.infeasible += r.status == ObjectiveStatus::Infeasible;
    suite.undecided += r.status == ObjectiveStatus::Undecided;
  }
  // Never an unchecked answer: the files as written replay green.
  ReplayResult replay = replay_suite(m, suite);
  for (const auto& t : replay.tests)
    if (!t.passed)
      throw checker::InternalError("generated test " + t.name + " does not replay green: " +
                                   (t.load_error.empty() ? (t.steps.empty() ? std::string("?") : [&] {
                                     for (const auto& s : t.steps)
                                       if (!s.failures.empty()) return s.failures.front();
                                     return std::string("?");
                                   }())
                                                         : t.load_error));
  return suite;
}

}  // namespace cemv::testgen
