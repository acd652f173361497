#include "cli/commands.hpp"

namespace cemv::cli {

void add_csv_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
