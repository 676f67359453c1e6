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
#pragma once

#include "lubrication/reynolds.h"

#include <vector>

namespace tribo::lubrication {

ReynoldsProblem parallel_discs_problem(double radius_m, double gap_m, double gap_rate_m_per_s, double viscosity_Pa_s,
                                       double sliding_speed_m_per_s, int n);

// h = h̄ + (z₁ − mean z₁) − (z₂ − mean z₂), floored at min_gap_m; z fields row-major as the grid.
// Returns the number of floored (contacting) nodes through `contact_nodes` when non-null.
std::vector<double> rough_pair_gap_m(const std::vector<double>& upper_height_m, const std::vector<double>& lower_height_m,
                                     double mean_gap_m, double min_gap_m, std::size_t* contact_nodes = nullptr);

}  // namespace tribo::lubrication
