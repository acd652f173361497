// The checker's one function (checker/check.hpp): the properties spread over
// worker threads, each decided by PropertyChecker (property_checker.cpp).
#include "checker/check.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "checker/property_checker.hpp"
#include "formats/matrix_json.hpp"

namespace cemv::checker {

CheckResult check_properties(const model::Matrix& m, const std::vector<properties::PropertyFile>& files,
                             const CheckOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const auto total_deadline =
      options.total_timeout_s > 0
          ? start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.total_timeout_s))
          : Clock::time_point::max();

  CheckResult result;
  result.matrix_name = m.name;
  result.matrix_signature = formats::signature(m);
  result.tool_version = CEMV_VERSION;
  result.standard = options.standard;
  if (options.shard_count > 1)
    result.shard = std::to_string(options.shard_index) + "/" + std::to_string(options.shard_count);
  for (const auto& f : files) result.property_files.push_back(f.file_name);

  struct Job { const properties::PropertyFile* file; const properties::Property* property; };
  std::vector<Job> jobs;
  std::size_t index = 0;
  for (const auto& f : files)
    for (const auto& p : f.properties)
      if (in_shard(index++, options.shard_index, options.shard_count)) jobs.push_back({&f, &p});

  result.properties.resize(jobs.size());
  WitnessPool witnesses;
  std::atomic<std::size_t> next{0};
  std::mutex report_mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      std::size_t i = next++;
      if (i >= jobs.size()) return;
      try {
        if (options.on_start) {
          std::lock_guard<std::mutex> lock(report_mutex);
          options.on_start(jobs[i].property->name);
        }
        auto deadline = total_deadline;
        if (options.property_timeout_s > 0)
          deadline = std::min(deadline, Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                          std::chrono::duration<double>(options.property_timeout_s)));
        PropertyChecker pc(m, *jobs[i].file, *jobs[i].property, options, deadline, &witnesses);
        PropertyResult r = pc.run();
        std::lock_guard<std::mutex> lock(report_mutex);
        result.properties[i] = std::move(r);
        if (options.on_result) options.on_result(result.properties[i]);
      } catch (...) {
        std::lock_guard<std::mutex> lock(report_mutex);
        if (!failure) failure = std::current_exception();
        next = jobs.size();
        return;
      }
    }
  };
  const int threads = std::max(1, std::min<int>(options.jobs, static_cast<int>(jobs.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  result.interrupted = total_deadline != Clock::time_point::max() && Clock::now() >= total_deadline;
  if (options.standard) result.unsupported = unsupported_elements(m, result.properties);
  return result;
}

}  // namespace cemv::checker
