// `tribo contact CONFIG.toml --out DIR`: one rough-surface (or sphere) normal/tangential contact
// solve, writing contact.json, pressure.npy and gap.npy.
// `tribo contact junction CONFIG.toml --out DIR`: BEM junction growth A(W, F) over F/W against
// Tabor's closed form (3.1.9), and the junction ODE (3.1.13) against the locus (3.1.24).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/output.h"
#include "contact/halfspace.h"
#include "contact/junction_growth.h"
#include "contact/junction_locus.h"
#include "contact/normal_contact.h"
#include "contact/reference/hertz.h"
#include "contact/surface.h"
#include "contact/surface_io.h"
#include "contact/tangential.h"

namespace tribo::cli {
namespace {

struct ContactArgs {
  std::string config;
  std::string out = "out/contact";
};

// Everything a run needs, read and validated before any file is written.
struct ContactRun {
  std::string surface_kind;
  double sphere_radius_m = 0.0;
  contact::Grid grid;
  bool periodic = false;
  Eigen::ArrayXXd gap0_m;        // initial gap h
  std::optional<contact::SurfaceStatistics> stats;
  double e_star_Pa = 0.0;
  std::optional<double> hardness_Pa;
  double alpha = 25.0;
  double normal_N = 0.0, tangential_N = 0.0;
  double tau_i_Pa = std::numeric_limits<double>::infinity();
  contact::NormalContactOptions solver;
  int threads = 0;
  // junction subcommand
  double f_over_w_max = 0.5;
  int junction_points = 11;
  contact::JunctionLocus locus;
};

ContactRun load_contact_run(const std::filesystem::path& path, bool junction) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path.string(), "");
  ContactRun run;
  auto surface = root.table("surface");
  auto domain = root.table("domain");
  auto material = root.table("material");
  auto load = root.table("load");
  if (!surface) root.fail("surface", "table [surface] is required");
  if (!material) root.fail("material", "table [material] is required");
  if (!load) root.fail("load", "table [load] is required");

  run.surface_kind = surface->choice("kind", "sphere", {"sphere", "gaussian", "file"});
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

  if (run.surface_kind == "sphere" || run.surface_kind == "gaussian") {
    if (!size_m) root.fail("domain", "[domain] size_m is required for a " + run.surface_kind + " surface");
    if (!grid_n) root.fail("domain", "[domain] grid is required for a " + run.surface_kind + " surface");
    run.grid = contact::Grid::patch(*grid_n, *grid_n, *size_m, *size_m);
  }
  if (run.surface_kind == "sphere") {
    run.sphere_radius_m = surface->required_number("radius_m", Range::positive);
    run.gap0_m = contact::sphere_gap(run.grid, run.sphere_radius_m);
  } else if (run.surface_kind == "gaussian") {
    contact::GaussianSurfaceParams p;
    p.grid = *grid_n;
    p.size_m = *size_m;
    const std::string spectrum = surface->choice("spectrum", "self_affine", {"self_affine", "gaussian_acf"});
    p.kind = spectrum == "self_affine" ? contact::SpectrumKind::self_affine : contact::SpectrumKind::gaussian_acf;
    p.rms_height_m = surface->number("rms_height_m", 0.0, Range::non_negative);
    p.rms_slope = surface->number("rms_slope", 0.0, Range::non_negative);
    p.seed = static_cast<std::uint64_t>(surface->integer("seed", 1, 0));
    if (p.kind == contact::SpectrumKind::self_affine) {
      p.hurst = surface->number("hurst", p.hurst, Range::positive);
      p.rolloff_wavelength_m = surface->number("rolloff_wavelength_m", 0.0, Range::non_negative);
      p.cutoff_wavelength_m = surface->number("cutoff_wavelength_m", 0.0, Range::non_negative);
    } else {
      p.correlation_length_m = surface->required_number("correlation_length_m", Range::positive);
      p.correlation_length_across_m = surface->number("correlation_length_across_m", 0.0, Range::non_negative);
    }
    const Eigen::ArrayXXd z = input_guard(*surface, "kind", [&] { return contact::gaussian_surface(p); });
    run.stats = contact::surface_statistics(z, p.size_m, p.size_m);
    run.gap0_m = contact::gap_from_heights(z);
  } else {
    const std::string rel = surface->required_string("path");
    const std::filesystem::path file = std::filesystem::path(rel).is_absolute() ? std::filesystem::path(rel)
                                                                                : path.parent_path() / rel;
    const double scale = surface->number("height_scale", 1.0, Range::positive);
    const contact::Topography topo = input_guard(*surface, "path", [&] { return contact::read_topography(file, scale); });
    double lx = topo.lx_m, ly = topo.ly_m;
    if (lx == 0.0) {
      if (!size_m) root.fail("domain", "[domain] size_m is required for a surface file without coordinates");
      lx = *size_m;
      ly = *size_m * static_cast<double>(topo.heights_m.cols()) / static_cast<double>(topo.heights_m.rows());
    } else if (size_m && std::abs(*size_m - lx) > 1e-9 * lx) {
      domain->fail("size_m", "does not match the x extent " + std::to_string(lx) + " m of " + file.string());
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

  run.normal_N = load->required_number("normal_N", Range::positive);
  run.tangential_N = load->number("tangential_N", 0.0, Range::non_negative);
  load->finish();
  if (run.tangential_N > 0.0 && !run.hardness_Pa) {
    load->fail("tangential_N", "junction growth under a tangential load needs [material] hardness_Pa");
  }
  if (run.hardness_Pa && run.normal_N > *run.hardness_Pa * run.grid.area_m2()) {
    load->fail("normal_N", "exceeds hardness_Pa * domain area: the whole domain would flow plastically");
  }

  if (auto s = root.table("solver")) {
    run.solver.tolerance = s->number("tolerance", run.solver.tolerance, Range::positive);
    run.solver.max_iterations = static_cast<int>(s->integer("max_iterations", 0, 0));
    run.threads = static_cast<int>(s->integer("threads", 0, 0));
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
      run.junction_points = static_cast<int>(j->integer("points", run.junction_points, 2));
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
  return run;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void write_npy_atomically(const std::filesystem::path& path, const Eigen::ArrayXXd& field) {
  AtomicFile f(path);
  contact::write_npy(f.stream(), field);
  f.commit();
}

// [solver] threads caps both FFTW's threads and the OpenMP loops of the solver.
void apply_thread_count(int threads) {
  if (threads > 0) omp_set_num_threads(threads);
}

void run_contact(const ContactArgs& args) {
  const ContactRun run = load_contact_run(args.config, false);
  apply_thread_count(run.threads);
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const auto start = std::chrono::steady_clock::now();
  contact::ElasticHalfSpace hs(run.grid, run.e_star_Pa, run.periodic, run.threads);

  nlohmann::json j;
  contact::NormalContactResult r;
  int total_iterations = 0;
  if (run.tangential_N > 0.0) {
    contact::TangentialContactOptions opt;
    opt.hardness_Pa = *run.hardness_Pa;
    opt.alpha = run.alpha;
    opt.interface_shear_strength_Pa = run.tau_i_Pa;
    opt.normal = run.solver;
    const contact::TangentialContactResult t =
        contact::solve_tangential_load(hs, run.gap0_m, run.normal_N, run.tangential_N, opt);
    r = t.contact;
    total_iterations = t.inner_iterations;
    j["shear_stress_Pa"] = t.shear_stress_Pa;
    j["pressure_cap_Pa"] = t.pressure_cap_Pa;
    j["slipped"] = t.slipped;
    j["junction_converged"] = t.converged;
    j["junction_message"] = t.message;
    j["junction_solves"] = t.outer_iterations;
    j["tabor_area_m2"] = contact::tabor_area_m2(run.normal_N, run.tangential_N, run.alpha, *run.hardness_Pa);
  } else {
    contact::NormalContactOptions opt = run.solver;
    if (run.hardness_Pa) opt.pressure_cap_Pa = *run.hardness_Pa;
    r = contact::solve_normal_load(hs, run.gap0_m, run.normal_N, opt);
  }
  const double wall = seconds_since(start);

  j["surface"] = run.surface_kind;
  j["grid"] = {run.grid.nx, run.grid.ny};
  j["size_m"] = {run.grid.period_x_m(), run.grid.period_y_m()};
  j["periodic"] = run.periodic;
  j["normal_N"] = r.normal_load_N;
  j["tangential_N"] = run.tangential_N;
  j["real_area_m2"] = r.real_area_m2;
  j["area_fraction"] = r.area_fraction;
  j["plastic_area_m2"] = r.plastic_area_m2;
  j["max_pressure_Pa"] = r.max_pressure_Pa;
  j["mean_gap_m"] = r.mean_gap_m;
  j["approach_m"] = r.approach_m;
  j["converged"] = r.summary.converged;
  // With a tangential load: CG iterations over all the elastic-plastic solves of the fixed point.
  j["iterations"] = run.tangential_N > 0.0 ? total_iterations : r.summary.iterations;
  j["residual"] = r.summary.residual;
  j["tolerance"] = run.solver.tolerance;
  j["message"] = r.summary.message;
  j["wall_s"] = wall;
  if (run.surface_kind == "sphere") {
    j["contact_radius_m"] = std::sqrt(r.real_area_m2 / std::numbers::pi);
    j["hertz_contact_radius_m"] = contact::reference::hertz_contact_radius_m(run.normal_N, run.sphere_radius_m, run.e_star_Pa);
    j["hertz_peak_pressure_Pa"] = contact::reference::hertz_peak_pressure_Pa(run.normal_N, run.sphere_radius_m, run.e_star_Pa);
  }
  if (run.stats) {
    j["surface_rq_m"] = run.stats->rq_m;
    j["surface_ra_m"] = run.stats->ra_m;
    j["surface_rms_slope"] = run.stats->rms_slope;
    j["surface_rms_curvature_per_m"] = run.stats->rms_curvature_per_m;
  }
  write_npy_atomically(dir / "pressure.npy", r.pressure_Pa);
  write_npy_atomically(dir / "gap.npy", r.gap_m);
  if (run.hardness_Pa) write_npy_atomically(dir / "plastic_displacement.npy", r.plastic_increment_m);
  write_file_atomically(dir / "contact.json", j.dump(2) + "\n");
  std::printf("%s: area %.6g m^2 (%.4g %%), max pressure %.6g Pa, %d iterations, residual %.3g, %.3f s -> %s\n",
              run.surface_kind.c_str(), r.real_area_m2, 100.0 * r.area_fraction, r.max_pressure_Pa,
              j["iterations"].get<int>(), r.summary.residual, wall, args.out.c_str());
  if (!r.summary.converged) throw std::runtime_error("contact solve " + r.summary.message);
}

void run_junction(const ContactArgs& args) {
  const ContactRun run = load_contact_run(args.config, true);
  apply_thread_count(run.threads);
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const auto start = std::chrono::steady_clock::now();
  contact::ElasticHalfSpace hs(run.grid, run.e_star_Pa, run.periodic, run.threads);
  contact::TangentialContactOptions opt;
  opt.hardness_Pa = *run.hardness_Pa;
  opt.alpha = run.alpha;
  opt.normal = run.solver;
  const double w = run.normal_N;
  // The largest F/W the domain can carry: √(W² + α F²) ≤ σ0 A_nominal.
  const double f_cap = std::sqrt(std::max(0.0, std::pow(opt.hardness_Pa * run.grid.area_m2(), 2) - w * w) / std::max(run.alpha, 1e-300));
  const double f_over_w_max = std::min(run.f_over_w_max, 0.999 * f_cap / w);

  AtomicFile csv(dir / "junction.csv");
  csv.stream() << "f_over_w,bem_area_m2,tabor_area_m2,bem_growth,tabor_growth,bem_over_tabor_growth,"
                  "plastic_fraction,pressure_cap_Pa,shear_stress_Pa,converged\n";
  nlohmann::json points = nlohmann::json::array();
  Progress progress("junction", run.junction_points);
  double a0 = 0.0, worst = 0.0, agree_until = 0.0;
  bool all_converged = true, agreeing = true;
  for (int k = 0; k < run.junction_points; ++k) {
    const double fw = f_over_w_max * k / (run.junction_points - 1);
    const contact::TangentialContactResult t = contact::solve_tangential_load(hs, run.gap0_m, w, fw * w, opt);
    const double area = t.contact.real_area_m2;
    if (k == 0) a0 = area;
    const double tabor = contact::tabor_area_m2(w, fw * w, run.alpha, opt.hardness_Pa);
    const double bem_growth = area / a0, tabor_growth = std::sqrt(1.0 + run.alpha * fw * fw);
    const double ratio = bem_growth / tabor_growth;
    const double plastic = t.contact.plastic_area_m2 / area;
    // "Agree" within 2 %: the grid quantisation of a fully plastic contact (tests/contact).
    if (agreeing && std::abs(ratio - 1.0) <= 0.02) agree_until = fw; else agreeing = false;
    worst = std::max(worst, std::abs(ratio - 1.0));
    all_converged = all_converged && t.converged;
    csv.stream() << fw << ',' << area << ',' << tabor << ',' << bem_growth << ',' << tabor_growth << ',' << ratio << ','
                 << plastic << ',' << t.pressure_cap_Pa << ',' << t.shear_stress_Pa << ',' << (t.converged ? 1 : 0) << '\n';
    points.push_back({{"f_over_w", fw}, {"bem_area_m2", area}, {"tabor_area_m2", tabor}, {"bem_growth", bem_growth},
                      {"tabor_growth", tabor_growth}, {"plastic_fraction", plastic}, {"converged", t.converged}});
    progress.step();
  }
  progress.done();

  // The ODE (3.1.13) at this load and hardness, against the locus, over load rates.
  AtomicFile rate_csv(dir / "junction_rate.csv");
  rate_csv.stream() << "phi_dot_per_s,mu_s_ramp,mu_s_locus,phi_dot_at_slip_per_s,slip_time_s\n";
  nlohmann::json rates = nlohmann::json::array();
  for (double e = -4.0; e <= 3.0 + 1e-9; e += 0.5) {
    const double phi_dot = std::pow(10.0, e);
    contact::JunctionRampParams p;
    p.normal_load_N = w;
    p.hardness_Pa = opt.hardness_Pa;
    p.interface_shear_strength_Pa = opt.hardness_Pa / run.locus.sigma0_over_tau_i;
    p.alpha = run.alpha;
    p.n = run.locus.n;
    p.damping_b = contact::damping_from_location(w, opt.hardness_Pa, run.locus.n, run.locus.location_per_s);
    p.load_rate_N_per_s = phi_dot * w;
    const contact::JunctionRampResult r = contact::integrate_junction_ramp(p);
    const double locus_mu = contact::static_friction_from_load_rate(run.locus, phi_dot);
    rate_csv.stream() << phi_dot << ',' << r.static_friction << ',' << locus_mu << ',' << r.phi_dot_at_slip_per_s << ','
                      << r.slip_time_s << '\n';
    rates.push_back({{"phi_dot_per_s", phi_dot}, {"mu_s_ramp", r.static_friction}, {"mu_s_locus", locus_mu}});
  }
  const double wall = seconds_since(start);
  nlohmann::json j;
  j["normal_N"] = w;
  j["hardness_Pa"] = opt.hardness_Pa;
  j["alpha"] = run.alpha;
  j["surface"] = run.surface_kind;
  j["f_over_w_max"] = f_over_w_max;
  j["bem_vs_tabor"] = points;
  j["agrees_within_2pct_up_to_f_over_w"] = agree_until;
  j["max_growth_deviation"] = worst;
  j["all_converged"] = all_converged;
  j["ode_vs_locus"] = rates;
  j["locus"] = {{"alpha", run.locus.alpha}, {"n", run.locus.n}, {"sigma0_over_tau_i", run.locus.sigma0_over_tau_i},
                {"location_per_s", run.locus.location_per_s}};
  j["wall_s"] = wall;
  csv.commit();
  rate_csv.commit();
  write_file_atomically(dir / "junction.json", j.dump(2) + "\n");
  std::printf("junction growth: BEM follows Tabor (3.1.9) within 2 %% up to F/W = %.3g; largest deviation %.1f %%; "
              "%.2f s -> %s\n",
              agree_until, 100.0 * worst, wall, args.out.c_str());
  if (!all_converged) throw std::runtime_error("some junction solves did not converge (see junction.csv)");
}

}  // namespace

void add_contact_command(CLI::App& app) {
  auto args = std::make_shared<ContactArgs>();
  auto jargs = std::make_shared<ContactArgs>();
  jargs->out = "out/junction";
  CLI::App* cmd = app.add_subcommand("contact", "Rough-surface or sphere contact by FFT boundary elements (TOML config)");
  cmd->add_option("config", args->config, "TOML config ([surface], [domain], [material], [load], [solver])");
  cmd->add_option("--out", args->out, "output directory (contact.json, pressure.npy, gap.npy)")->capture_default_str();
  CLI::App* junction = cmd->add_subcommand(
      "junction", "BEM junction growth A(W, F) over F/W vs Tabor (3.1.9); junction ODE (3.1.13) vs locus (3.1.24)");
  junction->add_option("config", jargs->config, "TOML config as for `tribo contact`, plus optional [junction]")->required();
  junction->add_option("--out", jargs->out, "output directory (junction.json, junction.csv, junction_rate.csv)")
      ->capture_default_str();
  junction->callback([jargs] { run_junction(*jargs); });
  cmd->callback([args, junction] {
    if (junction->parsed()) return;
    if (args->config.empty()) throw InputError("tribo contact: a CONFIG.toml argument is required");
    run_contact(*args);
  });
}

}  // namespace tribo::cli
