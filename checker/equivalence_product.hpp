// The parts of an equivalence question (checker/equivalence.hpp) that both
// its deciders use, the provers' path (checker/equivalence.cpp) and the
// random runs (checker/equivalence_falsifier.hpp): the slices a group is
// decided on, the product problem, and a product run replayed on both
// reference runtimes. Internal to checker/.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "checker/equivalence.hpp"
#include "checker/prover.hpp"

namespace cemv::checker {

// One observable of the group as both matrices know it.
struct KeyInfo {
  std::string key;
  model::FieldType type = model::FieldType::Bool;
  std::size_t index_a = 0, index_b = 0;  // in model::observables of each
};

// A group's question once its keys and slices are known.
struct EquivalenceQuestion {
  const model::Matrix& a;
  const model::Matrix& b;
  std::string group;                  // its name, for messages
  std::vector<KeyInfo> keys;
  std::vector<model::Node> ra, rb;    // the roots encoded in each (empty: whole matrix)
  Limits limits;                      // the group's wall clock and cancel token
  Work work = 0;                      // each engine's budget
  std::size_t random_cycles = 0;      // the random runs' budget of simulated cycles
  std::vector<std::string> key_names() const;
};

// The roots to encode in `m` for a group's nodes (see the definition).
std::vector<model::Node> roots_in(const model::Matrix& m, const model::Matrix& other,
                                  const std::vector<model::Node>& group);
// The part of `m` an encoding of `roots` reads; with `texts_aside`, every
// text no semantics reads set aside (two equal such restrictions have equal
// encodings term for term).
model::Matrix cone_matrix(const model::Matrix& m, const std::vector<model::Node>& roots, bool texts_aside);
std::string cone_configuration(const model::Matrix& m, const std::vector<model::Node>& roots);

// The product of the question's slices with `good` = every key equal in
// both copies (the owner is the encoder::Product).
ProblemFactory product_factory(const model::Matrix& a, const model::Matrix& b, const std::vector<model::Node>& ra,
                               const std::vector<model::Node>& rb, const std::vector<std::string>& keys);
ProblemFactory product_factory(const EquivalenceQuestion& q);

// Two runtime runs that first differ on `k` in `cycle`, both cut after it.
Distinction make_distinction(const KeyInfo& k, std::size_t cycle, ConcreteTrace ta, ConcreteTrace tb);

// Replays a run of the product `op` (built by product_factory(q)) on both
// runtimes, made readable first (inputs the difference does not need at
// rest); true (and `out` filled) when they differ on a key of the group,
// else false with `why`.
bool replay_product_run(const EquivalenceQuestion& q, const OwnedProblem& op, const Trace& cex,
                        GroupEquivalence& out, std::string& why);
// The same in a fresh context.
bool replay_product_run(const EquivalenceQuestion& q, const Trace& cex, GroupEquivalence& out, std::string& why);

}  // namespace cemv::checker
