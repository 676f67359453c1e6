// Each `tribo` subcommand registers itself on the top-level CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace tribo::cli {

void add_rig_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_contact_command(CLI::App& app);
void add_reynolds_command(CLI::App& app);
void add_gap_command(CLI::App& app);
void add_homogenise_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

}  // namespace tribo::cli
