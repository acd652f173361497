#include "cli/commands.hpp"

namespace cemv::cli {

void add_model_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
