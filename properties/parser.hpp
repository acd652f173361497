// The property language's parser (docs/properties.md): one text file holding
// many named properties, resolved against one matrix into the AST of
// properties/ast.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"
#include "properties/ast.hpp"

namespace cemv::properties {

// Parses and resolves a property file. Throws formats::LoadError with one issue
// whose place is "FILE:LINE:COL" and whose message says what was expected and
// what was found (e.g. "expected ')', found 'and'"), or which name is unknown
// (with a did-you-mean hint).
PropertyFile parse_properties(std::string_view text, const model::Matrix& m, const std::string& file_name);

// Reads a file (size-guarded) and parses it; the file name in messages is `file` as given.
PropertyFile load_properties(const std::filesystem::path& file, const model::Matrix& m);

// Property names are unique across every file of one run (and the standard
// set): reports, JUnit test cases and counterexample files are named after
// them, and two properties of one name would give two rows with opposite
// verdicts and one scenario file written twice. Names that differ only in
// case count as the same (their files would collide on a case-insensitive
// file system). Throws LoadError at the second definition (FILE:LINE:COL),
// naming the first.
void check_distinct_names(const std::vector<PropertyFile>& files);

// The verdicts a `# expect:` comment may name.
bool is_verdict(std::string_view word);

}  // namespace cemv::properties
