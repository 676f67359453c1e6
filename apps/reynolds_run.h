// `tribo reynolds CONFIG.toml` without the files: the config readers and the solve, shared by the
// CLI (apps/cmd_reynolds.cpp, which writes reynolds.json and the .npy fields) and the Python
// bindings (python/bind_cli_reynolds.cpp), so both give the same numbers from the same code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "lubrication/flow_factors.h"
#include "lubrication/reynolds.h"

namespace tribo::cli {

// Everything a `tribo reynolds` run needs, read and validated before any file is written.
struct ReynoldsRun {
  std::string kind;
  lubrication::ReynoldsProblem problem;
  lubrication::ReynoldsOptions options;
  nlohmann::json geometry;
  std::optional<double> reference_load_N;  // Appendix III for parallel discs
  std::optional<std::uint64_t> seed;       // of a rough pair's lower surface (the upper's is seed + 1)
  std::vector<std::filesystem::path> input_files;  // read besides the config: a gap file
};

// Reads and checks `path` ([geometry] parallel_discs | gap_file | rough_pair, [lubricant], [motion],
// [grid], [solver]; docs/lubrication.md). Bad input is an InputError naming file, key and reason.
ReynoldsRun load_reynolds_run(const std::filesystem::path& path);
// The same on a parsed document; `path` names it in errors and anchors relative file names.
ReynoldsRun load_reynolds_run(const toml::table& doc, const std::filesystem::path& path);

struct ReynoldsSolve {
  lubrication::ReynoldsSolution solution;
  nlohmann::json summary;  // reynolds.json without "provenance" and "fields"
};

// The solve `tribo reynolds` performs. Non-convergence is summary["converged"] = false, not an exception.
ReynoldsSolve solve_reynolds_run(const ReynoldsRun& run);

// `tribo reynolds flow-factors CONFIG.toml`: [surface] and [domain] (apps/surface_config.h),
// [homogenisation], [lubricant], [motion].
struct FlowFactorRun {
  lubrication::HomogenisationOptions options;
  double lift_contact_gap_fraction = 0.1;
};

FlowFactorRun load_flow_factor_run(const std::filesystem::path& path);

}  // namespace tribo::cli
