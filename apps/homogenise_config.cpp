#include "apps/homogenise_config.h"

#include <cmath>
#include <optional>

#include "apps/config.h"
#include "apps/surface_config.h"
#include "contact/surface_io.h"
#include "numerics/format.h"

namespace tribo::cli {
namespace {

// [surface] kind = "file": a measured composite topography (the readers of contact/surface_io.h),
// square, its side from the file or [domain] size_m; the mean removed and σ its Rq. One realisation.
void read_measured_surface(ConfigTable& surface, ConfigTable* domain, homogenise::HomogeniseOptions& o) {
  const std::filesystem::path file = surface.input_file("file");
  const double scale = surface.number("height_scale", 1.0, Range::positive);
  const contact::Topography topo = input_guard(surface, "file", [&] { return contact::read_topography(file, scale); });
  const Eigen::Index n = topo.heights_m.rows();
  if (topo.heights_m.cols() != n)
    surface.fail("file", file.string() + " is " + std::to_string(n) + "x" + std::to_string(topo.heights_m.cols()) +
                             ": homogenise needs a square map (crop it)");
  const std::optional<double> size_m = domain ? domain->optional_number("size_m", Range::positive) : std::nullopt;
  double side = topo.lx_m;
  if (side == 0.0) {
    if (!size_m) surface.fail("file", file.string() + " gives no lateral size: set [domain] size_m");
    side = *size_m;
  } else if (size_m && std::abs(*size_m - side) > 1e-9 * side) {
    domain->fail("size_m", "does not match the x extent " + numerics::shortest(side) + " m of " + file.string());
  }
  if (domain && domain->has("grid") && domain->integer("grid", 0, 1) != n)
    domain->fail("grid", "does not match the " + std::to_string(n) + " rows of " + file.string());
  Eigen::ArrayXXd z = topo.heights_m - topo.heights_m.mean();
  o.surface.grid = n;
  o.surface.size_m = side;
  o.surface.rms_height_m = std::sqrt(z.square().mean());
  o.surface.rms_slope = 0.0;
  if (!(o.surface.rms_height_m > 0.0)) surface.fail("file", file.string() + " is flat (Rq = 0)");
  o.measured_heights_m = std::move(z);
  o.realisations = 1;
}

}  // namespace

HomogeniseRun load_homogenise_run(const std::filesystem::path& path) {
  return load_homogenise_run(parse_toml_file(path), path);
}

HomogeniseRun load_homogenise_run(const toml::table& doc, const std::filesystem::path& path) {
  ConfigTable root(doc, path.string(), "");
  HomogeniseRun run;
  homogenise::HomogeniseOptions& o = run.options;

  auto surface = root.table("surface");
  if (!surface) root.fail("surface", "table [surface] is required (the composite roughness of the pair)");
  const std::string kind = surface->choice("kind", "gaussian", {"gaussian", "file"});
  auto domain = root.table("domain");
  if (kind == "gaussian") {
    o.surface = read_gaussian_surface(*surface, domain ? &*domain : nullptr);
  } else {
    read_measured_surface(*surface, domain ? &*domain : nullptr, o);
  }
  surface->finish();
  if (domain) domain->finish();

  if (auto m = root.table("material")) {
    o.e_star_Pa = m->number("e_star_Pa", o.e_star_Pa, Range::positive);
    o.hardness_Pa = m->number("hardness_Pa", o.hardness_Pa, Range::positive);
    o.alpha = m->number("alpha", o.alpha, Range::positive);
    o.interface_shear_strength_Pa = m->number("interface_shear_strength_Pa", o.hardness_Pa / 5.3, Range::positive);
    o.thermal.slider_conductivity_W_per_m_K =
        m->number("slider_conductivity_W_per_m_K", o.thermal.slider_conductivity_W_per_m_K, Range::positive);
    o.thermal.disc_conductivity_W_per_m_K =
        m->number("disc_conductivity_W_per_m_K", o.thermal.disc_conductivity_W_per_m_K, Range::positive);
    o.thermal.slider_diffusivity_m2_per_s =
        m->number("slider_diffusivity_m2_per_s", o.thermal.slider_diffusivity_m2_per_s, Range::positive);
    o.slider_expansion_per_K = m->number("slider_expansion_per_K", o.slider_expansion_per_K, Range::non_negative);
    o.slider_poisson_ratio = m->number("slider_poisson_ratio", o.slider_poisson_ratio, Range::non_negative);
    if (!(o.slider_poisson_ratio < 0.5)) m->fail("slider_poisson_ratio", "must lie in [0, 0.5)");
    m->finish();
  }
  if (auto j = root.table("junction")) {
    o.junction_n = j->number("n", o.junction_n, Range::non_negative);
    o.location_per_s = j->number("location_per_s", o.location_per_s, Range::positive);
    o.strain_rate_index_m = j->number("strain_rate_index_m", o.strain_rate_index_m, Range::non_negative);
    o.reference_load_rate_per_s = j->number("reference_load_rate_per_s", o.reference_load_rate_per_s, Range::positive);
    j->finish();
  }
  if (auto l = root.table("lubricant")) {
    o.lubricant.viscosity_Pa_s = l->number("viscosity_Pa_s", o.lubricant.viscosity_Pa_s, Range::positive);
    o.lubricant.pressure_viscosity_per_Pa =
        l->number("pressure_viscosity_per_Pa", o.lubricant.pressure_viscosity_per_Pa, Range::non_negative);
    o.lubricant.temperature_viscosity_per_K =
        l->number("temperature_viscosity_per_K", o.lubricant.temperature_viscosity_per_K, Range::non_negative);
    o.lubricant.reference_temperature_K =
        l->number("reference_temperature_K", o.lubricant.reference_temperature_K, Range::positive);
    l->finish();
  }
  if (auto p = root.table("pin")) {
    const std::string shape = p->choice("shape", "flat", {"flat", "spherical", "ball"});
    o.pin.shape = shape == "flat" ? homogenise::PinShape::flat
                                  : (shape == "spherical" ? homogenise::PinShape::spherical : homogenise::PinShape::ball);
    o.pin.radius_m = p->number("radius_m", o.pin.radius_m, Range::positive);
    o.pin.normal_load_N = p->number("normal_load_N", o.pin.normal_load_N, Range::positive);
    if (o.pin.shape == homogenise::PinShape::spherical) {
      o.pin.crown_radius_m = p->required_number("crown_radius_m", Range::positive);
    } else if (p->has("crown_radius_m")) {
      p->fail("crown_radius_m", "is only used with shape = \"spherical\"");
    }
    if (o.pin.shape == homogenise::PinShape::ball) {
      o.pin.film_grid = static_cast<int>(p->integer("film_grid", o.pin.film_grid, 17, 1025));
      if (p->has("tilt_rad")) p->fail("tilt_rad", "is not used with shape = \"ball\" (a ball has no tilt)");
      if (!root.has("micro_ehl"))
        p->fail("shape", "\"ball\" needs a [micro_ehl] table: its speeds are the ball film's axis, its eyring_stress_Pa the film's");
    } else if (p->has("film_grid")) {
      p->fail("film_grid", "is only used with shape = \"ball\"");
    }
    o.pin.tilt_rad = p->number("tilt_rad", o.pin.tilt_rad, Range::non_negative);
    if (!(o.pin.tilt_rad < homogenise::Pin::kMaxTiltRad))
      p->fail("tilt_rad", "must be below 0.01 rad (the thin film's slope is small)");
    p->finish();
  }
  double u_min = 1e-4, u_max = 1.0;
  int count = 25;
  if (auto s = root.table("speeds")) {
    u_min = s->number("min_m_per_s", u_min, Range::positive);
    u_max = s->number("max_m_per_s", u_max, Range::positive);
    count = static_cast<int>(s->integer("count", count, 2, 100'000));
    if (!(u_max > u_min)) s->fail("max_m_per_s", "must exceed min_m_per_s");
    s->finish();
  }
  for (int k = 0; k < count; ++k)
    run.speeds_m_per_s.push_back(u_min * std::pow(u_max / u_min, static_cast<double>(k) / (count - 1)));
  if (auto e = root.table("micro_ehl")) {
    homogenise::MicroEhl m;
    m.eyring_stress_Pa = e->number("eyring_stress_Pa", m.eyring_stress_Pa, Range::positive);
    m.tip_roughness_m = e->number("tip_roughness_m", m.tip_roughness_m, Range::positive);
    m.limiting_shear.stress_Pa = e->number("limiting_shear_stress_Pa", 0.0, Range::non_negative);
    m.limiting_shear.pressure_coefficient = e->number("limiting_shear_pressure_coefficient", 0.0, Range::non_negative);
    m.min_speed_m_per_s = e->number("min_speed_m_per_s", m.min_speed_m_per_s, Range::positive);
    m.max_speed_m_per_s = e->number("max_speed_m_per_s", m.max_speed_m_per_s, Range::positive);
    m.speeds_per_decade = static_cast<int>(e->integer("speeds_per_decade", m.speeds_per_decade, 1, 100));
    m.pressure_viscosity_law = e->choice("pressure_viscosity_law", "roelands", {"roelands", "barus"}) == "barus"
                                   ? lubrication::PressureViscosityLaw::barus
                                   : lubrication::PressureViscosityLaw::roelands;
    if (!(m.max_speed_m_per_s > m.min_speed_m_per_s)) e->fail("max_speed_m_per_s", "must exceed min_speed_m_per_s");
    if (m.max_speed_m_per_s < u_max)
      e->fail("max_speed_m_per_s", "must reach the Stribeck curve's [speeds] max_m_per_s = " + numerics::shortest(u_max) +
                                       " (the law is never extrapolated)");
    if (auto l = root.table("lubricant"); l && !(o.lubricant.pressure_viscosity_per_Pa > 0.0))  // only [lubricant] sets α
      l->fail("pressure_viscosity_per_Pa", "must be positive with [micro_ehl] (the films' thickness and shear need it)");
    o.micro_ehl = m;
    e->finish();
  }
  if (auto h = root.table("homogenise")) {
    o.realisations = static_cast<int>(h->integer("realisations", o.realisations, 1, 1'000'000));
    if (o.measured_heights_m && o.realisations != 1) h->fail("realisations", "a measured topography is one realisation: must be 1");
    if (h->has("separation_ratios")) o.separation_ratios = h->number_array("separation_ratios", Range::positive);
    o.flow_contact_gap_fraction = h->number("flow_contact_gap_fraction", o.flow_contact_gap_fraction, Range::positive);
    o.lift_contact_gap_fraction = h->number("lift_contact_gap_fraction", o.lift_contact_gap_fraction, Range::positive);
    o.bem_tolerance = h->number("bem_tolerance", o.bem_tolerance, Range::positive);
    o.pin_grid = static_cast<int>(h->integer("pin_grid", o.pin_grid, 9, 16384));
    o.min_contact_grid = static_cast<int>(h->integer("min_contact_grid", o.min_contact_grid, 1, 65536));
    o.junction_grid = static_cast<int>(h->integer("junction_grid", o.junction_grid, 0, 65536));
    o.target_relative_error = h->number("target_relative_error", o.target_relative_error, Range::positive);
    o.threads = static_cast<int>(h->integer("threads", o.threads, 0, 1'000'000));
    h->finish();
  }
  input_guard(root, "homogenise", [&] { homogenise::validate(o); return 0; });
  run.input_files = root.input_files();
  root.finish();
  return run;
}

}  // namespace tribo::cli
