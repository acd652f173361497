// A candidate invariant tested on sampled states (plc_check/sampling.hpp):
// the checker's mined candidates come from runs of its own, which never trip
// an effect's causes together nor start its override, so a clause over a
// flag those runs leave at rest ("effect[35].override.started_with[107] ->
// cause[120].off_delay.tm_prev") holds in all of them. The acceptance
// tests' runs break most of those; testing them here spares Houdini a
// solver round for each.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "encoder/evaluate.hpp"
#include "z3++.h"

namespace cemv::plc_check {

class SampleTest {
 public:
  // `c` over the variables `column` places in a sampled state (by Z3 AST
  // id); nullopt when it reads another term or an operator this does not
  // evaluate (Bool and Int connectives, comparisons, sums, products by a
  // numeral): such a candidate is left to Houdini.
  static std::optional<SampleTest> compile(const z3::expr& c, const std::unordered_map<unsigned, std::size_t>& column);
  // `c` in `state` (Bool 0/1, Int as is).
  bool holds(const std::vector<encoder::Evaluator::Value>& state) const;

 private:
  struct Node {
    Z3_decl_kind kind;
    std::int64_t value = 0;  // a numeral, or the column of a variable
    std::vector<std::size_t> args;
  };
  std::int64_t eval(std::size_t node, const std::vector<encoder::Evaluator::Value>& state) const;
  std::optional<std::size_t> add(const z3::expr& e, const std::unordered_map<unsigned, std::size_t>& column);
  std::vector<Node> nodes_;  // the root last
};

}  // namespace cemv::plc_check
