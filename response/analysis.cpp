#include "response/analysis.hpp"

#include <algorithm>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>

#include "checker/names.hpp"
#include "checker/work_queue.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::response {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::Ok: return "ok";
    case Verdict::Over: return "over";
    case Verdict::NoPst: return "no-pst";
    case Verdict::Unbounded: return "unbounded";
    case Verdict::Unknown: return "unknown";
  }
  return "unknown";
}

namespace {

struct Figures {
  Figure logic;
  std::optional<Figure> degraded;
};

// Total = sensor + T x cycle + the controller's share + actuator
// (docs/response-time.md, "The formula").
void complete(const model::Matrix& m, const ResponseOptions& o, const Figures& f, PathResult& r) {
  const Path& p = r.path;
  r.logic = f.logic;
  r.degraded = f.degraded;
  for (int id : p.causes) r.sensor_ms = std::max(r.sensor_ms, m.find_cause(id)->sensor_ms);
  r.actuator_ms = m.find_effect(p.effect)->actuator_ms;
  r.controller_ms = 2LL * (o.conservative ? *m.watchdog_ms : m.cycle_ms);
  auto total = [&](const Figure& g) -> std::optional<long long> {
    if (g.kind != Figure::Kind::Exact) return std::nullopt;
    return r.sensor_ms + g.cycles * static_cast<long long>(m.cycle_ms) + r.controller_ms + r.actuator_ms;
  };
  if (f.logic.kind == Figure::Kind::Exact) r.logic_ms = f.logic.cycles * static_cast<long long>(m.cycle_ms);
  r.total_ms = total(f.logic);
  if (f.degraded) r.degraded_total_ms = total(*f.degraded);
  if (auto it = m.process_safety_time_ms.find(p.sif); it != m.process_safety_time_ms.end())
    r.process_safety_time_ms = it->second;
  if (r.total_ms && r.process_safety_time_ms) {
    r.margin_ms = static_cast<long long>(*r.process_safety_time_ms) - *r.total_ms;
    r.margin_percent = 100.0 * static_cast<double>(*r.margin_ms) / *r.process_safety_time_ms;
  }
  if (f.logic.kind == Figure::Kind::Unbounded)
    r.verdict = Verdict::Unbounded;
  else if (f.logic.kind == Figure::Kind::Unknown)
    r.verdict = Verdict::Unknown;
  else if (!r.process_safety_time_ms)
    r.verdict = Verdict::NoPst;
  else
    r.verdict = *r.margin_ms >= 0 ? Verdict::Ok : Verdict::Over;
}

}  // namespace

ResponseResult analyse(const model::Matrix& m, const ResponseOptions& o) {
  for (int g : o.sifs)
    if (!m.sif_groups.count(g))
      throw std::invalid_argument("--sif " + std::to_string(g) + ": the matrix declares no SIF group " +
                                  std::to_string(g));
  if (o.conservative && !m.watchdog_ms)
    throw std::invalid_argument("--conservative needs the matrix's watchdog_ms, which it does not declare");
  ResponseResult result;
  result.matrix_name = m.name;
  result.matrix_signature = formats::signature(m);
  result.cycle_ms = m.cycle_ms;
  result.watchdog_ms = m.watchdog_ms;
  result.conservative = o.conservative;

  const std::vector<Path> paths = response_paths(m, o.sifs);
  // A path in several groups is decided once (the figures do not depend on the group).
  std::vector<const Path*> unique;
  std::map<std::string, std::size_t> index;
  for (const auto& p : paths)
    if (index.emplace(p.key(), unique.size()).second) unique.push_back(&p);
  std::vector<Figures> figures(unique.size());
  checker::CancelToken cancel(o.total_timeout_s > 0
                                  ? checker::Clock::now() + std::chrono::duration_cast<checker::Clock::duration>(
                                                                std::chrono::duration<double>(o.total_timeout_s))
                                  : checker::Clock::time_point::max());
  SearchOptions so;
  so.work = o.work;
  so.timeout_s = o.timeout_s;
  so.cancel = &cancel;
  so.out_dir = o.out_dir;

  std::mutex progress;  // serialises the progress callbacks
  if (o.on_plan) o.on_plan(unique.size());
  auto report = [&](const std::function<void(const std::string&)>& f, std::size_t i) {
    if (!f) return;
    std::lock_guard<std::mutex> lock(progress);
    f(unique[i]->key());
  };
  checker::WorkQueue(o.jobs, cancel).run(unique.size(), [&](std::size_t i) {
    report(o.on_start, i);
    const auto given = o.known.find(unique[i]->key());
    figures[i].logic = given != o.known.end() ? given->second : least_response(m, *unique[i], Mode::Normal, so);
    if (o.degraded && !unique[i]->voted.empty())
      figures[i].degraded = least_response(m, *unique[i], Mode::Degraded, so);
    if (cancel.cancelled()) {
      // Cut short by the run's bound: nothing it found stands.
      figures[i] = Figures{};
      figures[i].logic.reason = checker::to_string(checker::UnknownReason::TimeLimit);
      if (o.degraded && !unique[i]->voted.empty()) figures[i].degraded = figures[i].logic;
      return;
    }
    report(o.on_done, i);
  });
  result.interrupted = cancel.cancelled();
  for (std::size_t i = 0; i < unique.size(); ++i)
    if (result.interrupted && figures[i].logic.kind == Figure::Kind::Unknown && figures[i].logic.reason.empty())
      figures[i].logic.reason = checker::to_string(checker::UnknownReason::TimeLimit);

  for (const auto& p : paths) {
    PathResult r;
    r.path = p;
    r.sif_name = m.sif_groups.at(p.sif);
    complete(m, o, figures[index.at(p.key())], r);
    result.paths.push_back(std::move(r));
  }
  return result;
}

int exit_code(const ResponseResult& r) {
  bool unknown = false;
  for (const auto& p : r.paths) {
    if (p.verdict == Verdict::Over || p.verdict == Verdict::Unbounded) return 1;
    unknown |= p.verdict == Verdict::Unknown;
  }
  return unknown ? 3 : 0;
}

}  // namespace cemv::response
