// The mutation report of `cemv testgen --mutation-report` (docs/testgen.md,
// "Mutation adequacy") is built separately; until it is, the flag says so.
#include <iostream>

#include "cli/commands.hpp"

namespace cemv::cli {

int mutation_report(const model::Matrix&, const testgen::TestSuite&, const std::string&) {
  std::cerr << "error: testgen: --mutation-report is not built into this cemv\n";
  return 2;
}

}  // namespace cemv::cli
