#include "cli/commands.hpp"

namespace cemv::cli {

void add_smt_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
