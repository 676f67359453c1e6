// `tribo demo [--config HOMOGENISE.toml] [--out DIR]`: the product end to end. The thesis steel pair
// (examples/thesis-steel.toml) is homogenised into DIR/law/ (BEM contact, flow factors, pin-face
// Reynolds → law.json; cached, so a killed demo resumes), and the thesis rig (Appendix I) runs with
// that homogenised law over driven speeds 3e-5 … 12 in/s (thesis §4.1) and at the speeds of the
// thesis' figures. Writes sweep.csv, static_friction.csv, junction_locus.csv, traces/,
// thesis_comparison.csv, PNG plots and report.md with the thesis comparison.
// `--phenomenological` runs the hand-tuned effect model instead (demo_model.h): the other route,
// where the catalogue's effects are set by hand until the regimes fall at the thesis' speeds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <numbers>
#include <sstream>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/demo_model.h"
#include "apps/homogenise_config.h"
#include "apps/homogenise_run.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/rig_output.h"
#include "apps/thesis_comparison.h"
#include "rig/homogenised_law.h"
#include "rig/instrument.h"
#include "rig/observables.h"
#include "rig/sweep.h"

namespace tribo::cli {
namespace {

struct DemoArgs {
  std::string config = shipped_file("examples/thesis-steel.toml", "examples/thesis-steel.toml").string();
  std::string out = "out/demo";
  int speeds = 24;
  bool plots = true;
  bool phenomenological = false;
};

using SpeedRun = rig::SweepPoint;

void write_sweep(const std::filesystem::path& path, const rig::RigParameters& rig, const std::vector<SpeedRun>& runs,
                 const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "v_m_per_s,v_in_per_s,load_rate_per_s,regime,period_s,peak_to_peak_m,stick_time_s,slip_time_s,"
                "mu_s_mean,mean_friction_N,mean_mu,breakaways,reversals,completed\n";
  for (const SpeedRun& r : runs) {
    const auto& o = r.observables;
    f.stream() << r.drive_speed_m_per_s << ',' << r.drive_speed_m_per_s / kInch_m << ',' << rig.stiffness_N_per_m * r.drive_speed_m_per_s / rig.normal_load_N << ','
               << o.regime << ',' << fmt(o.period_s, "%.8g") << ',' << fmt(o.peak_to_peak_m, "%.8g") << ','
               << fmt(o.stick_time_s, "%.8g") << ',' << fmt(o.slip_time_s, "%.8g") << ',' << fmt(o.mu_s_mean, "%.6g") << ','
               << fmt(o.mean_friction_N, "%.6g") << ',' << fmt(o.mean_friction_N / rig.normal_load_N, "%.6g") << ','
               << o.breakaways << ',' << o.reversals << ',' << (r.result.summary.completed ? 1 : 0) << '\n';
  }
  f.commit();
}

void write_static_friction(const std::filesystem::path& path, const std::vector<SpeedRun>& runs,
                           const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "phi_dot_per_s,mu_s,v_m_per_s\n";
  for (const SpeedRun& r : runs) {
    for (const rig::Event& e : r.result.events) {
      if (e.kind == rig::EventKind::breakaway) f.stream() << e.load_rate_per_s << ',' << e.mu << ',' << r.drive_speed_m_per_s << '\n';
    }
  }
  f.commit();
}

// The law's static friction at rest against load rate (the junction locus, thesis (3.1.24)), for
// the μs–φ̇ plot.
void write_locus(const std::filesystem::path& path, const rig::FrictionLaw& law, double normal_load_N,
                 const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "phi_dot_per_s,mu_s\n";
  for (int i = 0; i <= 120; ++i) {
    const double phi_dot = std::pow(10.0, -5.0 + 7.0 * i / 120.0);
    f.stream() << phi_dot << ',' << static_coefficient_at_rest(law, normal_load_N, phi_dot) << '\n';
  }
  f.commit();
}

void write_trace(const std::filesystem::path& path, const rig::RigParameters& rig, const SpeedRun& r,
                 const nlohmann::json& provenance) {
  const auto measured = rig::measure_friction_N(rig, rig::InstrumentModel{}, r.result.samples);
  CsvFile f(path, provenance);
  write_trace_header(f.stream());
  for (std::size_t i = 0; i < r.result.samples.size(); ++i) write_trace_row(f.stream(), r.result.samples[i], measured[i]);
  f.commit();
}

void write_comparison(const std::filesystem::path& path, const std::vector<ComparisonRow>& rows,
                      const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "observation,source,thesis,tribo,tolerance,verdict,note\n";
  auto quoted = [](const std::string& v) { return '"' + v + '"'; };  // no field holds a double quote
  for (const ComparisonRow& r : rows)
    f.stream() << quoted(r.observation) << ',' << quoted(r.source) << ',' << r.thesis << ',' << r.tribo << ','
               << quoted(r.tolerance) << ',' << quoted(r.verdict) << ',' << quoted(r.note) << '\n';
  f.commit();
}

void write_report(const std::filesystem::path& path, const rig::RigParameters& rig, const std::string& law_label,
                  const std::vector<SpeedRun>& sweep, const std::vector<ComparisonRow>& rows, double wall_s) {
  std::ostringstream md;
  md << "# tribo demo — the thesis rig\n\n"
     << "Rig (thesis Appendix I): M = " << rig.mass_kg << " kg, k = " << rig.stiffness_N_per_m << " N/m, r = "
     << rig.damping_N_s_per_m << " N s/m, W = " << rig.normal_load_N << " N; omega_d = "
     << fmt(rig.damped_frequency_rad_per_s()) << " rad/s, r/2M = " << fmt(rig.decay_rate_per_s()) << " 1/s.\n\n"
     << "Friction law: " << law_label << ".\n\n"
     << "Swept " << sweep.size() << " driven speeds from 3e-5 to 12 in/s; " << fmt(wall_s, "%.1f") << " s wall in all.\n\n"
     << "## The thesis' observations (chapter V) beside the simulation\n\n"
     << "| observation | thesis | tribo | tolerance | verdict | how tribo's value was obtained |\n|---|---|---|---|---|---|\n";
  for (const ComparisonRow& r : rows) {
    md << "| " << r.observation << " (" << r.source << ") | " << r.thesis << " | " << (r.tribo.empty() ? "—" : r.tribo)
       << " | " << r.tolerance << " | " << r.verdict << " | " << r.note << " |\n";
  }
  md << "\n" << agreeing(rows) << " of " << rows.size() << " observations agree.\n\n"
     << "## Regime by driven speed\n\n| v (in/s) | v (m/s) | phi_dot (1/s) | regime | period (s) | peak-to-peak (m) | mean mu_s | mean mu |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (const SpeedRun& r : sweep) {
    md << "| " << fmt(r.drive_speed_m_per_s / kInch_m, "%.3g") << " | " << fmt(r.drive_speed_m_per_s, "%.3g") << " | "
       << fmt(rig.stiffness_N_per_m * r.drive_speed_m_per_s / rig.normal_load_N, "%.3g") << " | " << r.observables.regime << " | "
       << fmt(r.observables.period_s) << " | " << fmt(r.observables.peak_to_peak_m) << " | " << fmt(r.observables.mu_s_mean, "%.3f")
       << " | " << fmt(r.observables.mean_friction_N / rig.normal_load_N, "%.3f") << " |\n";
  }
  md << "\nPlots: `phase_plane.png` (x against xdot/omega_n at the thesis' figure speeds), `regime_map.png`, "
        "`mu_s_vs_phidot.png` (cf. Fig 5.1.2), `thesis_friction.png` (mean and steady friction against speed with "
        "the thesis' values). Data: `sweep.csv`, `static_friction.csv`, `junction_locus.csv`, `thesis_comparison.csv`, "
        "`traces/`; the homogenised law and its Stribeck curve in `law/`.\n";
  write_file_atomically(path, md.str());
}

void run_demo(const DemoArgs& args) {
  if (args.speeds < 2) throw InputError("--speeds: must be at least 2");
  rig::RigParameters rig;  // thesis rig (Appendix I)
  rig::FrictionModel model;
  std::optional<HomogeniseRun> run;
  if (args.phenomenological) {
    model = thesis_demo_model();
  } else {
    run = load_homogenise_run(args.config);  // checked before anything is written
    rig.normal_load_N = run->options.pin.normal_load_N;
  }
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  make_output_dir(dir / "traces");
  const auto start = std::chrono::steady_clock::now();
  std::string law_label = "`phenomenological` — the hand-tuned effect model of apps/demo_model.h";
  if (run) {
    homogenise_into(*run, args.config, dir / "law", args.plots);
    model.baseline.homogenised = rig::load_homogenised_base(dir / "law" / "law.json", rig.normal_load_N);
    law_label = "`homogenised` from " + args.config + " (law/law.json; docs/homogenise.md)";
  }
  const auto law = rig::make_friction_law(model);

  // Log-spaced sweep 3e-5 … 12 in/s plus the speeds of the thesis' figures 5.2.1, 5.2.2, 5.2.8.
  std::vector<double> speeds;
  const double lo = 3e-5 * kInch_m, hi = 12.0 * kInch_m;
  for (int i = 0; i < args.speeds; ++i) speeds.push_back(lo * std::pow(hi / lo, static_cast<double>(i) / (args.speeds - 1)));
  std::vector<double> all = speeds;
  all.insert(all.end(), {kStickSlipSpeed_m_per_s, kMultiCycleSpeed_m_per_s, kQuasiHarmonicSpeed_m_per_s});

  Progress progress("tribo demo: speed sweep", static_cast<int>(all.size()));
  rig::SweepOptions sweep_options;
  // Several stick-slip cycles at the largest Δμ ≈ 0.45, and at least 6 s for a quasi-harmonic
  // oscillation to grow and settle (growth rates of order 1/s).
  sweep_options.duration_for = [&](double v) { return rig::stick_slip_duration_s(rig, v, 0.45, 5.0, 6.0); };
  sweep_options.on_point_done = [&](const rig::SweepPoint& p) {
    progress.step(fmt(p.drive_speed_m_per_s / kInch_m, "%.3g in/s") + " " + p.observables.regime);
  };
  const std::vector<SpeedRun> runs = rig::sweep_drive_speeds(rig, *law, all, sweep_options);
  progress.done();
  for (const SpeedRun& r : runs) {
    if (!r.result.summary.completed) {
      std::fprintf(stderr, "tribo: warning: run at %g m/s stopped early: %s\n", r.drive_speed_m_per_s, r.result.summary.message.c_str());
    }
  }
  const std::vector<SpeedRun> sweep(runs.begin(), runs.begin() + args.speeds);
  const ThesisFigureRuns figures{runs[args.speeds], runs[args.speeds + 1], runs[args.speeds + 2]};
  const std::vector<ComparisonRow> rows = compare_with_thesis(rig, *law, model.baseline.homogenised.get(), figures);

  // The homogenise config for the homogenised law (its seeds are in law/law.json), none for the
  // phenomenological model, which is compiled in.
  const nlohmann::json provenance = provenance_json(run ? args.config : std::string());
  write_sweep(dir / "sweep.csv", rig, sweep, provenance);
  write_static_friction(dir / "static_friction.csv", sweep, provenance);
  write_locus(dir / "junction_locus.csv", *law, rig.normal_load_N, provenance);
  write_trace(dir / "traces" / "stick_slip_0.028in_per_s.csv", rig, figures.stick_slip, provenance);
  write_trace(dir / "traces" / "multi_cycle_1e-4in_per_s.csv", rig, figures.multi_cycle, provenance);
  write_trace(dir / "traces" / "quasi_harmonic_5.3in_per_s.csv", rig, figures.quasi_harmonic, provenance);
  write_comparison(dir / "thesis_comparison.csv", rows, provenance);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_report(dir / "report.md", rig, law_label, sweep, rows, wall);
  if (args.plots && run_plot_script("demo", args.out) != 0) {
    std::fprintf(stderr, "tribo: warning: plotting failed (needs python3-matplotlib); CSVs and report are written\n");
  }
  std::printf("tribo demo: %zu speeds in %.1f s; %d of %zu thesis observations agree -> %s (report.md)\n", sweep.size(),
              wall, agreeing(rows), rows.size(), args.out.c_str());
}

}  // namespace

void add_demo_command(CLI::App& app) {
  auto args = std::make_shared<DemoArgs>();
  CLI::App* cmd = app.add_subcommand(
      "demo", "The thesis steel pair homogenised and its rig swept over driven speed, compared with the thesis");
  cmd->add_option("--config", args->config, "homogenise config of the surface pair (tribo homogenise --help)")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "output directory")->capture_default_str();
  cmd->add_flag("--phenomenological", args->phenomenological,
                "run the hand-tuned effect model (apps/demo_model.h) instead of the homogenised law");
  cmd->add_option("--speeds", args->speeds, "number of log-spaced driven speeds from 3e-5 to 12 in/s")->capture_default_str();
  cmd->add_flag("!--no-plots", args->plots, "skip the PNG plots");
  cmd->callback([args] { run_demo(*args); });
}

}  // namespace tribo::cli
