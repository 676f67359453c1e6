#include "rig/instrument.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace tribo::rig {

InstrumentModel instrument_from(const FrictionModel& model, std::uint64_t seed) {
  InstrumentModel m;
  m.seed = seed;
  if (model.instrument) {
    m.gain = model.get(kInstrument, "gain");
    m.lag_s = model.get(kInstrument, "lag_s");
    m.time_constant_s = model.get(kInstrument, "time_constant_s");
    m.noise_N = model.get(kInstrument, "noise_N");
  }
  return m;
}

std::vector<double> measure_friction_N(const RigParameters& rig, const InstrumentModel& ins,
                                       const std::vector<Sample>& samples) {
  const double wn2 = rig.stiffness_N_per_m / rig.mass_kg;
  std::mt19937_64 rng(ins.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> out(samples.size());
  std::size_t j = 0;  // first sample with t ≥ t − τ, advanced monotonically
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double a = 0.0;  // the accelerometer's reading, τ behind; none on a spring-force channel
    if (ins.inertia_corrected) {
      const double t_lag = samples[i].t_s - ins.lag_s;
      while (j + 1 < samples.size() && samples[j + 1].t_s <= t_lag) ++j;
      a = samples[j].xddot_m_per_s2;
      if (ins.lag_s > 0.0 && t_lag > samples[j].t_s && j + 1 < samples.size()) {
        const Sample &s0 = samples[j], &s1 = samples[j + 1];
        const double w = (t_lag - s0.t_s) / (s1.t_s - s0.t_s);
        a = (1.0 - w) * s0.xddot_m_per_s2 + w * s1.xddot_m_per_s2;
      }
      if (ins.lag_s == 0.0) a = samples[i].xddot_m_per_s2;
    }
    out[i] = ins.gain * rig.stiffness_N_per_m * (samples[i].x_m + a / wn2);  // thesis (4.2.3)
  }
  if (ins.time_constant_s > 0.0) {
    // τ ẏ + y = u with u linear over [t0, t0 + h], slope m: y(h) = u0 + m (h − τ) + (y0 − u0 + m τ) e^{−h/τ}.
    double u0 = out.empty() ? 0.0 : out.front(), y = u0;
    for (std::size_t i = 1; i < out.size(); ++i) {
      const double h = samples[i].t_s - samples[i - 1].t_s, u1 = out[i];
      if (h > 0.0) {
        const double m = (u1 - u0) / h, tau = ins.time_constant_s;
        y = u0 + m * (h - tau) + (y - u0 + m * tau) * std::exp(-h / tau);
      }
      out[i] = y, u0 = u1;
    }
  }
  if (ins.noise_N > 0.0)
    for (double& f : out) f += ins.noise_N * noise(rng);
  return out;
}

}  // namespace tribo::rig
