// Traction of a solved EHL line contact (ehl_line.h): the shear the film passes from one surface to
// the other when they slide at Δu = u1 − u2 while rolling at u_m.
//
// Shear stress (Couette), with the Eyring model of a lubricant's non-Newtonian response (Eyring
// 1936; applied to EHL traction by Johnson & Tevaarwerk 1977, Proc. R. Soc. A 356:215):
//   τ(x) = τ0 asinh(η(p) Δu / (τ0 h)),     Newtonian τ = η(p) Δu / h as τ0 → ∞,
// τ0 the Eyring stress (a few MPa for mineral oils; Johnson & Tevaarwerk, Evans & Johnson 1986).
// Above a few τ0 the stress grows only with ln Δu: the flat, slowly falling traction curves of
// EHL rigs, where the Newtonian film would give a friction coefficient far above one.
// Limiting shear (optional, limiting_shear.h): τ = min(τ_Eyring, τ_L0 + Λ p). At high pressure
// the Eyring stress τ0 ln(2ηΔu/(τ0 h)) would keep growing with η(p) without bound; with the limit
// the traction coefficient of a contact sheared at its limit everywhere is τ_L0 A/W + Λ, the
// plateau of measured traction curves (Greenwood's review, Lubricants 8 (2020) 51, names the limit
// beside shear thinning).
// Heat (optional, FilmHeating): the shear dissipates τΔu/h per unit volume, conducted to both
// surfaces; across a Couette film between walls at T1 and T2 the temperature is then
// T(z) = T1 + (T2 − T1) z/h + (τΔu/(2kh)) z(h − z), its mean over the film
//   ΔT = (T1 + T2)/2 + τΔu h/(12k).
// The viscosity is taken at that mean, η(p) exp(−γ ΔT) (viscosity.h's exponential temperature law),
// and τ solves τ = min(τ0 asinh(η(p) e^{−γΔT(τ)} Δu/(τ0 h)), τ_L(p) e^{−βΔT(τ)}) at each node
// (β of LimitingShear, 0 by default) — one root, as the right side falls with τ (bisection). As
// Δu grows the heating outruns the shear rate and the traction falls: μ(Δu) rises, peaks and
// falls, the shape of measured EHL traction curves.
// The walls stay at the bulk temperature (T1 = T2 = 0 above it) unless FilmHeating::surfaces is set:
// then each surface warms by its flash temperature, Jaeger's fast moving heat source
// (moving_heat_source.h), the surfaces passing the contact at u1 = u_m + Δu/2 and u2 = u_m − Δu/2
// towards increasing x, each with its own solid's effusivity. With Q the heat made at a node — the film's τΔu plus any made at the
// interface outside it (FilmHeating::interface_heat_W_per_m2: the asperity contacts' friction in the
// mixed regime) — wall 1 takes Q/2 + k(T2 − T1)/h per unit area and wall 2 the rest, so the slower,
// hotter surface passes heat through the film to the faster one; the film's own rise τΔu h/(12k)
// counts its own heat only. A
// node's wall temperatures depend only on the heat at and upstream of it, so the nodes are solved
// from the inlet (along each line of nodes in x for a point contact; heat spreads in y only with
// the solid's conduction, left out as in the fast-source limit). The thesis §5.2b: heat from more
// than the film's own shear — metallic contacts' beside it — moves the traction maximum to a lower
// speed.
// Left out: the Poiseuille shear (h/2) dp/dx, equal and opposite on the two surfaces, so it adds
// no net traction to their sum and is small on each beside the Couette term in the loaded zone;
// the cavitated outlet (p = 0 at the nodes past the film's rupture, where the gap holds striations
// of unknown extent); and heat in the film solve itself (the pressure and film are isothermal).
// Traction force per unit length F = ∫ τ dx (trapezoidal rule over the solve's nodes), friction
// coefficient μ = F / w; over a point contact's area F = ∫∫ τ dA (each node its cell), μ = F / W.
#pragma once

#include <optional>

#include "lubrication/ehl_line.h"
#include "lubrication/ehl_point.h"
#include "lubrication/limiting_shear.h"
#include "lubrication/moving_heat_source.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

// The film's shear heating: off when thermal_conductivity_W_per_m_K is 0 (isothermal).
struct FilmHeating {
  double thermal_conductivity_W_per_m_K = 0.0;  // k of the lubricant (mineral oils ≈ 0.13)
  double temperature_viscosity_per_K = 0.0;     // γ in η ∝ exp(−γ ΔT) (viscosity.h: 0.03 for light mineral oils)
  // The surfaces' flash temperature: on when `surfaces` is set (then the film's k must be > 0).
  // The surfaces move at u1,2 = u_m ± Δu/2 with u_m = mean_speed_m_per_s; both are of the solid
  // `surfaces` unless `second_surface` gives the one moving at u2 (a steel ball on a glass disc).
  std::optional<HeatedSolid> surfaces;
  std::optional<HeatedSolid> second_surface;
  double mean_speed_m_per_s = 0.0;
  // Heat made at the interface outside the film — the asperity contacts' boundary friction in the
  // mixed regime (mixed_line.h, mixed_point.h set it) — in W/m², uniform over |x| ≤
  // interface_heat_half_width_m on a line and over x² + y² ≤ its square on a point, entering the
  // surfaces beside the film's own heat. Without `surfaces` the walls stay at the bulk temperature
  // and it changes nothing.
  double interface_heat_W_per_m2 = 0.0;
  double interface_heat_half_width_m = 0.0;
};

struct EhlTraction {
  double force_per_length_N_per_m = 0.0;
  double friction_coefficient = 0.0;
  double max_shear_stress_Pa = 0.0;
  double max_film_temperature_rise_K = 0.0;  // the largest mean film temperature rise ΔT (0 isothermal)
  // With FilmHeating::surfaces: the largest flash temperature rise of either surface, and the
  // smaller of the two surfaces' Péclet numbers u l/(2κ) over the sheared zone's half-length l
  // (moving_heat_source.h: the fast-source model wants it above 5). Both 0 without.
  double max_surface_temperature_rise_K = 0.0;
  double surface_peclet_number = 0.0;
  // With a LimitingShear: the share of the sheared nodes whose stress is at the limit (0 without).
  double limited_node_share = 0.0;
};

// Throws std::invalid_argument for a sliding speed that is not finite, an Eyring stress that is
// not positive (+∞ is the Newtonian film), a non-positive load, negative or non-finite heating
// constants, a negative or non-finite interface heat or half-width, surface heating without the
// film's conductivity, with a bad solid (or a second solid without the first) or with a surface
// that does not move through the contact (|Δu| ≥ 2 u_m: a surface at rest sees a stationary
// source, outside the fast-source model), or a film with fewer than two nodes or a non-positive
// film thickness where the pressure is positive, and a limiting shear stress, pressure coefficient
// or temperature coefficient that is negative or not finite.
EhlTraction ehl_line_traction(const EhlLineResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                              double eyring_stress_Pa, double load_per_length_N_per_m, const FilmHeating& heating = {},
                              const LimitingShear& limit = {});

// The same shear over a point contact's nodes (ehl_point.h), each node standing for its Δx Δy
// cell: traction force F = Σ τ Δx Δy over the pressurised nodes, μ = F / W.
struct EhlPointTraction {
  double force_N = 0.0;
  double friction_coefficient = 0.0;
  double max_shear_stress_Pa = 0.0;
  double max_film_temperature_rise_K = 0.0;
  double max_surface_temperature_rise_K = 0.0;  // as EhlTraction
  double surface_peclet_number = 0.0;
  double limited_node_share = 0.0;  // as EhlTraction: the share of the sheared nodes at the limit
};
// Throws std::invalid_argument as ehl_line_traction (a non-positive load in N), and for fields whose
// sizes do not match the grid.
EhlPointTraction ehl_point_traction(const EhlPointResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                                    double eyring_stress_Pa, double load_N, const FilmHeating& heating = {},
                                    const LimitingShear& limit = {});

}  // namespace tribo::lubrication
