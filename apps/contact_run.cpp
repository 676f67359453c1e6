// The reader and the solve of `tribo contact CONFIG.toml` (see contact_run.h).
#include "apps/contact_run.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include <omp.h>

#include "apps/config.h"
#include "apps/provenance.h"
#include "apps/surface_config.h"
#include "contact/halfspace.h"
#include "contact/junction_growth.h"
#include "contact/reference/hertz.h"
#include "contact/surface_io.h"
#include "contact/tangential.h"
#include "numerics/format.h"

namespace tribo::cli {

ContactRun load_contact_run(const std::filesystem::path& path, bool junction) {
  return load_contact_run(parse_toml_file(path), path, junction);
}

ContactRun load_contact_run(const toml::table& doc, const std::filesystem::path& path, bool junction) {
  ConfigTable root(doc, path.string(), "");
  ContactRun run;
  auto surface = root.table("surface");
  auto domain = root.table("domain");
  auto material = root.table("material");
  auto load = root.table("load");
  if (!surface) root.fail("surface", "table [surface] is required");
  if (!material) root.fail("material", "table [material] is required");
  if (!load) root.fail("load", "table [load] is required");

  run.surface_kind = surface->choice("kind", "gaussian", {"sphere", "gaussian", "file"});
  std::optional<double> size_m;
  std::optional<long long> grid_n;
  if (domain) {
    size_m = domain->optional_number("size_m", Range::positive);
    if (domain->has("grid")) grid_n = domain->integer("grid", 0, 2);
    run.periodic = domain->boolean("periodic", run.surface_kind != "sphere");
    domain->finish();
  } else {
    run.periodic = run.surface_kind != "sphere";
  }

  if (run.surface_kind == "sphere") {
    if (!size_m) root.fail("domain", "[domain] size_m is required for a sphere");
    if (!grid_n) root.fail("domain", "[domain] grid is required for a sphere");
    run.grid = contact::Grid::patch(*grid_n, *grid_n, *size_m, *size_m);
    run.sphere_radius_m = surface->required_number("radius_m", Range::positive);
    run.gap0_m = contact::sphere_gap(run.grid, run.sphere_radius_m);
  } else if (run.surface_kind == "gaussian") {
    const contact::GaussianSurfaceParams p = read_gaussian_surface(*surface, domain ? &*domain : nullptr);
    run.grid = contact::Grid::patch(p.grid, p.grid, p.size_m, p.size_m);
    run.seed = p.seed;
    const Eigen::ArrayXXd z = input_guard(*surface, "spectrum", [&] { return contact::gaussian_surface(p); });
    run.stats = contact::surface_statistics(z, p.size_m, p.size_m);
    run.gap0_m = contact::gap_from_heights(z);
  } else {
    surface->refuse_renamed("path", "surface.file");
    const std::filesystem::path file = surface->input_file("file");
    const double scale = surface->number("height_scale", 1.0, Range::positive);
    const contact::Topography topo = input_guard(*surface, "file", [&] { return contact::read_topography(file, scale); });
    double lx = topo.lx_m, ly = topo.ly_m;
    if (lx == 0.0) {
      if (!size_m) root.fail("domain", "[domain] size_m is required for a surface file without coordinates");
      lx = *size_m;
      ly = *size_m * static_cast<double>(topo.heights_m.cols()) / static_cast<double>(topo.heights_m.rows());
    } else if (size_m && std::abs(*size_m - lx) > 1e-9 * lx) {
      domain->fail("size_m", "does not match the x extent " + numerics::shortest(lx) + " m of " + file.string());
    }
    if (grid_n && *grid_n != topo.heights_m.rows()) {
      domain->fail("grid", "does not match the " + std::to_string(topo.heights_m.rows()) + " rows of " + file.string());
    }
    run.grid = contact::Grid::patch(topo.heights_m.rows(), topo.heights_m.cols(), lx, ly);
    run.stats = contact::surface_statistics(topo.heights_m, lx, ly);
    run.gap0_m = contact::gap_from_heights(topo.heights_m);
  }
  surface->finish();

  run.e_star_Pa = material->required_number("e_star_Pa", Range::positive);
  run.hardness_Pa = material->optional_number("hardness_Pa", Range::positive);
  run.alpha = material->number("alpha", 25.0, Range::non_negative);
  if (auto tau = material->optional_number("interface_shear_strength_Pa", Range::positive)) run.tau_i_Pa = *tau;
  material->finish();

  load->refuse_renamed("normal_N", "load.normal_load_N");
  run.normal_load_N = load->required_number("normal_load_N", Range::positive);
  load->refuse_renamed("tangential_N", "load.tangential_load_N");
  run.tangential_load_N = load->number("tangential_load_N", 0.0, Range::non_negative);
  load->finish();
  if (run.tangential_load_N > 0.0 && !run.hardness_Pa) {
    load->fail("tangential_load_N", "junction growth under a tangential load needs [material] hardness_Pa");
  }
  if (run.hardness_Pa && run.normal_load_N > *run.hardness_Pa * run.grid.area_m2()) {
    load->fail("normal_load_N", "exceeds hardness_Pa * domain area: the whole domain would flow plastically");
  }

  if (auto s = root.table("solver")) {
    run.solver.tolerance = s->number("tolerance", run.solver.tolerance, Range::positive);
    run.solver.max_iterations = static_cast<int>(s->integer("max_iterations", 0, 0, 1'000'000'000));
    run.solver.single_precision_above =
        s->number("single_precision_above", run.solver.single_precision_above, Range::non_negative);
    run.threads = static_cast<int>(s->integer("threads", 0, 0, 1'000'000));
    std::string why;
    if (!run.solver.is_valid(&why)) s->fail("tolerance", why);
    s->finish();
  }

  if (junction) {
    if (!run.hardness_Pa) root.fail("material", "the junction comparison needs [material] hardness_Pa");
    auto j = root.table("junction");
    run.locus.alpha = run.alpha;
    double mu_s_max = 0.55;  // thesis, steel on steel (DESIGN §5)
    if (j) {
      run.f_over_w_max = j->number("f_over_w_max", run.f_over_w_max, Range::positive);
      run.junction_points = static_cast<int>(j->integer("points", run.junction_points, 2, 10'000));  // a BEM solve each
      run.locus.n = j->number("n", run.locus.n, Range::non_negative);
      mu_s_max = j->number("mu_s_max", mu_s_max, Range::positive);
      run.locus.location_per_s = j->number("location_per_s", run.locus.location_per_s, Range::positive);
      j->finish();
    }
    run.locus.sigma0_over_tau_i = input_guard(root, "junction", [&] {
      return contact::sigma0_over_tau_i_from_upper_asymptote(mu_s_max, run.alpha);
    });
    input_guard(root, "junction", [&] { contact::validate(run.locus); return 0; });
  } else if (root.has("junction")) {
    root.accept("junction");
  }
  root.finish();
  run.input_files = root.input_files();
  return run;
}

void apply_thread_count(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

nlohmann::json contact_provenance(const std::filesystem::path& config, const ContactRun& run, const std::string& hash) {
  nlohmann::json p = provenance_json(config, hash, run.input_files);
  if (run.seed) p["seed"] = *run.seed;
  return p;
}

ContactSolve solve_contact_run(const ContactRun& run) {
  apply_thread_count(run.threads);
  const auto start = std::chrono::steady_clock::now();
  contact::ElasticHalfSpace hs(run.grid, run.e_star_Pa, run.periodic, run.threads);

  nlohmann::json j;
  contact::NormalContactResult r;
  int total_iterations = 0;
  if (run.tangential_load_N > 0.0) {
    contact::TangentialContactOptions opt;
    opt.hardness_Pa = *run.hardness_Pa;
    opt.alpha = run.alpha;
    opt.interface_shear_strength_Pa = run.tau_i_Pa;
    opt.normal = run.solver;
    const contact::TangentialContactResult t =
        contact::solve_tangential_load(hs, run.gap0_m, run.normal_load_N, run.tangential_load_N, opt);
    r = t.contact;
    total_iterations = t.inner_iterations;
    j["shear_stress_Pa"] = t.shear_stress_Pa;
    j["pressure_cap_Pa"] = t.pressure_cap_Pa;
    j["slipped"] = t.slipped;
    j["junction_converged"] = t.converged;
    j["junction_message"] = t.message;
    j["junction_solves"] = t.outer_iterations;
    j["tabor_area_m2"] = contact::tabor_area_m2(run.normal_load_N, run.tangential_load_N, run.alpha, *run.hardness_Pa);
  } else {
    contact::NormalContactOptions opt = run.solver;
    if (run.hardness_Pa) opt.pressure_cap_Pa = *run.hardness_Pa;
    r = contact::solve_normal_load(hs, run.gap0_m, run.normal_load_N, opt);
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  j["surface"] = run.surface_kind;
  j["grid"] = {run.grid.nx, run.grid.ny};
  j["size_m"] = {run.grid.period_x_m(), run.grid.period_y_m()};
  j["periodic"] = run.periodic;
  j["normal_load_N"] = r.normal_load_N;
  j["tangential_load_N"] = run.tangential_load_N;
  j["real_area_m2"] = r.real_area_m2;
  j["area_fraction"] = r.area_fraction;
  j["plastic_area_m2"] = r.plastic_area_m2;
  j["max_pressure_Pa"] = r.max_pressure_Pa;
  j["mean_gap_m"] = r.mean_gap_m;
  j["approach_m"] = r.approach_m;
  j["converged"] = r.summary.converged;
  // With a tangential load: CG iterations over all the elastic-plastic solves of the fixed point.
  j["iterations"] = run.tangential_load_N > 0.0 ? total_iterations : r.summary.iterations;
  j["residual"] = r.summary.residual;
  j["tolerance"] = run.solver.tolerance;
  if (run.tangential_load_N <= 0.0) {  // one solve: its half-space products (the fixed point's are many solves)
    j["fft_pairs"] = r.summary.fft_pairs;
    j["single_pairs"] = r.summary.single_pairs;
  }
  j["message"] = r.summary.message;
  j["wall_s"] = wall;
  if (run.surface_kind == "sphere") {
    j["contact_radius_m"] = std::sqrt(r.real_area_m2 / std::numbers::pi);
    j["hertz_contact_radius_m"] = contact::reference::hertz_contact_radius_m(run.normal_load_N, run.sphere_radius_m, run.e_star_Pa);
    j["hertz_peak_pressure_Pa"] = contact::reference::hertz_peak_pressure_Pa(run.normal_load_N, run.sphere_radius_m, run.e_star_Pa);
  }
  if (run.stats) {
    j["surface_rq_m"] = run.stats->rq_m;
    j["surface_ra_m"] = run.stats->ra_m;
    j["surface_rms_slope"] = run.stats->rms_slope;
    j["surface_rms_curvature_per_m"] = run.stats->rms_curvature_per_m;
  }
  return {std::move(r), std::move(j)};
}

}  // namespace tribo::cli
