// The checker's one function (checker/check.hpp): three passes of the run's
// work queue over the properties (checker/property_checker.hpp): decide,
// vacuity, support. The vacuity pass asks the runtime traces of the first
// pass, all of them and in property order, so that no answer depends on which
// worker finished first.
#include "checker/check.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <optional>

#include "checker/cone_group.hpp"
#include "checker/group_support.hpp"
#include "checker/property_checker.hpp"
#include "checker/work_queue.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::checker {

namespace {

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

// What is left of a property's --timeout when one of its passes starts (the
// passes share it).
struct PropertyClock {
  double limit_s = 0.0;
  double used_s = 0.0;
  Limits limits(const CancelToken& cancel, SolverSetup solvers) const {
    Limits l;
    l.cancel = &cancel;
    l.solvers = solvers;
    if (limit_s > 0) l.deadline = Clock::now() + seconds(std::max(0.0, limit_s - used_s));
    return l;
  }
};

// The result of a property that the run did not get to (the cancel token
// ended it first).
PropertyResult not_decided(const properties::PropertyFile& f, const properties::Property& p) {
  PropertyResult r;
  r.name = p.name;
  r.description = p.description;
  r.kind = properties::to_string(p.kind);
  r.line = p.loc.line;
  r.column = p.loc.column;
  r.file = f.file_name;
  r.notes = p.notes;
  r.verdict = PropertyVerdict::Unknown;
  r.unknown = UnknownReason::TimeLimit;
  r.reason = to_string(r.unknown);
  return r;
}

}  // namespace

CheckResult check_properties(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                             const CheckOptions& options) {
  std::optional<CancelToken> own;
  if (!options.cancel)
    own.emplace(options.total_timeout_s > 0 ? Clock::now() + seconds(options.total_timeout_s) : Clock::time_point::max());
  CancelToken& cancel = options.cancel ? *options.cancel : *own;

  CheckResult result;
  result.matrix_name = m.name;
  result.matrix_signature = formats::signature(m);
  result.tool_version = CEMV_VERSION;
  result.standard = options.standard;
  if (options.shard_count > 1)
    result.shard = std::to_string(options.shard_index) + "/" + std::to_string(options.shard_count);
  for (const auto& f : files) result.property_files.push_back(f.file_name);

  struct Job {
    const properties::PropertyFile* file;
    const properties::Property* property;
    std::unique_ptr<PropertyChecker> checker;
    std::optional<PropertyResult> result;
    PropertyClock clock;
    bool vacuity_settled = false;
    bool done = false;  // every pass it needs has run
  };
  std::vector<Job> jobs;
  std::size_t index = 0;
  for (const auto& f : files)
    for (const auto& p : f.properties)
      if (in_shard(index++, options.shard_index, options.shard_count))
        jobs.push_back({&f, &p, nullptr, std::nullopt, {options.property_timeout_s, 0.0}});

  std::mutex report_mutex;
  auto report = [&](Job& j) {
    j.done = true;
    if (!options.on_result) return;
    std::lock_guard<std::mutex> lock(report_mutex);
    options.on_result(*j.result);
  };
  WorkQueue queue(options.jobs, cancel);

  // 1. Decide, a cone group at a time (checker/cone_group.hpp): the group's
  // shared questions first, then each member's own checker.
  std::vector<GroupMember> members;
  for (const auto& j : jobs) members.push_back({j.file, j.property});
  const std::vector<std::vector<std::size_t>> groups = cone_groups(m, members);
  queue.run(groups.size(), [&](std::size_t g) {
    std::vector<GroupMember> group;
    for (std::size_t i : groups[g]) group.push_back(members[i]);
    Limits shared;
    shared.cancel = &cancel;
    shared.solvers = options.solvers;
    std::vector<EarlyAnswer> early = ConeGroup(m, group, options).decide(shared);
    for (std::size_t k = 0; k < groups[g].size(); ++k) {
      Job& j = jobs[groups[g][k]];
      if (options.on_start) {
        std::lock_guard<std::mutex> lock(report_mutex);
        options.on_start(j.property->name);
      }
      j.checker = std::make_unique<PropertyChecker>(m, *j.file, *j.property, options, std::move(early[k]));
      j.result = j.checker->decide(j.clock.limits(cancel, options.solvers));
      j.clock.used_s += j.result->seconds;
      if (!j.checker->needs_vacuity(*j.result) && !j.checker->needs_support(*j.result)) report(j);
    }
  });

  // 2. Vacuity, answered first from every run of the first pass.
  WitnessPool known;
  for (auto& j : jobs)
    if (j.checker)
      for (auto& t : j.checker->take_runs()) known.add(std::move(t));
  // A cone group at a time again, its members in order, sharing what they
  // find (checker/cone_group.hpp).
  std::vector<std::vector<Job*>> open(groups.size());
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t i : groups[g])
      if (jobs[i].result && !jobs[i].done) open[g].push_back(&jobs[i]);
  queue.run(open.size(), [&](std::size_t g) {
    WitnessPool group;
    for (Job* j : open[g]) {
      const double before = j->result->seconds;
      j->checker->settle_vacuity(*j->result, known, group, j->clock.limits(cancel, options.solvers));
      j->vacuity_settled = true;
      j->clock.used_s += j->result->seconds - before;
      if (!j->checker->needs_support(*j->result)) report(*j);
    }
  });

  // 3. Support, a cone group at a time as the decisions were: the unsat
  // cores of the group's proofs on one guarded encoding of its cone
  // (checker/group_support.hpp), then each member's support from its core,
  // re-checked by its own checker (checker/property_support.cpp).
  std::vector<std::size_t> with_proofs;
  for (std::size_t g = 0; g < open.size(); ++g)
    for (Job* j : open[g])
      if (!j->done && j->checker->needs_support(*j->result)) {
        with_proofs.push_back(g);
        break;
      }
  queue.run(with_proofs.size(), [&](std::size_t n) {
    const std::size_t g = with_proofs[n];
    std::vector<GroupMember> group;
    std::vector<SupportQuestion> questions;
    std::vector<Job*> asked;
    for (std::size_t k = 0; k < groups[g].size(); ++k) {
      Job& j = jobs[groups[g][k]];
      group.push_back(members[groups[g][k]]);
      if (j.done || !j.checker || !j.result || !j.checker->needs_support(*j.result)) continue;
      SupportQuestion q;
      q.member = k;
      q.proof = &*j.checker->proof();
      for (const auto& d : j.checker->support_candidates()) q.keys.insert(d.element.key);
      questions.push_back(std::move(q));
      asked.push_back(&j);
    }
    // The group's question runs on the first member's clock; interrupted
    // there, each member asks on its own encoding within its own.
    std::vector<std::optional<SupportCore>> cores(questions.size());
    try {
      cores = group_support_cores(m, group, questions, options, asked.front()->clock.limits(cancel, options.solvers));
    } catch (const Interrupted&) {
      if (cancel.cancelled()) throw;
    }
    for (std::size_t q = 0; q < asked.size(); ++q) {
      asked[q]->checker->find_support(*asked[q]->result, asked[q]->clock.limits(cancel, options.solvers), cores[q]);
      report(*asked[q]);
    }
  });

  for (auto& j : jobs) {
    // A proof whose later passes the cancel token cut short keeps its
    // verdict, with notes saying what was not done; a property never
    // decided is unknown.
    if (j.result && !j.done) {
      if (!j.vacuity_settled && j.checker->needs_vacuity(*j.result))
        j.result->notes.push_back("vacuity not decided (time limit)");
      else if (j.checker->needs_support(*j.result))
        j.result->notes.push_back("support not computed (time limit)");
    }
    result.properties.push_back(j.result ? std::move(*j.result) : not_decided(*j.file, *j.property));
    if (!j.done && j.result) {
      std::lock_guard<std::mutex> lock(report_mutex);
      if (options.on_result) options.on_result(result.properties.back());
    }
  }
  result.interrupted = cancel.cancelled();
  result.support_mode = options.support ? options.support_mode : SupportMode::Off;
  if (options.standard) result.unsupported = unsupported_elements(m, result.properties);
  return result;
}

}  // namespace cemv::checker
