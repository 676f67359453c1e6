#include "homogenise/law.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "contact/junction_locus.h"
#include "homogenise/ball_film.h"
#include "numerics/format.h"
#include "numerics/json_numbers.h"
#include "numerics/parallel.h"

namespace tribo::homogenise {

std::vector<PatchResult> solve_patches(const HomogeniseOptions& o, const std::vector<std::optional<PatchResult>>& cached,
                                       const std::function<void(int, const PatchResult&)>& on_patch) {
  validate(o);
  std::vector<PatchResult> out(static_cast<std::size_t>(o.realisations));
  std::vector<int> todo;
  for (int k = 0; k < o.realisations; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (i < cached.size() && cached[i]) {
      out[i] = *cached[i];
    } else {
      todo.push_back(k);
    }
  }
  // Kept one at a time, under a lock a throwing on_patch releases (numerics::parallel_for then
  // rethrows the first failure after the running solves and starts no more).
  std::mutex keep;
  numerics::parallel_for(
      todo.size(),
      [&](std::size_t t) {
        const int k = todo[t];
        PatchResult p = solve_patch(o, k);
        const std::lock_guard lock(keep);
        out[static_cast<std::size_t>(k)] = p;
        if (on_patch) on_patch(k, p);
      },
      o.threads);
  return out;
}

JunctionSummary junction(const HomogeniseOptions& o, const CellTable& cells) {
  JunctionSummary j;
  j.alpha = o.alpha;
  j.n = o.junction_n;
  j.mu_s_max = cells.mu_s_max.mean;
  j.mu_boundary = cells.mu_boundary.mean;
  if (!(std::isfinite(j.mu_s_max) && j.mu_s_max > 0))
    throw std::runtime_error("homogenise: no realisation gave the static friction (every junction solve failed)");
  j.sigma0_over_tau_i = contact::sigma0_over_tau_i_from_upper_asymptote(j.mu_s_max, o.alpha);  // thesis (3.1.23)
  j.location_per_s = o.location_per_s;
  j.strain_rate_index_m = o.strain_rate_index_m;
  j.reference_load_rate_per_s = o.reference_load_rate_per_s;
  j.interface_shear_strength_Pa = o.interface_shear_strength_Pa;
  return j;
}

std::vector<std::string> resolution_warnings(const HomogeniseOptions& o, const CellTable& cells) {
  std::vector<std::string> out;
  const auto check = [&](const char* name, const Estimate& value, double error) {
    const double relative = error / std::abs(value.mean);
    if (!(relative <= o.target_relative_error))
      out.push_back(std::string(name) + " = " + numerics::fmt(value.mean) + " carries a discretisation error of " +
                    numerics::fmt(error, "%.2g") + " (" + numerics::fmt(100.0 * relative, "%.2g") + " %, target " +
                    numerics::shortest(100.0 * o.target_relative_error) + " %) from the " + std::to_string(cells.junction_grid) +
                    "² junction grid; raise [homogenise] junction_grid");
  };
  check("mu_s_max", cells.mu_s_max, cells.mu_s_max_discretisation_error);
  check("mu_boundary", cells.mu_boundary, cells.mu_boundary_discretisation_error);
  return out;
}

namespace {

nlohmann::json means(const std::vector<Estimate>& c) {
  nlohmann::json a = nlohmann::json::array();
  for (const Estimate& e : c) a.push_back(e.mean);
  return a;
}
nlohmann::json errors(const std::vector<Estimate>& c) {
  nlohmann::json a = nlohmann::json::array();
  for (const Estimate& e : c) a.push_back(e.standard_error);
  return a;
}

// The cell separations left out, on the table's axis (the face centre's film: + face_drop_m).
std::vector<double> dropped_on_table_axis(const HomogeniseOptions& o, const CellTable& cells) {
  std::vector<double> out;
  for (double s : cells.dropped_separation_m) out.push_back(s + face_drop_m(o.pin));
  return out;
}

}  // namespace

nlohmann::json law_json(const HomogeniseOptions& o, const CellTable& cells, const PinTable& pin) {
  const JunctionSummary jn = junction(o, cells);
  // One realisation has no scatter to measure: its standard error is unknown (null), not 0.
  const auto standard_error = [&](const Estimate& e) {
    return cells.realisations > 1 ? nlohmann::json(e.standard_error) : nlohmann::json(nullptr);
  };
  std::vector<double> lift(pin.separation_m.size());
  for (std::size_t m = 0; m < lift.size(); ++m)
    lift[m] = std::max(pin.wedge_lift_per_eta_u_m[m], 0.0) + pin.rugosity_lift_per_eta_u_m[m];
  nlohmann::json j;
  // Micro-EHL films make the kinetic shear a function of ηU as well (rig/law_table.h "tribo-law-2").
  const bool films = !pin.eta_u_Pa_m.empty();
  j["format"] = films ? "tribo-law-2" : "tribo-law-1";
  const char* shape = o.pin.shape == PinShape::flat ? "flat" : (o.pin.shape == PinShape::spherical ? "spherical" : "ball");
  j["pin"] = {{"shape", shape},
              {"radius_m", o.pin.radius_m},
              {"crown_radius_m", o.pin.crown_radius_m},
              {"tilt_rad", o.pin.tilt_rad},
              {"nominal_area_m2", pin.nominal_area_m2},
              {"normal_load_N", o.pin.normal_load_N}};
  j["lubricant"] = {{"viscosity_Pa_s", o.lubricant.viscosity_Pa_s},
                    {"pressure_viscosity_per_Pa", o.lubricant.pressure_viscosity_per_Pa},
                    {"temperature_viscosity_per_K", o.lubricant.temperature_viscosity_per_K},
                    {"reference_temperature_K", o.lubricant.reference_temperature_K}};
  // The face's heat diffuses over the face radius (a ball's: its Hertz circle): τ = R²/κ1 (the
  // thermal time of the slider).
  const double face_radius_m = std::sqrt(pin.nominal_area_m2 / M_PI);
  j["thermal"] = {{"slider_conductivity_W_per_m_K", o.thermal.slider_conductivity_W_per_m_K},
                  {"disc_conductivity_W_per_m_K", o.thermal.disc_conductivity_W_per_m_K},
                  {"slider_diffusivity_m2_per_s", o.thermal.slider_diffusivity_m2_per_s},
                  {"time_constant_s", face_radius_m * face_radius_m / o.thermal.slider_diffusivity_m2_per_s}};
  j["junction"] = {{"alpha", jn.alpha},
                   {"n", jn.n},
                   {"sigma0_over_tau_i", jn.sigma0_over_tau_i},
                   {"location_per_s", jn.location_per_s},
                   {"strain_rate_index_m", jn.strain_rate_index_m},
                   {"reference_load_rate_per_s", jn.reference_load_rate_per_s},
                   {"interface_shear_strength_Pa", jn.interface_shear_strength_Pa},
                   {"hardness_Pa", o.hardness_Pa},
                   {"mu_s_max", jn.mu_s_max},
                   {"mu_s_max_standard_error", standard_error(cells.mu_s_max)},
                   {"mu_s_max_discretisation_error", cells.mu_s_max_discretisation_error},
                   {"mu_boundary", jn.mu_boundary},
                   {"mu_boundary_standard_error", standard_error(cells.mu_boundary)},
                   {"mu_boundary_discretisation_error", cells.mu_boundary_discretisation_error},
                   {"mu_s_max_on_junction_grid", cells.mu_s_max_on_junction_grid.mean},
                   {"mu_boundary_on_junction_grid", cells.mu_boundary_on_junction_grid.mean},
                   {"contact_grid", cells.contact_grid},
                   {"junction_grid", cells.junction_grid}};
  j["warnings"] = resolution_warnings(o, cells);
  j["table"] = {{"separation_m", pin.separation_m},
                {"solid_load_N", pin.solid_load_N},
                {"solid_load_standard_error_N", pin.solid_load_standard_error_N},
                {"solid_load_discretisation_error_N", pin.solid_load_discretisation_error_N},
                {"real_area_m2", pin.real_area_m2},
                {"real_area_standard_error_m2", pin.real_area_standard_error_m2},
                {"real_area_discretisation_error_m2", pin.real_area_discretisation_error_m2},
                {"lift_per_eta_u_m", lift},
                {"wedge_lift_per_eta_u_m", pin.wedge_lift_per_eta_u_m},
                {"rugosity_lift_per_eta_u_m", pin.rugosity_lift_per_eta_u_m},
                {"squeeze_per_eta_m", pin.squeeze_per_eta_m},
                {"shear_per_eta_u_m", pin.shear_per_eta_u_m},
                {"dropped_separations_m", dropped_on_table_axis(o, cells)}};
  if (films) {
    j["micro_ehl"] = {{"eyring_stress_Pa", o.micro_ehl->eyring_stress_Pa},
                      {"limiting_shear_stress_Pa", o.micro_ehl->limiting_shear.stress_Pa},
                      {"limiting_shear_pressure_coefficient", o.micro_ehl->limiting_shear.pressure_coefficient},
                      {"tip_roughness_m", o.micro_ehl->tip_roughness_m},
                      {"pressure_viscosity_per_Pa", o.lubricant.pressure_viscosity_per_Pa},
                      {"min_speed_m_per_s", o.micro_ehl->min_speed_m_per_s},
                      {"max_speed_m_per_s", o.micro_ehl->max_speed_m_per_s},
                      {"speeds_per_decade", o.micro_ehl->speeds_per_decade}};
    j["table"]["eta_u_Pa_m"] = pin.eta_u_Pa_m;
    j["table"]["solid_shear_Pa"] = pin.solid_shear_Pa;
    j["table"]["solid_shear_standard_error_Pa"] = pin.solid_shear_standard_error_Pa;
    j["table"]["solid_shear_discretisation_error_Pa"] = pin.solid_shear_discretisation_error_Pa;
    j["table"]["film_share"] = pin.film_share;
  }
  if (const auto& b = pin.ball) {
    nlohmann::json films = nlohmann::json::array();
    for (std::size_t k = 0; k < b->eta_u_Pa_m.size(); ++k) {
      films.push_back({{"eta_u_Pa_m", b->eta_u_Pa_m[k]},
                       {"central_film_m", numerics::finite_or_null(b->central_film_m[k])},
                       {"traction_N", numerics::finite_or_null(b->traction_N[k])}});
    }
    j["ball_film"] = {{"hertz_radius_m", b->hertz_radius_m},
                      {"film_grid", o.pin.film_grid},
                      {"share", b->share},
                      {"thinnest_film_m", b->thinnest_film_m},
                      {"not_needed", b->not_needed},
                      {"films", films},
                      {"unconverged", b->messages}};
  }
  j["cells"] = {{"sigma_m", cells.sigma_m},
                {"realisations", cells.realisations},
                {"unconverged", cells.unconverged},
                {"first_contact_separation_m", cells.first_contact_separation_m},
                {"separation_m", cells.separation_m},
                {"solid_pressure_Pa", means(cells.solid_pressure_Pa)},
                {"solid_pressure_standard_error_Pa", errors(cells.solid_pressure_Pa)},
                {"solid_pressure_discretisation_error_Pa", discretisation_error(cells.solid_pressure_Pa, cells.solid_pressure_coarse_Pa)},
                {"area_fraction", means(cells.area_fraction)},
                {"area_fraction_standard_error", errors(cells.area_fraction)},
                {"area_fraction_discretisation_error", discretisation_error(cells.area_fraction, cells.area_fraction_coarse)},
                {"contact_grid", cells.contact_grid},
                {"phi_x", means(cells.phi_x)},
                {"phi_y", means(cells.phi_y)},
                {"phi_s", means(cells.phi_s)},
                {"film_over_sigma", means(cells.film_over_sigma)},
                {"phi_f", means(cells.phi_f)},
                {"couette_shear_factor", means(cells.couette_shear_factor)},
                {"phi_fp", means(cells.phi_fp)},
                {"contact_fraction", means(cells.contact_fraction)},
                {"lift_per_eta_u_per_m", means(cells.lift_per_eta_u_per_m)},
                {"lift_per_eta_u_standard_error_per_m", errors(cells.lift_per_eta_u_per_m)}};
  if (films) {
    nlohmann::json tau = nlohmann::json::array();
    for (const auto& row : cells.spot_shear_Pa) tau.push_back(means(row));
    j["cells"]["spot_shear_Pa"] = tau;
  }
  return j;
}

}  // namespace tribo::homogenise
