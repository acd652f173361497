#include "checker/work_queue.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include <z3++.h>

namespace cemv::checker {

std::size_t WorkQueue::run(std::size_t n, const std::function<void(std::size_t)>& task) {
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> finished{0};
  std::mutex mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    for (;;) {
      if (cancel_.cancelled()) return;
      const std::size_t i = next++;
      if (i >= n) return;
      try {
        task(i);
        ++finished;
      } catch (const Interrupted&) {
        // The wall clock or the token ended the task (--timeout,
        // --total-timeout): it did not finish, and that is no failure.
        // What it left in its slot is the caller's to report as undecided.
        continue;
      } catch (const z3::exception&) {
        // After the token has interrupted a context, any call on it may
        // throw "canceled"; only without a cancellation is it a failure.
        if (cancel_.cancelled()) continue;
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        cancel_.cancel();
        return;
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        cancel_.cancel();
        return;
      }
    }
  };
  const int threads = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(jobs_), std::max<std::size_t>(n, 1)));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return finished;
}

}  // namespace cemv::checker
