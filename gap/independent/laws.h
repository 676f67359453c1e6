// The second, independent generator of the gap selftest (issue 15): friction mechanisms of the
// effect catalogue (DESIGN §8) written in *other published forms* than rig/effects/, so that the
// diagnosis, which fits the catalogue's forms, meets data it was not built from. Nothing here
// includes or links rig/: every form is written down again from its source.
//
// Solid friction (coefficient of the load the solid contact carries):
//   Coulomb baseline           μs (stick threshold), μk (slip)
//   rate_dependent_static  →   stick-time ageing, Kato, Sato & Matsubayashi (1972),
//                              "Mechanism of static friction", Wear 21 / Brockley & Davis (1968):
//                                μs(t) = μ∞ − (μ∞ − μ0) exp(−(t/t_c)^m),   t the time at rest
//                              (the catalogue uses the load rate φ̇ and the junction locus 3.1.24)
//   strain_rate_hardening  →   logarithmic rate sensitivity of the hardness, Johnson & Cook (1983):
//                                σ0 = σ_ref (1 + C ln(φ̇/φ̇_ref))  ⇒  μs(φ̇) = μs,ref / (1 + C ln(φ̇/φ̇_ref))
//                              (the catalogue: power law σ0 = κ φ̇^m, thesis 5.1.2)
//   slip_transient         →   Dieterich–Ruina rate-and-state friction (Dieterich 1979, Ruina 1983):
//                                μ(V, θ) = μ0 + a ln(1 + V/V0) + b ln(V0 θ / D_c)
//                              with the ageing law  θ̇ = 1 − Vθ/D_c  or the slip law
//                              θ̇ = −(Vθ/D_c) ln(Vθ/D_c). The direct effect is regularised at
//                              V ≲ V0 (as Baumberger & Caroli 2006, Adv. Phys. 55) so that
//                              μ(0, θ) = μ0 + b ln(V0θ/D_c) is finite; for V ≫ V0 it is the
//                              canonical law with steady state
//                                μss = μ0 + (a − b) ln(V/V0)                     (θss = D_c/V).
//                              At breakaway from the Coulomb threshold μs the state is that of a
//                              contact aged to μs, μ(0, θ) = μs; it then evolves with slip, so
//                              friction falls from μs to μss(V) over a slip distance ~ D_c (slip
//                              law: exponentially in ln θ; ageing law: ln θ falls linearly first).
//                              (the catalogue: Δμ = a(μs − μk) exp(−s/D_c) re-armed at breakaway)
// Load shared with a fluid film (solid fraction χ multiplies the solid friction and threshold):
//   hydrodynamic_lift      →   exponential Stribeck form (Stribeck 1902; Armstrong-Hélouvry,
//                              Dupont & Canudas de Wit 1994, Automatica 30, eq. 4):
//                                χ(U) = 1 − f_max (1 − exp(−(U/U_s)^δ)),  δ ∈ [1, 2]
//                              (the catalogue: rational f_max U/(U + U½))
//   squeeze_film           →   a film-thickness ODE: entrainment builds the film over a slip
//                              distance D_b, the load it carries squeezes it out by Reynolds'
//                              parallel-disc law (thesis Appendix III: W_f = (3π/2) η R⁴ (−ḣ)/h³):
//                                ḣ = |U| (h_e − h)/D_b − 2 W_f h³ / (3π η R⁴),  W_f = φ_max (h/h_e) W,
//                                χ = 1 − φ_max h/h_e;
//                              at rest h⁻³ = h0⁻³ + 3 c t, c = 2 φ_max W / (3π η R⁴ h_e) — algebraic,
//                              not the catalogue's exponential load share with one time τ_sq.
// Fluid shear force (N, along the slip):
//   viscous_friction       →   Eyring shear-thinning film (Eyring 1936; Johnson & Tevaarwerk 1977,
//                              Proc. R. Soc. A 356): τ = τ0 asinh(η U/(h τ0)) ⇒ F = c U0 asinh(U/U0),
//                              linear (c U) only for U ≪ U0 (the catalogue: c U)
//   thermal_thinning       →   Vogel (1921) viscosity η(T) = η∞ exp(B/(T − T∞)) with the flash
//                              temperature rising linearly with speed, T = T0 + θ_T U (thesis 5.2.2
//                              at the rig's speeds): F = c0 U η(T0 + θ_T U)/η(T0)
//                              (the catalogue: exponential law, F = c0 U exp(−U/U_T))
// The measuring chain (measuring_chain.h) stands for `instrument`.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

namespace tribo::gap::independent {

struct StickTimeAgeing {  // Kato et al. 1972
  double mu_0 = 0.2;      // μs after no time at rest
  double mu_inf = 0.5;    // upper asymptote after long contact
  double time_s = 0.2;    // t_c
  double exponent = 0.7;  // m
  double mu_s(double t_rest_s) const { return mu_inf - (mu_inf - mu_0) * std::exp(-std::pow(std::max(t_rest_s, 0.0) / time_s, exponent)); }
};

struct RateHardening {  // Johnson & Cook 1983, in the hardness σ0 that sets μs = τ_i/σ0
  double mu_s_ref = 0.3;
  double coefficient = 0.1;          // C
  double reference_rate_per_s = 1.0; // φ̇_ref
  double mu_s(double load_rate_per_s) const {
    return mu_s_ref / std::max(1.0 + coefficient * std::log(std::max(load_rate_per_s, 1e-12) / reference_rate_per_s), 0.1);
  }
};

struct RateState {  // Dieterich–Ruina
  enum class Evolution { ageing, slip };
  double mu_0 = 0.2, a = 0.002, b = 0.05;
  double reference_speed_m_per_s = 1e-3;  // V0
  double decay_distance_m = 5e-4;         // D_c
  Evolution evolution = Evolution::slip;
  // The contact's strength at rest is the Coulomb threshold μs: at each breakaway θ is set to
  // the state whose μ(0, θ) is μs (an aged contact), then evolves with slip. Without the reset the
  // threshold is μ(0, θ) itself and ages with the evolution law while stuck.
  bool reset_at_breakaway = true;

  // Regularised law used in the rig (finite at V = 0).
  double mu(double speed_m_per_s, double theta_s) const {
    return mu_0 + a * std::log1p(std::abs(speed_m_per_s) / reference_speed_m_per_s) +
           b * std::log(reference_speed_m_per_s * theta_s / decay_distance_m);
  }
  // The canonical law, V > 0 (Dieterich 1979; Ruina 1983).
  double mu_canonical(double speed_m_per_s, double theta_s) const {
    return mu_0 + a * std::log(speed_m_per_s / reference_speed_m_per_s) + b * std::log(reference_speed_m_per_s * theta_s / decay_distance_m);
  }
  double state_at_rest(double mu_at_rest) const {
    return decay_distance_m / reference_speed_m_per_s * std::exp((mu_at_rest - mu_0) / b);
  }
  double steady_mu_canonical(double speed_m_per_s) const { return mu_0 + (a - b) * std::log(speed_m_per_s / reference_speed_m_per_s); }
  double theta_rate_per_s(double speed_m_per_s, double theta_s) const {
    const double q = std::abs(speed_m_per_s) * theta_s / decay_distance_m;
    if (evolution == Evolution::ageing) return 1.0 - q;
    return q > 0.0 ? -q * std::log(q) : 0.0;
  }
};

struct StribeckLift {
  double max_fraction = 0.5, stribeck_speed_m_per_s = 0.02, exponent = 1.5;
  double solid_fraction(double speed_m_per_s) const {
    return 1.0 - max_fraction * (1.0 - std::exp(-std::pow(std::abs(speed_m_per_s) / stribeck_speed_m_per_s, exponent)));
  }
};

struct SqueezeFilmOde {
  double max_fraction = 0.5;        // φ_max, the load share of a fully built film
  double full_thickness_m = 1e-6;   // h_e
  double build_up_distance_m = 1e-3;// D_b
  double viscosity_Pa_s = 0.021;
  double radius_m = 2e-3;           // R of the squeezed patch
  double fluid_fraction(double h_m) const { return max_fraction * std::clamp(h_m / full_thickness_m, 0.0, 1.0); }
  // c of ḣ = −c h⁴ at rest (from W_f = φ_max (h/h_e) W and Reynolds' parallel-disc squeeze).
  double squeeze_constant(double normal_load_N) const {
    return 2.0 * max_fraction * normal_load_N / (3.0 * M_PI * viscosity_Pa_s * std::pow(radius_m, 4) * full_thickness_m);
  }
  double thickness_rate_m_per_s(double speed_m_per_s, double h_m, double normal_load_N) const {
    return std::abs(speed_m_per_s) * (full_thickness_m - h_m) / build_up_distance_m - squeeze_constant(normal_load_N) * std::pow(h_m, 4);
  }
  // Closed form at rest: h⁻³ = h0⁻³ + 3 c t.
  double thickness_at_rest_m(double h0_m, double t_s, double normal_load_N) const {
    return std::pow(std::pow(h0_m, -3.0) + 3.0 * squeeze_constant(normal_load_N) * t_s, -1.0 / 3.0);
  }
};

struct EyringFilm {
  double coefficient_N_s_per_m = 30.0;  // c, the slope at U → 0
  double eyring_speed_m_per_s = 0.05;   // U0
  double force_N(double speed_m_per_s) const {
    return coefficient_N_s_per_m * eyring_speed_m_per_s * std::asinh(speed_m_per_s / eyring_speed_m_per_s);
  }
};

struct VogelThinning {
  double coefficient_N_s_per_m = 300.0;  // c0 at the bulk temperature
  double heating_K_s_per_m = 1000.0;     // θ_T: flash temperature rise per unit speed
  double bulk_temperature_K = 300.0;     // T0
  double vogel_B_K = 900.0;              // B
  double vogel_T_inf_K = 160.0;          // T∞
  double viscosity_ratio(double speed_m_per_s) const {
    const double T = bulk_temperature_K + heating_K_s_per_m * std::abs(speed_m_per_s);
    return std::exp(vogel_B_K / (T - vogel_T_inf_K) - vogel_B_K / (bulk_temperature_K - vogel_T_inf_K));
  }
  double force_N(double speed_m_per_s) const { return coefficient_N_s_per_m * speed_m_per_s * viscosity_ratio(speed_m_per_s); }
  // θ_T that puts the force maximum at U_max: d/dU [U η(T0 + θU)] = 0 ⇔ θ U B = (T0 + θU − T∞)².
  static double heating_for_maximum_at(double u_max_m_per_s, double T0_K, double B_K, double T_inf_K);
};

inline double VogelThinning::heating_for_maximum_at(double u_max, double T0, double B, double T_inf) {
  // g(θ) = θ U B − (T0 − T∞ + θU)² rises from −(T0 − T∞)² at θ = 0 through zero (smaller root).
  double lo = 0.0, hi = 1.0;
  auto g = [&](double th) { const double d = T0 - T_inf + th * u_max; return th * u_max * B - d * d; };
  while (g(hi) < 0.0 && hi < 1e12) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// A friction law made of the forms above; each mechanism optional (none: Coulomb).
struct IndependentLaw {
  double mu_s = 0.3, mu_k = 0.2;  // Coulomb baseline (unused parts replaced by the forms present)
  std::optional<StickTimeAgeing> stick_ageing;
  std::optional<RateHardening> rate_hardening;
  std::optional<RateState> rate_state;  // replaces μs and μk altogether
  std::optional<StribeckLift> lift;
  std::optional<SqueezeFilmOde> squeeze;
  std::optional<EyringFilm> eyring;
  std::optional<VogelThinning> vogel;
};

}  // namespace tribo::gap::independent
