// Placeholder registration; replaced by the reynolds subcommand implementation.
#include "apps/commands.h"

namespace tribo::cli {

void add_reynolds_command(CLI::App& app) { app.add_subcommand("reynolds", "(not yet available)"); }

}  // namespace tribo::cli
