// The validation report of 11.5 for one or more matrix files, as `cemv
// validate` writes it (docs/validation.md): text, cemv-validation/1 JSON,
// compiler-style lines (gcc), JUnit XML and SARIF 2.1.0.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "model/validate.hpp"

namespace cemv::reports {

// One file given to `cemv validate`.
struct ValidatedFile {
  std::string file;  // as messages name it ("<stdin>" for "-")
  bool loaded = false;
  // When loaded:
  std::string matrix_name;
  std::string signature;
  std::vector<model::Diagnostic> diagnostics;
  // The line and column of each diagnostic's element in the file (0 = none).
  std::vector<std::pair<std::size_t, std::size_t>> positions;
  // When not: the load error, one line per issue as the CLI prints them.
  std::vector<std::string> load_errors;
};

enum class ValidationFormat { Text, Json, Gcc, Junit, Sarif };
std::optional<ValidationFormat> validation_format_from_string(const std::string& name);

struct ValidationOptions {
  bool warnings_as_errors = false;  // a warning counts as an error for the verdict
  bool quiet = false;               // text and gcc: error findings only, no summary
  std::string tool_version;
};

struct ValidationSummary {
  std::size_t files = 0, clean = 0, with_errors = 0, unreadable = 0;
  std::size_t errors = 0, warnings = 0;
  int exit_code = 0;  // the worst file's: 0 clean, 1 errors, 2 unreadable
};
ValidationSummary summarize(const std::vector<ValidatedFile>& files, const ValidationOptions& options);

// "3 files: 2 clean, 1 with errors; 4 errors, 7 warnings" (", N unreadable"
// after the files that have errors when some could not be read); plural
// forms always, like the single-file "1 errors, 0 warnings".
std::string summary_line(const ValidationSummary& s);

// The report. With one file, text and JSON are the single-file report of
// earlier versions, byte for byte; text adds the summary line with several files.
std::string validation_report(const std::vector<ValidatedFile>& files, ValidationFormat format,
                              const ValidationOptions& options);

}  // namespace cemv::reports
