// A reference for the elastic-plastic line contact independent of the EHL solvers: a rigid cylinder
// of radius R pressed with the load w per unit length on an elastic half-plane (plane strain, E*)
// whose surface pressure may not exceed a cap p_cap — the two-dimensional companion of
// capped_sphere.h.
//
// Pressure constant on N strips of width Δ over [−x_max, x_max]; the surface deflection at the
// strip centres from the closed form of a uniform strip load (Johnson, "Contact Mechanics", §2.6,
// (2.25b)): a pressure p on [s_a, s_b] deflects the surface at x by
//   −(2 p/(π E*)) ∫ ln|x − s| ds = −(2 p/(π E*)) [G(x − s_a) − G(x − s_b)],  G(t) = t ln|t| − t,
// up to a constant, which in two dimensions is the approach δ itself: it is an unknown fixed by
// the load. The box-constrained complementarity problem — p = 0 where the cylinder clears the
// surface, 0 < p < p_cap where it touches elastically, p = p_cap where the cap binds — is solved
// by an active-set iteration, each step a linear solve on the elastic strips bordered by the load
// balance. Exact in the limits: Hertz for p_cap ≥ p_0 (half width b = √(4 w R/(π E*)), the test
// checks), w/(2 p_cap) for a fully plastic contact.
#pragma once

#include <vector>

namespace tribo::contact::reference {

struct CappedCylinderContact {
  double contact_half_width_m = 0.0;  // outer edge of the loaded strips (the larger of both sides)
  double plastic_half_width_m = 0.0;  // outer edge of the strips at the cap (0: none)
  double peak_pressure_Pa = 0.0;
  std::vector<double> strip_x_m, strip_pressure_Pa;  // each strip's centre and pressure
};

// Throws std::invalid_argument for non-positive arguments or strips < 40 (or odd), and
// std::runtime_error if the active-set iteration does not settle.
CappedCylinderContact capped_cylinder_contact(double load_per_length_N_per_m, double radius_m, double e_star_Pa, double cap_Pa,
                                              int strips = 800);

// The pressure at x (m): linear between the strips' centres, 0 beyond the outermost.
double pressure_at_Pa(const CappedCylinderContact& c, double x_m);

}  // namespace tribo::contact::reference
