#include "model/node.hpp"

namespace cemv::model {

std::string to_string(const Node& n) {
  return std::string(n.kind == Node::Kind::Cause ? "cause[" : "effect[") + std::to_string(n.id) +
         "]";
}

}  // namespace cemv::model
