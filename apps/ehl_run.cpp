// The reader and the solve of `tribo ehl` (see ehl_run.h).
#include "apps/ehl_run.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "apps/config.h"
#include "apps/surface_config.h"
#include "contact/profile.h"
#include "contact/surface.h"
#include "contact/surface_io.h"
#include "lubrication/reference/ehl_film.h"
#include "lubrication/reference/ehl_point_film.h"
#include "lubrication/viscosity.h"
#include "numerics/format.h"

namespace tribo::cli {

namespace lub = tribo::lubrication;

namespace {

// [profile] file: a measured trace — one line of heights along the entrainment direction (a stylus
// profile, or the column `line` of a map, rows along x) — read and levelled; placed on the solver's
// domain once the node spacing is known (place_measured_profile).
void read_measured_profile(ConfigTable& pr, EhlRun::Profile& profile) {
  profile.file = pr.input_file("file");
  const double scale = pr.number("height_scale", 1.0, Range::positive);
  const contact::Topography topo = input_guard(pr, "file", [&] { return contact::read_topography(profile.file, scale); });
  const Eigen::Index rows = topo.heights_m.rows(), cols = topo.heights_m.cols();
  const bool along_y = rows == 1 && cols > 1;  // one row of numbers: a trace written across
  Eigen::ArrayXd z;
  double length_m = 0.0;
  if (along_y) {
    z = topo.heights_m.row(0).transpose(), length_m = topo.ly_m;
  } else if (cols == 1 || pr.has("line")) {
    const long long line = cols == 1 ? 0 : pr.integer("line", 0, 0, cols - 1);
    z = topo.heights_m.col(static_cast<Eigen::Index>(line)), length_m = topo.lx_m;
  } else {
    pr.fail("line", profile.file.string() + " is a " + std::to_string(rows) + " x " + std::to_string(cols) +
                        " map: name the column whose profile along x (the rows) the contact sees, 0 … " + std::to_string(cols - 1));
  }
  const std::optional<double> spacing = pr.optional_number("spacing_m", Range::positive);
  if (length_m > 0.0 && spacing && std::abs(*spacing * static_cast<double>(z.size()) - length_m) > 1e-9 * length_m)
    pr.fail("spacing_m", "disagrees with " + profile.file.string() + "'s own length " + numerics::shortest(length_m) + " m over " +
                             std::to_string(z.size()) + " samples");
  if (length_m == 0.0 && !spacing) pr.fail("file", profile.file.string() + " gives no lateral size: set spacing_m");
  profile.spacing_m = length_m > 0.0 ? length_m / static_cast<double>(z.size()) : *spacing;
  if (z.size() < 3) pr.fail("file", profile.file.string() + " holds " + std::to_string(z.size()) + " samples: a profile needs more");
  profile.levelled_m = contact::level_profile(z);
  profile.centre_m = pr.optional_number("centre_m", Range::non_negative);
  profile.cutoff_m = pr.optional_number("cutoff_m", Range::positive);
}

// The Rq (about the mean) of measured heights and of their filtered mean surface over the samples
// added: what inputs.profile and inputs.surface report over the solver's domain.
class RqOfMeasuredAndFiltered {
 public:
  void add(double measured_m, double filtered_m) {
    sum_ += measured_m, sum2_ += measured_m * measured_m, fsum_ += filtered_m, fsum2_ += filtered_m * filtered_m, ++n_;
  }
  double measured_m() const { return rq(sum_, sum2_); }
  double filtered_m() const { return rq(fsum_, fsum2_); }

 private:
  double rq(double s1, double s2) const {
    const double n = static_cast<double>(n_);
    return std::sqrt(std::max(0.0, s2 / n - (s1 / n) * (s1 / n)));
  }
  double sum_ = 0.0, sum2_ = 0.0, fsum_ = 0.0, fsum2_ = 0.0;
  long n_ = 0;
};

// The measured trace filtered at the cut-off (default: 8 node spacings, the shortest wavelength a
// waviness may have) and its samples over the domain [from, to] (m from the Hertz centre, a sample
// beyond either end), the trace's point centre_m at x = 0 (default: the domain in the middle of the
// filtered part).
void place_measured_profile(const ConfigTable& root, double from, double to, double node_spacing, EhlRun::Profile& pr) {
  if (!(pr.spacing_m <= node_spacing))
    root.fail("profile.file", pr.file.string() + " is sampled " + numerics::shortest(pr.spacing_m) + " m apart, coarser than the solver's " +
                                  numerics::shortest(node_spacing) + " m node spacing: a finer trace, or fewer solver.nodes");
  const double cutoff = pr.cutoff_m.value_or(8.0 * node_spacing);
  if (!(cutoff >= 8.0 * node_spacing * (1.0 - 1e-12)))
    root.fail("profile.cutoff_m", numerics::shortest(cutoff) + " m passes wavelengths the solver's nodes cannot resolve: at least 8 node "
                                  "spacings (" + numerics::shortest(8.0 * node_spacing) + " m), or refine solver.nodes");
  contact::FilteredProfile f;
  try {
    f = contact::gaussian_profile_filter(pr.levelled_m, pr.spacing_m, cutoff);
  } catch (const std::invalid_argument& e) {
    root.fail("profile.file", pr.file.string() + ": " + e.what());
  }
  const double s = pr.spacing_m, first = static_cast<double>(f.first) * s, last = first + static_cast<double>(f.height_m.size() - 1) * s;
  const double centre = pr.centre_m.value_or(0.5 * (first + last) - 0.5 * (from + to));  // the domain in the middle
  if (!(centre + from >= first && centre + to <= last))
    root.fail("profile.centre_m", "the solver's domain, " + numerics::shortest(to - from) + " m about " + numerics::shortest(centre) +
                                      " m of the trace, leaves the part the filter gives (" + numerics::shortest(first) + " … " +
                                      numerics::shortest(last) + " m of " + pr.file.string() +
                                      "): a longer trace, another centre_m, or a shorter domain");
  pr.cutoff_m = cutoff, pr.centre_m = centre;
  RqOfMeasuredAndFiltered rq;
  for (Eigen::Index k = 0; k < f.height_m.size(); ++k) {
    const double x = first + static_cast<double>(k) * s - centre;
    if (x < from - s || x > to + s) continue;
    pr.surface.x_m.push_back(x);
    pr.surface.height_m.push_back(f.height_m(k));
    if (x >= from && x <= to) rq.add(pr.levelled_m(f.first + k), f.height_m(k));
  }
  pr.rq_m = rq.measured_m(), pr.filtered_rq_m = rq.filtered_m();
}

// [surface]: a height map generated by the reader of `tribo contact` (kind = "gaussian"; its size_m and
// grid in this table) or read from a file (kind = "file", height_scale), levelled; placed once the
// nodes are known (place_surface_map).
void read_surface_map(ConfigTable& sf, EhlRun::SurfaceMap& m) {
  m.kind = sf.choice("kind", "gaussian", {"gaussian", "file"});
  Eigen::ArrayXXd z;
  if (m.kind == "gaussian") {
    const contact::GaussianSurfaceParams p = read_gaussian_surface(sf, &sf);
    z = input_guard(sf, "spectrum", [&] { return contact::gaussian_surface(p); });
    m.seed = p.seed;
    m.dx_m = m.dy_m = p.size_m / static_cast<double>(p.grid);
  } else {
    m.file = sf.input_file("file");
    const double scale = sf.number("height_scale", 1.0, Range::positive);
    const contact::Topography topo = input_guard(sf, "file", [&] { return contact::read_topography(m.file, scale); });
    if (topo.lx_m == 0.0) sf.fail("file", m.file.string() + " gives no lateral size (a map for a contact needs its coordinates)");
    z = topo.heights_m;
    m.dx_m = topo.lx_m / static_cast<double>(z.rows()), m.dy_m = topo.ly_m / static_cast<double>(z.cols());
  }
  if (z.rows() < 3 || z.cols() < 3) sf.fail("kind", "the map holds " + std::to_string(z.rows()) + " x " + std::to_string(z.cols()) + " samples");
  m.levelled_m = contact::level_map(z);
  m.centre_x_m = sf.optional_number("centre_x_m", Range::non_negative);
  m.centre_y_m = sf.optional_number("centre_y_m", Range::non_negative);
  m.cutoff_m = sf.optional_number("cutoff_m", Range::positive);
  sf.finish();
}

// The map filtered at the cut-off (default and least: 8 of the coarser node spacing) and placed with
// its point (centre_x_m, centre_y_m) at the Hertz centre (default: the domain in the middle of the
// filtered part), into `surface.map`; the domain is [from, to] × [−side, side] (m).
void place_surface_map(const ConfigTable& root, double from, double to, double side, double node_dx, double node_dy,
                       EhlRun::SurfaceMap& m, lub::EhlRoughness& surface) {
  const std::string what = m.kind == "file" ? m.file.string() : "the generated surface";
  if (!(m.dx_m <= node_dx && m.dy_m <= node_dy))
    root.fail("surface", what + " is sampled " + numerics::shortest(m.dx_m) + " x " + numerics::shortest(m.dy_m) +
                             " m apart, coarser than the solver's nodes (" + numerics::shortest(node_dx) + " x " + numerics::shortest(node_dy) +
                             " m): a finer map, or fewer solver nodes");
  const double least = 8.0 * std::max(node_dx, node_dy), cutoff = m.cutoff_m.value_or(least);
  if (!(cutoff >= least * (1.0 - 1e-12)))
    root.fail("surface.cutoff_m", numerics::shortest(cutoff) + " m passes wavelengths the solver's nodes cannot resolve: at least 8 node "
                                  "spacings (" + numerics::shortest(least) + " m), or more solver nodes");
  contact::FilteredMap f;
  try {
    f = contact::gaussian_areal_filter(m.levelled_m, m.dx_m, m.dy_m, cutoff);
  } catch (const std::invalid_argument& e) {
    root.fail("surface", what + ": " + e.what());
  }
  const double x_first = static_cast<double>(f.first_x) * m.dx_m, y_first = static_cast<double>(f.first_y) * m.dy_m;
  const double x_last = x_first + static_cast<double>(f.height_m.rows() - 1) * m.dx_m;
  const double y_last = y_first + static_cast<double>(f.height_m.cols() - 1) * m.dy_m;
  const double cx = m.centre_x_m.value_or(0.5 * (x_first + x_last) - 0.5 * (from + to)), cy = m.centre_y_m.value_or(0.5 * (y_first + y_last));
  if (!(cx + from >= x_first && cx + to <= x_last && cy - side >= y_first && cy + side <= y_last))
    root.fail("surface.centre_x_m", "the solver's domain, " + numerics::shortest(to - from) + " x " + numerics::shortest(2.0 * side) +
                                        " m about (" + numerics::shortest(cx) + ", " + numerics::shortest(cy) + ") m of " + what +
                                        ", leaves the part the filter gives ([" + numerics::shortest(x_first) + ", " + numerics::shortest(x_last) +
                                        "] x [" + numerics::shortest(y_first) + ", " + numerics::shortest(y_last) +
                                        "] m): a larger map, another centre, or a smaller domain");
  m.cutoff_m = cutoff, m.centre_x_m = cx, m.centre_y_m = cy;
  lub::EhlHeightMap map;
  map.x0_m = x_first - cx, map.y0_m = y_first - cy, map.dx_m = m.dx_m, map.dy_m = m.dy_m;
  map.height_m = f.height_m;
  RqOfMeasuredAndFiltered rq;
  for (Eigen::Index j = 0; j < f.height_m.cols(); ++j)
    for (Eigen::Index i = 0; i < f.height_m.rows(); ++i) {
      const double x = map.x0_m + static_cast<double>(i) * m.dx_m, y = map.y0_m + static_cast<double>(j) * m.dy_m;
      if (x >= from && x <= to && std::abs(y) <= side) rq.add(m.levelled_m(f.first_x + i, f.first_y + j), f.height_m(i, j));
    }
  m.rq_m = rq.measured_m(), m.filtered_rq_m = rq.filtered_m();
  surface.map = std::move(map);
}

}  // namespace

EhlRun load_ehl_run(const std::filesystem::path& path) { return load_ehl_run(parse_toml_file(path), path); }

EhlRun load_ehl_run(const toml::table& doc, const std::filesystem::path& path) {
  ConfigTable root(doc, path.string(), "");
  EhlRun run;
  auto c = root.table("contact");
  if (!c) root.fail("contact", "the [contact] table is required");
  const std::string geometry = c->choice("geometry", "line", {"line", "point"});
  if (geometry == "point") {
    if (c->has("load_per_length_N_per_m")) c->fail("load_per_length_N_per_m", "a point contact takes load_N");
    lub::EhlPointContact& p = run.point.emplace();
    p.load_N = c->required_number("load_N", Range::positive);
    p.reduced_radius_m = c->required_number("reduced_radius_m", Range::positive);
    p.reduced_modulus_Pa = c->required_number("reduced_modulus_Pa", Range::positive);
    p.mean_speed_m_per_s = c->required_number("mean_speed_m_per_s", Range::positive);
    run.contact.mean_speed_m_per_s = p.mean_speed_m_per_s;
  } else {
    if (c->has("load_N")) c->fail("load_N", "a line contact takes load_per_length_N_per_m");
    run.contact.load_per_length_N_per_m = c->required_number("load_per_length_N_per_m", Range::positive);
    run.contact.reduced_radius_m = c->required_number("reduced_radius_m", Range::positive);
    run.contact.reduced_modulus_Pa = c->required_number("reduced_modulus_Pa", Range::positive);
    run.contact.mean_speed_m_per_s = c->required_number("mean_speed_m_per_s", Range::positive);
  }
  // The sliding speed absolute, or as a share of the entrainment (a Stribeck sweep over u_m keeps it).
  if (c->has("slide_to_roll_ratio")) {
    if (c->has("sliding_speed_m_per_s")) c->fail("slide_to_roll_ratio", "give sliding_speed_m_per_s or slide_to_roll_ratio, not both");
    run.sliding_speed_m_per_s = c->number("slide_to_roll_ratio", 0.0) * run.contact.mean_speed_m_per_s;
  } else {
    run.sliding_speed_m_per_s = c->number("sliding_speed_m_per_s", 0.0);
  }
  c->finish();
  if (auto l = root.table("lubricant")) {
    run.lubricant.viscosity_Pa_s = l->number("viscosity_Pa_s", run.lubricant.viscosity_Pa_s, Range::positive);
    run.lubricant.pressure_viscosity_per_Pa =
        l->number("pressure_viscosity_per_Pa", run.lubricant.pressure_viscosity_per_Pa, Range::non_negative);
    run.lubricant.law = l->choice("pressure_viscosity_law", "roelands", {"roelands", "barus"}) == "barus"
                            ? lub::PressureViscosityLaw::barus
                            : lub::PressureViscosityLaw::roelands;
    run.lubricant.compressible = l->boolean("compressible", run.lubricant.compressible);
    // No default for τ0: it is the lubricant's, measured on a traction rig. shear = "newtonian"
    // takes the film as Newtonian instead (τ0 → ∞).
    if (l->choice("shear", "eyring", {"eyring", "newtonian"}) == "newtonian") {
      run.eyring_stress_Pa = std::numeric_limits<double>::infinity();
    } else {
      run.eyring_stress_Pa = l->required_number("eyring_stress_Pa", Range::positive);
    }
    // The film's shear heating (ehl_traction.h): on when the oil's conductivity is given; γ defaults
    // to viscosity.h's light mineral oil.
    run.heating.thermal_conductivity_W_per_m_K = l->number("thermal_conductivity_W_per_m_K", 0.0, Range::non_negative);
    run.heating.temperature_viscosity_per_K =
        l->number("temperature_viscosity_per_K", lub::Lubricant{}.temperature_viscosity_per_K, Range::non_negative);
    // The limiting shear stress τ_L = τ_L0 + Λ p (ehl_traction.h): off unless either is given.
    run.limiting_shear.stress_Pa = l->number("limiting_shear_stress_Pa", 0.0, Range::non_negative);
    run.limiting_shear.pressure_coefficient = l->number("limiting_shear_pressure_coefficient", 0.0, Range::non_negative);
    run.limiting_shear.temperature_coefficient_per_K = l->number("limiting_shear_temperature_per_K", 0.0, Range::non_negative);
    if (run.limiting_shear.temperature_coefficient_per_K > 0.0 && !run.limiting_shear.on())
      l->fail("limiting_shear_temperature_per_K",
              "needs a limit to act on: limiting_shear_stress_Pa or limiting_shear_pressure_coefficient > 0");
    l->finish();
  } else {
    root.fail("lubricant", "the [lubricant] table is required (at least eyring_stress_Pa, the lubricant's Eyring stress τ0)");
  }
  // The surfaces' flash temperature (ehl_traction.h, moving_heat_source.h), on when [solids] is given
  // (both surfaces of that solid, unless [solids.second] gives the one moving at u2 = u_m − Δu/2: a
  // steel ball on a glass disc); the heat reaches them through the film, so it needs the oil's conductivity.
  if (auto s = root.table("solids")) {
    const auto read_solid = [](ConfigTable& t) {
      lub::HeatedSolid solid;
      solid.thermal_conductivity_W_per_m_K = t.required_number("thermal_conductivity_W_per_m_K", Range::positive);
      solid.density_kg_per_m3 = t.required_number("density_kg_per_m3", Range::positive);
      solid.specific_heat_J_per_kg_K = t.required_number("specific_heat_J_per_kg_K", Range::positive);
      return solid;
    };
    const lub::HeatedSolid solid = read_solid(*s);
    if (auto second = s->table("second")) {
      run.heating.second_surface = read_solid(*second);
      second->finish();
    }
    if (!(run.heating.thermal_conductivity_W_per_m_K > 0.0))
      s->fail("thermal_conductivity_W_per_m_K",
              "the surfaces warm by the heat the film passes them: give [lubricant] thermal_conductivity_W_per_m_K too");
    if (!(std::abs(run.sliding_speed_m_per_s) < 2.0 * run.contact.mean_speed_m_per_s))
      s->fail("thermal_conductivity_W_per_m_K", "the surfaces' heating needs both surfaces moving through the contact: the sliding speed " +
                                                    numerics::shortest(run.sliding_speed_m_per_s) + " m/s must stay below twice the mean speed " +
                                                    numerics::shortest(run.contact.mean_speed_m_per_s) +
                                                    " m/s (a surface at rest sees a stationary heat source, outside the fast-source model)");
    s->finish();
    run.heating.surfaces = solid;
    run.heating.mean_speed_m_per_s = run.contact.mean_speed_m_per_s;
  }
  if (auto r = root.table("roughness")) {
    EhlRun::Roughness rough;
    rough.summits.summit_density_per_m2 = r->required_number("summit_density_per_m2", Range::positive);
    rough.summits.summit_radius_m = r->required_number("summit_radius_m", Range::positive);
    rough.summits.summit_std_m = r->required_number("summit_std_m", Range::positive);
    rough.summits.e_star_Pa = 0.5 * (run.point ? run.point->reduced_modulus_Pa : run.contact.reduced_modulus_Pa);
    rough.summit_height_m = r->required_number("summit_height_m", Range::non_negative);
    rough.boundary_friction_coefficient = r->required_number("boundary_friction_coefficient", Range::non_negative);
    r->finish();
    run.roughness = rough;
  }
  if (auto pr = root.table("profile")) {
    if (run.roughness) root.fail("profile", "give [roughness] (load sharing) or [profile] (node by node), not both");
    EhlRun::Profile profile;
    if (pr->has("file")) {
      for (const char* key : {"amplitude_m", "wavelength_m"})
        if (pr->has(key)) pr->fail(key, "give a waviness (amplitude_m, wavelength_m) or a measured trace (file), not both");
      read_measured_profile(*pr, profile);
    } else if (root.has("surface") && !pr->has("amplitude_m") && !pr->has("wavelength_m")) {
      // No ridges: the map of [surface] alone.
    } else {
      profile.amplitude_m = pr->required_number("amplitude_m", Range::non_negative);
      profile.wavelength_m = pr->required_number("wavelength_m", Range::positive);
    }
    profile.surface.contact_film_m = pr->number("contact_film_m", profile.surface.contact_film_m, Range::positive);
    profile.surface.contact_margin_m = pr->number("contact_margin_m", profile.surface.contact_margin_m, Range::non_negative);
    profile.boundary_friction_coefficient = pr->required_number("boundary_friction_coefficient", Range::non_negative);
    pr->finish();
    run.profile = profile;
  }
  if (auto m = root.table("material")) {
    // The touching surface's hardness (EhlRoughness::hardness_Pa): node by node only.
    if (!run.profile) root.fail("material", "a hardness caps the pressure where surfaces touch node by node: it needs [profile]");
    run.profile->surface.hardness_Pa = m->required_number("hardness_Pa", Range::positive);
    m->finish();
  }
  if (auto sf = root.table("surface")) {
    if (!run.point) root.fail("surface", "a height map is a point contact's (geometry = \"point\"); a line takes [profile]");
    if (!run.profile) root.fail("profile", "[surface] needs [profile] for the boundary layers and the boundary friction coefficient");
    read_surface_map(*sf, run.surface_map.emplace());
  }
  if (auto s = root.table("solver")) {
    // The cavitation's NCP function (lubrication/complementarity.h); the default is each contact's.
    const auto complementarity = [&](lub::Complementarity fallback) {
      const std::string name = s->choice("complementarity", fallback == lub::Complementarity::minimum ? "minimum" : "fischer_burmeister",
                                         {"minimum", "fischer_burmeister"});
      return name == "minimum" ? lub::Complementarity::minimum : lub::Complementarity::fischer_burmeister;
    };
    if (run.point) {
      lub::EhlPointOptions& o = run.point_options;
      // Beyond 21² Newton–Krylov (ehl_point.h): 257² takes ≈ 1–1.4 s, 513² ≈ 5–7 s and 0.4 GB — the limit.
      o.nodes_x = static_cast<int>(s->integer("nodes_x", o.nodes_x, 11, 513));
      o.nodes_y = static_cast<int>(s->integer("nodes_y", o.nodes_y, 11, 513));
      const std::string method = s->choice("linear_solver", "automatic", {"automatic", "dense_lu", "newton_krylov"});
      o.linear_solver = method == "dense_lu"        ? lub::EhlPointLinearSolver::dense_lu
                        : method == "newton_krylov" ? lub::EhlPointLinearSolver::newton_krylov
                                                    : lub::EhlPointLinearSolver::automatic;
      o.preconditioner_reach = static_cast<int>(s->integer("preconditioner_reach", o.preconditioner_reach, 0, 16));
      o.complementarity = complementarity(o.complementarity);
      // "fitted": the extents from the film the solve expects (lubrication::fit_domain_to_film).
      run.fitted_domain = s->choice("domain", "given", {"given", "fitted"}) == "fitted";
      if (run.fitted_domain)
        for (const char* key : {"inlet_over_radius", "outlet_over_radius", "side_over_radius"})
          if (s->has(key)) s->fail(key, "domain = \"fitted\" sets the extents; give them or fit them, not both");
      o.inlet_over_radius = s->number("inlet_over_radius", o.inlet_over_radius);
      o.outlet_over_radius = s->number("outlet_over_radius", o.outlet_over_radius);
      o.side_over_radius = s->number("side_over_radius", o.side_over_radius, Range::positive);
      o.tolerance = s->number("tolerance", o.tolerance, Range::positive);
      o.max_newton_iterations = static_cast<int>(s->integer("max_newton_iterations", o.max_newton_iterations, 1, 100000));
      o.max_continuation_steps = static_cast<int>(s->integer("max_continuation_steps", o.max_continuation_steps, 0, 1000));
    } else {
      run.options.nodes = static_cast<int>(s->integer("nodes", run.options.nodes, 11, 20001));
      run.options.complementarity = complementarity(run.options.complementarity);
      // "fitted": the inlet moved out, at the given node spacing, until the film no longer feels it
      // (lubrication::fit_inlet_to_film; solved in the run).
      run.fitted_domain = s->choice("domain", "given", {"given", "fitted"}) == "fitted";
      if (run.fitted_domain && s->has("inlet_over_half_width"))
        s->fail("inlet_over_half_width", "domain = \"fitted\" moves the inlet; give it or fit it, not both");
      run.options.inlet_over_half_width = s->number("inlet_over_half_width", run.options.inlet_over_half_width);
      run.options.outlet_over_half_width = s->number("outlet_over_half_width", run.options.outlet_over_half_width);
      run.options.tolerance = s->number("tolerance", run.options.tolerance, Range::positive);
      run.options.max_newton_iterations =
          static_cast<int>(s->integer("max_newton_iterations", run.options.max_newton_iterations, 1, 100000));
      run.options.max_continuation_steps =
          static_cast<int>(s->integer("max_continuation_steps", run.options.max_continuation_steps, 0, 1000));
    }
    s->finish();
  }
  root.finish();
  input_guard(root, "lubricant", [&] {
    lub::validate(run.lubricant);
    return 0;
  });
  // The solver's domain along x (m from the Hertz centre) and its nodes there, for the profile.
  double domain_from = 0.0, domain_to = 0.0;
  int nodes_along_x = 0;
  if (run.point) {
    if (run.fitted_domain)
      input_guard(root, "solver", [&] {
        run.point_options = lub::fit_domain_to_film(*run.point, run.lubricant, run.profile ? run.profile->surface.contact_film_m : 0.0,
                                                    run.point_options);
        return 0;
      });
    if (!(run.point_options.inlet_over_radius < -1.0)) root.fail("solver.inlet_over_radius", "must lie before the contact, below -1");
    if (!(run.point_options.outlet_over_radius > 1.0)) root.fail("solver.outlet_over_radius", "must lie past the contact, above 1");
    if (!(run.point_options.side_over_radius > 1.0)) root.fail("solver.side_over_radius", "must reach past the contact, above 1");
    const lub::EhlPointContact& c = *run.point;
    const double a = lub::reference::hertz_point_radius_m(c.load_N, c.reduced_radius_m, c.reduced_modulus_Pa);
    domain_from = run.point_options.inlet_over_radius * a, domain_to = run.point_options.outlet_over_radius * a;
    nodes_along_x = run.point_options.nodes_x;
    if (run.surface_map) {
      const double side = run.point_options.side_over_radius * a;
      place_surface_map(root, domain_from, domain_to, side, (domain_to - domain_from) / (nodes_along_x - 1),
                        2.0 * side / (run.point_options.nodes_y - 1), *run.surface_map, run.profile->surface);
    }
  } else {
    if (run.fitted_domain && run.profile)
      root.fail("solver.domain", "\"fitted\" fits a line contact's inlet to its smooth film; with [profile] give solver.inlet_over_half_width");
    if (!(run.options.inlet_over_half_width < -1.0)) root.fail("solver.inlet_over_half_width", "must lie before the contact, below -1");
    if (!(run.options.outlet_over_half_width > 1.0)) root.fail("solver.outlet_over_half_width", "must lie past the contact, above 1");
    const double b = lub::reference::hertz_line_half_width_m(run.contact.load_per_length_N_per_m, run.contact.reduced_radius_m,
                                                             run.contact.reduced_modulus_Pa);
    domain_from = run.options.inlet_over_half_width * b, domain_to = run.options.outlet_over_half_width * b;
    nodes_along_x = run.options.nodes;
  }
  run.input_files = root.input_files();
  if (run.profile && !run.profile->has_ridges()) return run;  // a [surface] map alone
  if (run.profile) {
    EhlRun::Profile& pr = *run.profile;
    const double spacing = (domain_to - domain_from) / (nodes_along_x - 1);
    if (!pr.file.empty()) {
      place_measured_profile(root, domain_from, domain_to, spacing, pr);
      return run;
    }
    // The waviness a cos(2π x/λ) sampled over the solver's domain, 64 points a wavelength.
    const double from = domain_from - pr.wavelength_m, to = domain_to + pr.wavelength_m;
    if (!(pr.wavelength_m >= 8.0 * spacing))
      root.fail("profile.wavelength_m", numerics::shortest(pr.wavelength_m) + " m spans fewer than 8 of the solver's node spacings (" +
                                            numerics::shortest(spacing) + " m): refine solver.nodes");
    const double points = std::ceil(64.0 * (to - from) / pr.wavelength_m) + 1.0;
    if (!std::isfinite(from) || !std::isfinite(to) || !(points <= 1e6))
      root.fail("profile.wavelength_m", "the solver's domain would need " + numerics::shortest(points) +
                                            " profile points (64 a wavelength), more than 1e6");
    lub::EhlRoughness ridges = lub::cosine_ridges(from, to, pr.amplitude_m, pr.wavelength_m, static_cast<std::size_t>(points));
    pr.surface.x_m = std::move(ridges.x_m), pr.surface.height_m = std::move(ridges.height_m);
  }
  return run;
}

namespace {

// ehl.json's inputs of a [solids] table (null when absent).
nlohmann::json solid_inputs(const std::optional<lub::HeatedSolid>& solid) {
  if (!solid) return nullptr;
  return {{"thermal_conductivity_W_per_m_K", solid->thermal_conductivity_W_per_m_K},
          {"density_kg_per_m3", solid->density_kg_per_m3},
          {"specific_heat_J_per_kg_K", solid->specific_heat_J_per_kg_K}};
}

// ehl.json's inputs beyond the contact's geometry: the sliding and the lubricant.
nlohmann::json lubricant_inputs(const EhlRun& run) {
  return {{"sliding_speed_m_per_s", run.sliding_speed_m_per_s},
          {"viscosity_Pa_s", run.lubricant.viscosity_Pa_s},
          {"pressure_viscosity_per_Pa", run.lubricant.pressure_viscosity_per_Pa},
          {"pressure_viscosity_law", run.lubricant.law == lub::PressureViscosityLaw::barus ? "barus" : "roelands"},
          {"compressible", run.lubricant.compressible},
          {"eyring_stress_Pa", std::isinf(run.eyring_stress_Pa) ? nlohmann::json("newtonian") : nlohmann::json(run.eyring_stress_Pa)},
          {"thermal_conductivity_W_per_m_K", run.heating.thermal_conductivity_W_per_m_K},
          {"temperature_viscosity_per_K", run.heating.temperature_viscosity_per_K},
          {"limiting_shear_stress_Pa", run.limiting_shear.stress_Pa},
          {"limiting_shear_pressure_coefficient", run.limiting_shear.pressure_coefficient},
          {"limiting_shear_temperature_per_K", run.limiting_shear.temperature_coefficient_per_K},
          {"surfaces", solid_inputs(run.heating.surfaces)},
          {"second_surface", solid_inputs(run.heating.second_surface)}};
}

nlohmann::json roughness_inputs(const EhlRun::Roughness& r) {
  return {{"summit_density_per_m2", r.summits.summit_density_per_m2},
          {"summit_radius_m", r.summits.summit_radius_m},
          {"summit_std_m", r.summits.summit_std_m},
          {"summit_height_m", r.summit_height_m},
          {"boundary_friction_coefficient", r.boundary_friction_coefficient}};
}

// The mixed contact of [roughness] around `film` (MixedLineContact or MixedPointContact).
template <class Mixed, class Film>
Mixed mixed_contact(const EhlRun& run, const Film& film) {
  Mixed mc;
  mc.film = film;
  mc.asperities = run.roughness->summits;
  mc.summit_height_m = run.roughness->summit_height_m;
  mc.boundary_friction_coefficient = run.roughness->boundary_friction_coefficient;
  mc.sliding_speed_m_per_s = run.sliding_speed_m_per_s;
  mc.eyring_stress_Pa = run.eyring_stress_Pa;
  mc.limiting_shear = run.limiting_shear;
  mc.heating = run.heating;
  return mc;
}

// ehl.json's "mixed" block; loads and forces per unit length for a line ("per_length_N_per_m",
// "N_per_m"), in N for a point ("N", "N").
struct MixedNumbers {
  double film_load, asperity_load, boundary_friction, film_friction;
};
template <class Result>
nlohmann::json mixed_json(const Result& m, const MixedNumbers& n, const std::string& load_unit, const std::string& force_unit) {
  return {{"converged", m.converged},
          {"film_solves", m.film_solves},
          {"load_balance_residual", m.residual},
          {"message", m.message},
          {"film_share", m.film_share},
          {"film_load_" + load_unit, n.film_load},
          {"asperity_load_" + load_unit, n.asperity_load},
          {"separation_m", m.separation_m},
          {"film_parameter", m.film_parameter},
          {"asperity_area_fraction", m.asperity_area_fraction},
          {"boundary_friction_" + force_unit, n.boundary_friction},
          {"film_friction_" + force_unit, n.film_friction}};
}

// ehl.json's convergence, film and traction fields, the same for both geometries: `mixed` the mixed
// contact's result (nullptr for smooth surfaces), whose friction coefficient is the whole
// contact's (boundary friction on the summits' share plus the film's traction); the traction force
// under `force_key` (per length for a line, in N for a point). No traction from a film that is not
// a solution: those fields are null then.
struct TractionNumbers {
  double friction_coefficient, force, max_shear_stress_Pa, max_film_temperature_rise_K;
  double max_surface_temperature_rise_K, surface_peclet_number;  // written only with [solids]
  double limited_node_share;                                      // written only with a limiting shear
};
template <class Film, class Mixed>
void film_summary(nlohmann::json& j, const Film& f, bool converged, const Mixed* mixed, const TractionNumbers& t, const std::string& force_key,
                  bool surfaces, bool limited) {
  j["converged"] = converged;
  j["iterations"] = f.iterations;
  j["continuation_steps"] = f.continuation_steps;
  j["residual"] = f.residual;
  j["message"] = mixed ? mixed->message : f.message;
  j["central_film_m"] = f.central_film_m;
  j["minimum_film_m"] = f.minimum_film_m;
  j["max_pressure_Pa"] = f.max_pressure_Pa;
  j["hertz_pressure_Pa"] = f.hertz_pressure_Pa;
  j["load_balance_error"] = f.load_balance_error;
  if (converged) {
    j["friction_coefficient"] = mixed ? mixed->friction_coefficient : t.friction_coefficient;
    j[force_key] = t.force;
    j["max_shear_stress_Pa"] = t.max_shear_stress_Pa;
    j["max_film_temperature_rise_K"] = t.max_film_temperature_rise_K;
  } else {
    for (const std::string& key : {std::string("friction_coefficient"), force_key, std::string("max_shear_stress_Pa"),
                                   std::string("max_film_temperature_rise_K")})
      j[key] = nullptr;
  }
  // The surfaces' flash temperature and the smaller of their Péclet numbers (null without [solids]).
  j["max_surface_temperature_rise_K"] = surfaces && converged ? nlohmann::json(t.max_surface_temperature_rise_K) : nlohmann::json(nullptr);
  j["surface_peclet_number"] = surfaces && converged ? nlohmann::json(t.surface_peclet_number) : nlohmann::json(nullptr);
  // The share of the sheared nodes at the limiting shear stress (null without one).
  j["limited_node_share"] = limited && converged ? nlohmann::json(t.limited_node_share) : nlohmann::json(nullptr);
}

// ehl.json's inputs.profile: the waviness, or the measured trace and what the filter kept of it.
nlohmann::json profile_inputs(const EhlRun::Profile& pr) {
  nlohmann::json j;
  if (!pr.has_ridges()) {
    j = {{"ridges", nullptr}};  // none: a [surface] map alone
  } else if (pr.file.empty()) {
    j = {{"amplitude_m", pr.amplitude_m}, {"wavelength_m", pr.wavelength_m}};
  } else {
    j = {{"file", pr.file.string()},
         {"sample_spacing_m", pr.spacing_m},
         {"cutoff_m", *pr.cutoff_m},
         {"centre_m", *pr.centre_m},
         {"rq_m", pr.rq_m},
         {"filtered_rq_m", pr.filtered_rq_m}};
  }
  j["contact_film_m"] = pr.surface.contact_film_m;
  j["contact_margin_m"] = pr.surface.contact_margin_m;
  j["boundary_friction_coefficient"] = pr.boundary_friction_coefficient;
  // [material]: the hardness, null for an elastic surface.
  if (std::isfinite(pr.surface.hardness_Pa)) {
    j["hardness_Pa"] = pr.surface.hardness_Pa;
  } else {
    j["hardness_Pa"] = nullptr;
  }
  return j;
}

// ehl.json's inputs.surface: the map's source, sampling, filter and placement, and its Rq over the domain.
nlohmann::json surface_inputs(const EhlRun::SurfaceMap& m) {
  nlohmann::json j = {{"kind", m.kind},
                      {"sample_spacing_x_m", m.dx_m},
                      {"sample_spacing_y_m", m.dy_m},
                      {"cutoff_m", *m.cutoff_m},
                      {"centre_x_m", *m.centre_x_m},
                      {"centre_y_m", *m.centre_y_m},
                      {"rq_m", m.rq_m},
                      {"filtered_rq_m", m.filtered_rq_m}};
  if (m.kind == "file") {
    j["file"] = m.file.string();
  } else {
    j["seed"] = m.seed;
  }
  return j;
}

// A film solved with [profile] (node by node, Hu & Zhu's unified model): ehl.json's "contact" block
// and the whole contact's friction. The film's traction (`traction_of`, into `traction`, its force in
// the member `force`) is taken over the nodes whose film is open — the contact nodes' pressure taken
// out, so that their nanometre films are not sheared as oil — and the boundary friction on the load
// the contact nodes carry is added: ehl.json's traction, friction coefficient and largest shear stress
// are the whole contact's (the temperature rise stays the film's: the contacts' flash heating is not
// modelled). Loads and forces per unit length for a line ("per_length_N_per_m", "N_per_m"), in N for
// a point ("N", "N"); null where the solve did not converge (an iterate, not a solution).
template <class Film, class Traction, class TractionOf>
void profile_friction(const Film& film, bool converged, double load, double boundary_coefficient, TractionOf&& traction_of,
                      Traction& traction, double Traction::*force, const std::string& load_unit, const std::string& force_unit,
                      nlohmann::json& j) {
  const std::string load_key = "contact_load_" + load_unit, boundary_key = "boundary_friction_" + force_unit,
                    film_key = "film_friction_" + force_unit;
  if (!converged) {
    j["contact"] = {{"contact_nodes", nullptr}, {"contact_load_share", nullptr}, {load_key, nullptr}, {boundary_key, nullptr}, {film_key, nullptr}};
    return;
  }
  const double contact_load = film.contact_load_share * load;
  Film open = film;
  double contact_pressure = 0.0;
  for (std::size_t k = 0; k < open.film_m.size(); ++k)
    if (open.in_contact[k]) contact_pressure = std::max(contact_pressure, open.pressure_Pa[k]), open.pressure_Pa[k] = 0.0;
  traction = traction_of(open);
  const double boundary = boundary_coefficient * contact_load, sheared = traction.*force;
  j["contact"] = {{"contact_nodes", film.contact_nodes},
                  {"contact_load_share", film.contact_load_share},
                  {load_key, contact_load},
                  {boundary_key, boundary},
                  {film_key, sheared}};
  traction.*force = sheared + boundary;
  traction.friction_coefficient = (sheared + boundary) / load;
  traction.max_shear_stress_Pa = std::max(traction.max_shear_stress_Pa, boundary_coefficient * contact_pressure);
}

// ehl.json's contact block, continued: the nodes at the hardness ([material]; none without) and the
// share of the load they carry; null where the solve did not converge.
template <class Film>
void plastic_contact(const Film& film, bool converged, nlohmann::json& j) {
  j["contact"]["plastic_nodes"] = converged ? nlohmann::json(film.plastic_nodes) : nlohmann::json(nullptr);
  j["contact"]["plastic_load_share"] = converged ? nlohmann::json(film.plastic_load_share) : nlohmann::json(nullptr);
}

// A line contact with [profile] (ehl_line.h).
void solve_profile(const EhlRun& run, EhlSolve& out) {
  const double w = run.contact.load_per_length_N_per_m;
  out.film = lub::solve_ehl_line(run.contact, run.profile->surface, run.lubricant, run.options);
  out.converged = out.film.converged;
  out.summary["regime"] = "mixed (node by node, lubrication/ehl_line.h: Hu & Zhu's unified model)";
  const auto traction_of = [&](const lub::EhlLineResult& f) {
    return lub::ehl_line_traction(f, run.lubricant, run.sliding_speed_m_per_s, run.eyring_stress_Pa, w, run.heating, run.limiting_shear);
  };
  profile_friction(out.film, out.converged, w, run.profile->boundary_friction_coefficient, traction_of, out.traction,
                   &lub::EhlTraction::force_per_length_N_per_m, "per_length_N_per_m", "N_per_m", out.summary);
  plastic_contact(out.film, out.converged, out.summary);
}

// A point contact with [profile]: ridges across the track (ehl_point.h).
void solve_point_profile(const EhlRun& run, EhlSolve& out) {
  const lub::EhlPointContact& c = *run.point;
  out.point_film = lub::solve_ehl_point(c, run.profile->surface, run.lubricant, run.point_options);
  out.converged = out.point_film->converged;
  out.summary["regime"] = "mixed (node by node, lubrication/ehl_point.h: Hu & Zhu's unified model, ridges across the track)";
  const auto traction_of = [&](const lub::EhlPointResult& f) {
    return lub::ehl_point_traction(f, run.lubricant, run.sliding_speed_m_per_s, run.eyring_stress_Pa, c.load_N, run.heating,
                                   run.limiting_shear);
  };
  profile_friction(*out.point_film, out.converged, c.load_N, run.profile->boundary_friction_coefficient, traction_of, out.point_traction,
                   &lub::EhlPointTraction::force_N, "N", "N", out.summary);
  plastic_contact(*out.point_film, out.converged, out.summary);
}

// The point contact's solve and summary (geometry = "point").
void solve_point(const EhlRun& run, EhlSolve& out) {
  nlohmann::json& j = out.summary;
  const lub::EhlPointContact& c = *run.point;
  if (run.roughness) {
    const auto mc = mixed_contact<lub::MixedPointContact>(run, c);
    lub::MixedPointOptions mo;
    mo.film = run.point_options;
    const lub::MixedPointResult& m = out.mixed_point.emplace(lub::solve_mixed_point(mc, run.lubricant, mo));
    out.point_film = m.film;
    out.point_traction = m.traction;
    out.converged = m.converged;
    j["regime"] = "mixed (load sharing, lubrication/mixed_point.h): the film fields are the film's share of the load";
    j["mixed"] = mixed_json(m, {m.film_load_N, m.asperity_load_N, m.boundary_friction_N, m.film_friction_N}, "N", "N");
  } else if (run.profile) {
    solve_point_profile(run, out);
  } else {
    out.point_film = lub::solve_ehl_point(c, run.lubricant, run.point_options);
    out.converged = out.point_film->converged;
    if (out.converged)
      out.point_traction =
          lub::ehl_point_traction(*out.point_film, run.lubricant, run.sliding_speed_m_per_s, run.eyring_stress_Pa, c.load_N, run.heating,
                                  run.limiting_shear);
    j["regime"] = "full film (smooth surfaces)";
  }
  const lub::EhlPointResult& f = *out.point_film;
  const lub::EhlPointTraction& t = out.point_traction;
  j["geometry"] = "point";
  j["hertz_radius_m"] = f.hertz_radius_m;
  j["linear_solver"] = f.linear_solver;
  j["krylov_iterations"] = f.krylov_iterations;
  film_summary(j, f, out.converged, out.mixed_point ? &*out.mixed_point : nullptr,
               {t.friction_coefficient, t.force_N, t.max_shear_stress_Pa, t.max_film_temperature_rise_K, t.max_surface_temperature_rise_K,
                t.surface_peclet_number, t.limited_node_share},
               "traction_N", run.heating.surfaces.has_value(), run.limiting_shear.on());
  const auto g = lub::reference::point_contact_groups(c.load_N, c.reduced_radius_m, c.reduced_modulus_Pa, c.mean_speed_m_per_s,
                                                      run.lubricant.viscosity_Pa_s, run.lubricant.pressure_viscosity_per_Pa);
  j["dimensionless"] = {{"W", g.load}, {"U", g.speed}, {"G", g.material}};
  // Hamrock & Dowson's fits at the same groups, for comparison (lubrication/reference/ehl_point_film.h).
  j["fits"] = {{"hamrock_dowson_central_film_m", lub::reference::hamrock_dowson_central_film(g) * c.reduced_radius_m},
               {"hamrock_dowson_minimum_film_m", lub::reference::hamrock_dowson_minimum_film(g) * c.reduced_radius_m}};
  j["inputs"] = {{"load_N", c.load_N},
                 {"reduced_radius_m", c.reduced_radius_m},
                 {"reduced_modulus_Pa", c.reduced_modulus_Pa},
                 {"mean_speed_m_per_s", c.mean_speed_m_per_s},
                 {"nodes_x", run.point_options.nodes_x},
                 {"nodes_y", run.point_options.nodes_y},
                 {"domain", run.fitted_domain ? "fitted" : "given"},
                 {"inlet_over_radius", run.point_options.inlet_over_radius},
                 {"outlet_over_radius", run.point_options.outlet_over_radius},
                 {"side_over_radius", run.point_options.side_over_radius}};
  j["inputs"].update(lubricant_inputs(run));
  if (run.roughness) j["inputs"]["roughness"] = roughness_inputs(*run.roughness);
  if (run.profile) j["inputs"]["profile"] = profile_inputs(*run.profile);
  if (run.surface_map) j["inputs"]["surface"] = surface_inputs(*run.surface_map);
}

}  // namespace

EhlSolve solve_ehl_run(const EhlRun& run) {
  EhlSolve out;
  out.line_options = run.options;
  const auto start = std::chrono::steady_clock::now();
  nlohmann::json& j = out.summary;
  if (run.point) {
    solve_point(run, out);
    j["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
  }
  // The fitted inlet: the smooth contact's at the full load (a film's share s < 1 is at most a little
  // thicker, s^−0.2 by the film fits, and only where the summits carry the rest: at low speed).
  std::optional<lub::FittedLineInlet> fit;
  if (run.fitted_domain && !run.profile) {
    fit = lub::fit_inlet_to_film(run.contact, run.lubricant, run.options);
    // Unsettled, the given inlet (with [roughness], the smooth film the fit solves may not exist at
    // low speed, where the summits carry the load: the inlet is then not what matters).
    if (!fit->settled) std::fprintf(stderr, "tribo: warning: solver.domain = \"fitted\": %s\n", fit->message.c_str());
    out.line_options = fit->options;
    j["inlet_fit"] = {{"settled", fit->settled}, {"solves", fit->solves}, {"message", fit->message}};
  }
  if (run.roughness) {
    const auto mc = mixed_contact<lub::MixedLineContact>(run, run.contact);
    lub::MixedLineOptions mo;
    mo.film = out.line_options;
    const lub::MixedLineResult& m = out.mixed.emplace(lub::solve_mixed_line(mc, run.lubricant, mo));
    out.film = m.film;
    out.traction = m.traction;
    out.converged = m.converged;
    j["regime"] = "mixed (load sharing, lubrication/mixed_line.h): the film fields are the film's share of the load";
    j["mixed"] = mixed_json(m, {m.film_load_per_length_N_per_m, m.asperity_load_per_length_N_per_m, m.boundary_friction_N_per_m,
                                m.film_friction_N_per_m},
                            "per_length_N_per_m", "N_per_m");
  } else if (run.profile) {
    solve_profile(run, out);
  } else if (fit) {
    out.film = fit->result;
    out.converged = out.film.converged;
  } else {
    out.film = lub::solve_ehl_line(run.contact, run.lubricant, run.options);
    out.converged = out.film.converged;
  }
  if (!run.roughness && !run.profile) {
    if (out.converged)  // no traction from a film that is not a solution
      out.traction = lub::ehl_line_traction(out.film, run.lubricant, run.sliding_speed_m_per_s, run.eyring_stress_Pa,
                                            run.contact.load_per_length_N_per_m, run.heating, run.limiting_shear);
    j["regime"] = "full film (smooth surfaces)";
  }
  const lub::EhlLineResult& f = out.film;
  const lub::EhlTraction& t = out.traction;
  j["geometry"] = "line";
  j["hertz_half_width_m"] = f.hertz_half_width_m;
  film_summary(j, f, out.converged, out.mixed ? &*out.mixed : nullptr,
               {t.friction_coefficient, t.force_per_length_N_per_m, t.max_shear_stress_Pa, t.max_film_temperature_rise_K,
                t.max_surface_temperature_rise_K, t.surface_peclet_number, t.limited_node_share},
               "traction_N_per_m", run.heating.surfaces.has_value(), run.limiting_shear.on());
  const lub::EhlLineContact& c = run.contact;
  const auto g = lub::reference::line_contact_groups(c.load_per_length_N_per_m, c.reduced_radius_m, c.reduced_modulus_Pa,
                                                     c.mean_speed_m_per_s, run.lubricant.viscosity_Pa_s,
                                                     run.lubricant.pressure_viscosity_per_Pa);
  j["dimensionless"] = {{"W", g.load}, {"U", g.speed}, {"G", g.material}};
  // The published fits at the same groups, for comparison (lubrication/reference/ehl_film.h).
  j["fits"] = {{"dowson_higginson_minimum_film_m", lub::reference::dowson_higginson_minimum_film(g) * c.reduced_radius_m},
               {"pan_hamrock_minimum_film_m", lub::reference::pan_hamrock_minimum_film(g) * c.reduced_radius_m},
               {"pan_hamrock_central_film_m", lub::reference::pan_hamrock_central_film(g) * c.reduced_radius_m},
               {"dowson_toyoda_central_film_m", lub::reference::dowson_toyoda_central_film(g) * c.reduced_radius_m}};
  j["inputs"] = {{"load_per_length_N_per_m", c.load_per_length_N_per_m},
                 {"reduced_radius_m", c.reduced_radius_m},
                 {"reduced_modulus_Pa", c.reduced_modulus_Pa},
                 {"mean_speed_m_per_s", c.mean_speed_m_per_s},
                 {"nodes", out.line_options.nodes},
                 {"domain", run.fitted_domain ? "fitted" : "given"},
                 {"inlet_over_half_width", out.line_options.inlet_over_half_width},
                 {"outlet_over_half_width", out.line_options.outlet_over_half_width}};
  j["inputs"].update(lubricant_inputs(run));
  if (run.roughness) j["inputs"]["roughness"] = roughness_inputs(*run.roughness);
  if (run.profile) j["inputs"]["profile"] = profile_inputs(*run.profile);
  j["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tribo::cli
