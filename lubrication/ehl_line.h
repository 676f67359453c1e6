// Elastohydrodynamic line contact: a cylinder of reduced radius R on a plane (or two cylinders),
// load w per unit length, entrained at the mean surface speed u_m = (u1 + u2)/2, steady,
// isothermal; smooth, or with a rough or wavy profile on the stationary surface (below).
//
// Equations (Dowson & Higginson 1966; the dimensionless form of Venner & Lubrecht 2000, ch. 8):
//   Reynolds   d/dx(ρ h³/(12 η) dp/dx) = u_m d(ρ h)/dx,   p ≥ 0 with p = dp/dx = 0 at the exit
//              (Swift–Stieber cavitation: p (complementary) the Reynolds residual)
//   film       h(x) = h0 + x²/(2R) − (4/(π E')) ∫ p(s) ln|x − s| ds
//              (plane-strain half-space, E' = 2 / [(1−ν1²)/E1 + (1−ν2²)/E2] = 2 E*)
//   load       ∫ p dx = w
//   fluid      η(p), ρ(p) of piezoviscous.h.
// Scaled by the dry Hertz contact: b = √(8 w R/(π E')), p_H = √(w E'/(2π R)), X = x/b, P = p/p_H,
// H = h R/b², the film is H = H0 + X²/2 − (1/π) ∫ P ln|X − S| dS, the load ∫ P dX = π/2, and
// Reynolds d/dX(ε dP/dX) = d(ρ̄H)/dX with ε = ρ̄ H³/(η̄ λ), λ = 12 η0 u_m R²/(b³ p_H).
//
// Discretisation: N nodes on [X_in, X_out], P = 0 at both ends; the Poiseuille term by central
// differences with ε at the half nodes (the mean of its neighbours; with roughness, below), the wedge term by second-order
// upwind differences (first order at the first interior node), the deformation with P constant on
// each node's cell (the exact integral of ln|t| over the cell). Second order in ΔX where the
// solution is smooth — observed in the tests.
//
// Method: Newton's method on the coupled system (pressures and H0 together, the dense Jacobian of
// the elastic integral included — the approach of Okamura 1982 and Hamrock & Jacobson 1984, robust
// where the film is stiff, i.e. at high loads where relaxation schemes stall). The cavitation
// complementarity P ≥ 0, R ≤ 0, P R = 0 is an NCP equation φ(P, −c R) = 0 (complementarity.h), each
// Reynolds row scaled by c = 1/|∂R/∂P| on its diagonal so that it reads as a pressure. Each step is
// limited so that no film changes by more than half of itself (with roughness: a closing film may fall
// to H_c/2, a film near H_c open by 2 H_c, ehl_newton.h), and a backtracking line search asks
// for a decrease of ‖F‖₂ (pressures are not clipped at zero: φ keeps them there at convergence, and
// clipping a step breaks the line search's descent). Where Newton does not converge
// from the start (a semi-ellipse of the load's area, the central film of Martin or Pan–Hamrock), it
// is continued in λ: from a thinner, more Hertzian film (λ lowered by decades) back to the target.
// Grids of 801 nodes and more start from the answer on a grid about half as fine, interpolated
// (nested iteration, down to the first grid below 801 nodes, which starts as above); where that
// start fails, the analytical one. Cost: O(N²) per residual and Jacobian, O(N³) per step (N = 401:
// ≈ 0.05 s).
//
// Mixed lubrication (solve_ehl_line with an EhlRoughness): the stationary surface carries a profile r(x)
// (transverse ridges, uniform along the line; stationary, so that the problem stays steady — a rough
// pin on a moving disc), the film is h − r, and where it closes the surfaces touch: the unified
// treatment of Hu & Zhu (ASME J. Tribol. 122, 2000) — one pressure field, the Reynolds equation
// everywhere, the pressure flow through the part of the film above the boundary layers
// (ε = ρ (H − H_c)₊³/(η̄λ), H_c = contact_film_m), so that where the film has closed to H_c only the
// surfaces' transport is left (Hu & Zhu's reduced equation, d(ρH)/dX = 0) and the pressure there is
// the contact's, whatever holds the surfaces together. ε at a half node is then the mean of ρ̄/(η̄λ)
// times the harmonic mean of (H − H_c)₊³, so that no flow passes a face once either side has closed
// (ehl_roughness.h: face_flow), and the wedge term takes the upwind faces' mass with a limited slope
// (limited_mass_face: second order where the film is smooth, first-order upwind where it closes — the
// unlimited second-order upwind extrapolates a converging inlet through zero at a contact's edge;
// until 2026-12-02 it was first order throughout: a film near the layers 13 % thick on 801 nodes
// against 5 % now, which moved the Stribeck transition with the grid); Newton's steps may close a film to H_c/2 in one
// step, and the continuation in λ also runs from a thicker film (ehl_newton.h). The film settles onto
// the layers only asymptotically; a node whose film lies within EhlRoughness::contact_margin_m of them
// is in contact (EhlLineResult::contact_nodes) — its film, what the transport leaves (≈ 4.5–6 nm in
// the tests), is a number the model does not resolve; it resolves the pressure.
// With a hardness (EhlRoughness::hardness_Pa) the surface yields as the point contact's does
// (ehl_point.h: an unknown is the pressure up to the cap and the plastic flow beyond it — so a film
// no longer has to close through zero under a capped pressure, which stalled Newton when the cap
// was a bound on P alone): crawling at 0.8 p_H on 401 nodes the plane-strain elastic–perfectly-
// plastic cylinder of contact/reference/capped_cylinder.h to 0.20 % of p_H, 4.5 s
// (ehl_line_mixed_test.cpp).
#pragma once

#include <string>
#include <vector>

#include "lubrication/complementarity.h"
#include "lubrication/ehl_roughness.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct EhlLineContact {
  double load_per_length_N_per_m = 0.0;  // w > 0
  double reduced_radius_m = 0.0;         // R = 1/(1/R1 + 1/R2) > 0
  double reduced_modulus_Pa = 0.0;       // E' = 2 E* > 0
  double mean_speed_m_per_s = 0.0;       // u_m = (u1 + u2)/2 > 0 (entrainment)
};

struct EhlLineOptions {
  double inlet_over_half_width = -4.5;  // X_in = x_in / b (the inlet must not starve the film)
  double outlet_over_half_width = 1.5;  // X_out = x_out / b (past the cavitation front)
  int nodes = 401;                      // N ≥ 11
  // Grids of 801 nodes and more start from the answer on a grid about half as fine, solved the same
  // way (recursively) — with a hardness, its capped answer, so that the cap is lowered on the coarsest
  // grid alone (ehl_line.cpp: solve_nested). Off: the analytical start, the cap lowered on this grid.
  bool start_from_coarser_grid = true;
  // Converged when the scaled residual ‖F‖∞ ≤ tolerance, F = (φ(P, −c R_Reynolds) in units of p_H,
  // load balance ΔX ΣP − π/2), and the pressures' error left is at most 10·tolerance·max(1, max P)
  // (the last step, or after a full step that step times the contraction: ehl_newton.h).
  double tolerance = 1e-10;
  int max_newton_iterations = 30;  // per solve (the direct one and each continuation step)
  int max_continuation_steps = 24;  // solves in the continuation (decades down, then steps up)
  // The NCP function of the cavitation (complementarity.h). The minimum function: quadratic Newton
  // steps to the end (examples/ehl-line.toml: 25 steps against Fischer–Burmeister's 149, W = 1e-5:
  // 7 against 388 through the continuation; every test's contact faster, the films equal to 1e-13).
  Complementarity complementarity = Complementarity::minimum;
};

struct EhlLineResult {
  std::vector<double> x_m, pressure_Pa, film_m;
  double central_film_m = 0.0;   // at x = 0 (the Hertz centre)
  double minimum_film_m = 0.0;   // smallest nodal film
  double max_pressure_Pa = 0.0;
  double hertz_half_width_m = 0.0, hertz_pressure_Pa = 0.0;
  double load_balance_error = 0.0;  // (∫p dx − w)/w
  // With roughness: the nodes where the surfaces touch (film below contact_film_m + contact_margin_m;
  // in_contact by node, empty without), their count and the share of the load they carry (0 without).
  std::vector<bool> in_contact;
  int contact_nodes = 0;
  double contact_load_share = 0.0;
  // The nodes whose pressure is at the hardness (EhlRoughness::hardness_Pa: their surface yielded) and
  // the share of the load they carry.
  int plastic_nodes = 0;
  double plastic_load_share = 0.0;
  bool converged = false;
  int iterations = 0;             // Newton iterations, continuation steps included
  int continuation_steps = 0;
  double residual = 0.0;          // ‖F‖∞ at return
  std::string message;
};

// The smooth contact's inlet moved out until the film no longer feels it: solved on `given`, then on
// inlets 1.5 times as far from the contact's edge (X = −1) each time, the node spacing kept (the nodes
// grow with the domain), until two converged solves in a row give central films within
// `film_tolerance` (relative) of each other; the shorter of the two is kept. A thick film — a fast
// or viscous contact — is starved by the default inlet at −4.5 b (u_m = 20 m/s on the rollers of
// docs/lubrication.md: not converged there, 3.00 µm at −8 b, 3.03 µm at −12 b), and its solve may
// not converge at all; a thin one keeps `given`. The rule bounds the change between successive
// inlets, not the distance to the flooded film: a light load's film, hung on a long, nearly rigid
// inlet, converges slowly and can be short by more (docs/lubrication.md, Crook's rollers). Stops unsettled — `given` and its solve returned,
// settled false, the message says why — past max_inlet_over_half_width or 20001 nodes, or after two
// solves in a row that do not converge (not the inlet's doing: a film collapsing on too coarse a
// grid, and longer domains would only cost more). Throws std::invalid_argument as solve_ehl_line
// does, and for a tolerance ≤ 0 or a limit not beyond given's inlet.
struct FittedLineInlet {
  EhlLineOptions options;  // given's, with the inlet (and nodes) found
  EhlLineResult result;    // the contact solved on them
  int solves = 0;
  bool settled = false;
  std::string message;
};
FittedLineInlet fit_inlet_to_film(const EhlLineContact& contact, const PiezoviscousLubricant& lubricant, const EhlLineOptions& given,
                                  double film_tolerance = 5e-3, double max_inlet_over_half_width = -100.0);

// Throws std::invalid_argument for bad input (non-positive or non-finite contact data, a domain
// that does not start before X = −1 and end after X = 0, fewer than 11 nodes); never throws for non-convergence (see
// `converged` and `message`).
EhlLineResult solve_ehl_line(const EhlLineContact& contact, const PiezoviscousLubricant& lubricant,
                             const EhlLineOptions& options = {});
// The same contact with a rough or wavy stationary surface, where films may close (header: mixed
// lubrication); also throws std::invalid_argument for a bad profile.
EhlLineResult solve_ehl_line(const EhlLineContact& contact, const EhlRoughness& roughness,
                             const PiezoviscousLubricant& lubricant, const EhlLineOptions& options = {});

}  // namespace tribo::lubrication
