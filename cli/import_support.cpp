#include "cli/import_support.hpp"

#include <ostream>

#include "cli/matrix_input.hpp"
#include "sheets/import_record.hpp"
#include "formats/params.hpp"

namespace cemv::cli {

std::map<std::string, model::LimitType> parameter_trip_sides(const std::string& params_file) {
  if (params_file.empty() || params_file == "-") return {};
  const std::string name = input_name(params_file);
  try {
    return formats::params_trip_sides(read_input(params_file), name);
  } catch (const formats::LoadError& e) {
    throw e.in_file(name);
  }
}

model::Matrix apply_params_file(const model::Matrix& m, const std::string& params_file, bool quiet, std::ostream& err) {
  const std::string name = input_name(params_file);
  formats::ParamsApplication applied;
  try {
    applied = formats::apply_params(m, read_input(params_file), name);
  } catch (const formats::LoadError& e) {
    throw e.in_file(name);
  }
  if (!quiet) {
    for (const auto& w : applied.warnings) err << w.message("warning") << "\n";
    for (const auto& n : applied.notes) err << name << ": note: " << n << "\n";
  }
  return std::move(applied.matrix);
}

model::Matrix finish_import(ImportedSheet sheet, const std::string& params_file, bool quiet, std::ostream& err) {
  std::vector<std::string> printed;
  for (const auto& w : sheet.warnings) {
    formats::LoadIssue issue = w;
    if (issue.file.empty()) issue.file = sheet.file;
    printed.push_back(issue.message("warning"));
    if (!quiet) err << printed.back() << "\n";
  }
  if (!quiet && !sheet.summary.empty()) err << sheet.file << ": note: " << sheet.summary << "\n";
  model::Matrix m = params_file.empty() ? std::move(sheet.matrix)
                                        : apply_params_file(sheet.matrix, params_file, quiet, err);
  if (sheet.reader.empty()) return m;
  // A grid states ids, descriptions and cells only: every other field is the
  // format's default unless the parameters set it, and the record says which.
  formats::record_import(m, sheet.file, sheet.bytes, sheet.reader, sheet.encoding, sheet.summary, printed);
  if (!quiet) {
    const auto& defaults = m.provenance.imports.back().defaults;
    if (!defaults.empty())
      err << sheet.file << ": note: " << defaults.size()
          << " defaults adopted: the sheet does not state these fields"
          << (params_file.empty() ? " (a parameters file can, docs/params.md)" : " and the parameters leave them")
          << ":\n";
    for (const auto& d : defaults) err << "  " << d << "\n";
  }
  return m;
}

}  // namespace cemv::cli
