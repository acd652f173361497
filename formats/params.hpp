// `cemv-params/1` (docs/params.md): the plant parameters beside a published
// sheet that a grid cannot state (override times, the soft-bypass and
// simulation policy, secure write, the cycle, SIF groups and process safety
// times, tag descriptions, what the sheet's footnotes mean), applied to a
// matrix so that every value set is recorded in it with its origin
// (docs/format.md "Provenance"), and the signature covers it.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"

namespace cemv::formats {

inline constexpr const char* kParamsFormat = "cemv-params/1";

struct ParamsApplication {
  model::Matrix matrix;              // the values set, provenance.parameters appended
  std::vector<std::string> notes;    // what was set, for the command's summary
  std::vector<LoadIssue> warnings;   // e.g. a footnote of the sheet the file does not explain
};

// Applies the parameters `text` (named `file_name` in messages; its base name
// and SHA-256 go into the record) to `m`. Throws LoadError, each issue at
// FILE:LINE:COL of the parameters file, for a file that is not
// cemv-params/1, an element or tag the matrix does not have, a value the
// matrix format refuses, a value set twice, or a file already applied.
// The trip sides the parameters `text` give a sheet's setpoints before the
// sheet is imported (docs/csv.md "Setpoints"): `limit_type` of each cause's
// `analog`, by the cause's key (sheet id or name). Throws LoadError for text
// that is not JSON; everything else is checked when the file is applied.
std::map<std::string, model::LimitType> params_trip_sides(std::string_view text, const std::string& file_name);

ParamsApplication apply_params(const model::Matrix& m, std::string_view text, const std::string& file_name);

}  // namespace cemv::formats
