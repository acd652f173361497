// Fuzz target: the cemv-matrix/1 loader (formats/matrix_json.hpp), the bytes
// `cemv fmt` / `cemv validate` read. Expected answers: a matrix, or a
// LoadError. Invariants of an accepted matrix (docs/format.md): its canonical
// form loads again and is a fixed point, and the validating loader (which
// places each finding at its element in the text) answers as well.
#include <cstddef>
#include <cstdint>

#include "formats/matrix_json.hpp"
#include "fuzz/fuzz_support.hpp"

using namespace cemv;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto text = fuzz::as_text(data, size);
  model::Matrix m;
  try {
    m = formats::parse_matrix(text, "fuzz.json");
  } catch (const formats::LoadError&) {
    return 0;
  }
  const std::string canonical = formats::to_canonical_json(m);
  try {
    if (formats::to_canonical_json(formats::parse_matrix(canonical, "canonical.json")) != canonical)
      fuzz::finding("the canonical form is not a fixed point", canonical);
  } catch (const formats::LoadError& e) {
    fuzz::finding("the canonical form of an accepted matrix does not load", e.issues().front().str());
  }
  try {
    formats::parse_valid_matrix(text, "fuzz.json", "fuzzed");
  } catch (const formats::LoadError&) {
    // validation errors: the expected refusal
  }
  (void)formats::signature(m);
  return 0;
}
