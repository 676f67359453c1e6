// Each `tribo` subcommand registers itself on the top-level CLI11 app.
#pragma once

#include <CLI/CLI.hpp>
#include "apps/output.h"
#include <toml++/toml.h>

#include <exception>
#include <filesystem>
#include <functional>
#include <string>

namespace tribo::cli {

void add_rig_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_contact_command(CLI::App& app);
void add_reynolds_command(CLI::App& app);
void add_ehl_command(CLI::App& app);
void add_gap_command(CLI::App& app);
void add_gap_generate_command(CLI::App& gap);  // `tribo gap generate` (cmd_gap_generate.cpp)
void add_homogenise_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

// `tribo ARGS...` in this process (apps/tribo.cpp): parses argv[1..] and runs the subcommand;
// returns the exit status (0 success, 1 run failure, 2 bad input). `tribo sweep` runs its points
// through it in forked children.
int run_command_line(int argc, char** argv);

// What `tribo` does with a command's exception: prints it to stderr ("tribo: error: …" for bad
// input, "tribo: failed: …" for a run failure) and returns the exit status (2 or 1).
int report_failure(std::exception_ptr failure);

// `--summary-only` on `tribo rig`, `contact` and `reynolds`: write the summary JSON alone, not the
// traces or fields. `tribo sweep` passes it unless the spec asks for the points' artefacts: its
// columns read only JSON, and on cheap points the trace's formatting and file creation are most of
// the point's cost.
inline CLI::Option* add_summary_only_flag(CLI::App* cmd, bool& summary_only, const char* summary_file) {
  return cmd->add_flag("--summary-only", summary_only,
                       std::string("write ") + summary_file + " only (no traces or fields), as `tribo sweep` does");
}

// Where a command's JSON result goes: into a file of its --out folder (the CLI), or back to a sweep
// in memory (apps/sweep_point.h). `name` is the file's name, e.g. "summary.json".
using JsonSink = std::function<void(const std::string& name, const std::string& text)>;

// The CLI's sink: each JSON into `dir / name`, atomically.
inline JsonSink folder_sink(const std::filesystem::path& dir) {
  return [dir](const std::string& name, const std::string& text) { write_file_atomically(dir / name, text); };
}

// `tribo rig|contact|reynolds CONFIG --out OUT --summary-only` on a config already in memory (a
// sweep's point): `path` names the config in errors and provenance and anchors its relative file
// names, `hash` is its text's bytes_hash; the JSON goes to `sink` and nothing is written. stdout and
// the errors thrown are the command's.
void run_rig_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                     const std::string& out, const JsonSink& sink);
void run_contact_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                         const std::string& out, const JsonSink& sink);
void run_reynolds_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                          const std::string& out, const JsonSink& sink);

}  // namespace tribo::cli
