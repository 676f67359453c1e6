// Closed forms and published fits for lubricated circular point contacts (a ball on a flat, or
// two balls) — references for the EHL solver of ehl_point.h and its start.
//
// Hertz (dry, Johnson, "Contact Mechanics", §4.2), with E' = 2 / [(1−ν1²)/E1 + (1−ν2²)/E2]:
// contact radius a = (3 W R/(2 E'))^{1/3}, peak pressure p_H = 3 W/(2π a²) = E' a/(π R), central
// approach δ = a²/R.
//
// Hamrock & Dowson (1977, ASME J. Lubr. Technol. 99:264), fits to their isothermal EHL solutions
// of elliptical contacts, here at ellipticity k = 1, in U = η0 u_m/(E' R), W = w/(E' R²), G = α E'
// (u_m the mean of the two surface speeds):
//   h_c/R   = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^{−0.73 k}),
//   h_min/R = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^{−0.68 k}).
// Later solutions (Venner & Lubrecht 2000, ch. 9; Nijenbanning, Venner & Moes 1994) fall within
// ≈ 20 % of the central film over the usual range and further from the minimum: a fit of fits, not
// a closed form, which sets what "agrees" can mean.
#pragma once

namespace tribo::lubrication::reference {

struct PointContactGroups {
  double speed = 0.0;     // U = η0 u_m / (E' R)
  double load = 0.0;      // W = w / (E' R²)
  double material = 0.0;  // G = α E'
};
PointContactGroups point_contact_groups(double load_N, double reduced_radius_m, double reduced_modulus_Pa, double mean_speed_m_per_s,
                                        double viscosity_Pa_s, double pressure_viscosity_per_Pa);

double hertz_point_radius_m(double load_N, double reduced_radius_m, double reduced_modulus_Pa);
double hertz_point_peak_pressure_Pa(double load_N, double reduced_radius_m, double reduced_modulus_Pa);

// h/R of the fits above, circular contact (k = 1).
double hamrock_dowson_central_film(const PointContactGroups& g);
double hamrock_dowson_minimum_film(const PointContactGroups& g);

// Hamrock & Dowson's fully flooded inlet boundary (1977, ASME J. Lubr. Technol. 99:264, the
// starvation study of the same paper series): the inlet distance from the contact's centre, in
// contact radii, beyond which more oil no longer thickens the film,
//   m* = 1 + 3.06 [(R/a)² H]^0.58,  H = h_c/R the central film.
double hamrock_dowson_flooded_inlet(double central_film_over_radius, double radius_over_contact_radius);

}  // namespace tribo::lubrication::reference
