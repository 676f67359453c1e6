// One realisation of the surface pair on a periodic patch: every micro solve the homogenised law
// needs, at the table's separations (options.h).
//
//   solid   elastic-plastic BEM (homogenise/solid_contact.h) on the realisation refined to the
//           contact grid, and on half of it: N_s/L² and A_r/L² at the separations; μs,max and the
//           dry μ_b at the pin's nominal pressure on the junction's three grids (options.h);
//   fluid   Patir–Cheng cells on the rigid film h̄ + z (lubrication/flow_factors.h): φx, φy, Φs,
//           h̄_T, the shear factors φf, φf − φfs (measured) and φfp; rugosity lift p̄/(ηU) with JFO
//           cavitation.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "homogenise/options.h"

namespace tribo::homogenise {

struct PatchResult {
  std::uint64_t seed = 0;
  double first_contact_separation_m = 0;  // −min z: contact vanishes above it
  std::vector<double> separation_m;       // the nodes (options' ratios × σ)
  std::vector<double> solid_pressure_Pa;  // N_s / L², on the contact grid
  std::vector<double> area_fraction;      // A_r / L², on the contact grid (extrapolated: below)
  std::vector<double> solid_pressure_coarse_Pa, area_fraction_coarse;  // the same on half of it
  // With a quarter of the contact grid solved too (contact grid ≥ 4 × surface grid): area_fraction
  // is the first-order extrapolation from the contact grid and its half, area_fraction_coarse the
  // one from its half and quarter (solid_contact.h: extrapolate_above), so the change between them
  // is the extrapolation's discretisation error.
  bool area_extrapolated = false;
  std::vector<double> phi_x, phi_y, phi_s, film_over_sigma, phi_f, couette_shear_factor, phi_fp, contact_fraction;
  std::vector<double> lift_per_eta_u_per_m;  // p̄ / (ηU) of the cavitating cell, 1/m
  double mu_s_max = 0;                     // at the pin's nominal pressure, on the junction grid
  double mu_boundary = 0;                  // τ_i A_r / W at the same pressure and grid
  double mu_s_max_coarse = 0, mu_boundary_coarse = 0;      // the same on half the junction grid
  double mu_s_max_coarser = 0, mu_boundary_coarser = 0;    // and on a quarter of it
  // With micro-EHL films: the spots' mean shear τ̄ per table node and ηU node, on the contact grid
  // and on half of it (empty without).
  std::vector<std::vector<double>> spot_shear_Pa, spot_shear_coarse_Pa;
  std::vector<std::vector<double>> spot_film_share;  // on the contact grid
  int contact_grid = 0;                    // nodes a side of the table's solid solves
  int junction_grid = 0;                   // nodes a side of the junction's finest solves (options.h)
  int bem_iterations = 0;                  // CG iterations summed over the solid solves
  // Wall time of the stages (s): BEM load–separation and junction solves, flow- and shear-factor
  // cells, cavitating lift cells.
  double bem_s = 0, flow_cells_s = 0, lift_cells_s = 0;
  int unconverged = 0;                     // solves that did not converge (their nodes are NaN)
  std::string messages;                    // why, for each unconverged solve
};

// Runs every solve of realisation k (seed = surface.seed + k) on one thread.
PatchResult solve_patch(const HomogeniseOptions& options, int realisation);

// Cache format of a patch (the CLI keeps finished patches so a killed run resumes).
nlohmann::json to_json(const PatchResult& patch);
PatchResult patch_from_json(const nlohmann::json& j);

}  // namespace tribo::homogenise
