// The dependency graph of a matrix and the one evaluation order of a scan cycle.
//
// The Safety Matrix orders its blocks by data flow when it is transferred (8.3:
// "The run sequence is oriented to the data flow"). Data flows along processed
// intersections (cause -> effect, 6.5.2) and along internal references (6.1.3:
// the state of a Cause, Effect or Effect tag "can be further processed as an
// input tag" of another element). Everything here is deterministic: nodes,
// edges, order, cycles and DOT depend only on the matrix, never on addresses or
// hash order.
#include "model/graph.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <sstream>
#include <tuple>

#include <boost/graph/adjacency_list.hpp>

#include "model/vocabulary.hpp"

namespace cemv::model {

std::vector<ReferenceUse> internal_references(const Matrix& m) {
  std::vector<ReferenceUse> out;
  auto use = [&](const Node& reader, std::string field, const std::optional<std::string>& tag) {
    if (!tag) return;
    auto ref = parse_internal_ref(*tag);
    if (!ref) return;
    ReferenceUse u;
    u.reader = reader;
    u.field = std::move(field);
    u.tag = *tag;
    u.source = Node{ref->kind == InternalRef::Kind::Cause ? Node::Kind::Cause : Node::Kind::Effect,
                    ref->id};
    u.source_tag = ref->kind == InternalRef::Kind::EffectTag ? ref->tag : 0;
    out.push_back(std::move(u));
  };
  std::vector<const Cause*> causes;
  for (const auto& c : m.causes) causes.push_back(&c);
  std::stable_sort(causes.begin(), causes.end(),
                   [](const Cause* a, const Cause* b) { return a->id < b->id; });
  std::vector<const Effect*> effects;
  for (const auto& e : m.effects) effects.push_back(&e);
  std::stable_sort(effects.begin(), effects.end(),
                   [](const Effect* a, const Effect* b) { return a->id < b->id; });
  for (const Cause* c : causes) {
    if (c->function == CauseFunction::Comment) continue;
    Node reader{Node::Kind::Cause, c->id};
    for (std::size_t i = 0; i < c->tags.size(); ++i)
      use(reader, "input tag " + std::to_string(i + 1), c->tags[i].name);
    use(reader, "bypass_tag", c->bypass_tag);
    use(reader, "inhibit_tag", c->inhibit_tag);
  }
  for (const Effect* e : effects) {
    if (e->function == EffectFunction::Comment) continue;
    Node reader{Node::Kind::Effect, e->id};
    use(reader, "bypass_tag", e->bypass_tag);
    use(reader, "reset_tag", e->reset_tag);
    if (e->process_data) {
      use(reader, "process_data.tag", e->process_data->tag);
      use(reader, "process_data.mask_tag", e->process_data->mask_tag);
    }
  }
  return out;
}

namespace {

struct VertexProps {
  Node node;
};
struct EdgeProps {
  Edge::Kind kind = Edge::Kind::Intersection;
  bool reads_previous = false;
};
using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::bidirectionalS, VertexProps,
                                    EdgeProps>;
using Vertex = Graph::vertex_descriptor;

// Strongly connected components of the subgraph induced by the vertices with
// in_set[v] (Tarjan, iterative so that no matrix can exhaust the stack).
// Returns the component index per vertex (-1 outside the set).
std::vector<int> components(const std::vector<std::vector<Vertex>>& succ,
                            const std::vector<bool>& in_set) {
  const std::size_t n = succ.size();
  std::vector<int> comp(n, -1), index(n, -1), low(n, 0);
  std::vector<bool> on_stack(n, false);
  std::vector<Vertex> stack;
  int next_index = 0, next_comp = 0;
  struct Frame {
    Vertex v;
    std::size_t child;
  };
  for (Vertex root = 0; root < n; ++root) {
    if (!in_set[root] || index[root] >= 0) continue;
    std::vector<Frame> frames{{root, 0}};
    index[root] = low[root] = next_index++;
    stack.push_back(root);
    on_stack[root] = true;
    while (!frames.empty()) {
      Frame& f = frames.back();
      if (f.child < succ[f.v].size()) {
        Vertex w = succ[f.v][f.child++];
        if (!in_set[w]) continue;
        if (index[w] < 0) {
          index[w] = low[w] = next_index++;
          stack.push_back(w);
          on_stack[w] = true;
          frames.push_back({w, 0});
        } else if (on_stack[w]) {
          low[f.v] = std::min(low[f.v], index[w]);
        }
        continue;
      }
      Vertex v = f.v;
      frames.pop_back();
      if (!frames.empty()) low[frames.back().v] = std::min(low[frames.back().v], low[v]);
      if (low[v] == index[v]) {
        Vertex w;
        do {
          w = stack.back();
          stack.pop_back();
          on_stack[w] = false;
          comp[w] = next_comp;
        } while (w != v);
        ++next_comp;
      }
    }
  }
  return comp;
}

}  // namespace

struct DependencyGraph::Impl {
  Graph g;
  std::vector<Node> nodes;                  // sorted; vertex v is nodes[v]
  std::vector<std::vector<Vertex>> succ;    // distinct successors, ascending
  std::vector<std::vector<Vertex>> pred;    // distinct predecessors, ascending
  std::vector<Node> order;
  std::vector<Edge> edges;
  std::vector<std::vector<Node>> cycles;

  std::optional<Vertex> vertex_of(const Node& n) const {
    auto it = std::lower_bound(nodes.begin(), nodes.end(), n);
    if (it == nodes.end() || *it != n) return std::nullopt;
    return static_cast<Vertex>(it - nodes.begin());
  }

  void build(const Matrix& m);
  void order_nodes();
  void find_cycles();
  std::vector<Node> closure(const std::vector<Node>& roots, bool backwards) const;
};

void DependencyGraph::Impl::build(const Matrix& m) {
  for (const auto& c : m.causes)
    if (c.function != CauseFunction::Comment) nodes.push_back({Node::Kind::Cause, c.id});
  for (const auto& e : m.effects)
    if (e.function != EffectFunction::Comment) nodes.push_back({Node::Kind::Effect, e.id});
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  // Sized construction, then the bundles: add_vertex(property, g) goes through
  // Boost's named-graph lookup, which GCC's sanitizer builds flag as
  // maybe-uninitialized.
  g = Graph(nodes.size());
  for (Vertex v = 0; v < nodes.size(); ++v) g[v].node = nodes[v];

  // One edge per (kind, from, to): a repeated intersection or two references to
  // the same element carry the same data dependency.
  std::set<std::tuple<Vertex, Vertex, Edge::Kind>> wanted;
  for (const auto& x : m.intersections) {
    if (!is_processed(x.type)) continue;
    auto from = vertex_of({Node::Kind::Cause, x.cause});
    auto to = vertex_of({Node::Kind::Effect, x.effect});
    if (from && to) wanted.insert({*from, *to, Edge::Kind::Intersection});
  }
  for (const auto& r : internal_references(m)) {
    auto from = vertex_of(r.source);
    auto to = vertex_of(r.reader);
    if (from && to) wanted.insert({*from, *to, Edge::Kind::Reference});
  }
  succ.assign(nodes.size(), {});
  pred.assign(nodes.size(), {});
  for (const auto& [from, to, kind] : wanted) {
    boost::add_edge(from, to, EdgeProps{kind, false}, g);
    if (succ[from].empty() || succ[from].back() != to) succ[from].push_back(to);
    pred[to].push_back(from);
  }
  for (auto& p : pred) {
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
  }
}

// Kahn's algorithm, always taking the smallest ready node (causes before
// effects, then by id). When no node is ready, the remaining nodes contain a
// cycle: among the strongly connected components that nothing else remaining
// feeds, take the one with the smallest node, evaluate that node next, and let
// it read its still unevaluated predecessors (all inside its own component,
// i.e. the references that close the cycle) from the previous scan cycle. A
// node that is merely downstream of a cycle never reads a stale value.
void DependencyGraph::Impl::order_nodes() {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> indegree(n, 0);
  for (Vertex v = 0; v < n; ++v) indegree[v] = boost::in_degree(v, g);
  std::vector<bool> done(n, false);
  std::priority_queue<Vertex, std::vector<Vertex>, std::greater<>> ready;
  for (Vertex v = 0; v < n; ++v)
    if (indegree[v] == 0) ready.push(v);

  while (order.size() < n) {
    if (ready.empty()) {
      std::vector<bool> remaining(n);
      for (Vertex v = 0; v < n; ++v) remaining[v] = !done[v];
      auto comp = components(succ, remaining);
      std::vector<bool> fed(n, false);  // component fed by another remaining component
      for (Vertex v = 0; v < n; ++v)
        if (remaining[v])
          for (Vertex w : succ[v])
            if (remaining[w] && comp[w] != comp[v]) fed[static_cast<std::size_t>(comp[w])] = true;
      Vertex breaker = n;
      for (Vertex v = 0; v < n && breaker == n; ++v)
        if (remaining[v] && !fed[static_cast<std::size_t>(comp[v])]) breaker = v;
      auto [it, end] = boost::in_edges(breaker, g);
      for (; it != end; ++it) {
        if (done[boost::source(*it, g)]) continue;
        g[*it].reads_previous = true;
        --indegree[breaker];
      }
      ready.push(breaker);
    }
    Vertex u = ready.top();
    ready.pop();
    done[u] = true;
    order.push_back(nodes[u]);
    auto [it, end] = boost::out_edges(u, g);
    for (; it != end; ++it) {
      Vertex w = boost::target(*it, g);
      if (done[w]) continue;
      if (--indegree[w] == 0) ready.push(w);
    }
  }

  auto [it, end] = boost::edges(g);
  for (; it != end; ++it) {
    const auto& p = g[*it];
    edges.push_back(Edge{p.kind, nodes[boost::source(*it, g)], nodes[boost::target(*it, g)],
                         p.reads_previous});
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return std::tie(a.from, a.to, a.kind) < std::tie(b.from, b.to, b.kind);
  });
}

// Johnson's algorithm (1975) for the elementary circuits: polynomial time per
// circuit, so stopping after kMaxReportedCycles bounds the work.
void DependencyGraph::Impl::find_cycles() {
  const std::size_t n = nodes.size();
  std::vector<bool> blocked(n, false);
  std::vector<std::set<Vertex>> blocked_by(n);
  std::vector<Vertex> path;
  std::vector<bool> in_scc(n, false);
  std::vector<std::vector<Vertex>> found;
  Vertex start = 0;

  std::function<void(Vertex)> unblock = [&](Vertex v) {
    blocked[v] = false;
    auto waiting = std::move(blocked_by[v]);
    blocked_by[v].clear();
    for (Vertex w : waiting)
      if (blocked[w]) unblock(w);
  };
  std::function<bool(Vertex)> circuit = [&](Vertex v) {
    bool closed = false;
    path.push_back(v);
    blocked[v] = true;
    for (Vertex w : succ[v]) {
      if (found.size() >= kMaxReportedCycles) break;
      if (!in_scc[w]) continue;
      if (w == start) {
        found.push_back(path);
        closed = true;
      } else if (!blocked[w] && circuit(w)) {
        closed = true;
      }
    }
    if (closed) {
      unblock(v);
    } else {
      for (Vertex w : succ[v])
        if (in_scc[w]) blocked_by[w].insert(v);
    }
    path.pop_back();
    return closed;
  };

  while (start < n && found.size() < kMaxReportedCycles) {
    std::vector<bool> upper(n, false);
    for (Vertex v = start; v < n; ++v) upper[v] = true;
    auto comp = components(succ, upper);
    std::vector<std::size_t> size(n, 0);
    for (Vertex v = start; v < n; ++v) ++size[static_cast<std::size_t>(comp[v])];
    // The smallest vertex that lies on a cycle of the subgraph {start..n-1}.
    Vertex least = n;
    for (Vertex v = start; v < n && least == n; ++v) {
      bool self_loop = std::binary_search(succ[v].begin(), succ[v].end(), v);
      if (size[static_cast<std::size_t>(comp[v])] > 1 || self_loop) least = v;
    }
    if (least == n) break;
    start = least;
    for (Vertex v = 0; v < n; ++v) {
      in_scc[v] = v >= start && comp[v] == comp[start];
      blocked[v] = false;
      blocked_by[v].clear();
    }
    circuit(start);
    ++start;
  }

  for (const auto& c : found) {
    std::vector<Node> cycle;
    for (Vertex v : c) cycle.push_back(nodes[v]);
    cycles.push_back(std::move(cycle));
  }
  std::sort(cycles.begin(), cycles.end());
}

std::vector<Node> DependencyGraph::Impl::closure(const std::vector<Node>& roots,
                                                 bool backwards) const {
  std::vector<bool> seen(nodes.size(), false);
  std::vector<Vertex> todo;
  for (const auto& r : roots)
    if (auto v = vertex_of(r); v && !seen[*v]) {
      seen[*v] = true;
      todo.push_back(*v);
    }
  while (!todo.empty()) {
    Vertex v = todo.back();
    todo.pop_back();
    for (Vertex w : backwards ? pred[v] : succ[v])
      if (!seen[w]) {
        seen[w] = true;
        todo.push_back(w);
      }
  }
  std::vector<Node> out;
  for (Vertex v = 0; v < nodes.size(); ++v)
    if (seen[v]) out.push_back(nodes[v]);
  return out;
}

DependencyGraph::DependencyGraph(const Matrix& m) : impl_(std::make_unique<Impl>()) {
  impl_->build(m);
  impl_->order_nodes();
  impl_->find_cycles();
}
DependencyGraph::~DependencyGraph() = default;
DependencyGraph::DependencyGraph(DependencyGraph&&) noexcept = default;
DependencyGraph& DependencyGraph::operator=(DependencyGraph&&) noexcept = default;

const std::vector<Node>& DependencyGraph::evaluation_order() const { return impl_->order; }
const std::vector<Edge>& DependencyGraph::edges() const { return impl_->edges; }

bool DependencyGraph::reads_previous(const Node& source, const Node& reader) const {
  for (const auto& e : impl_->edges)
    if (e.from == source && e.to == reader && e.reads_previous) return true;
  return false;
}

std::vector<Edge> DependencyGraph::cycle_closing_edges() const {
  std::vector<Edge> out;
  for (const auto& e : impl_->edges)
    if (e.reads_previous) out.push_back(e);
  return out;
}

std::vector<std::vector<Node>> DependencyGraph::cycles() const { return impl_->cycles; }

std::vector<Node> DependencyGraph::feeders_of(const Node& n) const {
  return impl_->closure({n}, true);
}
std::vector<Node> DependencyGraph::reach_of(const Node& n) const {
  return impl_->closure({n}, false);
}
std::vector<Node> DependencyGraph::feeders_of(const std::vector<Node>& roots) const {
  return impl_->closure(roots, true);
}

}  // namespace cemv::model
