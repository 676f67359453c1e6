// What a homogenisation is given: the surface pair, materials, lubricant, pin and load, and the
// separations at which the micro solves are tabulated (DESIGN §1, §4; issue 14).
//
// Separation h̄ (m) is the distance between the mean planes of the composite rough surface and
// its smooth counterpart — the rigid film is h_T = max(h̄ + z, 0) (Patir & Cheng 1978) and the
// elastic-plastic BEM is driven to the same h̄ by its approach δ = −min z − h̄, so solid and fluid
// columns of one table row belong to the same surfaces at the same separation.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "contact/surface.h"
#include "contact/thermoelastic.h"
#include "lubrication/limiting_shear.h"
#include "lubrication/micro_ehl.h"
#include "lubrication/viscosity.h"

namespace tribo::homogenise {

// flat and spherical: a pin's face of radius R. ball: a ball of radius R on the flat disc, its
// nominal contact Hertz's circle at the pin's load and its film elastohydrodynamic (ball_film.h).
enum class PinShape { flat, spherical, ball };

struct Pin {
  PinShape shape = PinShape::flat;
  double radius_m = 4.7625e-3;      // face radius R (thesis 3/16 in, Appendix I); a ball's radius
  double crown_radius_m = 0.0;      // spherical pin: radius of the crown, h = h̄ + r²/(2 R_c)
  // The face's slope along the sliding direction, its leading edge raised (either shape): the film
  // h = h̄ − θ x, x from the face's centre along the disc's motion — a converging wedge. A slider
  // seated a few µm out of true over its 9.5 mm face tilts by ≈ 1e-4 … 1e-3 rad.
  double tilt_rad = 0.0;
  // Below this the thin film's slope is small (0.01 rad is 95 µm across the thesis pin).
  static constexpr double kMaxTiltRad = 0.01;
  double normal_load_N = 93.86;     // W (thesis 21.1 lb)
  // A ball's EHL film solves (ball_film.h): nodes a side of each (≥ 17; lubrication/ehl_point.h).
  int film_grid = 65;
};

// Elastohydrodynamic films at the contact spots (lubrication/micro_ehl.h), tabulated over ηU: the
// spots' mean shear τ̄(h̄, ηU) that replaces τ_i in the law's kinetic force (law.json "tribo-law-2").
// The axis: ηU = 0, then η0 U at speeds from min to max, speeds_per_decade a decade (log-spaced);
// a rig whose η(ΔT)|U| leaves it is refused, never extrapolated.
struct MicroEhl {
  double eyring_stress_Pa = lubrication::MicroEhlOptions{}.eyring_stress_Pa;
  double tip_roughness_m = lubrication::MicroEhlOptions{}.tip_roughness_m;  // hand-set: thesis Appendix V
  lubrication::PressureViscosityLaw pressure_viscosity_law = lubrication::MicroEhlOptions{}.law;  // of the films' shear
  lubrication::LimitingShear limiting_shear;  // τ_L0 + Λ p of the films (the spots' and a ball's); off by default
  double min_speed_m_per_s = 1e-6;
  double max_speed_m_per_s = 10.0;
  int speeds_per_decade = 2;
};

struct HomogeniseOptions {
  // Composite roughness of the pair (σ = rms_height_m): grid, patch size, spectrum. Realisation k
  // uses seed surface.seed + k.
  contact::GaussianSurfaceParams surface;
  int realisations = 4;
  // A measured composite topography instead (mean removed; surface.grid² nodes over
  // surface.size_m, surface.rms_height_m its Rq): the one realisation, for the BEM and every cell.
  // Taken as periodic, as the synthesised patches are: its edges meet where the instrument's do not.
  std::optional<Eigen::ArrayXXd> measured_heights_m;
  double e_star_Pa = 1.137e11;         // composite modulus, steel on steel (DESIGN §5)
  double hardness_Pa = 1.18e9;         // σ0 of the softer body (disc, Brinell 120)
  double alpha = 25.0;                 // Tabor's α (3.1.5)
  // τ_i of the lubricated interface. Hand-set: no solve here gives the shear strength of a
  // boundary layer; default σ0/5.3 (thesis §5.1, α = 25, μs,max = 0.55 for fully plastic junctions).
  double interface_shear_strength_Pa = 1.18e9 / 5.3;
  // Anelastic junction rate law (3.1.13): area exponent n and location L = σ0^{1+n}/(Wⁿ b) at the
  // reference load rate. Hand-set: b is a material rate constant no quasi-static solve gives.
  double junction_n = 1.25;
  double location_per_s = 1.0;
  double strain_rate_index_m = 0.0;          // σ0 = κ φ̇^m (5.1.2); brass ≈ 0.1
  double reference_load_rate_per_s = 1.0;
  lubrication::Lubricant lubricant = lubrication::thesis_white_mineral_oil();
  lubrication::JaegerContact thermal;
  // The slider's thermal expansion and Poisson ratio: with thermal.slider_conductivity_W_per_m_K
  // they bound the thermal crown of its face beside the Stribeck curve (contact/thermoelastic.h).
  double slider_expansion_per_K = 11.5e-6;  // alloy steel
  double slider_poisson_ratio = 0.3;
  Pin pin;
  // Table nodes h̄/σ, strictly increasing. Nodes above a realisation's first contact (−min z)
  // carry no solid load; the largest must lie above every realisation's, so the table ends with
  // N_s = 0 and the fluid columns reach towards full film.
  std::vector<double> separation_ratios{0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0, 20.0, 50.0};
  double flow_contact_gap_fraction = 1e-3;   // film floor at contact in the flow-factor cells, × σ
  double lift_contact_gap_fraction = 0.1;    // film floor in the rugosity-lift cells, × σ
  double bem_tolerance = 1e-8;               // NormalContactOptions::tolerance
  // The solid solves (homogenise/solid_contact.h: N_s and A_r at the separations, μs,max, μ_b)
  // run on the realisation Fourier-refined to f · grid nodes a side, f the smallest power of two
  // ≥ 2 with f · grid ≥ min_contact_grid, and once more at f/2 · grid: the change is the load's
  // discretisation error. With f ≥ 4 also at f/4 · grid, and A_r is the first-order extrapolation
  // from f and f/2, its error the change of that extrapolation from f/2 and f/4 (patch.h). At the
  // thesis pressure the contact spots need ≈ 2048² on a 1 mm patch (at 128² alone μ_b came out
  // 40 % high: tests/homogenise/solid_contact_slow_test), which examples/thesis-steel.toml asks
  // for; the default is a cheaper start whose warning says when it is not enough.
  int min_contact_grid = 512;
  // The junction (μs,max and μ_b at the pin's nominal pressure) runs on three grids, each twice
  // the one before: the finest f_j · grid nodes a side, f_j the smallest power of two ≥ 4 and ≥ f
  // with f_j · grid ≥ junction_grid (0: no more than that). It reports the first-order Richardson
  // extrapolation from the two finest, and as its discretisation error the change of that
  // extrapolation from the two coarsest (solid_contact.h, cell_table.h). Only the two capped solves
  // run on grids finer than the contact grid, so the junction can be refined where the table need
  // not: on the thesis preset the error of μ_b is 1.4 % with 2048² and 0.6 % with 4096².
  int junction_grid = 0;
  // tribo homogenise warns (and law.json lists) where a discretisation error exceeds this
  // fraction of its value.
  double target_relative_error = 0.01;
  int pin_grid = 65;                         // nodes across the pin face (average Reynolds)
  std::optional<MicroEhl> micro_ehl;         // absent: the spots shear at τ_i ("tribo-law-1")
  int threads = 0;                           // realisations in parallel; 0 = all OpenMP threads
};

// Throws std::invalid_argument naming the first bad field.
void validate(const HomogeniseOptions& options);

// The refinement factor f of the solid solves (f · surface.grid nodes a side).
int contact_refinement(const HomogeniseOptions& options);
// The refinement factor f_j of the junction's finest grid (junction_grid above).
int junction_refinement(const HomogeniseOptions& options);

// The radius of the pin's nominal contact: the face's R, or a ball's Hertz circle at the pin's
// load, a = (3 W R / (4 E*))^{1/3} (Johnson 1985, (4.22)). Its area sets the nominal pressure of
// the junction solves and the face the pin stage integrates over.
double nominal_contact_radius_m(const HomogeniseOptions& options);

// The ηU axis of the micro-EHL columns (Pa·m): 0, then η0 U over the MicroEhl speeds; empty without them.
std::vector<double> micro_ehl_eta_u_Pa_m(const HomogeniseOptions& options);
// The films' constants: options.micro_ehl's with the pair's E*, τ_i and the lubricant's η0 and α
// (options.micro_ehl must be set).
lubrication::MicroEhlOptions micro_ehl_options(const HomogeniseOptions& options);
// The slider as a heated thermoelastic solid: its expansion, Poisson ratio and conductivity.
contact::ThermoelasticSolid slider_solid(const HomogeniseOptions& options);

}  // namespace tribo::homogenise
