// `tribo rig` configuration: TOML → rig parameters, drive history, friction law, run options.
//
//   [rig]       mass_kg, stiffness_N_per_m, damping_N_s_per_m, normal_load_N, slider_radius_m,
//               drive_speed_m_per_s                       (thesis rig for every key left out)
//   [drive]     kind = "constant" | "steps" | "slide_hold_slide" | "table"
//               times_s = [...], speeds_m_per_s = [...]    (steps, table)
//               speed_m_per_s, slide_s, hold_s             (slide_hold_slide)
//   [friction]  law = "coulomb" | "stribeck" | "table" | "homogenised", mu_s, mu_k, ..., effects = [...]
//               law = "homogenised": table = "law.json" (relative to the config; rig/law_table.h),
//               no mu_s / mu_k; rate_dependent_static and strain_rate_hardening are not allowed
//               [friction.<effect>] parameters            (docs/friction-effects.md)
//   [run]       duration_s, samples_per_period, relative_tolerance, analysis_start_fraction, seed
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "apps/config.h"
#include "rig/drive.h"
#include "rig/friction_law.h"
#include "rig/friction_model.h"
#include "rig/observables.h"
#include <cstdint>
#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::cli {

struct RigRun {
  rig::RigParameters rig;
  std::optional<rig::Drive> drive;
  rig::FrictionModel friction;
  std::shared_ptr<const rig::FrictionLaw> law;
  std::uint64_t seed = 1;                // instrument noise
  rig::SimulationOptions options;
  double analysis_start_fraction = rig::kStartupFraction;  // observables use the run from this fraction of duration on
  std::vector<std::filesystem::path> input_files;  // read besides the config: the law table, the drive table
};

// Reads and validates a whole config; throws InputError ("file: key 'a.b': reason") on bad input.
RigRun load_rig_run(const std::filesystem::path& path);
// The same on a parsed document; `path` names it in errors and anchors relative file names.
RigRun load_rig_run(const toml::table& doc, const std::filesystem::path& path);

// The pieces, for other commands that embed a rig (demo, gap): each reads its table and rejects
// unknown keys. `friction` may be absent (the Coulomb defaults μs = 0.3, μk = 0.2 then apply).
// law = "homogenised" needs the rig's normal load W (the film's initial equilibrium N_s(h̄0) = W);
// without `normal_load_N` it is an InputError, and so is a W outside the table's solid-load range.
rig::RigParameters read_rig_parameters(ConfigTable& rig_table);
rig::FrictionModel read_friction_model(ConfigTable* friction_table, std::optional<double> normal_load_N = std::nullopt);
rig::Drive read_drive(ConfigTable* drive_table, std::optional<double> drive_speed_m_per_s);

}  // namespace tribo::cli
