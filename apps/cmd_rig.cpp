// `tribo rig CONFIG.toml --out DIR`: one run of the friction rig.
#include <chrono>
#include <cstdio>
#include <memory>

#include "apps/commands.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/rig_config.h"
#include "apps/rig_output.h"
#include "rig/instrument.h"

namespace tribo::cli {
namespace {

struct RigArgs {
  std::string config;
  std::string out = "out/rig";
  bool plot = false;
  bool summary_only = false;
};

// One run of a loaded config (`hash`: the config's, for the provenance): summary.json to `sink`,
// and unless args.summary_only trace.csv and events.csv into args.out, which exists.
void run_rig(const RigRun& run, const RigArgs& args, const std::string& hash, const JsonSink& sink) {
  const std::filesystem::path dir(args.out);
  const auto start = std::chrono::steady_clock::now();

  const rig::SimulationResult result = rig::simulate(run.rig, *run.drive, *run.law, run.options);
  const rig::SimulationSummary& summary = result.summary;
  const auto& samples = result.samples;
  const auto& events = result.events;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::json provenance = provenance_json(args.config, hash, run.input_files);
  provenance["seed"] = run.seed;  // the instrument's noise
  const rig::RunObservables obs =
      rig::summarise(run.rig, samples, events, run.analysis_start_fraction * summary.end_time_s);
  nlohmann::json j = rig_summary_json(obs, summary, run.law->name(), run.rig, wall);
  j["provenance"] = provenance;

  if (!args.summary_only) {
    const std::vector<double> measured = rig::measure_friction_N(run.rig, rig::instrument_from(run.friction, run.seed), samples);
    CsvFile trace(dir / "trace.csv", provenance);
    write_trace_header(trace.stream());
    for (std::size_t i = 0; i < samples.size(); ++i) write_trace_row(trace.stream(), samples[i], measured[i]);
    CsvFile events_file(dir / "events.csv", provenance);
    write_events_csv(events_file.stream(), events);
    trace.commit();
    events_file.commit();
  }
  sink("summary.json", j.dump(2) + "\n");

  std::printf("regime %s, period %.6g s, peak-to-peak %.6g m, mean mu_s %.4g, %ld events, %.3f s wall -> %s\n",
              obs.regime.c_str(), obs.period_s, obs.peak_to_peak_m, obs.mu_s_mean, summary.events, wall,
              args.out.c_str());
  if (args.plot && run_plot_script("rig", args.out) != 0) {
    std::fprintf(stderr, "tribo: warning: plotting failed (needs python3-matplotlib)\n");
  }
  if (!summary.completed) throw std::runtime_error("rig run stopped early: " + summary.message);
}

void run_rig(const RigArgs& args) {
  const RigRun run = load_rig_run(args.config);  // everything validated before anything is written
  make_output_dir(args.out);
  run_rig(run, args, config_hash(args.config), folder_sink(args.out));
}

}  // namespace

void run_rig_summary(const toml::table& config, const std::filesystem::path& path, const std::string& hash,
                     const std::string& out, const JsonSink& sink) {
  RigArgs args;
  args.config = path.string();
  args.out = out;
  args.summary_only = true;
  run_rig(load_rig_run(config, path), args, hash, sink);
}

void add_rig_command(CLI::App& app) {
  auto args = std::make_shared<RigArgs>();
  CLI::App* cmd = app.add_subcommand("rig", "Simulate the pin-on-disc friction rig from a TOML config");
  cmd->add_option("config", args->config, "TOML config ([rig], [drive], [friction], [run])")->required();
  cmd->add_option("--out", args->out, "output directory (trace.csv, events.csv, summary.json)")->capture_default_str();
  cmd->add_flag("--plot", args->plot, "also draw phase_plane.png and trace.png (python3-matplotlib)");
  add_summary_only_flag(cmd, args->summary_only, "summary.json")->excludes("--plot");
  cmd->callback([args] { run_rig(*args); });
}

}  // namespace tribo::cli
