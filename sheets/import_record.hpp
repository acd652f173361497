// What an import of a sheet records in the matrix it makes (docs/format.md
// "Provenance", docs/csv.md "What the import makes of it"): the source file
// and its SHA-256, how it was read, its warnings, and every default the
// import adopted because the sheet does not state the field.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "model/matrix.hpp"

namespace cemv::formats {

// The fields a C&E grid cannot state that the matrix `m` still holds at the
// format's default, each with the elements it concerns ("36 of 36 causes:
// soft bypass allowed and untimed (soft_bypass {allowed: true, max_s: 0})").
// A field a parameters file set (m.provenance.parameters) is stated, not a
// default. One line per field, in the order of docs/format.md.
std::vector<std::string> adopted_defaults(const model::Matrix& m);

// Appends the record of reading `bytes` (the file as read, before any
// decoding) from `file` to m.provenance.imports; `warnings` as printed.
void record_import(model::Matrix& m, const std::string& file, std::string_view bytes, const std::string& reader,
                   const std::string& encoding, const std::string& summary, std::vector<std::string> warnings);

}  // namespace cemv::formats
