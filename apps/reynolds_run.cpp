// The readers and the solve of `tribo reynolds` (see reynolds_run.h).
#include "apps/reynolds_run.h"

#include <cmath>

#include "apps/config.h"
#include "apps/surface_config.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"
#include "contact/surface_io.h"
#include "lubrication/geometry.h"
#include "lubrication/reference/squeeze_film.h"
#include "lubrication/viscosity.h"

namespace tribo::cli {

namespace lub = tribo::lubrication;

namespace {

// Appendix V, thesis surfaces after test (Talysurf CLA): slider 1–3 µin, disc 13–14 µin. For a
// Gaussian height distribution Rq = √(π/2) · CLA ≈ 1.25 CLA.
constexpr double kMicroInch_m = 2.54e-8;
const double kSliderRq_m = std::sqrt(M_PI / 2) * 2.0 * kMicroInch_m;
const double kDiscRq_m = std::sqrt(M_PI / 2) * 13.5 * kMicroInch_m;
constexpr double kSliderRadius_m = 4.7625e-3;  // 3/16 in (Appendix I)

std::optional<ConfigTable> sub(ConfigTable& root, const std::string& key) { return root.table(key); }

// [lubricant]: η₀ (default the thesis oil) and, for `tribo reynolds`, Barus ψ (default 0:
// isoviscous, since the thesis films are far below the pressures where ψ matters).
double read_viscosity(ConfigTable& root, double* pressure_viscosity_per_Pa = nullptr) {
  const lub::Lubricant oil = lub::thesis_white_mineral_oil();
  auto t = sub(root, "lubricant");
  if (!t) return oil.viscosity_Pa_s;
  const double eta = t->number("viscosity_Pa_s", oil.viscosity_Pa_s, Range::positive);
  if (pressure_viscosity_per_Pa)
    *pressure_viscosity_per_Pa = t->number("pressure_viscosity_per_Pa", 0.0, Range::non_negative);
  t->finish();
  return eta;
}

double read_speed(ConfigTable& root) {
  auto t = sub(root, "motion");
  if (!t) return 0.0;
  const double u = t->number("sliding_speed_m_per_s", 0.0, Range::any);
  t->finish();
  return u;
}

}  // namespace

ReynoldsRun load_reynolds_run(const std::filesystem::path& path) { return load_reynolds_run(parse_toml_file(path), path); }

ReynoldsRun load_reynolds_run(const toml::table& doc, const std::filesystem::path& path) {
  ConfigTable root(doc, path.string(), "");
  ReynoldsRun run;
  double psi = 0.0;
  const double eta = read_viscosity(root, &psi);
  const double speed = read_speed(root);
  int n = 256;
  if (auto g = sub(root, "grid")) {
    // At most 8192 nodes a side: 8192² is 0.5 GiB a field, and a Reynolds problem holds several
    // (a grid of 15226 asked for 1.8 GB at load, found by fuzz_reynolds_config).
    n = static_cast<int>(g->integer("n", n, 3, 8192));
    g->finish();
  }
  lub::Cavitation cavitation = lub::Cavitation::mass_conserving;
  if (auto s = sub(root, "solver")) {
    cavitation = s->choice("cavitation", "mass_conserving", {"mass_conserving", "none"}) == "none"
                     ? lub::Cavitation::none
                     : lub::Cavitation::mass_conserving;
    run.options.newton_tolerance = s->number("newton_tolerance", run.options.newton_tolerance, Range::positive);
    run.options.max_newton_iterations =
        static_cast<int>(s->integer("max_newton_iterations", run.options.max_newton_iterations, 1, 100'000));
    s->finish();
  }
  auto g = sub(root, "geometry");
  if (!g) root.fail("geometry", "the [geometry] table is required");
  run.kind = g->choice("kind", "parallel_discs", {"parallel_discs", "gap_file", "rough_pair"});
  run.geometry["kind"] = run.kind;
  if (run.kind == "parallel_discs") {
    const double radius = g->number("radius_m", kSliderRadius_m, Range::positive);
    const double gap = g->required_number("gap_m", Range::positive);
    const double rate = g->number("gap_rate_m_per_s", 0.0, Range::any);
    if (n < 5) root.fail("grid", "n must be >= 5 for parallel discs");
    run.problem = lub::parallel_discs_problem(radius, gap, rate, eta, speed, n);
    run.reference_load_N = lub::squeeze_film_load_N(eta, radius, gap, rate);
    run.geometry.update({{"radius_m", radius}, {"gap_m", gap}, {"gap_rate_m_per_s", rate}});
  } else if (run.kind == "gap_file") {
    const std::filesystem::path gap_path = g->input_file("file");
    const double scale = g->number("height_scale", 1.0, Range::positive);
    const double dx = g->required_number("dx_m", Range::positive);
    const double dy = g->number("dy_m", dx, Range::positive);
    const double rate = g->number("gap_rate_m_per_s", 0.0, Range::any);
    const bool periodic = g->choice("boundary_y", "ambient", {"ambient", "periodic"}) == "periodic";
    const double p_in = g->number("inlet_pressure_Pa", 0.0, Range::non_negative);
    const double p_out = g->number("outlet_pressure_Pa", 0.0, Range::non_negative);
    const contact::Topography topo = input_guard(*g, "file", [&] { return contact::read_topography(gap_path, scale); });
    run.problem.grid = contact::Grid{topo.heights_m.rows(), topo.heights_m.cols(), dx, dy};
    run.problem.gap_m = topo.heights_m;
    run.problem.gap_rate_m_per_s = run.problem.grid.field(rate);
    run.problem.boundary_y = periodic ? lub::BoundaryY::periodic : lub::BoundaryY::ambient;
    run.problem.inlet_pressure_Pa = p_in;
    run.problem.outlet_pressure_Pa = p_out;
    run.geometry.update({{"file", gap_path.string()}, {"dx_m", dx}, {"dy_m", dy}, {"gap_rate_m_per_s", rate}});
  } else {
    // Upper surface: the worn slider; lower: the disc (Appendix V). Both Gaussian, the same
    // spectrum shape, independent seeds (upper = seed + 1), placed by lubrication::rough_pair_film.
    g->refuse_renamed("contact_load_N", "geometry.normal_load_N");
    const bool rigid = g->has("mean_gap_m");
    if (rigid == g->has("normal_load_N"))
      g->fail("mean_gap_m", "give exactly one of mean_gap_m (rigid surfaces) and normal_load_N (deformed by contact)");
    lub::RoughPairFilmOptions placement;
    if (rigid)
      placement.mean_gap_m = g->required_number("mean_gap_m", Range::positive);
    else
      placement.normal_load_N = g->required_number("normal_load_N", Range::positive);
    placement.composite_modulus_Pa = g->number("composite_modulus_Pa", placement.composite_modulus_Pa, Range::positive);
    placement.hardness_Pa = g->number("hardness_Pa", placement.hardness_Pa, Range::positive);
    placement.contact_gap_fraction = g->number("contact_gap_fraction", placement.contact_gap_fraction, Range::positive);
    // With one placement and positive values read, only the floor fraction's upper bound is left.
    if (std::string why; !placement.is_valid(&why)) g->fail("contact_gap_fraction", why);
    const double upper_rq = g->number("upper_rms_height_m", kSliderRq_m, Range::non_negative);
    // The lower surface: [geometry] holds its spectrum keys as [surface] would (surface_config.h),
    // with its size and rms height under rough-pair names and defaults.
    contact::GaussianSurfaceParams p;
    p.grid = n;
    p.size_m = g->number("size_m", 1e-3, Range::positive);
    p.rms_height_m = g->number("lower_rms_height_m", kDiscRq_m, Range::positive);
    read_spectrum(*g, p);
    input_guard(*g, "spectrum", [&] { contact::validate(p); return 0; });
    // Every key is read: an unknown one is refused before the surfaces are generated and the
    // contact solved, which takes seconds at large grids (found by fuzz_reynolds_config).
    g->finish();
    root.finish();
    const Eigen::ArrayXXd lower = contact::gaussian_surface(p);
    run.seed = p.seed;
    Eigen::ArrayXXd upper = Eigen::ArrayXXd::Zero(lower.rows(), lower.cols());
    if (upper_rq > 0) {
      contact::GaussianSurfaceParams q = p;
      q.rms_height_m = upper_rq;
      q.seed = p.seed + 1;
      upper = contact::gaussian_surface(q);
    }
    const lub::RoughPairFilm film = input_guard(*g, rigid ? "mean_gap_m" : "normal_load_N", [&] {
      return lub::rough_pair_film(upper, lower, p.size_m, placement);
    });
    if (film.contact) {
      const contact::NormalContactResult& c = *film.contact;
      if (!c.summary.converged) g->fail("normal_load_N", "contact solve did not converge: " + c.summary.message);
      run.geometry.update({{"normal_load_N", *placement.normal_load_N},
                           {"composite_modulus_Pa", placement.composite_modulus_Pa},
                           {"contact_area_fraction", c.area_fraction},
                           {"contact_mean_gap_m", c.mean_gap_m},
                           {"contact_iterations", c.summary.iterations}});
    } else {
      run.geometry["mean_gap_m"] = *placement.mean_gap_m;
    }
    run.problem = film.problem;
    run.geometry.update({{"rigid", rigid},
                         {"composite_rms_height_m", film.composite_rms_height_m},
                         {"upper_rms_height_m", upper_rq},
                         {"lower_rms_height_m", p.rms_height_m},
                         {"size_m", p.size_m},
                         {"contact_nodes", film.contact_nodes}});
  }
  g->finish();
  root.finish();
  run.problem.viscosity_Pa_s = eta;
  run.problem.pressure_viscosity_per_Pa = psi;
  run.problem.sliding_speed_m_per_s = speed;
  run.problem.cavitation = cavitation;
  input_guard(root, "geometry", [&] { lub::validate(run.problem); return 0; });
  run.input_files = root.input_files();
  return run;
}

ReynoldsSolve solve_reynolds_run(const ReynoldsRun& run) {
  lub::ReynoldsSolution s = lub::solve_reynolds(run.problem, run.options);
  const contact::Grid& g = run.problem.grid;
  nlohmann::json j;
  j["load_N"] = s.load_N;
  j["max_pressure_Pa"] = s.max_pressure_Pa;
  j["cavitated_fraction"] = s.cavitated_fraction;
  j["iterations"] = s.summary.iterations;
  j["wall_s"] = s.summary.wall_s;
  j["converged"] = s.summary.converged;
  j["residual"] = s.summary.residual;
  j["message"] = s.summary.message;
  j["linear_solver"] = s.summary.linear_solver;
  j["linear_solver_s"] = s.summary.linear_solver_s;
  j["geometry"] = run.geometry;
  j["grid"] = {{"nx", g.nx}, {"ny", g.ny}, {"dx_m", g.dx_m}, {"dy_m", g.dy_m}};
  j["viscosity_Pa_s"] = run.problem.viscosity_Pa_s;
  j["pressure_viscosity_per_Pa"] = run.problem.pressure_viscosity_per_Pa;
  j["sliding_speed_m_per_s"] = run.problem.sliding_speed_m_per_s;
  j["cavitation"] = run.problem.cavitation == lub::Cavitation::none ? "none" : "mass_conserving";
  if (run.reference_load_N) {
    j["reference_load_N"] = *run.reference_load_N;  // thesis (3.2.2)
    if (*run.reference_load_N != 0) j["load_relative_error"] = s.load_N / *run.reference_load_N - 1.0;
  }
  return {std::move(s), std::move(j)};
}

FlowFactorRun load_flow_factor_run(const std::filesystem::path& path) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path.string(), "");
  FlowFactorRun run;
  lub::HomogenisationOptions& o = run.options;
  o.viscosity_Pa_s = read_viscosity(root);
  if (auto m = sub(root, "motion")) {
    o.sliding_speed_m_per_s = m->number("sliding_speed_m_per_s", o.sliding_speed_m_per_s, Range::positive);
    m->finish();
  }
  auto s = sub(root, "surface");
  if (!s) root.fail("surface", "the [surface] table is required");
  s->choice("kind", "gaussian", {"gaussian"});
  s->refuse_renamed("size_m", "domain.size_m");
  s->refuse_renamed("grid", "domain.grid");
  auto domain = sub(root, "domain");
  o.surface = read_gaussian_surface(*s, domain ? &*domain : nullptr);
  s->finish();
  if (domain) domain->finish();
  if (auto h = sub(root, "homogenisation")) {
    if (h->has("gap_ratios")) o.gap_ratios = h->number_array("gap_ratios", Range::positive);
    o.realisations = static_cast<int>(h->integer("realisations", o.realisations, 1));
    o.first_seed = static_cast<std::uint64_t>(h->integer("first_seed", 1, 0));
    o.contact_gap_fraction = h->number("contact_gap_fraction", o.contact_gap_fraction, Range::positive);
    run.lift_contact_gap_fraction =
        h->number("lift_contact_gap_fraction", run.lift_contact_gap_fraction, Range::positive);
    o.pressure_drop_Pa = h->number("pressure_drop_Pa", o.pressure_drop_Pa, Range::positive);
    o.threads = static_cast<int>(h->integer("threads", 0, 0));
    h->finish();
  }
  root.finish();
  input_guard(root, "homogenisation", [&] {
    lub::validate(o);
    lub::HomogenisationOptions lift = o;
    lift.contact_gap_fraction = run.lift_contact_gap_fraction;
    lub::validate(lift);
    return 0;
  });
  return run;
}

}  // namespace tribo::cli
