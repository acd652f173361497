// What the evidence report says, before it is printed: one document that
// the HTML pages and the cemv-evidence/1 JSON both render, so the two hold
// the same content (docs/reports.md, "Evidence report"). Internal to
// reports/evidence*.cpp.
#pragma once

#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "reports/evidence.hpp"

namespace cemv::reports::evidence_detail {

using Cell2 = std::pair<int, int>;  // (cause id, effect id)

// One of the user's requirements with everything that ties its verdict.
struct Requirement {
  const checker::PropertyResult* result = nullptr;
  const PropertyText* text = nullptr;       // nullptr when the CLI gave none
  std::string file_sha256;                  // of its property file
  std::set<Cell2> support_cells;            // the cells its proof rests on
  std::set<Cell2> trace_cells;              // the cells its counterexample or witness runs through
};

// The standard set's properties of one element.
struct ElementSummary {
  std::string key;    // "effect[3]", "cause[2]"
  std::string label;  // "effect 3 TMA_A_3"
  std::array<int, 6> verdicts{};  // by checker::PropertyVerdict
  std::vector<const checker::PropertyResult*> properties;
};

// One line of the limitations chapter.
struct Limitation {
  std::string kind;    // "footnote not modelled", "stated limitation", "value supplied", "default adopted", "assumed away"
  std::string text;
  std::string source;  // where it comes from (a file, a footnote)
};

struct Document {
  Document(const model::Matrix& matrix, const EvidenceInputs& inputs) : m(matrix), in(inputs) {}
  const model::Matrix& m;
  const EvidenceInputs& in;
  bool valid = true;                 // no validation errors: the matrix was checked
  int errors = 0, warnings = 0;
  std::vector<Requirement> requirements;
  std::vector<const checker::PropertyResult*> standard;
  std::vector<ElementSummary> standard_by_element;
  std::set<Cell2> support_cells;     // of proved requirements
  std::set<Cell2> trace_cells;       // of counterexamples and witnesses
  std::vector<Limitation> limitations;
  std::array<int, 6> counts{};                 // every property, by verdict
  std::array<int, 6> requirement_counts{};     // the user's
  std::vector<std::string> requirements_not_passed;  // "req4 (falsified)"
  std::vector<std::string> conclusion;         // the overall statement, sentence by sentence
};

Document build_document(const model::Matrix& m, const EvidenceInputs& in);

// The formal text of a property: statement, then its assumptions, one per line.
std::string formal_text(const PropertyText& t);
// "passed" for proved and reachable.
bool passed(checker::PropertyVerdict v);

// The sections on response time and on test generation (evidence_tests.cpp).
class Pages;
void response_section(Pages& pages, const model::Matrix& m, const EvidenceInputs& in, const std::string& number);
void tests_section(Pages& pages, const EvidenceInputs& in, const std::string& number);
// The chapters on verdicts (evidence_verdicts.cpp): the user's requirements,
// the standard set per element, the standard set in full as an appendix.
void requirements_chapter(Pages& pages, const Document& d, const std::string& number);
void standard_chapter(Pages& pages, const Document& d, const std::string& number);
void appendix_chapter(Pages& pages, const Document& d, const std::string& number);

// The chapter on the PLC program (evidence_plc.cpp).
void plc_chapter(Pages& pages, const PlcFigures& p, const std::string& number);
// The chapters on the matrix (evidence_grid.cpp): grid with its legend,
// validation, provenance.
void grid_chapter(Pages& pages, const Document& d, const std::string& number);
void validation_chapter(Pages& pages, const Document& d, const std::string& number);
void provenance_chapter(Pages& pages, const Document& d, const std::string& number);

}  // namespace cemv::reports::evidence_detail
