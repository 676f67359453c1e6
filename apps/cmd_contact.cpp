// `tribo contact CONFIG.toml --out DIR`: one rough-surface (or sphere) normal/tangential contact
// solve, writing contact.json, pressure.npy and gap.npy.
// `tribo contact junction CONFIG.toml --out DIR`: BEM junction growth A(W, F) over F/W against
// Tabor's closed form (3.1.9), and the junction ODE (3.1.13) against the locus (3.1.24).
// The reader and the contact solve are apps/contact_run.h (shared with the Python bindings); this
// file parses argv and writes the files.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/contact_run.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "contact/halfspace.h"
#include "contact/junction_growth.h"
#include "contact/junction_locus.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"
#include "contact/tangential.h"

namespace tribo::cli {
namespace {

struct ContactArgs {
  std::string config;
  std::string out = "out/contact";
  bool summary_only = false;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One solve of a loaded config (`hash`: the config's, for the provenance): contact.json to `sink`,
// and unless args.summary_only the .npy fields into args.out, which exists.
void run_contact(const ContactRun& run, const ContactArgs& args, const std::string& hash, const JsonSink& sink) {
  const std::filesystem::path dir(args.out);
  const ContactSolve solved = solve_contact_run(run);
  const contact::NormalContactResult& r = solved.result;
  nlohmann::json j = solved.summary;
  j["provenance"] = contact_provenance(args.config, run, hash);
  if (!args.summary_only) {
    write_npy_atomically(dir / "pressure.npy", r.pressure_Pa);
    write_npy_atomically(dir / "gap.npy", r.gap_m);
    if (run.hardness_Pa) write_npy_atomically(dir / "plastic_displacement.npy", r.plastic_increment_m);
  }
  sink("contact.json", j.dump(2) + "\n");
  std::printf("%s: area %.6g m^2 (%.4g %%), max pressure %.6g Pa, %d iterations, residual %.3g, %.3f s -> %s\n",
              run.surface_kind.c_str(), r.real_area_m2, 100.0 * r.area_fraction, r.max_pressure_Pa,
              j["iterations"].get<int>(), r.summary.residual, j["wall_s"].get<double>(), args.out.c_str());
  if (!r.summary.converged) throw std::runtime_error("contact solve " + r.summary.message);
}

void run_contact(const ContactArgs& args) {
  const ContactRun run = load_contact_run(args.config, false);
  make_output_dir(args.out);
  run_contact(run, args, config_hash(args.config), folder_sink(args.out));
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
  const double w = run.normal_load_N;
  // The largest F/W the domain can carry: √(W² + α F²) ≤ σ0 A_nominal.
  const double f_cap = std::sqrt(std::max(0.0, std::pow(opt.hardness_Pa * run.grid.area_m2(), 2) - w * w) / std::max(run.alpha, 1e-300));
  const double f_over_w_max = std::min(run.f_over_w_max, 0.999 * f_cap / w);

  const nlohmann::json provenance = contact_provenance(args.config, run, config_hash(args.config));
  CsvFile csv(dir / "junction.csv", provenance);
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
  CsvFile rate_csv(dir / "junction_rate.csv", provenance);
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
  j["normal_load_N"] = w;
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
  j["provenance"] = provenance;
  csv.commit();
  rate_csv.commit();
  write_file_atomically(dir / "junction.json", j.dump(2) + "\n");
  std::printf("junction growth: BEM follows Tabor (3.1.9) within 2 %% up to F/W = %.3g; largest deviation %.1f %%; "
              "%.2f s -> %s\n",
              agree_until, 100.0 * worst, wall, args.out.c_str());
  if (!all_converged) throw std::runtime_error("some junction solves did not converge (see junction.csv)");
}

}  // namespace

void run_contact_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                         const std::string& out, const JsonSink& sink) {
  ContactArgs args;
  args.config = path.string();
  args.out = out;
  args.summary_only = true;
  run_contact(load_contact_run(config, path, false), args, hash, sink);
}

void add_contact_command(CLI::App& app) {
  auto args = std::make_shared<ContactArgs>();
  auto jargs = std::make_shared<ContactArgs>();
  jargs->out = "out/junction";
  CLI::App* cmd = app.add_subcommand("contact", "Rough-surface or sphere contact by FFT boundary elements (TOML config)");
  cmd->add_option("config", args->config, "TOML config ([surface], [domain], [material], [load], [solver])");
  cmd->add_option("--out", args->out, "output directory (contact.json, pressure.npy, gap.npy)")->capture_default_str();
  add_summary_only_flag(cmd, args->summary_only, "contact.json");
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
