#include "cli/commands.hpp"

namespace cemv::cli {

void add_simulate_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
