// The names the checker reports: how an answer was found and why a question
// stayed open. Enums in code, words only in output (one function each), so
// that no code compares the text it prints.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>

namespace cemv::checker {

// How an answer was found: an engine of the portfolio, or a run tried before
// any engine.
enum class Method {
  None,
  Bmc,                  // "bmc": incremental BMC, a shortest counterexample
  KInduction,           // "k-induction": strengthened by lemmas and mined invariants
  KInductionPlain,      // "k-induction-plain": the encoder's lemmas only (asked by name)
  InvariantsInduction,  // "invariants+induction": Houdini invariants, induction with k <= 1
  Pdr,                  // "pdr": IC3/PDR through Z3's Spacer
  AcceleratedBmc,       // "accelerated-bmc": macro steps of held inputs
  RelationalInduction,  // "relational-induction": on a product (equivalence)
  DirectedRun,          // "directed run": a caller's candidate run on the runtime
  RandomRun,            // "random run": a seeded random run of the cone on the runtime
  Portfolio,            // "portfolio": several engines, none of which answered
};
const char* to_string(Method m);
// The method's word with ", localized" when the answer came from the
// localization (checker/localize.hpp).
std::string method_text(Method m, bool localized);
// An engine by its word (command lines, benchmarks); nullopt for another word.
std::optional<Method> method_from_string(std::string_view word);

// Why a question stayed open.
enum class UnknownReason {
  None,
  TimeLimit,       // "time limit": the user's wall clock (--timeout, --total-timeout)
  WorkLimit,       // "work limit": the question's budget of work is spent
  BoundReached,    // "bound reached": the engine's depth or k bound
  MemoryLimit,     // "memory limit"
  SolverGaveUp,    // "solver gave up": Z3 answered unknown for a reason of its own
  NoDirectedRun,   // "no directed run violates it"
  CannotRun,       // "the evaluator cannot run this system" (accelerated BMC)
};
const char* to_string(UnknownReason r);

inline std::ostream& operator<<(std::ostream& out, Method m) { return out << '"' << to_string(m) << '"'; }
inline std::ostream& operator<<(std::ostream& out, UnknownReason r) { return out << '"' << to_string(r) << '"'; }

}  // namespace cemv::checker
