// The evidence report of `cemv evidence` (docs/reports.md, "Evidence report"):
// one self-contained, printable HTML file for an assessor. It holds the matrix
// as a cause & effect grid, the validation result (11.5), every property with
// its verdict, method and (for counterexamples and witnesses) its timing
// diagram, the response time of every SIF path when analysed, the
// test-generation and mutation figures when given, and on every page (the
// print header and footer) the matrix signature, the tool version and the date.
// Inline CSS and images only: no scripts, no external resources. The same
// inputs (and date) give the same bytes.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "checker/result.hpp"
#include "formats/acceptance.hpp"
#include "model/matrix.hpp"
#include "model/validate.hpp"

namespace cemv::reports {

// cemv-coverage/1 (docs/testgen.md), as read by the command line.
struct CoverageFigures {
  struct Objective {
    std::string id, kind, text, element, status, test, method;
  };
  struct Test {
    std::string id, file;
    long long sif = 0, steps = 0, cycles = 0;
    std::size_t objectives = 0;
  };
  std::string file;  // as given on the command line
  long long objectives = 0, covered = 0, infeasible = 0, undecided = 0, tests = 0, steps = 0, cycles = 0;
  std::vector<Objective> list;
  std::vector<Test> test_list;
};

// cemv-mutation-report/1 (docs/mutation.md), as read by the command line.
struct MutationFigures {
  struct Mutant {
    std::string id, op, element, description, status;
  };
  std::string file;
  long long mutants = 0, equivalent = 0, detected = 0, survived = 0, undecided = 0, refused = 0;
  std::vector<Mutant> open;  // survived or undecided: what the suite does not show
};

// The paths of `cemv response` (docs/response-time.md), as plain data: the
// command line fills them from response::analyse, which reports/ cannot use.
struct ResponseFigures {
  struct Path {
    int sif = 0;
    std::string sif_name;
    std::string path;     // "cause 1 -> effect 2"
    std::string logic;    // "20 cycles (2000 ms)", "unbounded", "unknown (time limit)"
    std::optional<long long> total_ms, process_safety_time_ms, margin_ms, degraded_total_ms;
    std::optional<double> margin_percent;
    std::string verdict;  // ok, over, no-pst, unbounded, unknown
  };
  std::string controller;  // "200 ms, 2 x cycle_ms"
  std::vector<Path> paths;
};

// The minimal defeat sets of `cemv defeats` (docs/defeats.md), as plain
// data: the command line reads them from its cemv-defeats/1 JSON.
struct DefeatFigures {
  struct Set {
    std::vector<std::string> actions;  // "override of effect 2 E2", one per action
    std::string set_class;             // "declared", "indirect"
    std::string counterexample;        // scenario file ("" = not written)
    std::vector<std::string> touches;  // the cells, elements and tags its actions touch: "effect 2", "tag LT_100A"
    std::vector<int> causes, effects;  // the elements it touches (ids), for the grid's marks
  };
  struct Path {
    int sif = 0;
    std::string sif_name;
    int sil = 0;
    std::string path;         // "cause 1 -> effect 2"
    std::string requirement;  // "20 cycles", "-"
    std::string status;       // complete, unbounded, unknown
    std::string distance;     // "1", "> 2", "unknown"
    std::vector<Set> sets;
  };
  std::string file;
  int max_size = 2;
  std::vector<Path> paths;
};

// `cemv evidence --plc` (docs/plc.md "Evidence with the program"): the PLC
// program proved against the matrix, as plain data the command line fills
// from plc_check's results.
struct PlcFigures {
  struct Binding {
    std::string what;      // "input tag LT_100A", "output tag XV_101", "command ack_cause cause 1"
    std::string variable;  // "" for a value held or a command declared unused
    std::string note;      // "bad quality LT_100A_BQ", "held at 50", "never issued"
  };
  struct Scan {
    int scan = 0;            // 1-based
    int matrix = 0, program = 0;
    std::string inputs;      // the program inputs that changed in this scan, "LT_100A = 91, ..."
  };
  struct Output {
    std::string tag, variable, verdict, method, reason;  // verdict: related, differs, unknown
    int effect = 0, k = 0;
    // differs: the run replayed on both sides, cut after the first differing scan
    int scan = 0, matrix_value = 0, program_value = 0;
    std::string assigned_at;  // "tank.st:118:1", "" when no statement set it
    std::vector<Scan> scans;
  };
  std::string file, sha256, pou, relation, map_source;
  long long scan_ms = 0;
  std::vector<Binding> map;
  std::vector<std::string> assumptions;
  std::vector<Output> outputs;
  bool interrupted = false;  // --total-timeout ended the check
};

// A property as written, for the report's formal text (docs/properties.md):
// its statement and the assumptions it is judged under, as properties/print
// writes them.
struct PropertyText {
  std::string file;                      // "" for the standard set
  std::string name;
  std::string statement;                 // "always ...", "whenever ... then ... within 5 cycles"
  std::vector<std::string> assumptions;  // "assume ..." (the file's first, marked "(every property of the file)")
};

// A property file as given: its SHA-256 ties a verdict to one version of the
// requirement text.
struct PropertyFileInfo {
  std::string file;                      // as given on the command line
  std::string sha256;                    // of its bytes
  std::size_t properties = 0;
  std::vector<std::string> assumptions;  // its top-level `assume` texts
  std::vector<std::string> warnings;     // traps found when it was read (properties/traps.hpp)
};

struct EvidenceInputs {
  std::string matrix_file;                    // as given on the command line
  std::vector<model::Diagnostic> validation;  // model::validate(m)
  checker::CheckResult check;                 // no properties: "no properties given"
  std::string date;                           // "2024-05-01 12:00 UTC"
  std::optional<ResponseFigures> response;    // absent: not analysed (the report says how to add it)
  std::optional<DefeatFigures> defeats;       // absent: none given
  std::optional<CoverageFigures> coverage;    // absent: none given
  std::optional<MutationFigures> mutation;
  std::vector<PropertyFileInfo> property_files;  // the user's, in command-line order
  std::vector<PropertyText> texts;               // every property checked, user's and standard
  // cemv-acceptance/1 of `cemv record` (docs/acceptance.md): the grid is then
  // coloured by acceptance status. Its signature is the matrix's (the CLI checks).
  std::optional<formats::Acceptance> acceptance;
  std::string acceptance_file;                   // as given on the command line
  std::optional<PlcFigures> plc;                 // absent: no program given
};

// The report as one printable HTML file (docs/reports.md, "Evidence report").
// A matrix with validation errors is reported too: a banner, its validation
// findings first, nothing checked.
std::string evidence_html(const model::Matrix& m, const EvidenceInputs& in);
// The same content as `cemv-evidence/1` JSON, for a quality system to file
// (docs/reports.md, "cemv-evidence/1").
std::string evidence_json(const model::Matrix& m, const EvidenceInputs& in);

// "YYYY-MM-DD HH:MM UTC" of a Unix time.
std::string utc_date(long long epoch_seconds);



}  // namespace cemv::reports
