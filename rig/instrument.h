// The friction instrument of the thesis (§4.2–4.3, Appendix IV): displacement and acceleration
// signals summed electrically, F_meas/k = x + ẍ/ω_n² (4.2.3), which neglects the damping force
// r ẋ. A model's instrument (FrictionModel::instrument) adds what a real channel does:
//
//     u(t) = g · k · [ x(t) + ẍ(t − τ) / ω_n² ],   τ_s Ḟ_meas + F_meas = u,   plus n(t),
//
// gain g, lag τ of the accelerometer channel behind the displacement channel, the first-order
// lag τ_s of the sensor that reads the sum (a load cell and its amplifier: most friction rigs
// read the force so, and their time constant smooths a slip drop that lasts a few τ_s), and
// white noise n of rms σ (seeded, so a run is reproducible).
#pragma once

#include <cstdint>
#include <vector>

#include "rig/friction_model.h"
#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::rig {

struct InstrumentModel {
  double gain = 1.0;
  double lag_s = 0.0;
  double time_constant_s = 0.0;
  double noise_N = 0.0;
  std::uint64_t seed = 1;
  // Whether the channel adds the accelerometer's inertia term, g k (x + ẍ/ω_n²) (4.2.3), or shows
  // the spring force alone, g k x: a rig without the thesis' accelerometer (paper on paper,
  // Colas et al. 2019). In a slip the two differ by M ẍ, as much as the drop itself.
  bool inertia_corrected = true;
};

// The model's instrument if it has one, else the ideal (4.2.3) instrument.
InstrumentModel instrument_from(const FrictionModel& model, std::uint64_t seed);

// The friction coefficient the channel shows at a breakaway, without noise: the slider has been at
// rest, ẍ ≈ 0, so (4.2.3) reads g k x = g F — the lag τ does not enter. The spring has loaded it
// at the rate μ̇ = `load_rate_per_s` (k V / W) for far longer than τ_s, so the sensor lags the
// ramp by τ_s μ̇ (a first-order lag's steady response to a ramp).
inline double breakaway_reading(const InstrumentModel& instrument, double mu, double load_rate_per_s) {
  return instrument.gain * (mu - instrument.time_constant_s * load_rate_per_s);
}

// Measured friction at every sample (samples ordered in time); the lagged acceleration is
// interpolated linearly between samples and held at its first value before the run starts. The
// sensor lag is integrated exactly for a signal linear between samples, from the steady state of
// the first value.
std::vector<double> measure_friction_N(const RigParameters& rig, const InstrumentModel& instrument,
                                       const std::vector<Sample>& samples);

}  // namespace tribo::rig
