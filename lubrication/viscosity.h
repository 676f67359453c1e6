// Lubricant viscosity, thermal traction and flash temperature — thesis §3.2 and §5.2.
//
// Viscosity (thesis §3.2, definitions under (3.2.4)): the pressure coefficient ψ and the
// temperature coefficient γ are defined by ψ = ln(η/η0)/(p − p0) and γ = ln(η0/η)/(T − T0), i.e.
//
//     η(p, T) = η0 · exp(ψ p) · exp(−γ (T − T0)),     (Barus × exponential temperature law)
//
// with p the gauge pressure above ambient (Pa) and T0 the reference temperature of η0.
//
// Crook's thermal traction (3.2.3)-(3.2.5): with h_min and the surface viscosity fixed, the
// traction of an EHL film reduces to
//
//     F(U) = (a/U)(b + ln U),                         thesis (3.2.5)
//
// with U the sliding speed in m/s (the logarithm takes U/(1 m/s)), a in N·m/s and b
// dimensionless. dF/dU = (a/U²)(1 − b − ln U), so F is largest at ln U = 1 − b, where
// F_max = a · e^{b−1}.
//
// Jaeger's flash temperature (5.2.1), reduced for a given pair of surfaces to
//
//     ΔT = T − T∞ = K μk v N_s^{1/2} / (a + v^{1/2} N_s^{1/4}),    thesis (5.2.2)
//
// with v in m/s and N_s (the load carried by solid contact) in N. For ΔT in K the constant a
// has the units of v^{1/2} N_s^{1/4}, i.e. (m/s)^{1/2}·N^{1/4}, and K has K·s^{1/2}/(m^{1/2}·N^{1/4}).
// a → 0 is Jaeger's high-speed limit (ΔT ∝ v^{1/2} N_s^{1/4}); v^{1/2}N_s^{1/4} ≪ a is the
// low-speed limit (ΔT ∝ v N_s^{1/2}).
#pragma once

namespace tribo::lubrication {

// Newtonian lubricant with Barus pressure and exponential temperature dependence.
struct Lubricant {
  // η0 at reference_temperature_K and ambient pressure. 0.021 Pa·s is the thesis' white mineral
  // oil, 120 SSU at 80 °F ≈ 25 cSt (ASTM D2161 conversion) × ≈ 850 kg/m³ (Appendix I; DESIGN §5).
  double viscosity_Pa_s = 0.021;
  // Barus ψ (1/Pa): 1–3e-8 for mineral oils at room temperature (Hamrock, Schmid & Jacobson,
  // "Fundamentals of Machine Elements", table of pressure-viscosity coefficients); 2e-8 mid-range.
  double pressure_viscosity_per_Pa = 2.0e-8;
  // γ (1/K): light mineral oils lose about half their viscosity per 20–25 K near room temperature
  // (ln 2 / 23 K ≈ 0.03 /K, consistent with a viscosity index near 100).
  double temperature_viscosity_per_K = 0.03;
  // T0 = 27 °C, the thesis oil's test temperature (80 °F ≈ 26.7 °C).
  double reference_temperature_K = 300.15;
};

// The thesis lubricant (white mineral oil, 120 SSU at 80 °F) with the defaults above.
Lubricant thesis_white_mineral_oil();

// Throws std::invalid_argument naming the bad field (η0 ≤ 0, ψ < 0, γ < 0, T0 ≤ 0 or non-finite).
void validate(const Lubricant& lubricant);

// η(p, T) = η0 exp(ψ p) exp(−γ (T − T0)); p is gauge pressure (Pa), T absolute (K > 0).
double viscosity_Pa_s(const Lubricant& lubricant, double pressure_Pa, double temperature_K);

// Crook's reduced traction (3.2.5), F = (a/U)(b + ln U); U > 0 in m/s.
double crook_traction_N(double a_N_m_per_s, double b, double speed_m_per_s);

// Speed of Crook's traction maximum, U* = exp(1 − b) m/s.
double crook_peak_speed_m_per_s(double b);

// Jaeger's reduced flash temperature rise (5.2.2), in K; units of K and a as documented above.
double jaeger_temperature_rise_K(double K, double a, double mu_k, double speed_m_per_s, double solid_load_N);

// Jaeger's flash temperature (5.2.1) itself, in SI (the thesis' g/J convert lbf·in to heat and
// drop out): with P = μk v N_s the frictional power (W) released on the real area A,
//
//     ΔT = P b / (1.9 √A [1.1 ξ2 b + 0.7 ξ1 A^{1/4} v^{1/2}]),
//
// ξ1, ξ2 the thermal conductivities of slider and disc (W/(m K)) and b = √κ1 (m/s^{1/2}) the
// square root of the slider's thermal diffusivity — the only choice of b for which both terms
// in the bracket have the same units. Low speed: ΔT → P/(2.09 ξ2 √A) (conduction into the
// disc); high speed: the slider's moving-source term 0.7 ξ1 A^{1/4} √v takes over.
struct JaegerContact {
  double slider_conductivity_W_per_m_K = 46.0;   // ξ1, alloy steel (≈ 1 % C)
  double disc_conductivity_W_per_m_K = 52.0;     // ξ2, annealed AISI 1020
  double slider_diffusivity_m2_per_s = 1.2e-5;   // κ1 = ξ1/(ρ c), steel
};
void validate(const JaegerContact& contact);
// ΔT in K for the frictional power P (W) on the real area A (m²) at sliding speed v (m/s);
// 0 when P = 0 or A = 0 (no heat, or no solid contact to carry it).
double jaeger_flash_temperature_rise_K(const JaegerContact& contact, double power_W, double real_area_m2,
                                       double speed_m_per_s);

}  // namespace tribo::lubrication
