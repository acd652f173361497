// What the fuzz targets share: the input as text, the matrices a scenario or a
// property file is resolved against, and how a broken invariant is reported.
// A documented error (formats::LoadError) is an expected answer to bad input;
// anything else the target lets escape (another exception, a sanitizer
// report, an abort from finding(), a hang) is a finding (docs/fuzzing.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "formats/matrix_json.hpp"
#include "model/matrix.hpp"

namespace cemv::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A matrix of the repository (path relative to its root), loaded once; the
// fuzz targets never fuzz it, they resolve names against it.
inline model::Matrix repository_matrix(const std::string& relative) {
  return formats::load_matrix(std::string(CEMV_SOURCE_DIR) + "/" + relative);
}

// An invariant of an importer does not hold for this input: abort, which
// libFuzzer records as a crash with the input saved.
[[noreturn]] inline void finding(const char* what, std::string_view detail = {}) {
  const std::string text(detail);  // never a null pointer for %s (GCC checks)
  std::fprintf(stderr, "fuzz finding: %s\n%s\n", what, text.c_str());
  std::abort();
}

}  // namespace cemv::fuzz
