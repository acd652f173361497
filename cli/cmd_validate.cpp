#include "cli/commands.hpp"

namespace cemv::cli {

void add_validate_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
