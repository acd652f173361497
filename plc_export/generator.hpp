// The generator's state while it builds one program (internal to plc_export/):
// the names it gave, the variables it declared and the statements of the
// body, section by section of docs/semantics.md. export.cpp holds the
// interface and the matrix level, causes.cpp section C, effects.cpp section E.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "model/graph.hpp"
#include "model/matrix.hpp"
#include "model/vocabulary.hpp"
#include "plc/ast.hpp"

namespace cemv::plc_export {

class Generator {
 public:
  explicit Generator(const model::Matrix& m);

  // A fresh identifier as close to `wanted` as ST allows, unique in the
  // program whatever the letter case.
  std::string claim(const std::string& wanted);

  // Declarations.
  std::string local(const std::string& wanted, plc::Type type, const std::string& comment,
                    std::optional<plc::Literal> initial = std::nullopt);
  std::string timer(const std::string& wanted, plc::StandardBlock b, const std::string& comment);

  // The value of a tag as the matrix reads it (input, or internal reference
  // I.3), as a BOOL (non-zero) and as a REAL.
  plc::Expr tag_bool(const std::string& tag) const;
  plc::Expr tag_real(const std::string& tag) const;
  // The BOOL input that reads a cause input tag's bad quality; FALSE for a
  // reference or a tag whose quality no cause reads.
  plc::Expr tag_bad(const std::string& tag) const;
  // An operator command's BOOL input gated by secure write (M.3).
  plc::Expr command(const std::string& variable) const;

  // The whole number of scans of a duration (T.2); Unsupported past DINT.
  std::int64_t scans(std::uint64_t ms, const std::string& element) const;
  // A TIME literal of `ms` for a timer's PT; Unsupported past TIME's range.
  plc::Expr preset(std::uint64_t ms, const std::string& element) const;

  void cause(const model::Cause& c);    // causes.cpp
  void effect(const model::Effect& e);  // effects.cpp

  const model::Matrix& m;
  model::InputTable inputs;
  model::DependencyGraph graph;

  std::vector<std::string> input_var;  // by InputTable index
  std::vector<std::string> bad_var;    // by InputTable index; empty: quality not read
  std::map<int, std::string> cause_var, effect_var;
  std::map<std::pair<int, int>, std::string> output_var;  // (effect id, 1-based tag)
  std::map<int, std::string> ack_var, reset_var, override_var, stop_override_var;
  std::string secure_write_var;   // empty: no secure write
  std::string group_deactivation; // the local that says M.2 fired this scan; empty: not needed
  std::string first_scan;         // empty: not needed

  std::vector<plc::Variable> in_vars, out_vars, locals;
  std::vector<plc::Statement> body;

 private:
  std::set<std::string> used_;  // upper case
};

std::string element_label(const model::Cause& c);
std::string element_label(const model::Effect& e);

}  // namespace cemv::plc_export
