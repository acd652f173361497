// The question of one output tag as a safety problem (docs/plc.md
// "Relations"): the matrix's transition system (encoder/) and the program's
// (plc_encoder/) in one system, both reading the same inputs in every scan as
// the map binds them, the map's assumptions as the per-scan assumption, and
// the relation of the program's output variable to the matrix's output tag as
// the property.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <z3++.h>

#include "checker/prover.hpp"
#include "encoder/encode.hpp"
#include "model/matrix.hpp"
#include "plc/ast.hpp"
#include "plc_check/map.hpp"

namespace cemv::plc_check {

enum class Relation { Equal, SafeSide };
const char* to_string(Relation r);  // "equal", "safe-side"

// One output tag: effect `effect`'s tag number `position` (1-based).
struct OutputQuestion {
  int effect = 0;
  int position = 0;
  std::string tag;
  std::string variable;  // the program's output variable
  bool ett = false;      // the safe value is 1 (ETT) or 0 (DTT)
};

// The product of one question, built in one context; owns its encodings.
struct ProductProblem {
  std::unique_ptr<encoder::Encoding> matrix;
  // Input variables of the product that only the program reads: matrix
  // input tags outside the effect's cone, commands the cone cannot act on
  // (by name, with the tag or command they stand for).
  struct Extra {
    std::string name;
    std::optional<std::size_t> tag;  // InputTable index, for a tag's value
    bool bad = false;                // the tag's bad-quality input
  };
  std::vector<Extra> extras;
  // What each VAR_INPUT of the program reads: an input variable of the
  // product or a constant (a replay reads the run's value of the one, takes
  // the other as it is).
  struct ProgramInput {
    std::string variable;
    plc::Type type = plc::Type::Bool;
    z3::expr term;
    std::optional<double> held;  // the value the map holds it at
  };
  std::vector<ProgramInput> program_inputs;
  z3::expr program_output;  // of the first question
  z3::expr matrix_output;
  std::vector<z3::expr> goods;  // each question's relation, in their order
  checker::SafetyProblem problem;  // good: every question's relation
};

// The names the product gives the program's state (prefix of every program
// variable) and a program input that reads a tag outside the cone.
inline constexpr const char* kProgramPrefix = "plc.";

// The product of several questions at once: the matrix's cones of their
// effects, the whole program, and the conjunction of their relations as the
// property (the product whose correspondence every output shares).
std::shared_ptr<ProductProblem> build_product(z3::context& ctx, const model::Matrix& m, const plc::Program& program,
                                              const plc::Pou& pou, const ResolvedMap& map,
                                              const std::vector<OutputQuestion>& qs, Relation relation);

// The factory for the checker's engines (a fresh context each).
checker::ProblemFactory product_factory(const model::Matrix& m, const plc::Program& program, const plc::Pou& pou,
                                        const ResolvedMap& map, std::vector<OutputQuestion> qs, Relation relation);

}  // namespace cemv::plc_check
