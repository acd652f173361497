// One processed element of a matrix, as the dependency graph, the evaluation
// order and the observable keys name it: a cause or an effect by id.
#pragma once

#include <compare>
#include <string>

namespace cemv::model {

struct Node {
  enum class Kind { Cause, Effect } kind = Kind::Cause;
  int id = 0;
  // Causes before effects, then by id: the tie-break of the evaluation order.
  auto operator<=>(const Node&) const = default;
};
std::string to_string(const Node& n);  // "cause[3]" / "effect[2]"

}  // namespace cemv::model
