#include "gap/synthesize.h"

#include <random>
#include <stdexcept>
#include <string>

#include "rig/drive.h"
#include "rig/instrument.h"
#include "rig/observables.h"
#include "rig/simulator.h"

namespace tribo::gap {
namespace {

// The slide-hold-slide history of SyntheticOptions::hold_times_s at speed v.
rig::Drive slide_hold_slide(double v, const SyntheticOptions& o) {
  std::vector<double> times{0.0}, speeds{v};
  double t = o.duration_s;
  for (double hold : o.hold_times_s) {
    if (!(hold > 0.0)) throw std::invalid_argument("synthesize: a hold time must be positive");
    times.push_back(t), speeds.push_back(0.0), t += hold;
    times.push_back(t), speeds.push_back(v), t += o.duration_s;
  }
  return rig::Drive::steps(times, speeds);
}

double history_duration_s(const SyntheticOptions& o) {
  double t = o.duration_s;
  for (double hold : o.hold_times_s) t += hold + o.duration_s;
  return t;
}

}  // namespace

ExperimentBundle synthesize_bundle(const rig::RigParameters& rig, const rig::FrictionModel& truth, const SyntheticOptions& o,
                                   std::uint64_t seed) {
  ExperimentBundle b;
  b.name = "synthetic";
  b.mass_kg = rig.mass_kg;
  b.stiffness_N_per_m = rig.stiffness_N_per_m;
  b.damping_N_s_per_m = rig.damping_N_s_per_m;
  b.normal_load_N = rig.normal_load_N;
  b.slider_radius_m = rig.slider_radius_m;
  const bool history = !o.hold_times_s.empty();
  if (history) b.kind = "slide_hold_slide";
  const auto law = rig::make_friction_law(truth);
  rig::InstrumentModel instrument = rig::instrument_from(truth, seed);
  const double mu_k = truth.baseline.kinetic ? truth.baseline.mu_s : truth.baseline.mu_k;
  instrument.noise_N = o.noise_fraction * mu_k * rig.normal_load_N;
  std::mt19937_64 rng(seed ^ 0x5bd1e995ULL);
  std::normal_distribution<double> noise(0.0, instrument.noise_N);
  const std::vector<double> speeds = history ? std::vector<double>{o.speeds_m_per_s.at(o.speeds_m_per_s.size() / 2)} : o.speeds_m_per_s;
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    rig::SimulationOptions so;
    so.duration_s = history ? history_duration_s(o) : o.duration_s;
    so.samples_per_period = o.samples_per_period;
    const rig::Drive drive = history ? slide_hold_slide(speeds[k], o) : rig::Drive::constant(speeds[k]);
    const rig::SimulationResult r = rig::simulate(rig, drive, *law, so);
    if (!r.summary.completed) throw std::runtime_error("synthesize: a synthetic run did not complete: " + r.summary.message);
    instrument.seed = seed * 1000 + k;
    const std::vector<double> F = rig::measure_friction_N(rig, instrument, r.samples);
    Run run;
    run.run_id = std::to_string(k);
    run.v_m_per_s = speeds[k];
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (!run.trace.t_s.empty() && !(r.samples[i].t_s > run.trace.t_s.back())) continue;
      run.trace.t_s.push_back(r.samples[i].t_s);
      run.trace.x_m.push_back(r.samples[i].x_m);
      run.trace.xdot_m_per_s.push_back(r.samples[i].xdot_m_per_s);
      run.trace.friction_N.push_back(F[i]);
      if (history) {
        run.trace.x_drive_m.push_back(r.samples[i].drive_displacement_m);
        run.trace.v_drive_m_per_s.push_back(r.samples[i].drive_speed_m_per_s);
      }
    }
    b.runs.push_back(std::move(run));
    if (history) continue;
    // One static-friction point per run, as a rig operator reports it: the mean of the measured
    // breakaways (each with its own sensor noise) at that load rate after the start-up transient.
    double phi_sum = 0.0, mu_sum = 0.0;
    int breakaways = 0;
    for (const rig::Event& e : r.events) {
      if (e.kind != rig::EventKind::breakaway || e.t_s < rig::analysis_start_s(0.0, o.duration_s)) continue;
      phi_sum += e.load_rate_per_s;
      mu_sum += rig::breakaway_reading(instrument, e.mu, e.load_rate_per_s) + noise(rng) / rig.normal_load_N;
      ++breakaways;
    }
    if (breakaways) b.static_points.push_back({phi_sum / breakaways, mu_sum / breakaways});
  }
  return b;
}

}  // namespace tribo::gap
