// libFuzzer harness for the `tribo ehl` config loader (apps/ehl_run.h): the input is the TOML text,
// parsed in memory. Bad input must end as InputError or std::invalid_argument (exit status 2); a
// config that loads must hold a contact (line or point) and options the solver accepts; anything
// else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "apps/config.h"
#include "apps/ehl_run.h"
#include "fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = "/nonexistent/tribo-fuzz/ehl.toml";
  try {
    const toml::table doc = tribo::cli::parse_toml_text(std::string_view(reinterpret_cast<const char*>(data), size), path);
    const tribo::cli::EhlRun run = tribo::cli::load_ehl_run(doc, path);
    if (run.point) {  // a ball on a disc
      const auto& p = *run.point;
      for (double v : {p.load_N, p.reduced_radius_m, p.reduced_modulus_Pa, p.mean_speed_m_per_s}) TRIBO_FUZZ_CHECK(std::isfinite(v) && v > 0.0);
      const auto& o = run.point_options;
      TRIBO_FUZZ_CHECK(o.nodes_x >= 11 && o.nodes_y >= 11 && o.nodes_x <= 513 && o.nodes_y <= 513 && o.preconditioner_reach >= 0 && o.preconditioner_reach <= 16);
      TRIBO_FUZZ_CHECK(o.inlet_over_radius < -1.0 && o.outlet_over_radius > 1.0 && o.side_over_radius > 1.0);
    } else {
      const auto& c = run.contact;
      for (double v : {c.load_per_length_N_per_m, c.reduced_radius_m, c.reduced_modulus_Pa, c.mean_speed_m_per_s})
        TRIBO_FUZZ_CHECK(std::isfinite(v) && v > 0.0);
      TRIBO_FUZZ_CHECK(run.options.nodes >= 11 && run.options.inlet_over_half_width < -1.0 && run.options.outlet_over_half_width > 1.0);
    }
    if (run.roughness) {  // either geometry (a rough ball since a5e6aa4): summits the GW model accepts
      const auto& r = *run.roughness;
      for (double v : {r.summits.summit_density_per_m2, r.summits.summit_radius_m, r.summits.summit_std_m, r.summits.e_star_Pa})
        TRIBO_FUZZ_CHECK(std::isfinite(v) && v > 0.0);
      TRIBO_FUZZ_CHECK(std::isfinite(r.summit_height_m) && r.summit_height_m >= 0.0);
      TRIBO_FUZZ_CHECK(std::isfinite(r.boundary_friction_coefficient) && r.boundary_friction_coefficient >= 0.0);
    }
    if (run.profile) {  // a waviness or trace, either geometry (a ridged ball since 2026-12-02): a profile the solvers accept
      const auto& r = run.profile->surface;
      TRIBO_FUZZ_CHECK((r.x_m.empty() && r.height_m.empty() && r.map) ||
                       (r.x_m.size() >= 2 && r.x_m.size() == r.height_m.size() && r.x_m.size() <= 1000001));
      for (std::size_t k = 0; k < r.x_m.size(); ++k)
        TRIBO_FUZZ_CHECK(std::isfinite(r.x_m[k]) && std::isfinite(r.height_m[k]) && (k == 0 || r.x_m[k] > r.x_m[k - 1]));
      TRIBO_FUZZ_CHECK(std::isfinite(r.contact_film_m) && r.contact_film_m > 0.0);
      TRIBO_FUZZ_CHECK(std::isfinite(r.contact_margin_m) && r.contact_margin_m >= 0.0);
      TRIBO_FUZZ_CHECK(r.hardness_Pa > 0.0);  // +∞ without [material]
      TRIBO_FUZZ_CHECK(std::isfinite(run.profile->boundary_friction_coefficient) && run.profile->boundary_friction_coefficient >= 0.0);
    }
    if (run.surface_map) {  // a point contact's map, placed: finite, within the solver's resolution
      TRIBO_FUZZ_CHECK(run.point && run.profile && run.profile->surface.map);
      const auto& m = *run.profile->surface.map;
      TRIBO_FUZZ_CHECK(m.height_m.rows() >= 2 && m.height_m.cols() >= 2 && m.height_m.allFinite());
      TRIBO_FUZZ_CHECK(m.dx_m > 0.0 && m.dy_m > 0.0 && std::isfinite(m.x0_m) && std::isfinite(m.y0_m));
      TRIBO_FUZZ_CHECK(run.surface_map->cutoff_m && *run.surface_map->cutoff_m > 0.0);
    }
    TRIBO_FUZZ_CHECK(std::isfinite(run.sliding_speed_m_per_s));
    TRIBO_FUZZ_CHECK(run.eyring_stress_Pa > 0.0);
    TRIBO_FUZZ_CHECK(run.heating.thermal_conductivity_W_per_m_K >= 0.0 && run.heating.temperature_viscosity_per_K >= 0.0);
    TRIBO_FUZZ_CHECK(run.limiting_shear.stress_Pa >= 0.0 && std::isfinite(run.limiting_shear.stress_Pa));  // τ_L0 + Λ p: finite, >= 0
    TRIBO_FUZZ_CHECK(run.limiting_shear.pressure_coefficient >= 0.0 && std::isfinite(run.limiting_shear.pressure_coefficient));
    TRIBO_FUZZ_CHECK(run.limiting_shear.temperature_coefficient_per_K >= 0.0 && std::isfinite(run.limiting_shear.temperature_coefficient_per_K));
    if (run.heating.surfaces) {  // [solids]: positive constants, the film conducting, both surfaces moving
      TRIBO_FUZZ_CHECK(run.heating.thermal_conductivity_W_per_m_K > 0.0 && run.heating.surfaces->density_kg_per_m3 > 0.0);
      TRIBO_FUZZ_CHECK(std::abs(run.sliding_speed_m_per_s) < 2.0 * run.heating.mean_speed_m_per_s);
    }
    TRIBO_FUZZ_CHECK(!run.heating.second_surface || run.heating.surfaces);
  } catch (const tribo::cli::InputError& e) {
    TRIBO_FUZZ_CHECK(std::string_view(e.what()).find(path) != std::string_view::npos);  // names the config
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
