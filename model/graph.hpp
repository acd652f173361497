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
#include "model/node.hpp"

namespace cemv::model {

// One internal reference (6.1.3) read by a processed cause or effect: which
// element reads it, in which field, and which element (and output tag) it names.
// The referenced element need not exist (validate() reports that).
struct ReferenceUse {
  Node reader;
  std::string field;  // "input tag 2", "bypass_tag", "inhibit_tag", "reset_tag",
                      // "process_data.tag", "process_data.mask_tag"
  std::string tag;    // as written, e.g. "Effect[4][2]"
  Node source;        // Cause[x] -> cause x; Effect[x] and Effect[x][y] -> effect x
  int source_tag = 0; // y of Effect[x][y] (1-based); 0 otherwise
};
// Every internal reference read by a processed element (comment-only causes and
// effects are not processed), in element order (causes by id, then effects by
// id) and field order. Output tags are never read, so they are not listed.
std::vector<ReferenceUse> internal_references(const Matrix& m);

// cycles() stops after this many elementary cycles, so that a pathological
// matrix (a dense knot of references) cannot make it run for ever.
inline constexpr std::size_t kMaxReportedCycles = 100;

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
  // before effects then by id; when only cycles remain, the smallest node of a
  // strongly connected component no other remaining component feeds goes next,
  // and its incoming references from the rest of its cycle read the previous
  // cycle (so a node merely downstream of a cycle never reads a stale value).
  const std::vector<Node>& evaluation_order() const;
  const std::vector<Edge>& edges() const;

  // Whether `reader` sees `source` from the previous cycle (source evaluated
  // after reader, i.e. the reference closes a cycle).
  bool reads_previous(const Node& source, const Node& reader) const;

  // The references that close a cycle, and each elementary cycle as a node
  // sequence starting at its smallest node, the list sorted (at most
  // kMaxReportedCycles of them).
  std::vector<Edge> cycle_closing_edges() const;
  std::vector<std::vector<Node>> cycles() const;

  // Cone of influence: every node whose value can reach `n` (n included), and
  // every node `n` can reach (n included); sorted.
  std::vector<Node> feeders_of(const Node& n) const;
  std::vector<Node> reach_of(const Node& n) const;
  std::vector<Node> feeders_of(const std::vector<Node>& roots) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cemv::model
