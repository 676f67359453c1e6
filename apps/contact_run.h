// `tribo contact CONFIG.toml` without the files: the config reader and the solve, shared by the CLI
// (apps/cmd_contact.cpp, which writes contact.json and the .npy fields) and the Python bindings
// (python/bind_cli_contact.cpp), so both give the same numbers from the same code.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "contact/grid.h"
#include "contact/junction_locus.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"

namespace tribo::cli {

// Everything a run needs, read and validated before any file is written.
struct ContactRun {
  std::string surface_kind;
  double sphere_radius_m = 0.0;
  contact::Grid grid;
  bool periodic = false;
  Eigen::ArrayXXd gap0_m;        // initial gap h
  std::optional<contact::SurfaceStatistics> stats;
  double e_star_Pa = 0.0;
  std::optional<double> hardness_Pa;
  double alpha = 25.0;
  double normal_load_N = 0.0, tangential_load_N = 0.0;
  double tau_i_Pa = std::numeric_limits<double>::infinity();
  contact::NormalContactOptions solver;
  int threads = 0;
  std::optional<std::uint64_t> seed;  // of a generated (Gaussian) surface
  std::vector<std::filesystem::path> input_files;  // read besides the config: the topography
  // junction subcommand
  double f_over_w_max = 0.5;
  int junction_points = 11;
  contact::JunctionLocus locus;
};

// Reads and checks `path` ([surface], [domain], [material], [load], [solver]; with `junction`,
// also [junction]). Bad input is an InputError naming file, key and reason.
ContactRun load_contact_run(const std::filesystem::path& path, bool junction);
// The same on a parsed document; `path` names it in errors and anchors relative file names.
ContactRun load_contact_run(const toml::table& doc, const std::filesystem::path& path, bool junction);

// [solver] threads caps both FFTW's threads and the OpenMP loops of the solver.
void apply_thread_count(int threads);

// The provenance block of contact.json / junction.json (after apply_thread_count, so that
// "threads" is the count the solve uses). `hash`: the config's (config_hash, or bytes_hash of a
// config held in memory).
nlohmann::json contact_provenance(const std::filesystem::path& config, const ContactRun& run, const std::string& hash);

struct ContactSolve {
  contact::NormalContactResult result;  // fields: pressure_Pa, gap_m, displacement_m, plastic_increment_m
  nlohmann::json summary;               // contact.json without "provenance"
};

// The solve `tribo contact` performs: applies run.threads, builds the half-space and solves the
// normal (elastic or elastic-plastic) or, with a tangential load, the junction-growth contact.
// Non-convergence is summary["converged"] = false, not an exception.
ContactSolve solve_contact_run(const ContactRun& run);

}  // namespace tribo::cli
