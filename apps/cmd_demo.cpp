#include "apps/commands.h"
namespace tribo::cli {
void add_demo_command(CLI::App& app) { app.add_subcommand("demo", "(in progress)"); }
}  // namespace tribo::cli
