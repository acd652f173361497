// The dependency graph of a matrix (Boost.Graph): causes and effects as nodes,
// intersections and internal references as edges. It fixes the one evaluation
// order of a scan cycle (8.3: the run sequence follows the data flow) that the
// runtime and the encoder both use, and answers cone-of-influence and
// change-impact questions.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::model {

struct Node {
  enum class Kind { Cause, Effect } kind = Kind::Cause;
  int id = 0;
  // Causes before effects, then by id: the tie-break of the evaluation order.
  auto operator<=>(const Node&) const = default;
};
std::string to_string(const Node& n);  // "cause[3]" / "effect[2]"

struct Edge {
  enum class Kind { Intersection, Reference } kind = Kind::Intersection;
  Node from;
  Node to;
  // A reference that closes a cycle: the reader sees the previous cycle's value.
  bool reads_previous = false;
  auto operator<=>(const Edge&) const = default;
};

class DependencyGraph {
 public:
  explicit DependencyGraph(const Matrix& m);
  ~DependencyGraph();
  DependencyGraph(DependencyGraph&&) noexcept;
  DependencyGraph& operator=(DependencyGraph&&) noexcept;

  // Every processed cause and effect (comment-only elements excluded), in the
  // order a scan cycle evaluates them: topological, ties broken by causes
  // before effects then by id; a cycle is broken at its smallest node, whose
  // incoming references from the rest of the cycle read the previous cycle.
  const std::vector<Node>& evaluation_order() const;
  const std::vector<Edge>& edges() const;

  // Whether `reader` sees `source` from the previous cycle (source evaluated
  // after reader, i.e. the reference closes a cycle).
  bool reads_previous(const Node& source, const Node& reader) const;

  // The references that close a cycle, and each cycle as a node sequence.
  std::vector<Edge> cycle_closing_edges() const;
  std::vector<std::vector<Node>> cycles() const;

  // Cone of influence: every node whose value can reach `n` (n included), and
  // every node `n` can reach (n included); sorted.
  std::vector<Node> feeders_of(const Node& n) const;
  std::vector<Node> reach_of(const Node& n) const;
  std::vector<Node> feeders_of(const std::vector<Node>& roots) const;

  std::string to_dot(const Matrix& m) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cemv::model
