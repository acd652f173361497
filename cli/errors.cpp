#include "cli/errors.hpp"

namespace cemv::cli {

void print_load_error(const formats::LoadError& e, std::ostream& out) {
  const auto& issues = e.issues();
  std::size_t shown = 0;
  for (const auto& issue : issues) {
    if (shown == kMaxPrintedIssues) break;
    out << issue.message() << "\n";
    ++shown;
  }
  if (shown < issues.size()) {
    const std::string& file = issues[shown].file;
    out << (file.empty() ? "" : file + ": ") << "... and " << issues.size() - shown << " more\n";
  }
  out.flush();
}

}  // namespace cemv::cli
