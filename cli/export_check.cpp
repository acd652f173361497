#include "cli/export_check.hpp"

#include "formats/diagnostics.hpp"
#include "formats/matrix_json.hpp"
#include "model/validate.hpp"

namespace cemv::cli {

void refuse_unreadable_export(const std::string& matrix_text, const std::string& matrix_name, const model::Matrix& m,
                              const std::string& what, const std::function<std::optional<std::string>()>& reimport) {
  if (!model::has_errors(model::validate(m))) return;
  std::optional<std::string> problem;
  try {
    problem = reimport();
  } catch (const formats::LoadError& e) {
    problem = "its import refuses it: " + e.issues().front().str();
  }
  if (!problem) return;
  // The refusal of load_valid_matrix: every validation error at its element.
  formats::parse_valid_matrix(matrix_text, matrix_name, "exported to " + what + ", which would not give it back (" + *problem +
                                     "); fix these validation errors first");
}

}  // namespace cemv::cli
