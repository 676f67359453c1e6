// Placeholder registration; replaced by the contact subcommand implementation.
#include "apps/commands.h"

namespace tribo::cli {

void add_contact_command(CLI::App& app) { app.add_subcommand("contact", "(not yet available)"); }

}  // namespace tribo::cli
