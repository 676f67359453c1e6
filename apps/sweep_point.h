// A sweep point's step as a worker runs it (apps/sweep_workers.h, the Task). Two kinds:
//  - a `tribo` command line on the point's config.toml, its outputs and log.txt in the point's
//    folder: chains, homogenise, and every point of a sweep with `artefacts = true`;
//  - a rig, contact or reynolds point without artefacts: the command on its config held in
//    memory, as `--summary-only` would run it, and the JSON the columns read sent back to the
//    sweep — no folder, no file. A cheap rig point is then pure computation: creating a folder
//    and three files per point made two cores contend in the file system (bench/README.md).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tribo::cli {

// Whether a point of COMMAND can run in memory: the commands with `--summary-only`.
bool runs_in_memory(const std::string& command);

// A step: `tribo ARGS…` (ARGS[0] is argv[0]).
std::vector<std::string> command_line_step(const std::vector<std::string>& args);

// A step: COMMAND on `config_text` as `tribo COMMAND PATH --out OUT --summary-only` would run it were
// PATH a file holding that text — PATH names the config in errors and provenance and anchors its
// relative file names — but nothing is read or written.
std::vector<std::string> in_memory_step(const std::string& command, const std::string& config_text,
                                        const std::filesystem::path& path, const std::string& out);

// Runs a step; returns its exit status (0, 1 failed, 2 bad input) with the error on stderr as
// `tribo` prints it. An in-memory step's JSON goes into `answer`: file name, text, name, text, ….
int run_step(std::vector<std::string>& message, std::vector<std::string>& answer);

}  // namespace tribo::cli
