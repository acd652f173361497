// Why a matrix's status fields change (docs/semantics.md): with explanations
// on (Runtime::explain), each scan cycle the runtime records, for every
// observable whose value changed, the rule of the semantics it applied, in
// words and with its paragraph: "R latch cleared without a reset: its R
// request fell while an override was running (E.5)". Taken from the
// runtime's own evaluation (what each function block did in that cycle), so
// a counterexample replayed with explanations on explains itself.
#pragma once

#include <cstddef>
#include <string>

namespace cemv::runtime {

struct Explanation {
  std::size_t observable = 0;  // index into model::observables(m)
  int before = 0;              // its value after the previous cycle (0 before cycle 1, T.3)
  int after = 0;               // after this cycle
  std::string why;             // the rule, with its paragraph of docs/semantics.md
};

}  // namespace cemv::runtime
