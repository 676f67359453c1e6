// From the patch to the pin: the homogenised columns integrated over the pin's face, one row per
// table separation h̄ (the film at the face centre).
//
// A ball's face is its Hertz circle at the pin's load, the film over it uniform (f = 0), its fluid
// the EHL film of ball_film.h. Otherwise:
// Nominal film over the face: h(x, y) = h̄ + f(x, y), f = 0 (flat) or r²/(2 R_c) (spherical crown),
// less θ x for a face tilted by θ (leading edge raised, x along the disc's motion). The rows put
// the face's lowest point on the cell table's separations: h̄ = s + d with d = −min f (face_drop_m),
// so no node of the face falls below the table. Per node
// the cell table gives p_s(h), A_r/A(h), φx, φy, Φs, h̄_T, the shear factors φf and φfp,
// and the rugosity lift Λ(h) = p̄/(ηU) (interpolated monotonically between nodes; above the last
// node the film is smooth: φ = 1, Φs = 0, φf = 1, Λ = 0, no contact). Then
//
//   solid     N_s = ∫ p_s(h) dA,   A_r = ∫ (A_r/A)(h) dA
//   wedge     the average Reynolds equation (Patir & Cheng 1978) on the face, rim at p = 0,
//               ∇·(φx h³/12η ∂p/∂x, φy h³/12η ∂p/∂y) = (U/2) ∂(h̄_T − σΦs)/∂x + (dh̄_T/dh) ∂h/∂t,
//             with JFO cavitation; p ∝ ηU exactly, so one solve at ηU = 1 gives N_w/(ηU).
//             An untilted flat pin has uniform coefficients: the Couette divergence vanishes and the
//             steady film carries no load — its lift is the rugosity lift of the asperity-scale
//             films; a slightly tilted one carries 3πθR⁴/(4φh̄³) per ηU (the squeeze of its slope);
//   rugosity  N_r = ηU ∫ Λ(h) dA (the cavitating cell solves; superposed on the wedge);
//   squeeze   the same equation at U = 0, ∂h/∂t = ḣ uniform, full film: N_sq = −η K ḣ; for an
//             untilted flat pin K = (3π R⁴ / 2) (dh̄_T/dh) / (φ h³) (thesis (3.2.2) with flow factors);
//   shear     on the stationary pin, τ = (ηU/h) φf − φfp (h/2) ∂p/∂x (Patir & Cheng 1979),
//             F_f = ∫ τ dA, with p from the wedge solve; at large h̄, F_f → ηU A/h̄ (Petroff).
//             The shear-induced pressure's part φfs is left out: the cells' measured φf − φfs turns
//             negative below h̄ ≈ 1.5σ (their nodal pressure gradient cannot resolve the films
//             next to contact spots), so it is kept in the tables for inspection but not used;
//             it is 1.5 (σ/h̄)² of φf at large h̄ (lubrication/flow_factors.h);
//   spots     with micro-EHL films, the contact spots' mean shear weighted by the real area over
//             the face (below), the τ_i of the law's kinetic force τ_i A_r made a function of h̄, ηU.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "homogenise/ball_film.h"
#include "homogenise/cell_table.h"
#include "homogenise/options.h"

namespace tribo::homogenise {

struct PinTable {
  double nominal_area_m2 = 0;
  std::vector<double> separation_m;
  // The ensemble's standard error integrated over the face as the values are (an upper bound where
  // it varies in sign); the solid columns integrated from half the contact grid too, and their
  // change (error_from_refinement) as the discretisation error.
  std::vector<double> solid_load_N, solid_load_standard_error_N, solid_load_coarse_N, solid_load_discretisation_error_N;
  std::vector<double> real_area_m2, real_area_standard_error_m2, real_area_coarse_m2, real_area_discretisation_error_m2;
  std::vector<double> wedge_lift_per_eta_u_m;    // N_w / (ηU)
  std::vector<double> rugosity_lift_per_eta_u_m; // N_r / (ηU)
  std::vector<double> squeeze_per_eta_m;         // K
  std::vector<double> shear_per_eta_u_m;         // F_f / (ηU)
  // With micro-EHL films: the ηU axis and the mean shear of the real contact area over the face,
  //   τ̄(h̄, ηU) = ∫ τ̄_cell(h, ηU) (A_r/A)(h) dA / ∫ (A_r/A)(h) dA   (τ_i where there is no contact),
  // with its standard error and discretisation error (half the contact grid), per node and ηU.
  std::vector<double> eta_u_Pa_m;
  std::vector<std::vector<double>> solid_shear_Pa, solid_shear_standard_error_Pa, solid_shear_discretisation_error_Pa;
  std::vector<std::vector<double>> solid_shear_coarse_Pa;  // the same from half the contact grid
  std::vector<std::vector<double>> film_share;  // the real area the films separate, weighted alike (0 without contact)
  // A ball (`shape = "ball"`): the face above is its Hertz circle, the lift and shear columns 0,
  // and its fluid is this EHL film (ball_film.h).
  std::optional<BallFilmTable> ball;
  int reynolds_unconverged = 0;
  std::string messages;
};

// d = −min f over the face (≥ 0): θR for a flat tilted face; θ²R_c/2 for a crown whose lowest point
// lies on the face (θR_c ≤ R), else θR − R²/(2R_c) at the trailing edge; 0 untilted.
double face_drop_m(const Pin& pin);

// The pin table from the cells. A ball's films are the next step, add_ball_film: the slow one, taken
// once the caller knows the table carries the load (homogenise refuses a law whose balance
// N_s(h̄) = W lies below the table, and says so before the films are solved).
PinTable pin_scale(const HomogeniseOptions& options, const CellTable& cells);
// A ball's EHL films (ball_film.h) on its pin table, the thinnest half the separation at which the
// asperities alone carry W (the rig's balance never lies below it), solved through `store`
// (finished speed nodes kept and reused). Throws std::invalid_argument unless options describe a ball.
void add_ball_film(const HomogeniseOptions& options, PinTable& pin, const BallFilmStore& store = {});

}  // namespace tribo::homogenise
