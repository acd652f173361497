// Acceptance-test generation (docs/testgen.md): coverage objectives derived
// from the matrix, tests found by the checker's BMC engine on each
// objective's cone of influence (the objective is a `reachable` cover of the
// property language, so its witness is a checker counterexample), objectives
// no run can reach proved so by the checker's proving engines, tests extended
// and combined greedily, every test replayed on the reference runtime, and
// the suite written as cemv-scenario/1 files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "checker/limits.hpp"
#include "formats/scenario.hpp"
#include "model/matrix.hpp"
#include "model/node.hpp"
#include "model/vocabulary.hpp"
#include "properties/ast.hpp"

namespace cemv::testgen {

enum class ObjectiveStatus { Covered, Infeasible, Undecided };
const char* to_string(ObjectiveStatus s);

struct Objective {
  std::string id;        // stable: "cause.1.vote.1oo2.k1", "intersection.c1.e2.alone", ...
  std::string kind;      // "voting-row", "mcdc", "limit", "hysteresis", "timer", ...
  std::string text;      // the sentence an engineer reads
  model::Node element;   // the cause or effect it is about (matrix level: the first element it names)
  int sif = 0;           // the SIF group the test of this objective is filed under (0 = none)
  properties::Property property;  // the objective: `reachable EXPR` with its assumptions, named obj_ID
  int horizon = 0;       // cycles a witness needs at least (timers): a search hint
  std::vector<std::string> observe;  // observable keys its checkpoint shows first (checklist)
  // The witness may force tags (simulate_tag / stop_simulation, O.8, E.10):
  // only the `reference` objectives, whose effect follows the cause through
  // an internal reference that only an output simulation interrupts.
  bool simulates = false;
};
// Every objective of the matrix, in a fixed order (element, then kind).
std::vector<Objective> derive_objectives(const model::Matrix& m);
// The objectives as one property file ("objectives"), each property with its
// own assumptions.
properties::PropertyFile objectives_file(const std::vector<Objective>& objectives);
// The same as text for people, each property after its sentence as a
// comment: what `cemv check` could decide too.
std::string objectives_file_text(const model::Matrix& m, const std::vector<Objective>& objectives);

struct ObjectiveResult {
  Objective objective;
  ObjectiveStatus status = ObjectiveStatus::Undecided;
  int test = -1;         // index into TestSuite::tests when covered
  int cycle = -1;        // 0-based cycle of the witness in that test
  std::string method;    // "bmc", "accelerated-bmc", a proving engine, or "replay"
  std::string reason;    // infeasible: the proof; undecided: the limit reached
  double seconds = 0.0;  // time spent on it (not in deterministic outputs)
};

// One step of a test as the checklist prints it: what the engineer does,
// how long the step lasts, what they should then observe.
struct FieldStep {
  std::vector<std::string> actions;   // "Set LT_100A to 95 % (limit 90, high)", "Press reset for effect 1 ..."
  std::uint64_t ms = 0;               // the step's duration
  std::vector<std::string> expected;  // "XV_101 = 0", "cause 1 LT100_HH active: yes"; empty: nothing to check
  std::string covers;                 // the objectives witnessed at the end of the step
};

struct Test {
  std::string id;                          // "T001", ... in suite order
  std::string file_name;                   // "T001-c1-lt100_hh.scenario.json"
  int sif = 0;
  std::string description;
  std::vector<model::CycleInput> inputs;   // one per scan cycle
  std::vector<std::size_t> checkpoints;    // 0-based cycles checked (ascending)
  std::vector<std::string> objectives;     // ids covered, witness order
  std::string scenario_json;               // the cemv-scenario/1 text
  std::size_t steps = 0;
  std::vector<FieldStep> field_steps;      // the scenario's steps, phrased for the field
};

struct TestSuite {
  std::string matrix_name;
  std::string signature;
  std::vector<ObjectiveResult> objectives;  // derive_objectives order (filtered by --sif)
  std::vector<Test> tests;                  // sorted by SIF group
  std::size_t covered = 0, infeasible = 0, undecided = 0;
  std::size_t total_steps = 0, total_cycles = 0;
};

// A test the suite takes as given (a change's distinguishing run,
// docs/change-acceptance.md): its inputs on the matrix, and the observable
// its last cycle shows first. Like every test it is written with the
// field's observables at that checkpoint and replayed green.
struct GivenTest {
  std::string name;         // for the file name: "effect[5]"
  std::string description;  // the sentence an engineer reads
  int sif = 0;              // the SIF group it is filed under
  std::vector<model::CycleInput> inputs;
  std::string key;          // observable key checked first at the last cycle
};

struct TestgenOptions {
  std::optional<int> sif;             // only the objectives filed under this SIF group
  // Only the objectives about these causes and effects (Objective::element):
  // a change's impact (`--changed-from`); unset: all.
  std::optional<std::set<model::Node>> elements;
  std::vector<GivenTest> given;       // tests C001, ... before the generated ones
  int jobs = 1;                       // SIF groups searched in parallel
  // Budgets of work (checker/limits.hpp: Z3 resource units), so that the
  // same matrix gives the same suite on every machine.
  checker::Work objective_work = 20 * checker::kMega;  // search per objective (BMC, then accelerated BMC)
  checker::Work proof_work = 3 * checker::kMega;       // infeasibility proof per objective
  checker::Work shrink_work = checker::kMega;          // a witness made readable (the solver's pass)
  // The run's cancel token (a failure elsewhere, or the caller's bound).
  checker::CancelToken* cancel = nullptr;
  int max_depth = 40;                 // BMC cycles beyond an objective's horizon
  std::size_t max_test_steps = 100;   // a test is not extended beyond this many steps
  std::size_t max_test_cycles = 600000;   // nor beyond this many cycles (memory, ~4 KB a cycle)
  std::string matrix_ref;             // the scenarios' `matrix` key ("" = none)
  std::function<void(const ObjectiveResult&)> on_decided;  // progress, serialised
};

// Throws checker::InternalError when a test does not replay green on the
// runtime (never a silent pass). When the options' cancel token ends the run
// first, the suite holds the tests made until then and every objective not
// decided is undecided ("time limit").
TestSuite generate_tests(const model::Matrix& m, const TestgenOptions& options = {});

// ---- replay -----------------------------------------------------------------

struct StepOutcome {
  std::size_t step = 0;    // 0-based scenario step
  std::size_t cycle = 0;   // 0-based last cycle of the step
  bool passed = true;
  std::vector<std::string> failures;  // "FAIL steps[1] (cycle 21, t = 2000 ms): ..."
};
struct TestOutcome {
  std::string name;
  bool passed = false;
  std::string load_error;  // the scenario does not load against this matrix
  std::string not_run;     // the replay target cannot run it (a command it does not implement)
  std::vector<StepOutcome> steps;
  std::size_t expectations = 0, failed = 0, cycles = 0;
  std::size_t skipped = 0;  // expectations on values the replay target does not have
};

// What a replay runs a scenario on, when not the reference runtime: another
// implementation of the matrix (a PLC program and its map, cli/plc_target.hpp).
class ReplayTarget {
 public:
  virtual ~ReplayTarget() = default;
  virtual void start() = 0;  // back to start-up, before each test
  // Why the target cannot run this cycle ("" when it can): a command it has no input for.
  virtual std::string cannot_run(const model::CycleInput& in) const = 0;
  virtual void step(const model::CycleInput& in) = 0;
  // Whether the target has a value for an expectation's target (others are
  // counted as skipped, never as passed).
  virtual bool observes(const formats::ExpectTarget& t) const = 0;
  virtual int value(const formats::ExpectTarget& t) const = 0;
};
struct ReplayResult {
  std::vector<TestOutcome> tests;
  bool all_passed() const;
  std::size_t passed() const;
};

// (name, cemv-scenario/1 text) pairs, each parsed against `m`.
// `target`: nullptr runs the reference runtime.
ReplayResult replay_texts(const model::Matrix& m,
                          const std::vector<std::pair<std::string, std::string>>& scenarios,
                          ReplayTarget* target = nullptr);
ReplayResult replay_suite(const model::Matrix& m, const TestSuite& suite);
// Which tests pass on the reference runtime, each test stopped after the
// cycle of its first failed expectation (a mutant's verdict, cemv mutate
// --suite): a failed test's steps, expectations, failed and cycles count
// only up to that cycle; a passed test is the same as replay_texts gives.
ReplayResult replay_verdicts(const model::Matrix& m,
                             const std::vector<std::pair<std::string, std::string>>& scenarios);
// Files, and folders (every *.json in them, by name). A file that cannot be
// read is a formats::LoadError; one that does not load against `m` is a
// failed test with its load_error.
ReplayResult replay_files(const model::Matrix& m, const std::vector<std::filesystem::path>& paths,
                          ReplayTarget* target = nullptr);

}  // namespace cemv::testgen
