#include "apps/homogenise_run.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>
#include <optional>
#include <utility>

#include "apps/config.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/rig_output.h"
#include "contact/thermoelastic.h"
#include "homogenise/law.h"
#include "numerics/format.h"
#include "homogenise/solid_contact.h"
#include "rig/law_table.h"
#include "rig/steady_sliding.h"

namespace tribo::cli {
namespace {

// A cached patch is reused only when the same build made it from the same inputs: its key is the
// config's hash, the hashes of the files it names (a measured topography) and the build
// (build_identity(): its commit, and for an uncommitted edit the executable's hash), so a newer
// build or an edited map solves the patches again rather than tabulate an older answer under the
// new provenance.
std::string cache_key(const std::string& config_hash, const std::vector<std::filesystem::path>& inputs) {
  std::string key = config_hash;
  for (const auto& f : inputs) key.append("+").append(tribo::cli::config_hash(f));  // not "+" + …: a false GCC 12 warning
  return key + "@" + build_identity();
}

// A cached result — a patch (DIR/patches/realisation-K.json) or a ball's film speed node
// (DIR/ball-film/node-K.json, which ball_film also checks is its own) — is {"cache_key", `member`},
// written whole or not at all; another key, a torn or a foreign file is solved again.
void write_cached(const std::filesystem::path& file, const std::string& key, const char* member, nlohmann::json value) {
  const nlohmann::json j{{"cache_key", key}, {member, std::move(value)}};
  write_file_atomically(file, j.dump() + "\n");
}

template <class T>
std::optional<T> read_cached(const std::filesystem::path& file, const std::string& key, const char* member,
                             T (*from_json)(const nlohmann::json&)) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    if (j.at("cache_key").get<std::string>() != key) return std::nullopt;
    return from_json(j.at(member));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// thermal_crown_bound_m: how far the slider's face would crown if all the frictional power μWU
// flowed into it (contact/thermoelastic.h) — a bound, the disc takes its share — to set beside the
// crowns and tilts that make a film carry load (docs/homogenise.md).
std::vector<double> thermal_crown_bounds_m(const homogenise::HomogeniseOptions& o, const std::vector<rig::SteadySliding>& points) {
  const contact::ThermoelasticSolid slider = homogenise::slider_solid(o);
  std::vector<double> crowns;
  for (const rig::SteadySliding& s : points)
    crowns.push_back(contact::thermoelastic_crown_m(slider, s.mu * o.pin.normal_load_N * s.speed_m_per_s));
  return crowns;
}

// film_parameter: Λ = h̄/σ, the separation over the composite rms roughness (the Stribeck curve's
// usual abscissa besides the speed).
void write_stribeck_csv(const std::filesystem::path& path, const std::vector<rig::SteadySliding>& points,
                        const std::vector<double>& mu_errors, const std::vector<double>& crowns_m, double sigma_m,
                        const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "U_m_per_s,mu,mu_discretisation_error,fluid_share,separation_m,film_parameter,temperature_rise_K,solid_load_N,lift_N,"
                "fluid_shear_N,solid_shear_Pa,film_share_of_contact,thermal_crown_bound_m\n";
  for (std::size_t k = 0; k < points.size(); ++k) {
    const rig::SteadySliding& s = points[k];
    f.stream() << s.speed_m_per_s << ',' << s.mu << ',' << csv_number(mu_errors[k]) << ',' << s.fluid_share << ','
               << s.separation_m << ',' << s.separation_m / sigma_m << ',' << s.temperature_rise_K << ',' << s.solid_load_N << ','
               << s.lift_N << ',' << s.fluid_shear_N << ',' << s.solid_shear_Pa << ',' << s.film_share_of_contact << ','
               << crowns_m[k] << '\n';
  }
  f.commit();
}

// The Stribeck μ's discretisation error: the same steady sliding on the law whose solid columns
// come from half the contact grid (the pin table's coarse integrals), error_from_refinement of the
// two μ at each speed; NaN where the coarse law has no converged point.
std::vector<double> stribeck_discretisation_errors(nlohmann::json law, const homogenise::PinTable& pin,
                                                   const std::vector<rig::SteadySliding>& points, double normal_load_N,
                                                   const std::string& source) {
  law["table"]["solid_load_N"] = pin.solid_load_coarse_N;
  law["table"]["real_area_m2"] = pin.real_area_coarse_m2;
  if (!pin.solid_shear_coarse_Pa.empty()) law["table"]["solid_shear_Pa"] = pin.solid_shear_coarse_Pa;
  const rig::HomogenisedBase coarse(rig::law_table_from_json(law, source + " (solid columns on half the contact grid)"), normal_load_N);
  std::vector<double> errors;
  for (const rig::SteadySliding& s : points) {
    double e = std::numeric_limits<double>::quiet_NaN();
    try {
      const rig::SteadySliding c = rig::steady_sliding(coarse, s.speed_m_per_s);
      if (c.converged) e = homogenise::error_from_refinement(c.mu, s.mu);
    } catch (const std::out_of_range&) {
      // beyond the coarse table: no estimate at this speed
    }
    errors.push_back(e);
  }
  return errors;
}

void write_area_csv(const std::filesystem::path& path, const homogenise::PinTable& pin, double sigma,
                    const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  f.stream() << "separation_m,separation_over_sigma,solid_load_N,solid_load_standard_error_N,solid_load_discretisation_error_N,"
                "real_area_m2,real_area_fraction,real_area_standard_error_m2,real_area_discretisation_error_m2,lift_per_eta_u_m,"
                "squeeze_per_eta_m,shear_per_eta_u_m\n";
  for (std::size_t m = 0; m < pin.separation_m.size(); ++m)
    f.stream() << pin.separation_m[m] << ',' << pin.separation_m[m] / sigma << ',' << pin.solid_load_N[m] << ','
               << pin.solid_load_standard_error_N[m] << ',' << pin.solid_load_discretisation_error_N[m] << ','
               << pin.real_area_m2[m] << ',' << pin.real_area_m2[m] / pin.nominal_area_m2 << ','
               << pin.real_area_standard_error_m2[m] << ',' << pin.real_area_discretisation_error_m2[m] << ','
               << pin.wedge_lift_per_eta_u_m[m] + pin.rugosity_lift_per_eta_u_m[m] << ',' << pin.squeeze_per_eta_m[m]
               << ',' << pin.shear_per_eta_u_m[m] << '\n';
  f.commit();
}

}  // namespace

StribeckCurve stribeck_curve(const std::vector<double>& speeds_m_per_s, const std::function<rig::SteadySliding(double)>& solve) {
  StribeckCurve curve;
  for (double u : speeds_m_per_s) {
    rig::SteadySliding s;
    try {
      s = solve(u);
    } catch (const std::out_of_range& e) {
      curve.unconverged.push_back({{"what", "stribeck point"}, {"U_m_per_s", u}, {"reason", std::string("the curve stops here: ") + e.what()}});
      break;
    }
    if (!s.converged) {
      curve.unconverged.push_back({{"what", "stribeck point"}, {"U_m_per_s", u}, {"reason", s.message}});
      continue;
    }
    curve.points.push_back(s);
  }
  return curve;
}

nlohmann::json homogenise_into(const HomogeniseRun& run, const std::filesystem::path& config,
                               const std::filesystem::path& out, bool plots) {
  make_output_dir(out);
  const std::filesystem::path& dir = out;
  const std::filesystem::path patches = dir / "patches";
  make_output_dir(patches);
  remove_previous_results(dir, {"law.json", "stribeck.csv", "area.csv", "stribeck.png", "area.png"});
  const auto start = std::chrono::steady_clock::now();
  const std::string hash = config_hash(config), key = cache_key(hash, run.input_files);
  const homogenise::HomogeniseOptions& o = run.options;

  const auto patch_file = [&](int k) { return patches / ("realisation-" + std::to_string(k) + ".json"); };
  std::vector<std::optional<homogenise::PatchResult>> cached;
  int reused = 0;
  for (int k = 0; k < o.realisations; ++k) {
    cached.push_back(read_cached(patch_file(k), key, "patch", &homogenise::patch_from_json));
    reused += cached.back() ? 1 : 0;
  }
  Progress progress("homogenise: realisations", o.realisations);
  for (int k = 0; k < reused; ++k) progress.step("cached");
  const auto patch_results = homogenise::solve_patches(o, cached, [&](int k, const homogenise::PatchResult& p) {
    write_cached(patch_file(k), key, "patch", homogenise::to_json(p));
    progress.step("seed " + std::to_string(p.seed));
  });
  progress.done();

  const homogenise::CellTable cells = homogenise::aggregate(o, patch_results);
  homogenise::PinTable pin = homogenise::pin_scale(o, cells);
  if (!(pin.solid_load_N.front() >= o.pin.normal_load_N)) {
    // The steady film's equilibrium N_s(h̄) = W would lie below the table (the rig refuses it) —
    // said before a ball's films, the slow stage, are solved.
    const bool shaped = o.pin.shape == homogenise::PinShape::spherical || o.pin.tilt_rad > 0.0;
    throw std::invalid_argument(
        config.string() + ": [pin] normal_load_N = " + numerics::shortest(o.pin.normal_load_N) +
        " N exceeds the solid load at the table's smallest separation (" + numerics::fmt(pin.solid_load_N.front()) +
        " N at h̄ = " + numerics::fmt(pin.separation_m.front()) + " m)" +
        (shaped ? ": a crowned or tilted face touches over part of it only — reduce the tilt or crown, or add smaller "
                  "[homogenise] separation_ratios"
                : ": add smaller [homogenise] separation_ratios"));
  }
  // A ball's films, speed node by speed node, kept as they finish so that a killed run resumes.
  int nodes_reused = 0;
  if (o.pin.shape == homogenise::PinShape::ball) {
    const std::filesystem::path film_nodes = dir / "ball-film";
    make_output_dir(film_nodes);
    const auto node_file = [&](std::size_t k) { return film_nodes / ("node-" + std::to_string(k) + ".json"); };
    Progress film_progress("homogenise: ball film speeds", static_cast<int>(homogenise::micro_ehl_eta_u_Pa_m(o).size()) - 1);
    homogenise::BallFilmStore ball_store;
    ball_store.load = [&](std::size_t k) {
      return read_cached(node_file(k), key, "node", &homogenise::ball_film_node_from_json);
    };
    ball_store.finished = [&](std::size_t k, const homogenise::BallFilmNode& node, bool taken) {
      if (taken) {
        ++nodes_reused;
        film_progress.step("cached");
        return;
      }
      write_cached(node_file(k), key, "node", homogenise::to_json(node));
      film_progress.step("U = " + numerics::shortest(node.eta_u_Pa_m / o.lubricant.viscosity_Pa_s) + " m/s");
    };
    homogenise::add_ball_film(o, pin, ball_store);
    film_progress.done();
  }
  nlohmann::json law = homogenise::law_json(o, cells, pin);
  law["provenance"] = provenance_json(config, hash, run.input_files);
  law["provenance"]["seeds"] = nlohmann::json::array();
  for (const auto& p : patch_results) law["provenance"]["seeds"].push_back(p.seed);
  law["provenance"]["realisations_reused"] = reused;
  if (pin.ball) law["provenance"]["ball_film_speeds_reused"] = nodes_reused;

  // The Stribeck curve the rig's law implies at the pin's load: steady sliding at each speed.
  const rig::HomogenisedBase base(rig::law_table_from_json(law, (dir / "law.json").string()), o.pin.normal_load_N);
  const StribeckCurve curve = stribeck_curve(run.speeds_m_per_s, [&](double u) { return rig::steady_sliding(base, u); });
  const std::vector<rig::SteadySliding>& stribeck = curve.points;
  const std::vector<double> mu_errors =
      stribeck_discretisation_errors(law, pin, stribeck, o.pin.normal_load_N, (dir / "law.json").string());
  const std::vector<double> crowns_m = thermal_crown_bounds_m(o, stribeck);
  nlohmann::json sj = nlohmann::json::array();
  for (std::size_t k = 0; k < stribeck.size(); ++k) {
    const rig::SteadySliding& s = stribeck[k];
    sj.push_back({{"U_m_per_s", s.speed_m_per_s},
                  {"mu", s.mu},
                  {"mu_discretisation_error", mu_errors[k]},
                  {"fluid_share", s.fluid_share},
                  {"film_share_of_contact", s.film_share_of_contact},
                  {"separation_m", s.separation_m},
                  {"film_parameter", s.separation_m / cells.sigma_m},
                  {"temperature_rise_K", s.temperature_rise_K},
                  {"thermal_crown_bound_m", crowns_m[k]},
                  {"regime", rig::to_string(s.regime)}});
  }
  law["stribeck"] = sj;
  // Everything left out, with why: the Stribeck points above, and the table's separations without
  // a converged solve (issue 37's interface; empty when all converged).
  law["unconverged"] = curve.unconverged;
  if (pin.ball)
    for (const std::string& m : pin.ball->messages) law["unconverged"].push_back({{"what", "ball film solve"}, {"reason", m}});
  for (const auto& h : law["table"]["dropped_separations_m"])
    law["unconverged"].push_back({{"what", "law table separation"}, {"separation_m", h}, {"reason", "no converged solve at this separation"}});
  law["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  int bem_iterations = 0;
  double bem_s = 0, flow_s = 0, lift_s = 0;  // summed over realisations (CPU-thread seconds)
  for (const auto& p : patch_results) {
    bem_iterations += p.bem_iterations;
    bem_s += p.bem_s, flow_s += p.flow_cells_s, lift_s += p.lift_cells_s;
  }
  law["bem_iterations"] = bem_iterations;
  law["stage_thread_s"] = {{"bem", bem_s}, {"flow_cells", flow_s}, {"lift_cells", lift_s}};

  const nlohmann::json& provenance = law["provenance"];
  write_area_csv(dir / "area.csv", pin, cells.sigma_m, provenance);
  write_stribeck_csv(dir / "stribeck.csv", stribeck, mu_errors, crowns_m, cells.sigma_m, provenance);
  write_file_atomically(dir / "law.json", law.dump(2) + "\n");
  std::printf("mu_s,max %.4g ± %.2g (BEM extrapolated from %d², %d realisations; ± the discretisation error), dry mu %.4g ± %.2g; Stribeck over %zu speeds at W = %.4g N; %.1f s -> %s\n",
              cells.mu_s_max.mean, cells.mu_s_max_discretisation_error, cells.junction_grid, cells.realisations, cells.mu_boundary.mean,
              cells.mu_boundary_discretisation_error, stribeck.size(), o.pin.normal_load_N,
              law["wall_s"].get<double>(), out.string().c_str());
  if (!law["table"]["dropped_separations_m"].empty())
    std::fprintf(stderr, "tribo: warning: %zu separations left out of the law table (no converged solve there): %s\n",
                 law["table"]["dropped_separations_m"].size(), law["table"]["dropped_separations_m"].dump().c_str());
  for (const auto& p : curve.unconverged)
    std::fprintf(stderr, "tribo: warning: Stribeck point at %.4g m/s left out: %s\n", p["U_m_per_s"].get<double>(),
                 p["reason"].get<std::string>().c_str());
  for (const auto& w : law["warnings"]) std::fprintf(stderr, "tribo: warning: %s\n", w.get<std::string>().c_str());
  if (cells.unconverged > 0 || pin.reynolds_unconverged > 0)
    std::fprintf(stderr, "tribo: warning: %d cell and %d pin-face solves did not converge (left out; see law.json)\n",
                 cells.unconverged, pin.reynolds_unconverged);
  if (pin.ball && pin.ball->unconverged > 0)
    std::fprintf(stderr, "tribo: warning: %d of the ball's film solves did not converge (left out of its table; see law.json ball_film)\n",
                 pin.ball->unconverged);
  if (plots && run_plot_script("homogenise", out.string()) != 0)
    std::fprintf(stderr, "tribo: warning: plotting failed (needs python3-matplotlib); CSVs and law.json are written\n");
  return law;
}

}  // namespace tribo::cli
