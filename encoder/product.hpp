// The synchronous product of two matrices' transition systems (docs/encoding.md,
// "Product"): both copies read the same inputs and operator commands in every
// cycle, so a state of the product is a pair of states reached by one input
// history. Equivalence of two matrices, for a set of observables, is then a
// safety property of the product: "each observable of copy a equals the same
// observable of copy b in every cycle" (checker/equivalence.hpp).
//
// Naming: every state variable, named term, constraint and lemma of copy a is
// prefixed "a.", of copy b "b." ("a.effect[1].active"). Input variables keep
// their names ("input.LT_100A", "cmd.ack[cause 3]"), which is what makes them
// shared: an input that only one matrix reads is an input of the product that
// the other copy ignores.
//
// Relational lemmas: for every state variable that both copies have (same name,
// same sort), the lemma "eq.NAME": a.NAME = b.NAME. They are claims, like the
// encoder's range lemmas: engines keep the inductive subset (Houdini), which
// is what proves two copies equal where they are built alike.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "encoder/encode.hpp"

namespace cemv::encoder {

struct Product {
  explicit Product(z3::context& ctx) : ts(ctx) {}
  TransitionSystem ts;
  // The two encodings as encode() built them (their terms are over their own,
  // unprefixed variables; input variables are the product's). What turns a
  // product trace into each matrix's cycle inputs (checker/replay.hpp).
  std::unique_ptr<Encoding> a;
  std::unique_ptr<Encoding> b;

  // The observable `key` of one copy as a term of the product; nullopt when
  // that copy does not encode it.
  std::optional<z3::expr> term_a(const std::string& key) const { return ts.term("a." + key); }
  std::optional<z3::expr> term_b(const std::string& key) const { return ts.term("b." + key); }
};

// Both matrices must be valid. Throws std::invalid_argument when an input
// name has different sorts in the two (a tag analog in one, discrete in the
// other): no shared input can stand for both. `roots_a` / `roots_b`: the cones to encode in
// each (empty: the whole matrix), as for encode().
std::unique_ptr<Product> product(z3::context& ctx, const model::Matrix& a, const model::Matrix& b,
                                 const std::vector<model::Node>& roots_a = {},
                                 const std::vector<model::Node>& roots_b = {});

}  // namespace cemv::encoder
