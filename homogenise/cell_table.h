// The patch results of all realisations, averaged: each column's mean and its standard error
// s/√n over the realisations (lubrication::Estimate), node by node.
#pragma once

#include <vector>

#include "homogenise/patch.h"
#include "lubrication/flow_factors.h"

namespace tribo::homogenise {

using lubrication::Estimate;

struct CellTable {
  double sigma_m = 0;
  std::vector<double> separation_m;
  std::vector<Estimate> solid_pressure_Pa, area_fraction;              // on the contact grid
  std::vector<Estimate> solid_pressure_coarse_Pa, area_fraction_coarse;  // on half of it
  std::vector<Estimate> phi_x, phi_y, phi_s, film_over_sigma, phi_f, couette_shear_factor, phi_fp, contact_fraction;
  std::vector<Estimate> lift_per_eta_u_per_m;
  // With micro-EHL films: the spots' mean shear τ̄ per node and ηU node (options' micro_ehl_eta_u_Pa_m),
  // on the contact grid and on half of it; empty without.
  std::vector<std::vector<Estimate>> spot_shear_Pa, spot_shear_coarse_Pa, spot_film_share;
  // μs,max and μ_b at the pin's nominal pressure: the first-order extrapolation 2 μ(Δ) − μ(2Δ) from
  // the junction grid (spacing Δ) and its half, mean and standard error over the realisations; its
  // discretisation error, the realisations' mean change of their extrapolation from one grid
  // coarser (the half and the quarter: error_from_refinement with p = 1); and the junction grid's
  // own values.
  Estimate mu_s_max, mu_boundary;
  double mu_s_max_discretisation_error = 0, mu_boundary_discretisation_error = 0;
  Estimate mu_s_max_on_junction_grid, mu_boundary_on_junction_grid;
  int contact_grid = 0, junction_grid = 0;  // nodes a side
  double first_contact_separation_m = 0;  // the largest over the realisations
  int realisations = 0;
  int unconverged = 0;                    // solves left out (NaN) over all realisations
  // Separations where some column converged in no realisation: left out of the table (the pin
  // scale and the rig interpolate over finite nodes only).
  std::vector<double> dropped_separation_m;
};

// A column's discretisation error node by node: error_from_refinement of its mean on half the
// contact grid against its mean on it.
std::vector<double> discretisation_error(const std::vector<Estimate>& fine, const std::vector<Estimate>& coarse);

// Throws std::invalid_argument when the patches do not share their nodes or none is given, or when
// fewer than two nodes keep a finite value in every column.
CellTable aggregate(const HomogeniseOptions& options, const std::vector<PatchResult>& patches);

}  // namespace tribo::homogenise
