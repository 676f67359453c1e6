// `tribo reynolds CONFIG.toml --out DIR`: one Reynolds film solve (parallel discs, a gap file or
// a rough pair from contact/), writing DIR/reynolds.json and the fields as .npy.
// `tribo reynolds flow-factors CONFIG.toml --out DIR`: Patir–Cheng flow factors and rugosity
// lift homogenised over rough-surface realisations, as CSV tables with standard errors.
// Every key is read and checked before anything is written (see docs/lubrication.md). The readers
// and the film solve are apps/reynolds_run.h (shared with the Python bindings); this file parses
// argv and writes the files.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/reynolds_run.h"
#include "contact/surface.h"
#include "lubrication/flow_factors.h"
#include "lubrication/reynolds.h"

namespace tribo::cli {
namespace {

namespace lub = tribo::lubrication;

struct ReynoldsArgs {
  std::string config;
  std::string out = "out/reynolds";
  bool summary_only = false;
};

// One solve of a loaded config (`hash`: the config's, for the provenance): reynolds.json to
// `sink`, and unless args.summary_only the .npy fields into args.out, which exists.
void run_reynolds(const ReynoldsRun& run, const ReynoldsArgs& args, const std::string& hash, const JsonSink& sink) {
  const std::filesystem::path dir(args.out);
  const ReynoldsSolve solved = solve_reynolds_run(run);
  const lub::ReynoldsSolution& s = solved.solution;
  nlohmann::json j = solved.summary;
  j["provenance"] = provenance_json(args.config, hash, run.input_files);
  if (run.seed) j["provenance"]["seed"] = *run.seed;
  if (!args.summary_only) {
    j["fields"] = {{"pressure_Pa", "pressure_Pa.npy"}, {"fill_fraction", "fill_fraction.npy"}, {"gap_m", "gap_m.npy"},
                   {"layout", "float64 array of shape (nx, ny): a[i, j] at x = i dx, y = j dy"}};
    write_npy_atomically(dir / "pressure_Pa.npy", s.pressure_Pa);
    write_npy_atomically(dir / "fill_fraction.npy", s.fill_fraction);
    write_npy_atomically(dir / "gap_m.npy", run.problem.gap_m);
  }
  sink("reynolds.json", j.dump(2) + "\n");
  std::printf("%s: load %.6g N, max pressure %.6g Pa, cavitated %.3g, %d iterations, %.3f s -> %s\n", run.kind.c_str(),
              s.load_N, s.max_pressure_Pa, s.cavitated_fraction, s.summary.iterations, s.summary.wall_s,
              args.out.c_str());
  if (!s.summary.converged) throw std::runtime_error("reynolds solve did not converge: " + s.summary.message);
}

void run_reynolds(const ReynoldsArgs& args) {
  if (args.config.empty()) throw InputError("reynolds: a CONFIG.toml is required (see tribo reynolds --help)");
  const ReynoldsRun run = load_reynolds_run(args.config);
  make_output_dir(args.out);
  run_reynolds(run, args, config_hash(args.config), folder_sink(args.out));
}


void run_flow_factors(const ReynoldsArgs& args) {
  if (args.config.empty()) throw InputError("reynolds flow-factors: a CONFIG.toml is required");
  const FlowFactorRun run = load_flow_factor_run(args.config);
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const auto start = std::chrono::steady_clock::now();
  const lub::HomogenisationOptions& o = run.options;
  const double gamma = o.surface.kind == contact::SpectrumKind::gaussian_acf && o.surface.correlation_length_across_m > 0
                           ? o.surface.correlation_length_m / o.surface.correlation_length_across_m
                           : 1.0;
  std::fprintf(stderr, "flow factors: %zu gap ratios x %d realisations on %ld^2 ...\n", o.gap_ratios.size(),
               o.realisations, static_cast<long>(o.surface.grid));
  nlohmann::json provenance = provenance_json(args.config);
  provenance["seed"] = o.first_seed;  // realisation k has seed first_seed + k
  const auto factors = lub::flow_factors(o);
  {
    CsvFile f(dir / "flow_factors.csv", provenance);
    f.stream() << "h_over_sigma,phi_x,phi_x_se,phi_y,phi_y_se,phi_s,phi_s_se,mean_film_over_sigma,contact_fraction,"
                  "patir_cheng_phi_x,patir_cheng_phi_y,patir_cheng_phi_s,unconverged\n";
    for (const auto& r : factors)
      f.stream() << csv_number(r.h_over_sigma) << ',' << csv_number(r.phi_x.mean) << ','
                 << csv_number(r.phi_x.standard_error) << ',' << csv_number(r.phi_y.mean) << ','
                 << csv_number(r.phi_y.standard_error) << ',' << csv_number(r.phi_s.mean) << ','
                 << csv_number(r.phi_s.standard_error) << ',' << csv_number(r.mean_film_over_sigma.mean) << ','
                 << csv_number(r.contact_fraction.mean) << ','
                 << csv_number(lub::patir_cheng_phi_x(r.h_over_sigma, gamma)) << ','
                 << csv_number(lub::patir_cheng_phi_y(r.h_over_sigma, gamma)) << ','
                 << csv_number(lub::patir_cheng_shear_factor(r.h_over_sigma, gamma)) << ',' << r.unconverged << '\n';
    f.commit();
  }
  std::fprintf(stderr, "rugosity lift ...\n");
  lub::HomogenisationOptions lift_options = o;
  lift_options.contact_gap_fraction = run.lift_contact_gap_fraction;
  const auto lift = lub::rugosity_lift(lift_options);
  {
    CsvFile f(dir / "rugosity_lift.csv", provenance);
    f.stream() << "h_over_sigma,mean_gap_m,mean_pressure_Pa,mean_pressure_se_Pa,pressure_per_eta_u_per_m,"
                  "pressure_per_eta_u_se_per_m,full_film_mean_pressure_Pa,full_film_se_Pa,cavitated_fraction,"
                  "newton_iterations,unconverged\n";
    for (const auto& r : lift)
      f.stream() << csv_number(r.h_over_sigma) << ',' << csv_number(r.h_over_sigma * o.surface.rms_height_m) << ','
                 << csv_number(r.mean_pressure_Pa.mean) << ',' << csv_number(r.mean_pressure_Pa.standard_error) << ','
                 << csv_number(r.mean_pressure_per_eta_u.mean) << ','
                 << csv_number(r.mean_pressure_per_eta_u.standard_error) << ','
                 << csv_number(r.mean_pressure_full_film_Pa.mean) << ','
                 << csv_number(r.mean_pressure_full_film_Pa.standard_error) << ','
                 << csv_number(r.cavitated_fraction.mean) << ',' << csv_number(r.newton_iterations.mean) << ','
                 << r.unconverged << '\n';
    f.commit();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  nlohmann::json j;
  j["rms_height_m"] = o.surface.rms_height_m;
  j["gamma"] = gamma;
  j["grid"] = o.surface.grid;
  j["size_m"] = o.surface.size_m;
  j["realisations"] = o.realisations;
  j["viscosity_Pa_s"] = o.viscosity_Pa_s;
  j["sliding_speed_m_per_s"] = o.sliding_speed_m_per_s;
  j["contact_gap_fraction"] = o.contact_gap_fraction;
  j["lift_contact_gap_fraction"] = run.lift_contact_gap_fraction;
  j["tables"] = {"flow_factors.csv", "rugosity_lift.csv"};
  j["error_bars"] = "standard error of the mean across realisations";
  j["wall_s"] = wall;
  j["provenance"] = provenance;
  write_file_atomically(dir / "flow_factors.json", j.dump(2) + "\n");
  std::printf("flow factors and rugosity lift for %zu gap ratios, %d realisations, %.1f s -> %s\n",
              o.gap_ratios.size(), o.realisations, wall, args.out.c_str());
}

}  // namespace

void run_reynolds_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                          const std::string& out, const JsonSink& sink) {
  ReynoldsArgs args;
  args.config = path.string();
  args.out = out;
  args.summary_only = true;
  run_reynolds(load_reynolds_run(config, path), args, hash, sink);
}

void add_reynolds_command(CLI::App& app) {
  auto args = std::make_shared<ReynoldsArgs>();
  auto ff_args = std::make_shared<ReynoldsArgs>();
  ff_args->out = "out/flow-factors";
  CLI::App* cmd = app.add_subcommand("reynolds", "Solve the Reynolds equation for a lubricant film (TOML config)");
  cmd->add_option("config", args->config, "TOML config ([geometry], [lubricant], [motion], [grid], [solver])");
  cmd->add_option("--out", args->out, "output directory (reynolds.json, pressure_Pa.npy, ...)")->capture_default_str();
  add_summary_only_flag(cmd, args->summary_only, "reynolds.json");
  CLI::App* ff = cmd->add_subcommand("flow-factors", "Patir-Cheng flow factors and rugosity lift over rough realisations");
  ff->add_option("config", ff_args->config, "TOML config ([surface], [homogenisation], [lubricant], [motion], [domain])")
      ->required();
  ff->add_option("--out", ff_args->out, "output directory (flow_factors.csv, rugosity_lift.csv, flow_factors.json)")
      ->capture_default_str();
  cmd->require_subcommand(0, 1);
  ff->callback([ff_args] { run_flow_factors(*ff_args); });
  cmd->callback([cmd, ff, args] {
    if (cmd->got_subcommand(ff)) return;
    run_reynolds(*args);
  });
}

}  // namespace tribo::cli
