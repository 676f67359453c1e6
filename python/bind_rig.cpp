// The friction rig: one run from a `tribo rig` config, read by the CLI's own reader
// (apps/rig_config.h) so every key, default and error is the CLI's, and computed with the same
// library calls as apps/cmd_rig.cpp — the summary dict holds the numbers summary.json holds.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <vector>

#include "apps/rig_config.h"
#include "apps/rig_output.h"
#include "python/common.h"
#include "rig/friction_model.h"
#include "rig/instrument.h"
#include "rig/observables.h"
#include "rig/simulator.h"

namespace tribo::python {
namespace {

// Column `member` of a vector of structs as a float64 array.
template <class T, class F>
py::array_t<double> column(const std::vector<T>& rows, F member) {
  py::array_t<double> a(static_cast<py::ssize_t>(rows.size()));
  auto v = a.mutable_unchecked<1>();
  for (std::size_t i = 0; i < rows.size(); ++i) v(static_cast<py::ssize_t>(i)) = member(rows[i]);
  return a;
}

py::dict run_rig(const std::filesystem::path& config) {
  const cli::RigRun run = cli::load_rig_run(config);
  rig::SimulationResult result;
  std::vector<double> measured;
  double wall = 0.0;
  {
    py::gil_scoped_release release;
    const auto start = std::chrono::steady_clock::now();
    result = rig::simulate(run.rig, *run.drive, *run.law, run.options);
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    measured = rig::measure_friction_N(run.rig, rig::instrument_from(run.friction, run.seed), result.samples);
  }
  const rig::SimulationSummary& summary = result.summary;
  const rig::RunObservables obs =
      rig::summarise(run.rig, result.samples, result.events, run.analysis_start_fraction * summary.end_time_s);
  // summary.json, key for key (apps/cmd_rig.cpp).
  const nlohmann::json j = cli::rig_summary_json(obs, summary, run.law->name(), run.rig, wall);

  using rig::Sample;
  const auto& s = result.samples;
  py::dict trace;  // trace.csv's columns
  trace["t_s"] = column(s, [](const Sample& x) { return x.t_s; });
  trace["x_m"] = column(s, [](const Sample& x) { return x.x_m; });
  trace["xdot_m_per_s"] = column(s, [](const Sample& x) { return x.xdot_m_per_s; });
  trace["friction_N"] = py::array(py::cast(measured));
  trace["xddot_m_per_s2"] = column(s, [](const Sample& x) { return x.xddot_m_per_s2; });
  trace["friction_true_N"] = column(s, [](const Sample& x) { return x.friction_N; });
  trace["relative_velocity_m_per_s"] = column(s, [](const Sample& x) { return x.drive_speed_m_per_s - x.xdot_m_per_s; });
  trace["drive_speed_m_per_s"] = column(s, [](const Sample& x) { return x.drive_speed_m_per_s; });
  trace["x_drive_m"] = column(s, [](const Sample& x) { return x.drive_displacement_m; });
  trace["slip_distance_m"] = column(s, [](const Sample& x) { return x.slip_distance_m; });
  trace["slipping"] = py::array(py::cast([&] {
    std::vector<bool> v;
    for (const Sample& x : s) v.push_back(x.phase == rig::Phase::slip);
    return v;
  }()));

  using rig::Event;
  const auto& e = result.events;
  py::dict events;  // events.csv's columns
  events["t_s"] = column(e, [](const Event& x) { return x.t_s; });
  std::vector<std::string> kinds;
  for (const Event& x : e) kinds.emplace_back(rig::to_string(x.kind));
  events["event"] = py::array(py::cast(kinds));
  events["slip_direction"] = column(e, [](const Event& x) { return double(x.slip_direction); });
  events["x_m"] = column(e, [](const Event& x) { return x.x_m; });
  events["xdot_m_per_s"] = column(e, [](const Event& x) { return x.xdot_m_per_s; });
  events["friction_N"] = column(e, [](const Event& x) { return x.friction_N; });
  events["mu"] = column(e, [](const Event& x) { return x.mu; });
  events["load_rate_per_s"] = column(e, [](const Event& x) { return x.load_rate_per_s; });
  events["phase_duration_s"] = column(e, [](const Event& x) { return x.phase_duration_s; });
  events["slip_distance_m"] = column(e, [](const Event& x) { return x.slip_distance_m; });

  py::dict d;
  d["summary"] = to_python(j);
  d["trace"] = trace;
  d["events"] = events;
  return d;
}

py::list catalogue() {
  py::list out;
  for (const rig::EffectInfo& e : rig::effect_catalogue()) {
    py::list params;
    for (const rig::ParameterSpec& p : e.parameters) {
      py::dict pd;
      pd["name"] = p.name;
      pd["unit"] = p.unit;
      pd["default"] = p.default_value;
      pd["lower"] = p.lower;
      pd["upper"] = p.upper;
      pd["meaning"] = p.meaning;
      params.append(pd);
    }
    py::dict ed;
    ed["name"] = e.name;
    ed["summary"] = e.summary;
    ed["thesis_reference"] = e.thesis_reference;
    ed["parameters"] = params;
    out.append(ed);
  }
  return out;
}

}  // namespace

void bind_rig(py::module_& m) {
  using namespace pybind11::literals;
  m.def("rig_from_toml", &run_rig,
        R"(One run of the pin-on-disc rig from a `tribo rig` config (docs/rig.md), read by the CLI's reader.

Returns dict:
  summary  summary.json as `tribo rig` writes it: regime ("stick_slip", "multi_cycle_slip",
           "quasi_harmonic", "steady_sliding", "stuck"), period_s, peak_to_peak_m, stick_time_s,
           slip_time_s, mu_s_mean, load_rate_mean_per_s (1/s), mean_friction_N, mu_at_reversal_mean (μ where
           a slip runs through a velocity match), breakaways, …,
           completed, message, end_time_s, integrator_steps, events, friction_law, rig {…}, wall_s.
           Observables that do not exist are None. A run that stops early says completed = False.
  trace    trace.csv's columns as float64 arrays: t_s, x_m, xdot_m_per_s, friction_N (as the
           instrument measures it), xddot_m_per_s2, friction_true_N, relative_velocity_m_per_s,
           drive_speed_m_per_s, x_drive_m, slip_distance_m; slipping (bool).
  events   events.csv's columns: t_s, event (str), slip_direction, x_m, xdot_m_per_s, friction_N,
           mu, load_rate_per_s, phase_duration_s, slip_distance_m.
Bad config raises ValueError with the CLI's message (file: key: reason).)",
        "path"_a);
  m.def("effect_catalogue", &catalogue,
        "The rig's friction effects: list of dicts name, summary, thesis_reference, parameters "
        "[{name, unit, default, lower, upper, meaning}] (the keys of [friction.<effect>]).");
}

}  // namespace tribo::python
