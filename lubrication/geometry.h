// Film geometries for the Reynolds solver (lubrication/reynolds.h).
//
//   parallel discs   — the thesis' 3/8 in slider face on the disc (Appendix III): a circular
//                      domain of radius R with uniform gap h and gap rate ḣ, centred on a square
//                      grid of n × n nodes spanning 2R + 2 dx (one node beyond the rim each side).
//   gap field        — any h(x, y) on a rectangular grid.
//   rough pair       — two rough surfaces z₁(x, y) (upper) and z₂(x, y) (lower) at mean
//                      separation h̄: h = h̄ + z₁ − z₂, with the mean of z₁ − z₂ removed so h̄ is
//                      the mean gap. Where this falls below `min_gap_m` the surfaces touch; the
//                      gap is floored there (the contact spots carry the load elastically, and
//                      the Reynolds flux through them is negligible as h³ → 0).
//   periodic cell    — an n × n periodic film on a patch of side L as a Reynolds problem
//                      (periodic_film_cell): the film wraps along x, so the grid has n + 1 nodes
//                      along x (x = L ≡ 0, for p prescribed at both ends) and n across, periodic,
//                      at the surface's spacing L/n (contact/grid.h).
//   rough pair film  — the periodic cell of a rough pair (rough_pair_film): rigid at a mean gap,
//                      or pressed together by a solid load on an elastic(-plastic) periodic
//                      half-space (contact/normal_contact.h) with the film filling the deformed
//                      gap (`tribo reynolds` geometry kind "rough_pair").
#pragma once

#include "contact/normal_contact.h"
#include "lubrication/reynolds.h"

#include <Eigen/Core>

#include <limits>
#include <optional>
#include <string>

namespace tribo::lubrication {

ReynoldsProblem parallel_discs_problem(double radius_m, double gap_m, double gap_rate_m_per_s, double viscosity_Pa_s,
                                       double sliding_speed_m_per_s, int n);

// h = h̄ + (z₁ − mean z₁) − (z₂ − mean z₂), floored at min_gap_m, on the grid of the two height
// fields. Returns the number of floored (contacting) nodes through `contact_nodes` when non-null.
Eigen::ArrayXXd rough_pair_gap_m(const Eigen::ArrayXXd& upper_height_m, const Eigen::ArrayXXd& lower_height_m,
                                 double mean_gap_m, double min_gap_m, std::size_t* contact_nodes = nullptr);

// The Reynolds cell of an n × n periodic film h (rows along x, n ≥ 3) on a patch of side size_m:
// grid (n + 1) × n at spacing size_m/n, gap(i, j) = h(i mod n, j), periodic y; nothing else set.
ReynoldsProblem periodic_film_cell(const Eigen::ArrayXXd& film_m, double size_m);

// How the two rough surfaces of rough_pair_film are placed. Exactly one of mean_gap_m and
// normal_load_N is given.
struct RoughPairFilmOptions {
  // Rigid surfaces: mean planes this far apart, h = h̄ + (z₁ − z̄₁) − (z₂ − z̄₂) (rough_pair_gap_m).
  std::optional<double> mean_gap_m;
  // Or pressed together by this solid load (N) on the periodic patch: the rigid profile
  // gap_from_heights(lower − upper) against an elastic(-plastic) periodic half-space of modulus
  // E* with the pressure cap hardness_Pa, load-controlled (contact::solve_normal_load); the film
  // is the deformed gap g.
  std::optional<double> normal_load_N;
  // E* (contact mode); default steel on steel, E = 206.8 GPa, ν = 0.3 (thesis Appendix I)
  double composite_modulus_Pa = contact::composite_modulus_Pa(206.8e9, 0.3, 206.8e9, 0.3);
  double hardness_Pa = std::numeric_limits<double>::infinity();  // plastic pressure cap; ∞ = elastic
  contact::NormalContactOptions contact;  // tolerance, iterations (its pressure cap is replaced by hardness_Pa)
  // The film is floored at contact_gap_fraction · σ (σ = √(Rq₁² + Rq₂²) of the two arrays) where
  // the surfaces touch (rigid: h < floor; deformed: g < floor); those are the contact nodes.
  double contact_gap_fraction = 1e-3;

  // False with a reason naming the field: neither or both placements, a non-positive or
  // non-finite value, a fraction outside (0, 0.5], invalid contact options.
  bool is_valid(std::string* why) const;
};

struct RoughPairFilm {
  ReynoldsProblem problem;            // periodic_film_cell of the film: nothing else set
  std::size_t contact_nodes = 0;      // surface nodes (of n × n) where the film is at the floor
  double composite_rms_height_m = 0;  // σ = √(Rq(upper)² + Rq(lower)²), each about its mean
  double floor_m = 0;                 // contact_gap_fraction · σ
  double mean_film_m = 0;             // mean film over the n × n surface nodes
  // Contact mode only: the contact solve. Non-convergence is returned, not thrown (check
  // contact->summary.converged); the film is then built from the solver's last iterate.
  std::optional<contact::NormalContactResult> contact;
};

// The rough-pair Reynolds cell. upper_m (slider) and lower_m (disc) are n × n periodic height
// fields (rows along x, n ≥ 3) on a square patch of side size_m. Throws std::invalid_argument
// for bad input (shapes, NaN, invalid options, a rigid mean gap not above the floor, a load the
// capped contact cannot carry).
RoughPairFilm rough_pair_film(const Eigen::ArrayXXd& upper_m, const Eigen::ArrayXXd& lower_m, double size_m,
                              const RoughPairFilmOptions& options);

}  // namespace tribo::lubrication
