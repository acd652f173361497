// `cemv plc-check` (docs/plc.md): for every output tag of the matrix, the
// program's output variable proved related to it as asked (equal at every
// scan, or in the safe state whenever the matrix is) for every input sequence
// the map allows, or a run where it is not, replayed on both the matrix's
// reference runtime and the program's interpreter. A run that does not show
// the difference on both is an InternalError, never an answer.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "checker/limits.hpp"
#include "checker/result.hpp"
#include "model/matrix.hpp"
#include "plc/ast.hpp"
#include "plc/interpreter.hpp"
#include "plc_check/map.hpp"
#include "plc_check/product.hpp"

namespace cemv::plc_check {

enum class OutputVerdict { Related, Differs, Unknown };
const char* to_string(OutputVerdict v);  // "related", "differs", "unknown"

// A run on which the program's output breaks the relation, as both sides
// executed it, cut after the first scan where it does.
struct Difference {
  int scan = 0;                                   // 0-based: the first scan that breaks the relation
  std::vector<model::CycleInput> matrix_inputs;   // indexed by InputTable(m)
  std::vector<std::map<std::string, plc::Value>> program_inputs;  // every VAR_INPUT, each scan
  std::vector<int> matrix_values;                 // the output tag on the runtime, each scan
  std::vector<int> program_values;                // the output variable on the interpreter, each scan
  checker::ConcreteTrace runtime;                 // every observable of the matrix, each scan
  std::optional<plc::Position> assigned_at;       // where the program last set the output in `scan`
};

struct OutputResult {
  OutputQuestion question;
  OutputVerdict verdict = OutputVerdict::Unknown;
  std::string method;   // the engine's words
  int k = 0;            // induction depth of a proof, length of a run
  std::string reason;   // of unknown
  std::optional<Difference> difference;
};

struct CheckOptions {
  Relation relation = Relation::Equal;
  checker::Work work = 20 * checker::kMega;  // per output and engine
  int first_depth = 3;                       // the short search before the proof
  int bmc_depth = 40;                        // the shortest-run search after it, before the engines
  bool by_groups = true;                     // first the proof of the output's cone group (shared_proof.hpp)
  checker::Limits limits;                    // the user's wall clock, the cancel token
};

// The questions of a matrix: one per output tag of a processed effect, with
// the program variable the completed map binds to it.
std::vector<OutputQuestion> questions(const model::Matrix& m, const ResolvedMap& map);

// Decides one question. Throws checker::InternalError when a run does not
// replay on both sides.
OutputResult check_output(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                          const ResolvedMap& map, const OutputQuestion& q, const CheckOptions& options);

}  // namespace cemv::plc_check
