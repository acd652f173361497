// How the CLI prints a load error: one compiler-style line per issue
// (`FILE:LINE:COL: error: message`, formats::LoadIssue::message), at most
// kMaxPrintedIssues of them, then "... and N more".
#pragma once

#include <cstddef>
#include <ostream>

#include "formats/diagnostics.hpp"

namespace cemv::cli {

inline constexpr std::size_t kMaxPrintedIssues = 20;

void print_load_error(const formats::LoadError& e, std::ostream& out);

}  // namespace cemv::cli
