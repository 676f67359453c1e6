#include "apps/rig_config.h"

#include <cstdio>
#include <stdexcept>

#include "rig/csv_table.h"
#include "rig/friction_model.h"
#include "rig/homogenised_law.h"
#include "rig/kinetic_laws.h"
#include "numerics/format.h"

namespace tribo::cli {
namespace {

// Thesis Fig 5.2.1: v = 2.8e-2 in/s, where μs = 0.26 was measured.
constexpr double kDefaultDriveSpeed_m_per_s = 7.112e-4;

// A drive history as CSV (rig/csv_table.h: the bundle's rules) with columns t_s and v_m_per_s;
// other columns are ignored with a warning.
void read_drive_table_csv(const std::filesystem::path& path, std::vector<double>& times, std::vector<double>& speeds) {
  std::vector<std::string> warnings;
  const rig::CsvTable t = rig::read_csv_table(path, {"t_s", "v_m_per_s"}, warnings);
  for (const std::string& w : warnings) std::fprintf(stderr, "tribo: warning: %s\n", w.c_str());
  const int ct = t.required("t_s"), cv = t.required("v_m_per_s");
  for (const auto& [line, row] : t.rows) {
    times.push_back(t.number(line, row, ct));
    speeds.push_back(t.number(line, row, cv));
    if (speeds.back() < 0.0) rig::fail_at(path, line, "v_m_per_s is negative");
    if (times.size() > 1 && !(times.back() > times[times.size() - 2])) rig::fail_at(path, line, "t_s does not increase");
  }
}

}  // namespace

rig::RigParameters read_rig_parameters(ConfigTable& t) {
  rig::RigParameters p;
  p.mass_kg = t.number("mass_kg", p.mass_kg, Range::positive);
  p.stiffness_N_per_m = t.number("stiffness_N_per_m", p.stiffness_N_per_m, Range::positive);
  p.damping_N_s_per_m = t.number("damping_N_s_per_m", p.damping_N_s_per_m, Range::non_negative);
  p.normal_load_N = t.number("normal_load_N", p.normal_load_N, Range::positive);
  p.slider_radius_m = t.number("slider_radius_m", p.slider_radius_m, Range::positive);
  input_guard(t, "damping_N_s_per_m", [&] { rig::validate(p); return 0; });
  return p;
}

rig::Drive read_drive(ConfigTable* t, std::optional<double> speed) {
  if (!t) return rig::Drive::constant(speed.value_or(kDefaultDriveSpeed_m_per_s));
  if (speed) t->fail("kind", "give the drive either as [rig] drive_speed_m_per_s or as a [drive] table, not both");
  const std::string kind = t->choice("kind", "constant", {"constant", "steps", "slide_hold_slide", "table"});
  rig::Drive drive = rig::Drive::constant(kDefaultDriveSpeed_m_per_s);
  if (kind == "constant") {
    drive = rig::Drive::constant(t->number("speed_m_per_s", kDefaultDriveSpeed_m_per_s, Range::non_negative));
  } else if (kind == "slide_hold_slide") {
    const double v = t->required_number("speed_m_per_s", Range::non_negative);
    const double slide = t->required_number("slide_s", Range::positive);
    const double hold = t->required_number("hold_s", Range::positive);
    drive = rig::Drive::slide_hold_slide(v, slide, hold);
  } else {
    std::vector<double> times = t->number_array("times_s", Range::non_negative);
    std::vector<double> speeds = t->number_array("speeds_m_per_s", Range::non_negative);
    if (t->has("file")) {
      if (!times.empty() || !speeds.empty()) t->fail("file", "give the drive table either inline or as a file, not both");
      const std::filesystem::path file = t->input_file("file");
      input_guard(*t, "file", [&] { read_drive_table_csv(file, times, speeds); return 0; });
    }
    if (times.empty()) t->fail("times_s", "is required for kind = \"" + kind + "\" (or file = \"drive.csv\")");
    drive = input_guard(*t, "times_s", [&] {
      return kind == "steps" ? rig::Drive::steps(times, speeds) : rig::Drive::table(times, speeds);
    });
  }
  t->finish();
  return drive;
}

rig::FrictionModel read_friction_model(ConfigTable* t, std::optional<double> normal_load_N) {
  rig::FrictionModel model;
  if (!t) return model;
  const std::string law = t->choice("law", "coulomb", {"coulomb", "stribeck", "table", "homogenised"});
  if (law != "homogenised") model.baseline.mu_s = t->number("mu_s", model.baseline.mu_s, Range::non_negative);
  if (law == "homogenised") {
    // table = "law.json" (relative to the config's folder), written by `tribo homogenise`.
    const std::filesystem::path path = t->input_file("table");
    if (!normal_load_N) t->fail("law", "\"homogenised\" needs the rig's normal load, which this command does not provide");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) t->fail("table", "cannot open '" + path.string() + "' (missing or not a regular file)");
    model.baseline.homogenised = input_guard(*t, "table", [&] { return rig::load_homogenised_base(path, *normal_load_N); });
  } else if (law == "coulomb") {
    model.baseline.mu_k = t->number("mu_k", model.baseline.mu_k, Range::non_negative);
    if (model.baseline.mu_k > model.baseline.mu_s) {
      t->fail("mu_k", "must not exceed mu_s (" + numerics::shortest(model.baseline.mu_s) + ")");
    }
  } else if (law == "stribeck") {
    rig::StribeckParameters p;
    p.mu_coulomb = t->number("mu_k", p.mu_coulomb, Range::non_negative);
    p.mu_breakaway = t->number("mu_k0", p.mu_breakaway, Range::non_negative);
    p.stribeck_speed_m_per_s = t->number("stribeck_speed_m_per_s", p.stribeck_speed_m_per_s, Range::positive);
    p.exponent = t->number("exponent", p.exponent, Range::positive);
    p.viscous_per_m_per_s = t->number("viscous_per_m_per_s", p.viscous_per_m_per_s, Range::non_negative);
    model.baseline.kinetic = input_guard(*t, "law", [&] { return std::make_shared<rig::StribeckCurve>(p); });
  } else {
    const auto speeds = t->number_array("speeds_m_per_s", Range::non_negative);
    const auto mu = t->number_array("mu_k", Range::non_negative);
    model.baseline.kinetic = input_guard(*t, "speeds_m_per_s", [&] { return std::make_shared<rig::TabulatedCurve>(speeds, mu); });
  }
  // effects = ["name", ...]; each may have a [friction.name] table of parameters.
  for (const std::string& name : t->string_array("effects")) {
    const rig::EffectInfo& info = input_guard(*t, "effects", [&]() -> const rig::EffectInfo& { return rig::effect_info(name); });
    if (model.has(name)) t->fail("effects", "effect \"" + name + "\" is listed twice");
    model.add(name);
    if (auto params = t->table(name)) {
      for (const rig::ParameterSpec& spec : info.parameters) {
        const double value = params->number(spec.name, spec.default_value);
        if (value < spec.lower || value > spec.upper) {
          params->fail(spec.name, "must lie in [" + numerics::shortest(spec.lower) + ", " + numerics::shortest(spec.upper) + "] " + spec.unit +
                                      " (got " + numerics::shortest(value) + ")");
        }
        model.set(name, spec.name, value);
      }
      params->finish();
    }
  }
  for (const rig::EffectInfo& info : rig::effect_catalogue()) {
    if (!model.has(info.name) && t->has(info.name)) {
      t->fail(info.name, "parameters given for an effect not listed in friction.effects");
    }
  }
  input_guard(*t, "law", [&] { rig::validate(model); return 0; });
  t->finish();
  return model;
}

RigRun load_rig_run(const std::filesystem::path& path) { return load_rig_run(parse_toml_file(path), path); }

RigRun load_rig_run(const toml::table& doc, const std::filesystem::path& path) {
  ConfigTable root(doc, path.string(), "");
  RigRun run;

  std::optional<double> speed;
  if (auto t = root.table("rig")) {
    run.rig = read_rig_parameters(*t);
    speed = t->optional_number("drive_speed_m_per_s", Range::non_negative);
    t->finish();
  }
  auto drive_table = root.table("drive");
  run.drive = read_drive(drive_table ? &*drive_table : nullptr, speed);
  auto friction_table = root.table("friction");
  run.friction = read_friction_model(friction_table ? &*friction_table : nullptr, run.rig.normal_load_N);
  run.law = rig::make_friction_law(run.friction);
  if (auto t = root.table("run")) {
    run.options.duration_s = t->number("duration_s", run.options.duration_s, Range::positive);
    run.options.samples_per_period =
        static_cast<int>(t->integer("samples_per_period", run.options.samples_per_period, 8, 1'000'000));
    run.options.relative_tolerance = t->number("relative_tolerance", run.options.relative_tolerance, Range::positive);
    if (run.options.relative_tolerance >= 1e-2) t->fail("relative_tolerance", "must be below 1e-2");
    run.options.start_in_steady_sliding = t->choice("start", "stuck", {"stuck", "sliding"}) == "sliding";
    run.seed = static_cast<std::uint64_t>(t->integer("seed", static_cast<long long>(run.seed), 0));
    run.analysis_start_fraction = t->number("analysis_start_fraction", run.analysis_start_fraction, Range::unit_interval);
    if (run.analysis_start_fraction >= 1.0) t->fail("analysis_start_fraction", "must be below 1");
    t->finish();
  }
  root.finish();
  run.input_files = root.input_files();
  return run;
}

}  // namespace tribo::cli
