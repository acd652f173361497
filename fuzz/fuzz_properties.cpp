// Fuzz target: the property-language parser (properties/parser.hpp,
// docs/properties.md), the bytes `cemv check MATRIX PROPS` reads, resolved
// against each example matrix (names resolve differently in each). Expected
// answers: a property file, or a LoadError at FILE:LINE:COL. Invariant of an
// accepted property (properties/print.hpp): its statement printed back parses
// against the same matrix and prints the same (printing is a fixed point).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "model/vocabulary.hpp"
#include "properties/parser.hpp"
#include "properties/print.hpp"

using namespace cemv;

namespace {

struct Example {
  model::Matrix matrix;
  model::InputTable inputs;
  explicit Example(const std::string& name)
      : matrix(fuzz::repository_matrix("examples/" + name + "/matrix.json")), inputs(matrix) {}
};

void parse_and_reprint(std::string_view text, const Example& ex) {
  properties::PropertyFile file;
  try {
    file = properties::parse_properties(text, ex.matrix, "fuzz.props");
  } catch (const formats::LoadError&) {
    return;
  }
  for (const auto& p : file.properties) {
    const std::string statement = properties::statement_text(p, ex.inputs);
    const std::string again = "property p {\n  " + statement + "\n}\n";
    try {
      const auto reparsed = properties::parse_properties(again, ex.matrix, "printed.props");
      if (reparsed.properties.size() != 1 ||
          properties::statement_text(reparsed.properties[0], ex.inputs) != statement)
        fuzz::finding("printing a property is not a fixed point", statement);
    } catch (const formats::LoadError& e) {
      fuzz::finding("a printed property does not parse", statement + "\n" + e.issues().front().str());
    }
    (void)properties::signals_of(p, file.assumptions);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<Example> examples = [] {
    std::vector<Example> v;
    for (const char* name : {"tank-overfill", "burner-management", "pipeline-hipps", "compressor"})
      v.emplace_back(name);
    return v;
  }();
  const auto text = fuzz::as_text(data, size);
  for (const auto& ex : examples) parse_and_reprint(text, ex);
  return 0;
}
