// `tribo homogenise CONFIG.toml --out DIR`: the micro solves of a surface pair (BEM contact,
// Patir–Cheng cells, rugosity lift, the pin-face average Reynolds equation) turned into the
// friction-law tables the rig reads (DIR/law.json), with the Stribeck curve at the pin's load
// (law.json "stribeck", stribeck.csv, stribeck.png) and the load–separation curve (area.csv,
// area.png). Finished realisations are kept in DIR/patches/, and a ball's film speeds in
// DIR/ball-film/, and reused when the same command runs again, so a killed run resumes; a changed
// config starts them afresh.
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/homogenise_config.h"
#include "apps/homogenise_run.h"

namespace tribo::cli {
namespace {

struct HomogeniseArgs {
  std::string config;
  std::string out = "out/homogenise";
  bool plots = true;
};

void run_homogenise(const HomogeniseArgs& args) {
  if (args.config.empty()) throw InputError("homogenise: a CONFIG.toml is required (see tribo homogenise --help)");
  const HomogeniseRun run = load_homogenise_run(args.config);  // everything checked before anything is written
  homogenise_into(run, args.config, args.out, args.plots);
}

}  // namespace

void add_homogenise_command(CLI::App& app) {
  auto args = std::make_shared<HomogeniseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "homogenise", "friction-law tables (law.json) from BEM contact and Reynolds solves on a rough surface pair");
  cmd->add_option("config", args->config, "CONFIG.toml: [surface] [domain] [material] [junction] [lubricant] [pin] [speeds] [homogenise] [micro_ehl] (docs/homogenise.md)")
      ->required();
  cmd->add_option("--out", args->out, "output directory (law.json, stribeck.csv, area.csv, PNGs; patches/ and a ball's ball-film/ kept so a killed run resumes)")
      ->capture_default_str();
  cmd->add_flag("!--no-plots", args->plots, "skip stribeck.png and area.png");
  cmd->callback([args] { run_homogenise(*args); });
}

}  // namespace tribo::cli
