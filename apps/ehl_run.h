// `tribo ehl CONFIG.toml` without the files: the config reader and the solve (film and traction),
// shared by the CLI (apps/cmd_ehl.cpp writes ehl.json and the profiles) and any other front end.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include "lubrication/ehl_line.h"
#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "lubrication/mixed_line.h"
#include "lubrication/mixed_point.h"
#include "lubrication/piezoviscous.h"

namespace tribo::cli {

// Everything a `tribo ehl` run needs, read and validated before any file is written.
struct EhlRun {
  lubrication::EhlLineContact contact;   // geometry = "line"
  // geometry = "point": a ball on a flat (ehl_point.h); `contact` then unused.
  std::optional<lubrication::EhlPointContact> point;
  lubrication::EhlPointOptions point_options;
  // [solver] domain = "fitted": a point contact's extents from the expected film (fit_domain_to_film),
  // a line contact's inlet moved out until its smooth film no longer feels it (fit_inlet_to_film;
  // with [roughness] too, not with [profile]).
  bool fitted_domain = false;
  double sliding_speed_m_per_s = 0.0;  // u1 − u2 (the traction's; the film depends on u_m only)
  lubrication::PiezoviscousLubricant lubricant;
  double eyring_stress_Pa = 0.0;       // τ0; +inf for a Newtonian film
  lubrication::LimitingShear limiting_shear;  // τ_L0 + Λ p; off unless [lubricant] gives either
  lubrication::FilmHeating heating;    // off unless [lubricant] thermal_conductivity_W_per_m_K is given
  lubrication::EhlLineOptions options;
  // With [roughness]: the rough contact's mixed regime by load sharing (mixed_line.h, mixed_point.h) — the summits,
  // their offset y_s and the boundary friction; the film and traction are then the film's share.
  struct Roughness {
    contact::GreenwoodWilliamson summits;  // e_star_Pa = E'/2
    double summit_height_m = 0.0;
    double boundary_friction_coefficient = 0.0;
  };
  std::optional<Roughness> roughness;
  // With [profile]: a wavy stationary surface and its asperity contact, solved node by node (ehl_line.h,
  // ehl_point.h — ridges across the track; Hu & Zhu's unified model); the contact nodes shear at the
  // boundary friction, the others as the film.
  // The profile is a waviness a cos(2π x/λ) or a measured trace (`file`): levelled, Gaussian-filtered
  // at `cutoff_m` (contact/profile.h) and placed with its point `centre_m` at the Hertz centre.
  struct Profile {
    lubrication::EhlRoughness surface;  // the samples the solver interpolates
    double amplitude_m = 0.0, wavelength_m = 0.0;
    double boundary_friction_coefficient = 0.0;
    std::filesystem::path file;     // empty for a waviness
    Eigen::ArrayXd levelled_m;      // the measured trace, levelled
    double spacing_m = 0.0;         // its sample spacing
    // As given, else unset; once loaded, the values used (the domain mid-trace, 8 node spacings).
    std::optional<double> centre_m, cutoff_m;
    double rq_m = 0.0, filtered_rq_m = 0.0;  // Rq over the solver's domain: as measured (levelled), as solved
    // A waviness or a trace; without either, [profile] holds only the boundary layers and the
    // contacts' friction for a [surface] map.
    bool has_ridges() const { return !file.empty() || wavelength_m > 0.0; }
  };
  std::optional<Profile> profile;
  // With [surface] (a point contact, beside [profile], whose ridges then are optional): a height map,
  // generated (kind = "gaussian", the reader of `tribo contact`) or measured (kind = "file"),
  // levelled, filtered at `cutoff_m` by the areal Gaussian filter (contact/profile.h) and placed with
  // its point (centre_x_m, centre_y_m) at the Hertz centre; it becomes profile->surface.map.
  struct SurfaceMap {
    std::string kind;               // "gaussian" | "file"
    std::filesystem::path file;     // kind = "file"
    std::uint64_t seed = 0;         // kind = "gaussian"
    Eigen::ArrayXXd levelled_m;     // rows along x (the entrainment direction), columns along y
    double dx_m = 0.0, dy_m = 0.0;  // its sample spacings
    // As given, else unset; once loaded, the values used (the map's middle, 8 node spacings).
    std::optional<double> centre_x_m, centre_y_m, cutoff_m;
    double rq_m = 0.0, filtered_rq_m = 0.0;  // Rq over the solver's domain: as measured (levelled), as solved
  };
  std::optional<SurfaceMap> surface_map;
  std::vector<std::filesystem::path> input_files;  // files the config names (a measured profile)
};

// Reads and checks `path`: [contact] (geometry = "line" with load_per_length_N_per_m, or "point"
// with load_N; radius, modulus, entrainment, and the sliding speed or the slide-to-roll ratio), [lubricant] (η0, α, law, compressible,
// eyring_stress_Pa, the limiting shear, the film's heating), optionally [roughness] (summit density, radius, standard
// deviation and mean height, boundary friction coefficient) or [profile] (a waviness's amplitude and
// wavelength or a measured trace's file, the boundary layers' thickness and contact margin, boundary
// friction coefficient) and, for a point, [surface] (a generated or measured height map), and
// [solver] (docs/lubrication.md).
// Bad input is an InputError naming file, key and reason.
EhlRun load_ehl_run(const std::filesystem::path& path);
EhlRun load_ehl_run(const toml::table& doc, const std::filesystem::path& path);

struct EhlSolve {
  lubrication::EhlLineResult film;    // with roughness: the film's share of the load
  lubrication::EhlTraction traction;  // the film's traction
  std::optional<lubrication::EhlPointResult> point_film;  // geometry = "point" (film, traction above unused)
  lubrication::EhlPointTraction point_traction;           // with roughness: the film's share's
  std::optional<lubrication::MixedPointResult> mixed_point;  // geometry = "point" with roughness
  std::optional<lubrication::MixedLineResult> mixed;  // with roughness
  bool converged = false;
  lubrication::EhlLineOptions line_options;  // the line solve's (the run's, or its fitted inlet's)
  nlohmann::json summary;  // ehl.json without "provenance" and "fields"
};

// The solve `tribo ehl` performs. Non-convergence is summary["converged"] = false, not an exception.
EhlSolve solve_ehl_run(const EhlRun& run);

}  // namespace tribo::cli
