// The one work queue of a run (`cemv check`, `testgen`, `response`, `mutate`,
// `diff`): `jobs` workers take the tasks in order. The first failure cancels
// the run's token, so the other workers stop at their next check (every
// engine polls the token through Limits), and is rethrown to the caller once
// every worker has returned. The token also carries the run's wall-clock
// bound (--total-timeout): tasks not started by then are skipped, a task
// that throws Interrupted ends unfinished (not a failure), and the caller
// reports both as not decided. What a task computes must not depend
// on which worker runs it or when: results go to the task's own slot.
#pragma once

#include <cstddef>
#include <functional>

#include "checker/limits.hpp"

namespace cemv::checker {

class WorkQueue {
 public:
  WorkQueue(int jobs, CancelToken& cancel) : jobs_(jobs < 1 ? 1 : jobs), cancel_(cancel) {}
  // task(i) for every i in [0, n) (in order of i, spread over the workers),
  // unless the token is cancelled first. Returns the number of tasks that
  // ran to their end; rethrows the first exception a task threw, other than
  // Interrupted (checker/limits.hpp), which leaves its task unfinished.
  std::size_t run(std::size_t n, const std::function<void(std::size_t)>& task);

 private:
  int jobs_;
  CancelToken& cancel_;
};

}  // namespace cemv::checker
