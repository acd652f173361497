// The AST back as property-language text, and the signals a property reads:
// for reports (the property as resolved, with ids instead of names) and for
// counterexample tables limited to the signals that matter.
#pragma once

#include <string>
#include <vector>

#include "model/vocabulary.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// An expression in the property language, fully parenthesised where the
// precedence needs it; observables by key (`cause[3].active`), input tags by
// their matrix name, floats in shortest round-trip form. Parsing the text
// against the same matrix gives the same AST up to source locations (an
// empty and/or prints as true/false).
std::string to_text(const Expr& e, const model::InputTable& inputs);

// The statement of a property (`always ...`, `whenever ... then ... within N cycles`).
std::string statement_text(const Property& p, const model::InputTable& inputs);

// What a property (with the file's assumptions) reads, each list in first-use
// order without repeats.
struct Signals {
  std::vector<std::size_t> inputs;        // InputTable indices (values or quality)
  std::vector<std::string> observables;   // observable keys
  bool commands = false;                  // some issued(...) atom
};
Signals signals_of(const Property& p, const std::vector<Assumption>& file_assumptions);

}  // namespace cemv::properties
