#include "defeats/analysis.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>
#include <stdexcept>

#include "checker/names.hpp"
#include "checker/work_queue.hpp"
#include "defeats/enumerate.hpp"
#include "formats/matrix_json.hpp"
#include "response/analysis.hpp"

namespace cemv::defeats {

const char* to_string(SetClass c) { return c == SetClass::Declared ? "declared" : "indirect"; }

const char* to_string(PathStatus s) {
  switch (s) {
    case PathStatus::Complete: return "complete";
    case PathStatus::Unbounded: return "unbounded";
    case PathStatus::Unknown: return "unknown";
  }
  return "unknown";
}

int group_sil(const model::Matrix& m, int sif) {
  int sil = 0;
  for (const auto& c : m.causes)
    if (std::count(c.sif.begin(), c.sif.end(), sif)) sil = std::max(sil, c.sil);
  for (const auto& e : m.effects)
    if (std::count(e.sif.begin(), e.sif.end(), sif)) sil = std::max(sil, e.sil);
  return sil;
}

DefeatsResult analyse(const model::Matrix& m, const DefeatsOptions& o) {
  if (o.max_size < 0) throw std::invalid_argument("--max-size must be 0 or more");
  const auto start = checker::Clock::now();
  auto deadline = [&]() {
    return o.total_timeout_s > 0 ? start + std::chrono::duration_cast<checker::Clock::duration>(
                                               std::chrono::duration<double>(o.total_timeout_s))
                                 : checker::Clock::time_point::max();
  };
  // The trip requirement of every path: its exact logic response T, as
  // cemv response proves it (throws for an undeclared group).
  response::ResponseOptions ro;
  ro.sifs = o.sifs;
  ro.timeout_s = o.timeout_s;
  ro.total_timeout_s = o.total_timeout_s;
  ro.work = o.work;
  ro.jobs = o.jobs;
  ro.known = o.known_figures;
  ro.degraded = false;  // the requirement is the normal figure T; the degraded one is never read here
  const response::ResponseResult times = response::analyse(m, ro);

  DefeatsResult result;
  result.matrix_name = m.name;
  result.matrix_signature = formats::signature(m);
  result.max_size = o.max_size;
  result.interrupted = times.interrupted;

  // A path in several groups is decided once (the sets do not depend on the group).
  std::vector<PathDefeats> unique;
  std::map<std::string, std::size_t> index;
  for (const auto& r : times.paths) {
    if (!index.emplace(r.path.key(), unique.size()).second) continue;
    PathDefeats pd;
    pd.path = r.path;
    pd.actions = actions_of(m, r.path);
    if (r.logic.kind == response::Figure::Kind::Exact) {
      pd.requirement = r.logic.cycles;
    } else if (r.logic.kind == response::Figure::Kind::Unbounded) {
      pd.status = PathStatus::Unbounded;
      pd.distance = 0;
      pd.reason = "cemv response: no bound holds without any action (unbounded)";
    } else {
      pd.reason = "cemv response: the logic response is unknown (" + r.logic.reason + ")";
    }
    unique.push_back(std::move(pd));
  }

  checker::CancelToken cancel(deadline());
  AskOptions ao;
  ao.work = o.work;
  ao.timeout_s = o.timeout_s;
  ao.cancel = &cancel;
  ao.out_dir = o.out_dir;
  std::mutex progress;
  auto report = [&](const std::function<void(const std::string&)>& f, std::size_t i) {
    if (!f) return;
    std::lock_guard<std::mutex> lock(progress);
    f(unique[i].path.key());
  };
  if (o.on_plan) o.on_plan(unique.size());
  checker::WorkQueue(o.jobs, cancel).run(unique.size(), [&](std::size_t i) {
    report(o.on_start, i);
    if (unique[i].requirement) enumerate_minimal_sets(m, unique[i], o.max_size, ao, o.enumeration);
    report(o.on_done, i);
  });
  result.interrupted = result.interrupted || cancel.cancelled();
  for (auto& pd : unique)
    if (pd.requirement && pd.questions.empty()) {
      pd.status = PathStatus::Unknown;
      pd.reason = checker::to_string(checker::UnknownReason::TimeLimit);
    }

  for (const auto& r : times.paths) {
    PathDefeats pd = unique[index.at(r.path.key())];
    pd.path = r.path;
    pd.sif_name = r.sif_name;
    pd.sil = group_sil(m, r.path.sif);
    result.paths.push_back(std::move(pd));
  }
  return result;
}

std::vector<const PathDefeats*> gate_failures(const DefeatsResult& r, int require_distance) {
  std::vector<const PathDefeats*> out;
  if (require_distance <= 0) return out;
  for (const auto& p : r.paths)
    if (p.sil >= 2 && p.distance && *p.distance < require_distance) out.push_back(&p);
  return out;
}

int exit_code(const DefeatsResult& r, int require_distance) {
  bool unknown = false;
  for (const auto& p : r.paths) {
    if (p.status == PathStatus::Unbounded) return 1;
    unknown |= p.status == PathStatus::Unknown;
  }
  if (!gate_failures(r, require_distance).empty()) return 1;
  return unknown ? 3 : 0;
}

}  // namespace cemv::defeats
