// Observable equivalence of two matrices (docs/checker.md, "Equivalence"):
// for a group of observables (an effect's status fields and outputs, one
// output tag, or everything), either a proof that both matrices give the same
// values in every cycle of every run, over all inputs and operator commands,
// or a shortest run where they differ, replayed on both reference runtimes.
//
// The question is a safety property of the synchronous product of the two
// transition systems (encoder/product.hpp), "a.o = b.o for every observable o
// of the group", decided by the engine portfolio like any property: proofs
// re-checked in a fresh context (the relational lemmas a.x = b.x that the
// product carries are what invariants+induction keeps), distinguishing runs
// replayed on both runtimes, where they must differ too; a run that does not
// is an InternalError (exit 4), never an answer.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "checker/names.hpp"
#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "model/vocabulary.hpp"

namespace cemv::checker {

enum class EquivalenceVerdict { Equivalent, Differs, Unknown };
const char* to_string(EquivalenceVerdict);  // "equivalent", "differs", "unknown"

// Observables judged together. Keys that only one matrix has make the group
// differ without a run (the observable interface itself changed).
struct ObservableGroup {
  std::string name;               // "effect[2]", "effect[2].tag[1]", "matrix"
  std::vector<std::string> keys;  // model::observable_key spellings
  // The nodes whose cone is encoded (empty: both whole matrices). A node
  // that one matrix lacks is left out of that matrix's roots.
  std::vector<model::Node> roots;
};

// One group per effect of either matrix (by id): its status fields and output
// tags; one per output tag; the whole observable interface.
std::vector<ObservableGroup> effect_groups(const model::Matrix& a, const model::Matrix& b);
std::vector<ObservableGroup> output_groups(const model::Matrix& a, const model::Matrix& b);
ObservableGroup whole_matrix(const model::Matrix& a, const model::Matrix& b);

// A run on which the two matrices differ, as both runtimes executed it; cut
// after the first cycle where an observable of the group differs.
struct Distinction {
  std::string key;          // the first differing observable (group order)
  model::FieldType type = model::FieldType::Bool;
  int cycle = 0;            // 0-based
  int value_a = 0;
  int value_b = 0;
  ConcreteTrace run_a;      // inputs indexed by InputTable(a)
  ConcreteTrace run_b;      // inputs indexed by InputTable(b)
};

// What an equivalence answer rests on.
enum class EquivalenceBasis {
  None,
  Engine,         // an engine of the portfolio (its words in `method`)
  Simulation,     // "simulation": runs of both runtimes that differ
  IdenticalCone,  // "identical cone": both cones are the same configuration once
                  // texts are set aside (the encodings are equal term for term)
  Interface,      // "interface": keys only one matrix has
  InterfaceOnly,  // "interface-only": equivalent on the common keys, the interface differs
  Suite,          // "suite": a test of the suite fails on one and passes on the other
};
const char* to_string(EquivalenceBasis b);  // the words above; "" for None and Engine

struct GroupEquivalence {
  std::string group;
  EquivalenceVerdict verdict = EquivalenceVerdict::Unknown;
  EquivalenceBasis basis = EquivalenceBasis::None;
  std::string method;  // as printed: the engine's words, or to_string(basis)
  void rest_on(EquivalenceBasis b) {
    basis = b;
    method = to_string(b);
  }
  void rest_on_engine(std::string engine_words) {
    basis = EquivalenceBasis::Engine;
    method = std::move(engine_words);
  }
  int k = 0;                // induction depth of a proof
  UnknownReason unknown = UnknownReason::None;  // Unknown: why (its words in `reason`)
  std::string reason;       // Unknown: why; Differs by interface: which keys
  std::optional<Distinction> distinction;
  double seconds = 0.0;
};

struct EquivalenceOptions {
  // Each engine's budget of work (the portfolio's; a third of it for the
  // first BMC and for relational induction), and the random runs' budget of
  // simulated cycles: the same budgets give the same answer everywhere.
  Work work = 20 * kMega;
  std::size_t random_cycles = 1500000;
  // The user's wall clock (--timeout per group) and the run's cancel token:
  // they only interrupt, an interrupted group is Unknown ("time limit").
  double timeout_s = 0.0;
  const CancelToken* cancel = nullptr;
  bool identical_cone_shortcut = true;
};

// Throws InternalError when a distinguishing run does not replay, and when
// an answer fails its re-check.
GroupEquivalence decide_equivalence(const model::Matrix& a, const model::Matrix& b, const ObservableGroup& group,
                                    const EquivalenceOptions& options = {});

}  // namespace cemv::checker
