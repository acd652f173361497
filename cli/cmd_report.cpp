#include "cli/commands.hpp"

namespace cemv::cli {

void add_report_commands(CLI::App&, Context&) {}

}  // namespace cemv::cli
