// `tribo ehl CONFIG.toml --out DIR`: one elastohydrodynamic contact, a line or a circular point
// contact, writing DIR/ehl.json (films, pressures, traction, convergence, the published fits at the
// same dimensionless groups, provenance), the fields x_m.npy, pressure_Pa.npy and film_m.npy
// (a point contact: y_m.npy too, and nx × ny fields), and with --plot ehl.png. Every key is read and checked before anything is written (docs/lubrication.md).
// The reader and the solve are apps/ehl_run.h; this file parses argv and writes the files.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/ehl_run.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/rig_output.h"

namespace tribo::cli {
namespace {

struct EhlArgs {
  std::string config;
  std::string out = "out/ehl";
  bool plot = false, summary_only = false;
};

void run_ehl(const EhlArgs& args) {
  if (args.config.empty()) throw InputError("ehl: a CONFIG.toml is required (see tribo ehl --help)");
  const EhlRun run = load_ehl_run(args.config);
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const EhlSolve solved = solve_ehl_run(run);
  nlohmann::json j = solved.summary;
  j["provenance"] = provenance_json(args.config, run.input_files);
  if (!args.summary_only && solved.point_film) {
    const lubrication::EhlPointResult& f = *solved.point_film;
    j["fields"] = {{"x_m", "x_m.npy"},
                   {"y_m", "y_m.npy"},
                   {"pressure_Pa", "pressure_Pa.npy"},
                   {"film_m", "film_m.npy"},
                   {"layout", "float64 arrays; x_m (nx,) in the rolling direction and y_m (ny,) across it, from the contact centre; "
                              "pressure_Pa, film_m (and with a hardness plastic_flow_m) of shape (nx, ny): [i, j] is the node at x_m[i], y_m[j]"}};
    write_npy_atomically(dir / "x_m.npy", f.x_m);
    write_npy_atomically(dir / "y_m.npy", f.y_m);
    const auto field = [&](const std::vector<double>& v) {
      return Eigen::Map<const Eigen::ArrayXXd>(v.data(), static_cast<Eigen::Index>(f.x_m.size()), static_cast<Eigen::Index>(f.y_m.size()));
    };
    write_npy_atomically(dir / "pressure_Pa.npy", Eigen::ArrayXXd(field(f.pressure_Pa)));
    write_npy_atomically(dir / "film_m.npy", Eigen::ArrayXXd(field(f.film_m)));
    // With a hardness: how far the yielded surface flowed, the film raised by it (0 where elastic).
    if (run.profile && std::isfinite(run.profile->surface.hardness_Pa) && !f.plastic_flow_m.empty()) {
      j["fields"]["plastic_flow_m"] = "plastic_flow_m.npy";
      write_npy_atomically(dir / "plastic_flow_m.npy", Eigen::ArrayXXd(field(f.plastic_flow_m)));
    }
  } else if (!args.summary_only) {
    j["fields"] = {{"x_m", "x_m.npy"},
                   {"pressure_Pa", "pressure_Pa.npy"},
                   {"film_m", "film_m.npy"},
                   {"layout", "float64 arrays of shape (nodes,): the value at node i, x_m[i] from the contact centre in the rolling direction"}};
    write_npy_atomically(dir / "x_m.npy", solved.film.x_m);
    write_npy_atomically(dir / "pressure_Pa.npy", solved.film.pressure_Pa);
    write_npy_atomically(dir / "film_m.npy", solved.film.film_m);
  }
  write_file_atomically(dir / "ehl.json", j.dump(2) + "\n");
  const auto& f = solved.film;
  const std::string mu = solved.converged ? fmt(j["friction_coefficient"].get<double>(), "%.4g") : "-";
  if (solved.mixed_point) {
    const lubrication::MixedPointResult& m = *solved.mixed_point;
    std::printf("point contact, mixed: film share %s of the load, film parameter %s, central film %s m, friction coefficient %s, %d film solves -> %s\n",
                fmt(m.film_share, "%.4g").c_str(), fmt(m.film_parameter, "%.3g").c_str(), fmt(m.central_film_m, "%.4g").c_str(), mu.c_str(),
                m.film_solves, args.out.c_str());
    if (!solved.converged) throw std::runtime_error("mixed-lubrication solve did not converge: " + m.message);
  } else if (solved.point_film) {
    const lubrication::EhlPointResult& p = *solved.point_film;
    std::printf("point contact: central film %s m, minimum %s m, max pressure %s Pa, friction coefficient %s, %d iterations -> %s\n",
                fmt(p.central_film_m, "%.4g").c_str(), fmt(p.minimum_film_m, "%.4g").c_str(), fmt(p.max_pressure_Pa, "%.4g").c_str(),
                mu.c_str(), p.iterations, args.out.c_str());
    if (!solved.converged) throw std::runtime_error("EHL solve did not converge (residual " + fmt(p.residual, "%.3g") + "): " + p.message);
  } else if (solved.mixed)
    std::printf("line contact, mixed: film share %s of the load, film parameter %s, central film %s m, friction coefficient %s, %d film solves -> %s\n",
                fmt(solved.mixed->film_share, "%.4g").c_str(), fmt(solved.mixed->film_parameter, "%.3g").c_str(),
                fmt(f.central_film_m, "%.4g").c_str(), mu.c_str(), solved.mixed->film_solves, args.out.c_str());
  else
    std::printf("line contact: central film %s m, minimum %s m, max pressure %s Pa, friction coefficient %s, %d iterations -> %s\n",
                fmt(f.central_film_m, "%.4g").c_str(), fmt(f.minimum_film_m, "%.4g").c_str(), fmt(f.max_pressure_Pa, "%.4g").c_str(),
                mu.c_str(), f.iterations, args.out.c_str());
  if (!solved.converged)
    throw std::runtime_error(solved.mixed ? "mixed-lubrication solve did not converge: " + solved.mixed->message
                                          : "EHL solve did not converge (residual " + fmt(f.residual, "%.3g") + "): " + f.message);
  // The surfaces' flash temperature is Jaeger's fast-source limit (moving_heat_source.h): say when
  // the slower surface is too slow for it (it then overstates the rise).
  if (j["surface_peclet_number"].is_number() && j["surface_peclet_number"].get<double>() < 5.0)
    std::fprintf(stderr, "tribo: warning: the slower surface's Peclet number is %s, below the fast-source model's 5: its flash temperature is overstated\n",
                 fmt(j["surface_peclet_number"].get<double>(), "%.3g").c_str());
  if (args.plot && run_plot_script("ehl", args.out) != 0)
    std::fprintf(stderr, "tribo: warning: plotting failed (needs python3-matplotlib)\n");
}

}  // namespace

void add_ehl_command(CLI::App& app) {
  auto args = std::make_shared<EhlArgs>();
  CLI::App* cmd = app.add_subcommand("ehl", "Solve an elastohydrodynamic line or point contact: film, pressure and traction (TOML config)");
  cmd->add_option("config", args->config, "TOML config ([contact], [lubricant], optional [roughness] for the mixed regime by load sharing or [profile] (a waviness or a measured trace; on a ball, ridges across the track) for it node by node, on a ball [surface] (a generated or measured height map), [material] hardness_Pa with [profile] (the pressure cap where the surfaces touch), [solids] the bodies' thermal constants for their surfaces' flash temperature, [solver])")->required();
  cmd->add_option("--out", args->out, "output directory (ehl.json, x_m.npy, pressure_Pa.npy, film_m.npy; a point contact y_m.npy too)")->capture_default_str();
  CLI::Option* plot = cmd->add_flag("--plot", args->plot, "also draw ehl.png: pressure and film along the contact (python3-matplotlib)");
  add_summary_only_flag(cmd, args->summary_only, "ehl.json")->excludes(plot);
  cmd->callback([args] { run_ehl(*args); });
}

}  // namespace tribo::cli
