// Placeholder registration; replaced by the gap subcommand implementation.
#include "apps/commands.h"

namespace tribo::cli {

void add_gap_command(CLI::App& app) { app.add_subcommand("gap", "(not yet available)"); }

}  // namespace tribo::cli
