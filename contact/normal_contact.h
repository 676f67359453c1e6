// Frictionless normal contact of a rigid rough profile and an elastic(-plastic) half-space by
// constrained conjugate gradients (after Polonsky & Keer, Wear 231 (1999) 206), with the pressure
// cap of the saturated plasticity model (Sainsot & Lubrecht 2011; Almqvist et al. 2007).
//
// Unknown: pressure p_i ≥ 0 on the cells of a Grid. Initial gap (profile) h_i ≥ 0, rigid approach δ,
// elastic displacement u = G p (contact/halfspace.h). The gap and the conditions are
//   g_i = h_i + u_i − δ,
//   free cells       0 < p_i < p_cap :  g_i = 0
//   out of contact       p_i = 0     :  g_i ≥ 0
//   plastic cells        p_i = p_cap :  g_i ≤ 0   (−g_i is the new plastic displacement)
// and, for load control, Σ p_i ΔA = W (δ is then the Lagrange multiplier of the load, computed as
// the mean of h + u over the free cells). Elastic contact is the case p_cap = ∞. Surface
// plasticity with p_cap = σ0 ≈ 3Y is the thesis' fully plastic junction pressure (3.1.9) at F = 0.
//
// The iteration takes one half-space product each and keeps u = G p exact (no re-synchronisation;
// in double, see "Mixed precision" below for the products far from the tolerance):
// from a feasible p (0 ≤ p ≤ p_cap, Σ p ΔA = W) with v = h + u,
//   t = g − β s on the free cells, β = Σ_F g w / Σ_F s w   (G-conjugate to the last step s, w = G s:
//                                                          Daniel's formula, robust to projected steps)
//   y = p − τ t (free), p − τ g (open and plastic: Polonsky & Keer's recovery of cells that overlap
//       or open), projected onto the feasible set: s = clamp(y − c, 0, p_cap) − p, c the load shift
//   w = G s (the product), α = min(−Σ g s / Σ s w, α_max): the exact minimum of the energy
//       ½ p·G p + h·p along s within the box, p += α s, v += α w
//   τ ← τ · clamp(α*, 1/4, 4), α* = −Σ g s / Σ s w: the next trial length, the best multiple of this one.
// Where nothing is clamped the step is CG's own (α τ = Σ g t / Σ t G t). Polonsky & Keer take the
// product of the direction t and then clamp, which moves p off the step and so needs a second
// product u = G p (or an error carried in u) whenever a cell changes set; here the product is of
// the step actually taken. Each iteration also makes three passes over the grid (direction and
// trial; the step; the update with the sums of the next direction): vectorised loops that select
// on the scattered sets instead of branching, compiled for AVX-512, AVX2 and baseline x86-64 (the
// CPU picks one at load time; they agree to round-off). On a periodic grid the step and update
// passes run inside the product, line by line (ElasticHalfSpace::displacement_by_rows): a line of
// the step is transformed while it is in cache, and a line of w used as it comes back, so neither
// grid makes an extra trip through memory for the transform.
//
// Mixed precision (periodic grids): far from the tolerance the products are taken in single
// precision (NormalContactOptions::single_precision_above). Their round-off, about 1e-7 of w, adds
// up in v over the iterations, so at that residual u = G p is taken again in double — one product
// more — and the solve goes on in double: the returned state is that of double products, its
// residual that of the tolerance. A CG whose products are inexact keeps its rate while their error
// stays below the residual (Simoncini & Szyld, SIAM J. Sci. Comput. 25 (2003) 454; van den
// Eshof & Sleijpen 2004); the elastic 1024² bench solve takes 109 iterations either way, 78 of them
// single (bench/README.md).
//
// Plastic displacement is kept by the caller: after a solve, profile + plastic_increment_m is the
// flattened profile; unloading and reloading from it are elastic up to the previous peak load.
#pragma once

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

#include "contact/halfspace.h"

namespace tribo::contact {

struct NormalContactOptions {
  // Stop when the complementarity residual, relative to the elastic displacement,
  //   ε = ‖r‖₂ / ‖u − ū‖₂ ≤ tolerance,   r_i = g_i (free), min(g_i, 0) (p_i = 0), max(g_i, 0) (p_i = p_cap),
  // i.e. the rms gap error of the contact conditions above measured against the rms elastic
  // deflection (a scale the problem sets, so the tolerance is dimensionless).
  double tolerance = 1e-8;
  // 0 → 1000 + 4 max(nx, ny); CG needs O(√condition) ~ O(√n) iterations, plus set changes.
  int max_iterations = 0;
  // Local pressure cap p_cap (Pa): the hardness σ0 for surface plasticity; ∞ for elastic contact.
  double pressure_cap_Pa = std::numeric_limits<double>::infinity();
  // Products in single precision while ε > single_precision_above, then u = G p again in double
  // and double to the tolerance (see above); ≤ tolerance (e.g. 0): double throughout. Periodic
  // half-spaces only (a padded one is always double). 1e-6 is where the single products' round-off,
  // added up over the iterations before it, is still a tenth of the residual or less.
  double single_precision_above = 1e-6;
  // False: the result carries pressure_Pa and the scalars only — gap_m, displacement_m and
  // plastic_increment_m stay empty — for callers that need no more (a 4096² solve ends 3 grids,
  // 384 MB, lighter).
  bool full_fields = true;

  // False with a reason when an option is out of range (tolerance in (0, 1), cap > 0, iterations ≥ 0).
  bool is_valid(std::string* why) const;
};

struct NormalContactSummary {
  bool converged = false;
  int iterations = 0;
  double residual = 0.0;  // ε at exit (see NormalContactOptions::tolerance)
  int fft_pairs = 0;      // half-space evaluations (r2c + c2r pairs): one per iteration, one for the start
                          // and, after single-precision ones, one where the solve goes on in double
  int single_pairs = 0;   // how many of them in single precision
  std::string message;
};

struct NormalContactResult {
  Eigen::ArrayXXd pressure_Pa;
  Eigen::ArrayXXd gap_m;                // max(g, 0)
  Eigen::ArrayXXd displacement_m;       // elastic u
  Eigen::ArrayXXd plastic_increment_m;  // max(−g, 0) on plastic cells, 0 elsewhere
  double normal_load_N = 0.0;
  double approach_m = 0.0;              // δ
  double real_area_m2 = 0.0;            // cells with p > 0
  double plastic_area_m2 = 0.0;         // cells at the cap
  double area_fraction = 0.0;
  double max_pressure_Pa = 0.0;
  double mean_gap_m = 0.0;              // mean of gap_m over the grid
  NormalContactSummary summary;
};

// Load-controlled solve: total normal load W (N) on the profile `gap0_m` (the initial gap h, m,
// same shape as the half-space grid). `warm_start_Pa` (optional, same shape) seeds the pressure.
// Throws std::invalid_argument for bad input (shape mismatch, NaN, W ≤ 0, or W above the
// saturation load p_cap · L_x L_y that no pressure field within the cap can carry).
NormalContactResult solve_normal_load(ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0_m, double normal_load_N,
                                      const NormalContactOptions& options = {},
                                      const Eigen::ArrayXXd* warm_start_Pa = nullptr);

// Displacement-controlled solve at rigid approach δ (m).
NormalContactResult solve_approach(ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0_m, double approach_m,
                                   const NormalContactOptions& options = {},
                                   const Eigen::ArrayXXd* warm_start_Pa = nullptr);

// Mean-gap-controlled solve on a periodic half-space: on a periodic grid ū = 0, so the mean of
// h + u − δ is mean(h) − δ and the target fixes δ. Throws for a non-periodic half-space.
NormalContactResult solve_mean_gap(ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0_m, double mean_gap_m,
                                   const NormalContactOptions& options = {},
                                   const Eigen::ArrayXXd* warm_start_Pa = nullptr);

// The load–gap curve N_s(ḡ) that lubrication/ homogenises (DESIGN §1): load-controlled solves at
// increasing loads, each warm-started from the previous pressure, all on the same profile.
struct LoadGapPoint {
  double normal_load_N = 0.0;
  double mean_gap_m = 0.0;
  double approach_m = 0.0;
  double real_area_m2 = 0.0;
  NormalContactSummary summary;
};
// Throws std::invalid_argument when the loads are not positive and strictly increasing.
std::vector<LoadGapPoint> load_gap_curve(ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0_m,
                                         const std::vector<double>& loads_N, const NormalContactOptions& options = {});

// Initial gap of a rigid rough surface with heights z against a flat: h = max(z) − z.
Eigen::ArrayXXd gap_from_heights(const Eigen::ArrayXXd& heights_m);

// Initial gap of a sphere of radius R centred on the grid, paraboloidal (Hertz) approximation
// h = r² / (2R) with r measured from the domain centre.
Eigen::ArrayXXd sphere_gap(const Grid& grid, double radius_m);

}  // namespace tribo::contact
