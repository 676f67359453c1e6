#include "homogenise/patch.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "contact/surface.h"
#include "homogenise/solid_contact.h"
#include "lubrication/flow_factors.h"
#include "numerics/format.h"

namespace tribo::homogenise {
namespace {

[[noreturn]] void bad(const std::string& what) { throw std::invalid_argument("homogenise: " + what); }

// The cell options of lubrication/flow_factors.h for this one realisation, single-threaded.
lubrication::HomogenisationOptions cell_options(const HomogeniseOptions& o, std::uint64_t seed, const Eigen::ArrayXXd& z,
                                                double floor_fraction) {
  lubrication::HomogenisationOptions c;
  c.surface = o.surface;
  c.heights_m = z;  // the realisation the BEM solved, not one generated again from its seed
  c.gap_ratios = o.separation_ratios;
  c.realisations = 1;
  c.first_seed = seed;
  c.viscosity_Pa_s = o.lubricant.viscosity_Pa_s;
  c.contact_gap_fraction = floor_fraction;
  c.threads = 1;
  return c;
}

}  // namespace

void validate(const HomogeniseOptions& o) {
  contact::validate(o.surface);
  if (!(o.surface.rms_height_m > 0)) bad("surface.rms_height_m (σ) must be > 0 (give the rms height, not the slope)");
  if (o.realisations < 1) bad("realisations must be >= 1");
  if (!(o.e_star_Pa > 0 && std::isfinite(o.e_star_Pa))) bad("e_star_Pa must be finite and > 0");
  if (!(o.hardness_Pa > 0 && std::isfinite(o.hardness_Pa))) bad("hardness_Pa must be finite and > 0");
  if (!(o.alpha > 0 && std::isfinite(o.alpha))) bad("alpha must be finite and > 0");
  const double tau = o.interface_shear_strength_Pa;
  if (!(tau > 0 && std::isfinite(tau))) bad("interface_shear_strength_Pa must be finite and > 0");
  if (!(o.hardness_Pa * o.hardness_Pa > o.alpha * tau * tau))
    bad("interface_shear_strength_Pa must satisfy alpha tau_i^2 < hardness^2 (thesis 3.1.23: a finite static friction)");
  if (!(o.junction_n >= 0 && std::isfinite(o.junction_n))) bad("junction n must be finite and >= 0");
  if (!(o.location_per_s > 0 && std::isfinite(o.location_per_s))) bad("location_per_s must be finite and > 0");
  lubrication::validate(o.lubricant);
  lubrication::validate(o.thermal);
  contact::validate(slider_solid(o));
  if (!(o.pin.radius_m > 0 && std::isfinite(o.pin.radius_m))) bad("pin radius_m must be finite and > 0");
  if (!(o.pin.normal_load_N > 0 && std::isfinite(o.pin.normal_load_N))) bad("pin normal_load_N must be finite and > 0");
  if (o.pin.shape == PinShape::spherical && !(o.pin.crown_radius_m > 0 && std::isfinite(o.pin.crown_radius_m)))
    bad("a spherical pin needs crown_radius_m > 0");
  if (o.pin.shape == PinShape::ball) {
    if (!o.micro_ehl) bad("a ball (pin shape = ball) needs [micro_ehl]: its speeds are the ball film's ηU axis, its eyring_stress_Pa the film's");
    if (o.pin.tilt_rad != 0.0) bad("a ball has no tilt: tilt_rad must be 0");
    if (o.pin.film_grid < 17) bad("pin film_grid must be >= 17");
  }
  if (!(o.pin.tilt_rad >= 0 && o.pin.tilt_rad < Pin::kMaxTiltRad))
    bad("pin tilt_rad must lie in [0, 0.01) (the thin film's slope is small; 0.01 rad is 95 µm across the thesis pin)");
  if (o.separation_ratios.size() < 3) bad("separation_ratios needs at least 3 values");
  for (std::size_t k = 0; k < o.separation_ratios.size(); ++k)
    if (!(o.separation_ratios[k] > 0 && std::isfinite(o.separation_ratios[k])) ||
        (k > 0 && !(o.separation_ratios[k] > o.separation_ratios[k - 1])))
      bad("separation_ratios must be finite, > 0 and strictly increasing");
  if (!(o.flow_contact_gap_fraction > 0 && o.flow_contact_gap_fraction <= 0.5))
    bad("flow_contact_gap_fraction must lie in (0, 0.5]");
  if (!(o.lift_contact_gap_fraction > 0 && o.lift_contact_gap_fraction <= 0.5))
    bad("lift_contact_gap_fraction must lie in (0, 0.5]");
  if (!(o.bem_tolerance > 0 && o.bem_tolerance < 1)) bad("bem_tolerance must lie in (0, 1)");
  if (o.pin_grid < 9) bad("pin_grid must be >= 9");
  if (o.min_contact_grid < 1) bad("min_contact_grid must be >= 1");
  if (o.junction_grid < 0) bad("junction_grid must be >= 0");
  if (!(o.target_relative_error > 0 && o.target_relative_error < 1)) bad("target_relative_error must lie in (0, 1)");
  if (o.threads < 0) bad("threads must be >= 0");
  if (const auto& e = o.micro_ehl) {
    if (!(e->eyring_stress_Pa > 0 && std::isfinite(e->eyring_stress_Pa))) bad("micro_ehl eyring_stress_Pa must be finite and > 0");
    if (!(e->tip_roughness_m > 0 && std::isfinite(e->tip_roughness_m))) bad("micro_ehl tip_roughness_m must be finite and > 0");
    if (!(e->min_speed_m_per_s > 0 && e->max_speed_m_per_s > e->min_speed_m_per_s && std::isfinite(e->max_speed_m_per_s)))
      bad("micro_ehl speeds must satisfy 0 < min_speed_m_per_s < max_speed_m_per_s (finite)");
    if (e->speeds_per_decade < 1 || e->speeds_per_decade > 100) bad("micro_ehl speeds_per_decade must lie in [1, 100]");
    lubrication::validate(e->limiting_shear, "homogenise: micro_ehl");
    if (!(o.lubricant.pressure_viscosity_per_Pa > 0)) bad("micro_ehl needs the lubricant's pressure_viscosity_per_Pa > 0");
  }
  if (const auto& m = o.measured_heights_m) {
    if (o.realisations != 1) bad("a measured topography is one realisation: realisations must be 1");
    if (m->rows() != o.surface.grid || m->cols() != o.surface.grid)
      bad("the measured topography is " + std::to_string(m->rows()) + "x" + std::to_string(m->cols()) + ", surface.grid is " +
          std::to_string(o.surface.grid) + " (a square map is needed)");
    if (!m->allFinite()) bad("the measured topography holds a non-finite height");
  }
}

std::vector<double> micro_ehl_eta_u_Pa_m(const HomogeniseOptions& o) {
  if (!o.micro_ehl) return {};
  const MicroEhl& e = *o.micro_ehl;
  const double decades = std::log10(e.max_speed_m_per_s / e.min_speed_m_per_s);
  const int steps = std::max(1, static_cast<int>(std::ceil(decades * e.speeds_per_decade - 1e-9)));
  std::vector<double> axis{0.0};
  for (int k = 0; k <= steps; ++k)
    axis.push_back(o.lubricant.viscosity_Pa_s * e.min_speed_m_per_s * std::pow(e.max_speed_m_per_s / e.min_speed_m_per_s, static_cast<double>(k) / steps));
  return axis;
}

double nominal_contact_radius_m(const HomogeniseOptions& o) {
  if (o.pin.shape != PinShape::ball) return o.pin.radius_m;
  return std::cbrt(3.0 * o.pin.normal_load_N * o.pin.radius_m / (4.0 * o.e_star_Pa));
}

contact::ThermoelasticSolid slider_solid(const HomogeniseOptions& o) {
  return {o.slider_expansion_per_K, o.slider_poisson_ratio, o.thermal.slider_conductivity_W_per_m_K};
}

lubrication::MicroEhlOptions micro_ehl_options(const HomogeniseOptions& o) {
  lubrication::MicroEhlOptions films;
  films.e_star_Pa = o.e_star_Pa;
  films.pressure_viscosity_per_Pa = o.lubricant.pressure_viscosity_per_Pa;
  films.viscosity_Pa_s = o.lubricant.viscosity_Pa_s;
  films.law = o.micro_ehl.value().pressure_viscosity_law;
  films.eyring_stress_Pa = o.micro_ehl.value().eyring_stress_Pa;
  films.limiting_shear = o.micro_ehl.value().limiting_shear;
  films.tip_roughness_m = o.micro_ehl.value().tip_roughness_m;
  films.interface_shear_strength_Pa = o.interface_shear_strength_Pa;
  return films;
}

int contact_refinement(const HomogeniseOptions& o) {
  int f = 2;
  while (f * o.surface.grid < o.min_contact_grid) f *= 2;
  return f;
}

int junction_refinement(const HomogeniseOptions& o) {
  int f = std::max(4, contact_refinement(o));
  while (f * o.surface.grid < o.junction_grid) f *= 2;
  return f;
}

PatchResult solve_patch(const HomogeniseOptions& o, int realisation) {
  validate(o);
  PatchResult r;
  r.seed = o.surface.seed + static_cast<std::uint64_t>(realisation);
  contact::GaussianSurfaceParams sp = o.surface;
  sp.seed = r.seed;
  const Eigen::ArrayXXd z = o.measured_heights_m ? *o.measured_heights_m : contact::gaussian_surface(sp);
  const double sigma = o.surface.rms_height_m;
  const std::size_t nodes = o.separation_ratios.size();
  for (double ratio : o.separation_ratios) r.separation_m.push_back(ratio * sigma);

  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto bem_start = Clock::now();

  // Solid: on the contact grid, and on half of it for the discretisation error.
  const int f = contact_refinement(o);
  const Eigen::ArrayXXd z_fine = contact::fourier_refine(z, f);
  r.first_contact_separation_m = -z_fine.minCoeff();  // the refined surface's lowest point (≤ the grid's)
  if (!(r.separation_m.back() > r.first_contact_separation_m))
    bad("the largest separation ratio " + numerics::shortest(o.separation_ratios.back()) +
        " lies below the first contact of seed " + std::to_string(r.seed) + " at h/σ = " +
        numerics::shortest(r.first_contact_separation_m / sigma) + "; add a larger one");
  // The table on the contact grid, on half of it and — when the contact grid is at least four
  // times the surface's — on a quarter of it, each grid started from the one below.
  SolidPressures coarser_pressures, coarse_pressures, fine_pressures;
  std::optional<SolidContact> coarser;
  if (f >= 4) coarser = solid_contact(o, contact::fourier_refine(z, f / 4), nullptr, &coarser_pressures);
  const SolidContact coarse = solid_contact(o, contact::fourier_refine(z, f / 2), coarser ? &coarser_pressures : nullptr, &coarse_pressures);
  coarser_pressures = {};
  const bool refine_junction = junction_refinement(o) > f;
  const SolidContact fine = solid_contact(o, z_fine, &coarse_pressures, refine_junction ? &fine_pressures : nullptr);
  coarse_pressures = {};
  fine_pressures.at_node.clear();  // only the junction's fields start its finer solves
  r.contact_grid = f * static_cast<int>(o.surface.grid);
  r.solid_pressure_Pa = fine.solid_pressure_Pa, r.area_fraction = fine.area_fraction;
  r.solid_pressure_coarse_Pa = coarse.solid_pressure_Pa, r.area_fraction_coarse = coarse.area_fraction;
  if (coarser) {
    // A_r's excess is first order in Δ as the junction's (solid_contact.h): the column is the
    // extrapolation from the two finest grids, its coarse twin the one from the two coarsest (so the
    // law's discretisation errors are the extrapolation's change), both kept above the plastic
    // bound N_s/σ0. The load converges fast (its change 1024² → 2048² on the thesis preset ≤ 0.13 %)
    // and stays the contact grid's.
    // Where the coarsest solve failed, the middle grid's value stands in for the coarse twin (the
    // error is then the extrapolation's own correction, on the safe side); where the middle one
    // failed, the node keeps the contact grid's value and its error is unknown, as without.
    for (std::size_t m = 0; m < nodes; ++m) {
      const double fine_area = fine.area_fraction[m], coarse_area = coarse.area_fraction[m];
      if (!std::isfinite(coarse_area)) continue;
      r.area_fraction[m] = extrapolate_above(coarse_area, fine_area, fine.solid_pressure_Pa[m] / o.hardness_Pa);
      const double below = extrapolate_above(coarser->area_fraction[m], coarse_area, coarse.solid_pressure_Pa[m] / o.hardness_Pa);
      r.area_fraction_coarse[m] = std::isfinite(below) ? below : coarse_area;
    }
    r.bem_iterations += coarser->bem_iterations;
    r.unconverged += coarser->unconverged;
    r.messages += coarser->messages;
  }
  r.area_extrapolated = coarser.has_value();
  r.spot_shear_Pa = fine.spot_shear_Pa, r.spot_shear_coarse_Pa = coarse.spot_shear_Pa;
  r.spot_film_share = fine.spot_film_share;
  r.bem_iterations += fine.bem_iterations + coarse.bem_iterations;
  r.unconverged += fine.unconverged + coarse.unconverged;
  r.messages += fine.messages + coarse.messages;

  // The junction on its three grids, coarsest first: the solid solves' where they coincide, the
  // others alone, each finer one started from the one below it.
  const int fj = junction_refinement(o);
  r.junction_grid = fj * static_cast<int>(o.surface.grid);
  std::array<SolidContact, 3> junction;
  for (int level = 0; level < 3; ++level) {
    const int fl = fj >> (2 - level);
    if (coarser && fl == f / 4) {
      junction[level] = *coarser;
    } else if (fl == f / 2) {
      junction[level] = coarse;
    } else if (fl == f) {
      junction[level] = fine;
    } else {
      SolidPressures next;
      junction[level] = junction_contact(o, contact::fourier_refine(z, fl), fl > f ? &fine_pressures : nullptr, &next);
      fine_pressures = std::move(next);
      r.bem_iterations += junction[level].bem_iterations;
      r.unconverged += junction[level].unconverged;
      r.messages += junction[level].messages;
    }
  }
  fine_pressures = {};
  r.mu_s_max_coarser = junction[0].mu_s_max, r.mu_boundary_coarser = junction[0].mu_boundary;
  r.mu_s_max_coarse = junction[1].mu_s_max, r.mu_boundary_coarse = junction[1].mu_boundary;
  r.mu_s_max = junction[2].mu_s_max, r.mu_boundary = junction[2].mu_boundary;
  r.bem_s = seconds_since(bem_start);

  // Fluid cells on the same realisation.
  const auto flow_start = Clock::now();
  const auto ff = lubrication::flow_factors(cell_options(o, r.seed, z, o.flow_contact_gap_fraction));
  r.flow_cells_s = seconds_since(flow_start);
  const auto lift_start = Clock::now();
  const auto lift = lubrication::rugosity_lift(cell_options(o, r.seed, z, o.lift_contact_gap_fraction));
  r.lift_cells_s = seconds_since(lift_start);
  for (std::size_t m = 0; m < nodes; ++m) {
    r.phi_x.push_back(ff[m].phi_x.mean);
    r.phi_y.push_back(ff[m].phi_y.mean);
    r.phi_s.push_back(ff[m].phi_s.mean);
    r.film_over_sigma.push_back(ff[m].mean_film_over_sigma.mean);
    r.phi_f.push_back(ff[m].phi_f.mean);
    r.couette_shear_factor.push_back(ff[m].couette_shear_factor.mean);
    r.phi_fp.push_back(ff[m].phi_fp.mean);
    r.contact_fraction.push_back(ff[m].contact_fraction.mean);
    r.lift_per_eta_u_per_m.push_back(lift[m].mean_pressure_per_eta_u.mean);
    if (ff[m].unconverged > 0 || lift[m].unconverged > 0) {
      ++r.unconverged;
      r.messages += "Reynolds cell at h/σ = " + numerics::shortest(o.separation_ratios[m]) + " did not converge; ";
    }
  }
  return r;
}

nlohmann::json to_json(const PatchResult& p) {
  return {{"seed", p.seed},
          {"first_contact_separation_m", p.first_contact_separation_m},
          {"separation_m", p.separation_m},
          {"solid_pressure_Pa", p.solid_pressure_Pa},
          {"area_fraction", p.area_fraction},
          {"phi_x", p.phi_x},
          {"phi_y", p.phi_y},
          {"phi_s", p.phi_s},
          {"film_over_sigma", p.film_over_sigma},
          {"phi_f", p.phi_f},
          {"couette_shear_factor", p.couette_shear_factor},
          {"phi_fp", p.phi_fp},
          {"contact_fraction", p.contact_fraction},
          {"lift_per_eta_u_per_m", p.lift_per_eta_u_per_m},
          {"mu_s_max", p.mu_s_max},
          {"mu_boundary", p.mu_boundary},
          {"solid_pressure_coarse_Pa", p.solid_pressure_coarse_Pa},
          {"area_fraction_coarse", p.area_fraction_coarse},
          {"mu_s_max_coarse", p.mu_s_max_coarse},
          {"mu_boundary_coarse", p.mu_boundary_coarse},
          {"mu_s_max_coarser", p.mu_s_max_coarser},
          {"mu_boundary_coarser", p.mu_boundary_coarser},
          {"junction_grid", p.junction_grid},
          {"area_extrapolated", p.area_extrapolated},
          {"spot_shear_Pa", p.spot_shear_Pa},
          {"spot_shear_coarse_Pa", p.spot_shear_coarse_Pa},
          {"spot_film_share", p.spot_film_share},
          {"contact_grid", p.contact_grid},
          {"bem_iterations", p.bem_iterations},
          {"stage_wall_s", {{"bem", p.bem_s}, {"flow_cells", p.flow_cells_s}, {"lift_cells", p.lift_cells_s}}},
          {"unconverged", p.unconverged},
          {"messages", p.messages}};
}

PatchResult patch_from_json(const nlohmann::json& j) {
  PatchResult p;
  j.at("seed").get_to(p.seed);
  j.at("first_contact_separation_m").get_to(p.first_contact_separation_m);
  j.at("separation_m").get_to(p.separation_m);
  j.at("solid_pressure_Pa").get_to(p.solid_pressure_Pa);
  j.at("area_fraction").get_to(p.area_fraction);
  j.at("phi_x").get_to(p.phi_x);
  j.at("phi_y").get_to(p.phi_y);
  j.at("phi_s").get_to(p.phi_s);
  j.at("film_over_sigma").get_to(p.film_over_sigma);
  j.at("phi_f").get_to(p.phi_f);
  j.at("couette_shear_factor").get_to(p.couette_shear_factor);
  j.at("phi_fp").get_to(p.phi_fp);
  j.at("contact_fraction").get_to(p.contact_fraction);
  j.at("lift_per_eta_u_per_m").get_to(p.lift_per_eta_u_per_m);
  j.at("mu_s_max").get_to(p.mu_s_max);
  j.at("mu_boundary").get_to(p.mu_boundary);
  j.at("solid_pressure_coarse_Pa").get_to(p.solid_pressure_coarse_Pa);
  j.at("area_fraction_coarse").get_to(p.area_fraction_coarse);
  j.at("mu_s_max_coarse").get_to(p.mu_s_max_coarse);
  j.at("mu_boundary_coarse").get_to(p.mu_boundary_coarse);
  j.at("mu_s_max_coarser").get_to(p.mu_s_max_coarser);
  j.at("mu_boundary_coarser").get_to(p.mu_boundary_coarser);
  j.at("junction_grid").get_to(p.junction_grid);
  j.at("area_extrapolated").get_to(p.area_extrapolated);
  j.at("spot_shear_Pa").get_to(p.spot_shear_Pa);
  j.at("spot_shear_coarse_Pa").get_to(p.spot_shear_coarse_Pa);
  j.at("spot_film_share").get_to(p.spot_film_share);
  j.at("contact_grid").get_to(p.contact_grid);
  j.at("bem_iterations").get_to(p.bem_iterations);
  const nlohmann::json& t = j.at("stage_wall_s");
  t.at("bem").get_to(p.bem_s);
  t.at("flow_cells").get_to(p.flow_cells_s);
  t.at("lift_cells").get_to(p.lift_cells_s);
  j.at("unconverged").get_to(p.unconverged);
  j.at("messages").get_to(p.messages);
  return p;
}

}  // namespace tribo::homogenise
