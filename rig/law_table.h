// The homogenised friction-law table `law.json` (formats "tribo-law-1" and "tribo-law-2"), written by
// `tribo homogenise` (homogenise/) and read here as plain data — the rig does not link the micro
// solvers (DESIGN §1, §4). Every column is a function of the pin face's mean separation h̄ (m):
//
//   N_s(h̄)       table.solid_load_N        load carried by asperity contact (N), non-increasing, last 0
//   A_r(h̄)       table.real_area_m2        real contact area (m²), non-increasing, last 0
//   L(h̄)         table.lift_per_eta_u_m    N_lift = η U L(h̄)   rugosity / wedge lift (m), ≥ 0
//   K(h̄)         table.squeeze_per_eta_m   N_sq = −η K(h̄) ḣ     squeeze film (m), > 0
//   S(h̄)         table.shear_per_eta_u_m   F_fluid = η U S(h̄)  viscous shear of the film (m), > 0
//
// and in "tribo-law-2" a second axis, ηU (Pa·m, the disc speed times the oil's viscosity at its
// temperature), for the shear of the real contact area:
//
//   τ̄(h̄, ηU)    table.solid_shear_Pa [h][ηU]  F_solid = τ̄ A_r (τ_i A_r in "tribo-law-1"), > 0
//   s_f(h̄, ηU)   table.film_share [h][ηU]      share of A_r the films separate (optional), in [0, 1]
//
// and, for a ball (optional), its EHL film: "ball_film" holds the shares s_j of the load the film
// was solved at and, per ηU node, the central film and traction at each (null where a solve was
// left out) — the rig reads the film's load W_f(h̄, ηU) and traction F_f(h̄, ηU) from them
// (rig/ball_film.h). A ball's table holds its fluid there: its L and S are 0 (S > 0 otherwise),
// and it was solved at the ball's load pin.normal_load_N (its Hertz circle and film shares are
// that load's), so the rig takes it at that load only (rig/homogenised_law.h).
//
// plus the pin, the lubricant (η = η0 exp(−γ ΔT), lubrication/viscosity.h), the thermal constants
// of Jaeger's flash temperature (thesis (5.2.1)) and the junction locus (thesis (3.1.24)) with the
// interface shear strength τ_i. Unknown keys (provenance, standard errors, the Stribeck curve) are
// ignored.
//
// Interpolation: MonotoneTable is the piecewise-cubic Hermite interpolant with Fritsch–Carlson
// slopes (F. N. Fritsch and R. E. Carlson, "Monotone piecewise cubic interpolation",
// SIAM J. Numer. Anal. 17 (1980) 238–246): C¹, exact at the nodes and on linear data, and
// monotone on every interval where the data are, so a non-increasing, non-negative column (N_s,
// A_r) stays non-increasing and non-negative between its nodes. It never extrapolates. Over ηU
// (EtaUTable) the columns are interpolated linearly in ln ηU between positive nodes and linearly
// in ηU between 0 and the first, and never extrapolated either.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "contact/junction_locus.h"

namespace tribo::rig {

struct LawPin {
  std::string shape;              // e.g. "flat" (informational)
  double radius_m = 0.0;          // informational
  double nominal_area_m2 = 0.0;   // apparent area of the pin face; floors Jaeger's heat-path area
  double normal_load_N = 0.0;     // load the provenance solves used (informational: the table is load-independent)
};

struct LawLubricant {
  double viscosity_Pa_s = 0.0;                // η0 at the reference temperature; 0 = dry
  double temperature_viscosity_per_K = 0.0;   // γ
  double reference_temperature_K = 300.15;    // T0
};

struct LawThermal {
  double slider_conductivity_W_per_m_K = 0.0;   // ξ1
  double disc_conductivity_W_per_m_K = 0.0;     // ξ2
  double slider_diffusivity_m2_per_s = 0.0;     // b² (b = √diffusivity in (5.2.1))
  double time_constant_s = 0.0;                 // relaxation time of ΔT towards Jaeger's ΔT_J
};

struct LawJunction {
  contact::JunctionLocus locus;                 // α, n, σ0/τ_i, L, m, φ̇_ref (thesis (3.1.24), (5.1.2))
  double interface_shear_strength_Pa = 0.0;     // τ_i
};

struct LawTable {
  std::string source;   // where it was read from (for messages); empty when built in code
  LawPin pin;
  LawLubricant lubricant;
  LawThermal thermal;
  LawJunction junction;
  std::vector<double> separation_m;         // h̄, strictly increasing, > 0
  std::vector<double> solid_load_N;         // N_s
  std::vector<double> real_area_m2;         // A_r
  std::vector<double> lift_per_eta_u_m;     // L
  std::vector<double> squeeze_per_eta_m;    // K
  std::vector<double> shear_per_eta_u_m;    // S
  // "tribo-law-2" only (empty in "tribo-law-1"): the mean shear of the real contact area with the
  // asperity tops' EHL films (lubrication/micro_ehl.h), τ̄(h̄, ηU), per separation and ηU node.
  std::vector<double> eta_u_Pa_m;                 // ηU axis (Pa·m): starts at 0, strictly increasing
  std::vector<std::vector<double>> solid_shear_Pa;  // [separation][ηU], > 0
  // Optional (informational: the rig reports it, its forces do not use it): the share of the real
  // area the films separate, [separation][ηU] in [0, 1]; empty when absent.
  std::vector<std::vector<double>> film_share;
  // Optional: a ball's EHL film (rig/ball_film.h) — the shares of the load it was solved at
  // (strictly increasing, the last 1) and per ηU node [ηU][share] its central film (m) and traction
  // (N), NaN where the solve was left out (the row at ηU = 0 all NaN); empty for a pin.
  std::vector<double> ball_share;
  std::vector<std::vector<double>> ball_central_film_m, ball_traction_N;
  bool has_ball_film() const { return !ball_share.empty(); }
};

// Reads law.json. Any defect (unreadable file, malformed JSON, wrong format, missing key, wrong
// type, NaN, columns of different lengths or shorter than 3, separation not increasing, a
// negative entry, ...) throws std::invalid_argument "law table FILE: key 'a.b': reason".
LawTable read_law_table(const std::filesystem::path& path);
// The same from a parsed document; `source` names it in messages.
LawTable law_table_from_json(const nlohmann::json& doc, const std::string& source);

// The checks read_law_table applies, for tables built in code; messages as above.
void validate(const LawTable& table);

// Monotone C¹ interpolant y(x) through (x_i, y_i) (Fritsch–Carlson PCHIP, see the top of this file).
class MonotoneTable {
 public:
  // x strictly increasing and finite, y finite, same length ≥ 2; else std::invalid_argument.
  // `axis` names the abscissa in out-of-range messages (e.g. "separation_m").
  MonotoneTable(std::vector<double> x, std::vector<double> y, std::string axis = "x");

  // y(x) and dy/dx for x in [x.front(), x.back()]; outside it std::out_of_range naming the axis,
  // the value and the range.
  double value(double x) const;
  double slope(double x) const;

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  const std::string& axis() const { return axis_; }

 private:
  std::size_t interval(double x) const;

  std::vector<double> x_, y_, d_;   // nodes, values, Hermite slopes
  std::string axis_;
};

// A "tribo-law-2" column over h̄ and ηU (τ̄, the film share): PCHIP over h̄ at each ηU node
// (MonotoneTable), linear between ηU nodes (in ln ηU above the first positive node). Outside either
// axis std::out_of_range.
class EtaUTable {
 public:
  // The table's separation axis, its ηU axis and the column's rows; std::invalid_argument on a shape mismatch.
  EtaUTable(const std::vector<double>& separation_m, std::vector<double> eta_u_Pa_m, const std::vector<std::vector<double>>& rows);
  double value(double h_m, double eta_u_Pa_m) const;
  // ∂/∂h̄ of value at fixed ηU.
  double slope_h(double h_m, double eta_u_Pa_m) const;

 private:
  // The ηU interval k holding eta_u and the weight of its upper node (std::out_of_range outside).
  std::pair<std::size_t, double> locate(double eta_u_Pa_m) const;

  std::vector<double> eta_u_;
  std::vector<MonotoneTable> at_eta_u_;  // the column over h̄ at each ηU node
};

}  // namespace tribo::rig
