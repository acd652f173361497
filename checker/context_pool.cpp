#include "checker/context_pool.hpp"

#include <exception>
#include <mutex>
#include <unordered_set>
#include <vector>

namespace cemv::checker {

namespace {

// At most as many contexts as are in use at once (threads times nesting) come
// back; the cap only bounds memory should that ever be large.
constexpr std::size_t kMaxPooled = 16;

std::mutex& pool_mutex() {
  static std::mutex m;
  return m;
}

std::vector<std::unique_ptr<z3::context>>& pool() {
  static std::vector<std::unique_ptr<z3::context>> p;
  return p;
}

std::unordered_set<const void*>& interrupted() {
  static std::unordered_set<const void*> s;
  return s;
}

}  // namespace

void discard_when_released(const z3::context& ctx) {
  std::lock_guard<std::mutex> lock(pool_mutex());
  interrupted().insert(&ctx);
}

PooledContext::PooledContext() : exceptions_(std::uncaught_exceptions()) {
  {
    std::lock_guard<std::mutex> lock(pool_mutex());
    if (!pool().empty()) {
      ctx_ = std::move(pool().back());
      pool().pop_back();
    }
  }
  if (!ctx_) ctx_ = std::make_unique<z3::context>();
}

PooledContext::~PooledContext() {
  std::lock_guard<std::mutex> lock(pool_mutex());
  const bool was_interrupted = interrupted().erase(ctx_.get()) > 0;
  if (was_interrupted || std::uncaught_exceptions() > exceptions_) return;
  if (pool().size() < kMaxPooled) pool().push_back(std::move(ctx_));
}

}  // namespace cemv::checker
