// Graphviz DOT output of the dependency graph (`cemv graph`).
#pragma once

#include <string>

#include "model/graph.hpp"
#include "model/matrix.hpp"

namespace cemv::reports {

// Deterministic: depends only on the matrix and its graph.
std::string to_dot(const model::Matrix& m, const model::DependencyGraph& graph);

}  // namespace cemv::reports
