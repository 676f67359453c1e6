#include "apps/rig_output.h"

#include <spawn.h>
#include <sys/wait.h>

#include <vector>

#include <cstdlib>
#include <filesystem>

#include "apps/output.h"
#include "numerics/json_numbers.h"

extern char** environ;  // posix_spawnp passes the environment on

namespace tribo::cli {

void write_trace_header(std::ostream& os) {
  os << "t_s,x_m,xdot_m_per_s,friction_N,xddot_m_per_s2,friction_true_N,relative_velocity_m_per_s,"
        "drive_speed_m_per_s,x_drive_m,slip_distance_m,phase\n";
}

void write_trace_row(std::ostream& os, const rig::Sample& s, double measured_friction_N) {
  os << s.t_s << ',' << s.x_m << ',' << s.xdot_m_per_s << ',' << measured_friction_N << ','
     << s.xddot_m_per_s2 << ',' << s.friction_N << ',' << (s.drive_speed_m_per_s - s.xdot_m_per_s) << ','
     << s.drive_speed_m_per_s << ',' << s.drive_displacement_m << ',' << s.slip_distance_m << ','
     << (s.phase == rig::Phase::stick ? "stick" : "slip") << '\n';
}

void write_events_csv(std::ostream& os, const std::vector<rig::Event>& events) {
  os << "t_s,event,slip_direction,x_m,xdot_m_per_s,friction_N,mu,load_rate_per_s,phase_duration_s,slip_distance_m\n";
  for (const rig::Event& e : events) {
    os << e.t_s << ',' << rig::to_string(e.kind) << ',' << e.slip_direction << ',' << e.x_m << ',' << e.xdot_m_per_s
       << ',' << e.friction_N << ',' << e.mu << ',' << e.load_rate_per_s << ',' << e.phase_duration_s << ','
       << e.slip_distance_m << '\n';
  }
}

nlohmann::json observables_json(const rig::RunObservables& o) {
  return {{"regime", o.regime},
          {"window_start_s", o.window_start_s},
          {"period_s", numerics::finite_or_null(o.period_s)},
          {"peak_to_peak_m", numerics::finite_or_null(o.peak_to_peak_m)},
          {"mean_displacement_m", numerics::finite_or_null(o.mean_displacement_m)},
          {"stick_time_s", numerics::finite_or_null(o.stick_time_s)},
          {"slip_time_s", numerics::finite_or_null(o.slip_time_s)},
          {"mu_s_mean", numerics::finite_or_null(o.mu_s_mean)},
          {"load_rate_mean_per_s", numerics::finite_or_null(o.load_rate_mean_per_s)},
          {"mean_friction_N", numerics::finite_or_null(o.mean_friction_N)},
          {"mu_at_reversal_mean", numerics::finite_or_null(o.mu_at_reversal_mean)},
          {"breakaways", o.breakaways},
          {"reattachments", o.reattachments},
          {"reversals", o.reversals}};
}

nlohmann::json rig_json(const rig::RigParameters& rig) {
  return {{"mass_kg", rig.mass_kg},
          {"stiffness_N_per_m", rig.stiffness_N_per_m},
          {"damping_N_s_per_m", rig.damping_N_s_per_m},
          {"normal_load_N", rig.normal_load_N},
          {"slider_radius_m", rig.slider_radius_m},
          {"natural_frequency_rad_per_s", rig.natural_frequency_rad_per_s()},
          {"damped_frequency_rad_per_s", rig.damped_frequency_rad_per_s()},
          {"decay_rate_per_s", rig.decay_rate_per_s()}};
}

nlohmann::json rig_summary_json(const rig::RunObservables& o, const rig::SimulationSummary& summary, const std::string& law_name,
                                const rig::RigParameters& rig, double wall_s) {
  nlohmann::json j = observables_json(o);
  j["completed"] = summary.completed;
  j["message"] = summary.message;
  j["end_time_s"] = summary.end_time_s;
  j["integrator_steps"] = summary.integrator_steps;
  j["events"] = summary.events;
  j["friction_law"] = law_name;
  j["rig"] = rig_json(rig);
  j["wall_s"] = wall_s;
  return j;
}

int run_plot_script(const std::string& mode, const std::string& dir) {
  const std::string script = shipped_file("tribo_plots.py", "tools/tribo_plots.py").string();
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::vector<std::string> args{python, script, mode, dir};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return 127;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return 127;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

}  // namespace tribo::cli
