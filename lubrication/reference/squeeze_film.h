// Squeeze film between parallel circular discs — thesis (3.2.2), Appendix III.
//
// Two parallel flat discs of radius R separated by a Newtonian film of thickness h(t) and
// constant viscosity η; the gap closes at ḣ = dh/dt (ḣ < 0 when approaching). Reynolds'
// equation in polar co-ordinates with p(R) = 0 and dp/dρ(0) = 0 gives
//
//     p(ρ) = (3η/h³)(ρ² − R²) ḣ,                      (Appendix III)
//     N_f  = ∫ p 2πρ dρ = −(3/2) π η R⁴ ḣ / h³,        thesis (3.2.2)
//
// so the load is positive while the gap closes. Under a constant load W the gap obeys
// ḣ = −2 W h³ / (3π η R⁴); integrating from h0 to h1 < h0,
//
//     t(h0 → h1) = (3π η R⁴ / (4 W)) (1/h1² − 1/h0²).
//
// These closed forms are library code (STYLE §9): the rig's squeeze_film effect, the Reynolds
// solver's tests and the benchmarks share them. All arguments are SI; bad arguments (non-finite,
// non-positive where a positive value is needed, h1 ≥ h0) throw std::invalid_argument.
#pragma once

namespace tribo::lubrication {

// Pressure at radius ρ (Pa), Appendix III; ρ in [0, R].
double squeeze_film_pressure_Pa(double viscosity_Pa_s, double radius_m, double gap_m, double gap_rate_m_per_s,
                                double rho_m);

// Load carried by the film (N), thesis (3.2.2); positive for ḣ < 0.
double squeeze_film_load_N(double viscosity_Pa_s, double radius_m, double gap_m, double gap_rate_m_per_s);

// Gap rate ḣ (m/s, negative) under a constant load W: (3.2.2) solved for ḣ.
double squeeze_film_gap_rate_m_per_s(double viscosity_Pa_s, double radius_m, double gap_m, double load_N);

// Time for the gap to fall from h0 to h1 (0 < h1 < h0) under the constant load W.
double squeeze_out_time_s(double viscosity_Pa_s, double radius_m, double load_N, double h0_m, double h1_m);

}  // namespace tribo::lubrication
