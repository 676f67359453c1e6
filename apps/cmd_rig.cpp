#include "apps/commands.h"
namespace tribo::cli {
void add_rig_command(CLI::App& app) { app.add_subcommand("rig", "(in progress)"); }
}  // namespace tribo::cli
