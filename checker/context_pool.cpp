#include "checker/context_pool.hpp"

namespace cemv::checker {

void discard_when_released(const z3::context&) {}

PooledContext::PooledContext() : ctx_(std::make_unique<z3::context>()) {}

PooledContext::~PooledContext() = default;

}  // namespace cemv::checker
