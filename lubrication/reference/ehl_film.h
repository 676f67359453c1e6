// Closed forms and published fits for lubricated line contacts — references for the EHL solver
// (ehl_line.h) and its start.
//
// Hertz (dry line contact, Johnson, "Contact Mechanics", §4.2): half width b = √(8 w R/(π E')),
// peak pressure p_H = √(w E'/(2π R)) = 2 w/(π b).
//
// Rigid, isoviscous cylinder on a plane (Martin 1916) with the Reynolds (Swift–Stieber) exit
// condition, in closed form: with ξ = x/√(2 R h_min) and p = 12 η0 u_m √(2R h_min)/h_min² Π(ξ),
//   dΠ/dξ = (ξ² − ξe²)/(1 + ξ²)³,   Π(ξ_in) = 0,   Π(ξe) = 0 (the exit, where dΠ/dξ = 0 too),
// integrated with J_n = ∫ dξ/(1+ξ²)^n (J1 = atan ξ, J_{n+1} = ξ/(2n(1+ξ²)^n) + (2n−1)/(2n) J_n)
// and ∫J2 = ½ ξ atan ξ, ∫J3 = −1/(8(1+ξ²)) + (3/8) ξ atan ξ. The load is w = C η0 u_m R/h_min with
// C = 24 ∫Π dξ = 4.8950 for an inlet at ξ_in → −∞ (ξe = 0.47513; Hamrock, "Fundamentals of Fluid
// Film Lubrication", rounds it to H_min = 4.9 U/W) and less for a finite inlet (4.8817 at −30).
//
// Pan & Hamrock (1989), a fit to Newton–Raphson EHL solutions of the smooth isothermal line contact
// (Roelands viscosity, Dowson–Higginson density), in U = η0 u_m/(E' R), W = w/(E' R), G = α E':
//   h_min/R = 1.714 W^−0.128 U^0.694 G^0.568,     h_c/R = 2.922 W^−0.166 U^0.692 G^0.470.
// Dowson & Higginson (1966/1977) minimum film: h_min/R = 2.65 U^0.70 G^0.54 W^−0.13; Dowson &
// Toyoda (1979) central film: h_c/R = 3.06 U^0.69 G^0.56 W^−0.10. The fits of the two groups
// differ by up to ≈ 30 % in h_c at the same point: together they bound what "agrees" can mean.
#pragma once

#include <limits>

namespace tribo::lubrication::reference {

struct LineContactGroups {
  double speed = 0.0;     // U = η0 u_m / (E' R)
  double load = 0.0;      // W = w / (E' R)
  double material = 0.0;  // G = α E'
};
LineContactGroups line_contact_groups(double load_per_length_N_per_m, double reduced_radius_m,
                                      double reduced_modulus_Pa, double mean_speed_m_per_s,
                                      double viscosity_Pa_s, double pressure_viscosity_per_Pa);

double hertz_line_half_width_m(double load_per_length_N_per_m, double reduced_radius_m, double reduced_modulus_Pa);
double hertz_line_peak_pressure_Pa(double load_per_length_N_per_m, double reduced_radius_m, double reduced_modulus_Pa);

// C of the rigid isoviscous cylinder for an inlet at ξ_in < 0 (−∞ allowed).
double martin_load_constant(double inlet_xi = -std::numeric_limits<double>::infinity());
// h_min of the rigid isoviscous cylinder with a flooded inlet (C = 4.8950), m.
double martin_minimum_film_m(double load_per_length_N_per_m, double reduced_radius_m, double mean_speed_m_per_s,
                             double viscosity_Pa_s);

// h/R of the fits above.
double pan_hamrock_minimum_film(const LineContactGroups& g);
double pan_hamrock_central_film(const LineContactGroups& g);
double dowson_higginson_minimum_film(const LineContactGroups& g);
double dowson_toyoda_central_film(const LineContactGroups& g);

}  // namespace tribo::lubrication::reference
