// What `import-csv`, `import-workbook` and `apply-params` do after reading a
// matrix: apply a parameters file (cemv-params/1, docs/params.md), record a
// lossy import (a C&E grid) with its source, warnings and the defaults it
// adopted (docs/format.md "Provenance"), and say so on standard error.
#pragma once

#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include "formats/diagnostics.hpp"
#include "model/matrix.hpp"

namespace cemv::cli {

// A matrix as an importer read it.
struct ImportedSheet {
  model::Matrix matrix;
  std::string file;            // as messages name it
  std::string bytes;           // the file as read (its SHA-256 goes into the record)
  std::string reader;          // "import-csv grid"; empty: a lossless layout, not recorded
  std::string encoding;        // "UTF-8", "Windows-1252"
  std::string summary;
  std::vector<formats::LoadIssue> warnings;
};

// Applies `params_file` (none when empty), records the import when it is
// lossy, and prints the warnings, the summary, what the parameters set and
// the defaults adopted to `err` (nothing when quiet). Throws LoadError for a
// parameters file that cannot be applied.
model::Matrix finish_import(ImportedSheet sheet, const std::string& params_file, bool quiet, std::ostream& err);

// The trip sides a parameters file gives the sheet's setpoints, read before
// the sheet (formats::params_trip_sides); none without a file or from
// standard input (read once, when it is applied).
std::map<std::string, model::LimitType> parameter_trip_sides(const std::string& params_file);

// Applies one parameters file to `m` and prints what it set (unless quiet).
model::Matrix apply_params_file(const model::Matrix& m, const std::string& params_file, bool quiet, std::ostream& err);

}  // namespace cemv::cli
