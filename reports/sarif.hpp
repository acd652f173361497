// What every SARIF 2.1.0 log of cemv shares (cemv check, cemv validate, cemv
// diff): the documentation a rule links to, as URIs relative to the root of
// cemv's repository (docs/checker.md, "sarif"), file paths as URI
// references, and the line of a matrix element in its file, where
// code-review annotations belong.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "formats/diagnostics.hpp"

namespace cemv::reports {

// tool.driver.informationUri: the README, relative to the repository root.
inline constexpr const char* kSarifInformationUri = "README.md";
// A rule's helpUri: the document that explains it ("docs/checker.md").
inline std::string sarif_help_uri(std::string_view document) { return "docs/" + std::string(document); }

// A relative path as a URI reference: percent-encodes what a path may hold
// but a URI may not (RFC 3986 section 2).
std::string uri_of_path(const std::string& path);

// Lines of a matrix's elements in the text of its file: "cause[3]",
// "effect[2]", "intersection[3,2]" (the support keys of docs/checker.md) or
// "intersection cause[3]/effect[2]" (formats::element_offset's names).
// Nothing is found in an empty text (standard input, or no text given).
class MatrixLines {
 public:
  explicit MatrixLines(std::string_view matrix_text);
  // 1-based line and column (in bytes) where the element starts.
  std::optional<std::pair<std::size_t, std::size_t>> find(std::string_view element) const;

 private:
  std::string_view text_;
  std::optional<formats::JsonPositions> positions_;
};

}  // namespace cemv::reports
