// The solid side of one realisation (issue 37): the elastic-plastic BEM (contact/normal_contact.h,
// cap σ0) on the realisation refined to the contact grid.
//
//   load–separation  at the table's separations h̄, approach δ = −min z − h̄ (the rigid film of the
//           fluid cells is h̄ + z, so solid and fluid columns belong to the same surfaces at the
//           same separation): nominal solid pressure p_s(h̄) = N/L² and real-area fraction A_r/L²;
//   static  the junction at slip: with the interfacial shear τ = F/A equal to τ_i the Tabor cap
//           (3.1.5) is p_cap = √(σ0² − α τ_i²), so one capped solve at the pin's nominal pressure
//           gives the slip area A_s and μs,max = τ_i A_s / W (contact/tangential.h's fixed point at
//           its slip end; fully plastic it is (3.1.23)'s 1/√(S² − α));
//   dry     μ_b = τ_i A_r / W with the cap σ0 at the same pressure (Bowden–Tabor shear of the
//           junctions while sliding);
//   films   with options.micro_ehl, each node's contact spots (contact/contact_spots.h) as EHL point
//           contacts: their mean shear τ̄(ηU) (lubrication/micro_ehl.h).
//
// At the thesis' pressure (1.3 MPa, A_r/A0 ≈ 0.16 %) a 128² patch resolves ≈ 27 contact cells and
// overstates the area by the elastic rim of every spot (μ_b 40 % high). The solves therefore run
// on the realisation Fourier-refined (contact/surface.h: the same continuous surface, sampled more
// finely) to the contact grid and to coarser and finer grids (homogenise/options.h: min_contact_grid,
// junction_grid); the area-like results are extrapolated to first order (extrapolate_above below),
// and the changes between grids are the discretisation errors. The flow and lift cells keep their
// own grid (the patch's).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

#include "homogenise/options.h"

namespace tribo::homogenise {

struct SolidContact {
  double first_contact_separation_m = 0;  // −min z: contact vanishes above it
  std::vector<double> solid_pressure_Pa;  // at options.separation_ratios × σ; NaN where unconverged
  std::vector<double> area_fraction;
  double mu_s_max = 0;     // NaN when its solve did not converge
  double mu_boundary = 0;  // NaN when its solve did not converge
  // With options.micro_ehl: the contact spots' mean shear τ̄ (lubrication/micro_ehl.h) per table node
  // and ηU node (micro_ehl_eta_u_Pa_m); τ_i where a node has no contact, NaN where its solve failed.
  std::vector<std::vector<double>> spot_shear_Pa;
  std::vector<std::vector<double>> spot_film_share;  // the spots' area the films separate (0 without contact)
  int bem_iterations = 0;  // CG iterations summed over the solves
  int unconverged = 0;
  std::string messages;    // why, for each unconverged solve
};

// The pressure fields of every solve of a SolidContact (empty where a node had no contact or its
// solve failed): kept from one grid to warm-start the next finer one.
struct SolidPressures {
  std::vector<Eigen::ArrayXXd> at_node;  // per table node
  Eigen::ArrayXXd at_slip_cap, at_hardness_cap;
};

// Every solid solve on the heights `z_m` (a periodic patch of side options.surface.size_m, any grid).
// `coarse` (optional): the pressures of the same solves on half this grid, each the start of its
// solve here (spread over the 2 × 2 fine cells of its coarse cell: the same load) — a quarter fewer
// CG iterations than starting from the neighbouring node's pressure at 2048² (measured on the
// thesis preset, 464 against 622). `keep` (optional) receives this grid's pressures.
SolidContact solid_contact(const HomogeniseOptions& options, const Eigen::ArrayXXd& z_m, const SolidPressures* coarse = nullptr,
                           SolidPressures* keep = nullptr);

// The junction alone on the heights `z_m`: the two capped solves at the pin's nominal pressure of
// solid_contact (μs,max, μ_b, their iterations and failures); the table columns stay empty.
// `coarse` / `keep`: the junction's fields (at_slip_cap, at_hardness_cap) as in solid_contact.
SolidContact junction_contact(const HomogeniseOptions& options, const Eigen::ArrayXXd& z_m, const SolidPressures* coarse = nullptr,
                              SolidPressures* keep = nullptr);

// The discretisation error of a quantity solved at spacing Δ (value `coarse`) and Δ/2 (`fine`),
// converging as Δ^p: the error of the fine value is |fine − coarse| / (2^p − 1) (Richardson).
// The table's columns use p = 1: a BEM's contact area converges at first order at best (the
// perimeter's cells are half in, half out) and irregularly (observed orders 0.2 – 3.7 between
// successive grids), so the estimate is the change itself, the error's size rather than its digits.
inline double error_from_refinement(double coarse, double fine, double order = 1.0) {
  return std::abs(fine - coarse) / (std::pow(2.0, order) - 1.0);
}

// The first-order Richardson extrapolation 2 fine − coarse of a quantity whose leading error is
// proportional to Δ (value `coarse` at Δ, `fine` at Δ/2): what the junction reports (cell_table.h).
// The excess contact area of a BEM is its perimeter's cells, perimeter × O(Δ) (Yastrebov, Anciaux &
// Molinari 2017, arXiv:1701.02727); on the thesis preset's surfaces 2 A(Δ/2) − A(Δ) from 1024²
// and 2048² lies within 0.6 % of the same from 2048² and 4096², where A itself is 1.5 – 3 % high
// (tests/homogenise/solid_contact_slow_test.cpp).
inline double extrapolate_first_order(double coarse, double fine) { return 2.0 * fine - coarse; }

// The same, kept at or above `bound`: the fully plastic value (A ≥ W/p_cap, since Σ p = W with p ≤
// p_cap on every grid and in the continuum), which the extrapolation could otherwise cross where
// the approach is irregular (0.2 % under it for μs,max on one of six seeds from 1024² and 2048²).
inline double extrapolate_above(double coarse, double fine, double bound) {
  const double e = extrapolate_first_order(coarse, fine);
  return e < bound ? bound : e;  // NaN stays NaN
}

}  // namespace tribo::homogenise
