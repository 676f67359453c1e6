// One realisation of the surface pair on a periodic patch: every micro solve the homogenised law
// needs, at the table's separations (options.h).
//
//   solid   elastic-plastic BEM (contact/normal_contact.h, cap σ0) at approach δ = −min z − h̄:
//           nominal solid pressure p_s(h̄) = N/L² and real-area fraction A_r/L²;
//   fluid   Patir–Cheng cells on the rigid film h̄ + z (lubrication/flow_factors.h): φx, φy, Φs,
//           h̄_T, the shear factors φf, φf − φfs (measured) and φfp; rugosity lift p̄/(ηU) with JFO
//           cavitation;
//   static  the junction at slip: with the interfacial shear τ = F/A equal to τ_i the Tabor cap
//           (3.1.5) is p_cap = √(σ0² − α τ_i²), so one capped solve at the pin's nominal pressure
//           gives the slip area A_s and μs,max = τ_i A_s / W (contact/tangential.h's fixed point at
//           its slip end; fully plastic it is (3.1.23)'s 1/√(S² − α));
//   dry     μ_b = τ_i A_r / W with the cap σ0 at the same pressure (Bowden–Tabor shear of the
//           junctions while sliding).
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
  std::vector<double> solid_pressure_Pa;  // N_s / L²
  std::vector<double> area_fraction;      // A_r / L²
  std::vector<double> phi_x, phi_y, phi_s, film_over_sigma, phi_f, couette_shear_factor, phi_fp, contact_fraction;
  std::vector<double> lift_per_eta_u_per_m;  // p̄ / (ηU) of the cavitating cell, 1/m
  double mu_s_max = 0;                     // at the pin's nominal pressure
  double mu_boundary = 0;                  // τ_i A_r / W at the same pressure
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
