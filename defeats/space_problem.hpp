// The problem of one path that ActionSpace solves (docs/defeats.md, "One
// encoding per path"): the requirement with every action excluded, parsed
// once; its monitor compiled into the cone's encoding without the
// exclusions, and each exclusion compiled on its own into a term of one
// cycle, reduced together. Internal to defeats/.
#pragma once

#include <vector>

#include <z3++.h>

#include "checker/reduce.hpp"
#include "defeats/analysis.hpp"
#include "model/node.hpp"
#include "properties/ast.hpp"

namespace cemv::defeats {

// The path's problem in one context: the requirement with no action
// excluded, and each action's exclusion (`not TERM`) as a term of one cycle,
// reduced together (checker/reduce.hpp) so that the terms keep their cone.
struct Built {
  checker::OwnedProblem problem;
  std::vector<z3::expr> keep;  // keep[i]: action i does not occur in the cycle
};

class Builder {
 public:
  Builder(const model::Matrix& m, const PathDefeats& pd);

  // `none`: the problem with every action excluded, reduced as the checker
  // reduces a question (the commands it excludes constants), no terms kept.
  Built build(z3::context& ctx, bool none = false) const;

  // The requirement with the actions of `allowed` allowed, for the runtime's judge.
  properties::Property property(const std::vector<int>& allowed) const;
  const properties::Expr& exclusion(int i) const { return exclusions_[static_cast<std::size_t>(i)].body; }

 private:
  const model::Matrix& m_;
  properties::PropertyFile file_;
  std::vector<model::Node> roots_;
  properties::Property free_;
  std::vector<properties::Property> exclusions_;
};

// The relations that hold while no action occurs, over the variables of `ts`.
std::vector<z3::expr> mined_without_actions(const Builder& b, const encoder::TransitionSystem& ts);

}  // namespace cemv::defeats
