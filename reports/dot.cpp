// The dependency graph as Graphviz DOT (`cemv graph`, docs/reports.md): one
// node per processed cause and effect, labelled with its place in the
// evaluation order (8.3), one edge per intersection and internal reference; a
// reference that closes a cycle is drawn red (it reads the previous cycle).
#include "reports/dot.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "model/graph.hpp"

namespace cemv::reports {

using namespace cemv::model;

namespace {

std::string dot_quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

}  // namespace

std::string to_dot(const Matrix& m, const DependencyGraph& graph) {
  std::ostringstream out;
  out << "digraph " << dot_quote(m.name.empty() ? "matrix" : m.name) << " {\n";
  out << "  graph [rankdir=LR, labelloc=t, label="
      << dot_quote((m.name.empty() ? std::string("matrix") : m.name) +
                   ": dependency graph (dashed: internal reference, red: reads the previous "
                   "cycle)")
      << "];\n";
  out << "  node [fontname=\"Helvetica\", fontsize=10];\n";
  out << "  edge [fontname=\"Helvetica\", fontsize=9];\n";

  std::map<Node, std::size_t> position;
  const std::vector<Node>& order = graph.evaluation_order();
  for (std::size_t i = 0; i < order.size(); ++i) position[order[i]] = i + 1;
  // Nodes in their sorted order (causes, then effects, by id), each labelled
  // with its position in the evaluation order.
  std::vector<Node> nodes = order;
  std::sort(nodes.begin(), nodes.end());
  for (const auto& n : nodes) {
    std::string label;
    std::string shape;
    if (n.kind == Node::Kind::Cause) {
      const Cause* c = m.find_cause(n.id);
      label = "cause " + std::to_string(n.id);
      if (c) label += "\n" + c->name + "\n" + to_string(c->function);
      shape = "box";
    } else {
      const Effect* e = m.find_effect(n.id);
      label = "effect " + std::to_string(n.id);
      if (e) label += "\n" + e->name;
      shape = "ellipse";
    }
    label += "\n#" + std::to_string(position[n]);
    out << "  " << dot_quote(to_string(n)) << " [shape=" << shape << ", label=" << dot_quote(label)
        << "];\n";
  }

  // Labels: the intersection type (with its XooN assignment) or the tags read.
  std::map<std::pair<Node, Node>, std::string> ref_labels;
  for (const auto& r : internal_references(m)) {
    auto& l = ref_labels[{r.source, r.reader}];
    std::string part = r.tag + " as " + r.field;
    if (l.find(part) != std::string::npos) continue;
    if (!l.empty()) l += "\n";
    l += part;
  }
  for (const auto& e : graph.edges()) {
    std::string label;
    std::string attrs;
    if (e.kind == Edge::Kind::Intersection) {
      const Intersection* x = m.find_intersection(e.from.id, e.to.id);
      label = x ? to_string(x->type) : "?";
      if (x && x->xoon) {
        int count = 0;
        for (const auto* y : m.intersections_of_effect(e.to.id))
          if (y->xoon) ++count;
        label += " " + std::to_string(*x->xoon) + "oo" + std::to_string(count);
      }
    } else {
      label = ref_labels[{e.from, e.to}];
      attrs = ", style=dashed";
      if (e.reads_previous) {
        label += "\n(previous cycle)";
        attrs += ", color=red, fontcolor=red";
      }
    }
    out << "  " << dot_quote(to_string(e.from)) << " -> " << dot_quote(to_string(e.to))
        << " [label=" << dot_quote(label) << attrs << "];\n";
  }
  out << "}\n";
  return out.str();
}

}  // namespace cemv::reports
