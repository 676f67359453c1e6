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

// `tribo ARGS...` in this process (apps/tribo.cpp): parses argv[1..] and runs the subcommand;
// returns the exit status (0 success, 1 run failure, 2 bad input). `tribo sweep` runs its points
// through it in forked children.
int run_command_line(int argc, char** argv);

}  // namespace tribo::cli
