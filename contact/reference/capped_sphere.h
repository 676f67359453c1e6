// A reference for the elastic-plastic sphere independent of the FFT BEM: a rigid sphere of radius R
// pressed with the load W on an elastic half-space (E*) whose surface pressure may not exceed a
// cap p_cap (the BEM's elastic–perfectly-plastic surface model), solved in axisymmetry.
//
// Pressure constant on N rings of width Δ = r_max/N; the surface deflection at the ring mid-radii
// from closed forms (Johnson, "Contact Mechanics", §3.4, (3.33)): a uniform pressure p on a disc of
// radius a deflects the surface at radius r by
//   (4 p a/(π E*)) E(r/a)                              for r ≤ a,
//   (4 p r/(π E*)) [E(a/r) − (1 − a²/r²) K(a/r)]       for r > a,
// K, E the complete elliptic integrals of modulus k; a ring is the difference of two discs. For an
// approach δ the box-constrained complementarity problem — p = 0 where the sphere clears the
// surface, 0 < p < p_cap where it touches elastically, p = p_cap where the cap binds — is solved by
// an active-set iteration (a linear solve on the elastic rings, the sets updated from the signs),
// and δ by bisection on the load. Exact in the limits: Hertz for p_cap ≥ p_0 (the test checks),
// W/p_cap for a fully plastic contact.
#pragma once

#include <vector>

namespace tribo::contact::reference {

struct CappedSphereContact {
  double contact_radius_m = 0.0;  // outer edge of the loaded rings
  double plastic_radius_m = 0.0;  // outer edge of the rings at the cap (0: none)
  double area_m2 = 0.0;           // loaded rings' area
  double approach_m = 0.0;        // δ
  double peak_pressure_Pa = 0.0;
  std::vector<double> ring_radius_m, ring_pressure_Pa;  // each ring's mid-radius and pressure, out to r_max
};

// The pressure at radius r (m): linear between the rings' mid-radii, the first ring's inside it, 0 past the last.
double pressure_at_Pa(const CappedSphereContact& c, double r_m);

// Throws std::invalid_argument for non-positive arguments or rings < 20, and std::runtime_error if
// the active-set iteration cycles or the domain r_max (4 × the Hertz radius, or the fully plastic
// radius if larger) cannot carry W under the cap.
CappedSphereContact capped_sphere_contact(double load_N, double radius_m, double e_star_Pa, double cap_Pa,
                                          int rings = 400);

}  // namespace tribo::contact::reference
