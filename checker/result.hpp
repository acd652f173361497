// What `cemv check` found: one verdict per property, each already checked
// independently (counterexamples replayed on the reference runtime and judged
// by the concrete property evaluator; invariants and induction steps re-proved
// by a fresh solver). Data only: the printers in reports/ turn it into text,
// cemv-result/1 JSON, JUnit XML and SARIF (docs/checker.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "checker/names.hpp"
#include "model/vocabulary.hpp"

namespace cemv::checker {

// The verdicts of docs/checker.md. Invariant, Never and Response end Proved or
// Falsified; Reachable ends Reachable or Unreachable. Vacuous: the assumptions
// cannot hold together, or the antecedent of an implication or the trigger of
// a response can never hold. Unknown carries its reason.
enum class PropertyVerdict { Proved, Falsified, Reachable, Unreachable, Vacuous, Unknown };
// The verdict's word, as every output writes it (cemv-result/1, docs/checker.md).
inline const char* to_string(PropertyVerdict v) {
  switch (v) {
    case PropertyVerdict::Proved: return "proved";
    case PropertyVerdict::Falsified: return "falsified";
    case PropertyVerdict::Reachable: return "reachable";
    case PropertyVerdict::Unreachable: return "unreachable";
    case PropertyVerdict::Vacuous: return "vacuous";
    case PropertyVerdict::Unknown: return "unknown";
  }
  return "unknown";
}

// Exit status of `cemv check` for a set of verdicts: 0 all proved/reachable,
// 1 something falsified, unreachable or vacuous, 3 some unknown and nothing
// falsified. (2 invalid input and 4 internal error never come from verdicts.)
inline int exit_code(const std::vector<PropertyVerdict>& verdicts) {
  bool unknown = false;
  for (auto v : verdicts) {
    if (v == PropertyVerdict::Falsified || v == PropertyVerdict::Unreachable || v == PropertyVerdict::Vacuous)
      return 1;
    if (v == PropertyVerdict::Unknown) unknown = true;
  }
  return unknown ? 3 : 0;
}

// One matrix element a proof depends on (its support, an inductive validity
// core over matrix elements): "intersection[3,2]", "cause[1].bypass_tag", ...
struct SupportElement {
  std::string key;
  std::string description;
};

// How the support of proofs is found (docs/checker.md, "Support"; `cemv check
// --support`): not at all; the unsat core of the proof's obligations over
// activation literals of the cells, re-checked on the matrix without the
// others (sound, maybe not minimal); that core then minimised by deleting its
// cells one at a time under a budget of work (minimal when every trial
// decided).
enum class SupportMode { Off, Core, Full };
inline const char* to_string(SupportMode m) {
  switch (m) {
    case SupportMode::Off: return "off";
    case SupportMode::Core: return "core";
    case SupportMode::Full: return "full";
  }
  return "off";
}

// A concrete run: the cycle inputs and the runtime's observables (in
// model::observables order) after each cycle.
struct ConcreteTrace {
  std::vector<model::CycleInput> inputs;
  std::vector<std::vector<int>> observables;
};

// One step of a counterexample's or witness's explanation (docs/checker.md,
// "Why, per step"): in cycle `cycle` (1-based) the signal `signal` (an
// observable key or an input tag the property reads) went from `before` to
// `after`, because of `why`: for an observable, the rule of docs/semantics.md
// the runtime applied (filled by the command line, which re-runs the trace on
// the runtime with explanations on).
struct StepNote {
  int cycle = 0;
  std::string signal;
  std::string before, after;
  std::string why;
};

struct PropertyResult {
  std::string name;
  std::string description;
  std::string kind;            // "invariant", "never", "reachable", "response"
  int line = 0;                // of the property in its file (0 = generated)
  int column = 0;
  std::string file;            // the property file ("" for --standard)
  PropertyVerdict verdict = PropertyVerdict::Unknown;
  std::string method;          // "k-induction", "pdr", "bmc", "invariants+induction", ...
  int depth = 0;               // k of the proof, or length of the trace in cycles
  UnknownReason unknown = UnknownReason::None;  // Unknown: why (its words in `reason`)
  std::string reason;          // Unknown: "time limit", "work limit", ...; Vacuous: why
  std::string invariant;       // the proof's strengthening invariant (SMT-LIB text), if any
  std::vector<std::string> notes;  // e.g. duration rounding
  std::vector<SupportElement> support;  // Proved: the elements the proof needs
  bool support_minimal = false;         // support reduced to a minimal set by re-proving
  std::optional<ConcreteTrace> trace;   // Falsified / Reachable: the replayed run
  int violation_cycle = -1;             // 0-based cycle of the violation / witness
  std::string scenario_file;            // the trace as cemv-scenario/1 (under --out)
  std::string diagram_file;             // its timing diagram, SVG (under --out; written by the CLI)
  std::string vcd_file;                 // the trace as a VCD (under --out; written by the CLI)
  std::string timing_table;             // readable table of the signals that matter
  double seconds = 0.0;                 // wall time (not in deterministic outputs)
  std::uint64_t work = 0;               // Z3 resource units the decision spent (deterministic)
  std::vector<std::string> matters;     // observable keys the property reads (for tables)
  // Filled by the command line, not the checker (cemv check --expect,
  // --baseline, --cache; docs/checker.md "Gating"):
  std::string expected;       // the verdict a gate expects ("" = none: proved/reachable pass)
  std::string expected_from;  // where that expectation comes from: "# expect:", "baseline FILE"
  bool cached = false;        // the verdict was taken from the result cache (--cache)
  // Falsified: the matrix cells the counterexample needs (deleting one makes
  // the run pass), as support keys ("intersection[3,2]"); SARIF points at them.
  std::vector<std::string> counterexample_support;
  std::vector<StepNote> explanation;    // Falsified / Reachable: why each signal changed, per cycle
};

struct CheckResult {
  std::string matrix_name;
  std::string matrix_signature;
  std::string tool_version;
  std::vector<std::string> property_files;
  bool standard = false;
  std::string shard;                  // "i/n" or ""
  std::vector<PropertyResult> properties;
  std::vector<SupportElement> unsupported;  // --standard: elements no property depends on
  bool interrupted = false;           // the overall time limit ended the run
  SupportMode support_mode = SupportMode::Off;  // how the supports of the proofs were found
};

}  // namespace cemv::checker
