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

// `--summary-only` on `tribo rig`, `contact` and `reynolds`: write the summary JSON alone, not the
// traces or fields. `tribo sweep` passes it unless the spec asks for the points' artefacts: its
// columns read only JSON, and on cheap points the trace's formatting and file creation are most of
// the point's cost.
inline CLI::Option* add_summary_only_flag(CLI::App* cmd, bool& summary_only, const char* summary_file) {
  return cmd->add_flag("--summary-only", summary_only,
                       std::string("write ") + summary_file + " only (no traces or fields), as `tribo sweep` does");
}

}  // namespace tribo::cli
