#include "rig/sweep.h"

#include <omp.h>

#include <algorithm>
#include <numbers>

namespace tribo::rig {

double stick_slip_duration_s(const RigParameters& rig, double v, double delta_mu, double cycles, double minimum_s) {
  const double cycle = 2.0 * delta_mu * rig.normal_load_N / (rig.stiffness_N_per_m * v) +
                       2.0 * std::numbers::pi / rig.natural_frequency_rad_per_s();
  return std::max(minimum_s, cycles * cycle);
}

std::vector<SweepPoint> sweep_drive_speeds(const RigParameters& rig, const FrictionLaw& law,
                                           const std::vector<double>& speeds, const SweepOptions& options) {
  std::vector<SweepPoint> points(speeds.size());
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    SweepPoint& p = points[i];
    p.drive_speed_m_per_s = speeds[i];
    SimulationOptions opt = options.simulation;
    if (options.duration_for) opt.duration_s = options.duration_for(speeds[i]);
    p.result = simulate(rig, Drive::constant(speeds[i]), law, opt);
    p.observables = summarise(rig, p.result.samples, p.result.events,
                              analysis_start_s(0.0, p.result.summary.end_time_s));
    if (options.on_point_done) {
#pragma omp critical(tribo_sweep_progress)
      options.on_point_done(p);
    }
  }
  return points;
}

}  // namespace tribo::rig
