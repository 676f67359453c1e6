// Experiment bundles (DESIGN §7): measured data a model is compared with. A bundle is a directory
//
//   experiment.toml       [rig] mass_kg, stiffness_N_per_m, damping_N_s_per_m, normal_load_N,
//                         slider_radius_m (each optional: missing keys are calibrated or taken
//                         from the model), kind = "pin_on_disc" | "velocity_step" |
//                         "slide_hold_slide" — the analysis (compare.h): constant driven speed
//                         per run, or a drive history read from v_drive_m_per_s;
//                         [rig.relative_uncertainty] mass_kg, stiffness_N_per_m,
//                         damping_N_s_per_m: how well the bundle knows the constants it gives,
//                         as a fraction u (the true value within ± u of the stated one, as
//                         "k = 168 N/m ± 3 %"); the diagnosis refines a constant within that
//                         interval, and takes one without a stated uncertainty as exact;
//                         optional [materials], [lubricant], [notes] (kept as text, not read)
//   static_friction.csv   phi_dot_per_s,mu_s                 one row per stick event (optional)
//   runs.csv              run_id,v_m_per_s,file               one trace per driven speed (optional)
//     trace files         t_s and any of x_m, xdot_m_per_s, friction_N, mu, x_drive_m,
//                         v_drive_m_per_s, normal_stress_Pa   (at least one friction signal:
//                         friction_N, mu or x_m)
//   regimes.csv           v_m_per_s,regime,amplitude_m,frequency_rad_per_s   (optional)
//
// Any subset may be present (at least one of the three data files). The CSV files are read by
// rig/csv_table.h's rules: unknown columns are ignored with a warning; malformed files throw
// std::invalid_argument naming file, line and reason.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tribo::gap {

struct StaticPoint {
  double phi_dot_per_s = 0.0;
  double mu_s = 0.0;
};

// Columns that were absent in the file are empty vectors.
struct Trace {
  std::vector<double> t_s, x_m, xdot_m_per_s, friction_N, mu, x_drive_m, v_drive_m_per_s, normal_stress_Pa;
  bool has_drive_history() const { return !v_drive_m_per_s.empty(); }
};

struct Run {
  std::string run_id;
  double v_m_per_s = 0.0;  // driven speed (the initial speed when the trace has a drive history)
  std::string file;        // as written in runs.csv
  Trace trace;
};

struct RegimePoint {
  double v_m_per_s = 0.0;
  std::string regime;      // rig/observables.h names: stick_slip, multi_cycle_slip, quasi_harmonic, steady_sliding, stuck
  double amplitude_m = 0.0;
  double frequency_rad_per_s = 0.0;
};

struct ExperimentBundle {
  std::string name;  // directory name
  std::string kind = "pin_on_disc";
  std::optional<double> mass_kg, stiffness_N_per_m, damping_N_s_per_m, normal_load_N, slider_radius_m;
  // [rig] key → relative uncertainty u ∈ (0, 1) of the value given there (refinable keys only:
  // refinable_rig_keys()).
  std::map<std::string, double> relative_uncertainty;
  // [rig] friction_channel: "inertia_corrected" (the default: the thesis' F = k (x + ẍ/ω_n²),
  // (4.2.3)) or "spring_force" (k x alone, a rig without an accelerometer): how the traces'
  // friction was measured, and so how the simulation reads its own.
  bool spring_force_channel = false;
  std::vector<StaticPoint> static_points;
  std::vector<Run> runs;
  std::vector<RegimePoint> regimes;
  std::vector<std::string> warnings;  // unknown columns and keys, one line each
  std::vector<std::filesystem::path> files;  // every file read_bundle read, in the order it read them
};

// The [rig] constants a bundle may state an uncertainty for. The normal load is not among them:
// friction laws proportional to W leave a W error indistinguishable from a scale of μ, which the
// calibration fits anyway.
const std::vector<std::string>& refinable_rig_keys();

// Reads and validates a bundle directory.
ExperimentBundle read_bundle(const std::filesystem::path& dir);

// Writes `bundle` in the same format (traces under traces/run_<id>.csv); used for synthetic data.
void write_bundle(const ExperimentBundle& bundle, const std::filesystem::path& dir);

}  // namespace tribo::gap
