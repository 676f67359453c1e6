// The independent generator's measuring chain (issue 15): what stands between a rig's true
// signal and the numbers in a bundle. Per channel, in the order the signal meets them:
//
//   sensor     y = g · L[u](t − τ_d)           gain g, transport delay τ_d, first-order sensor lag
//                                              L: τ_s ẏ + y = u (a load cell with its amplifier)
//   anti-alias Butterworth low-pass of even order N at f_c (bilinear transform, cut-off
//              pre-warped: |H(f)| = 1/√(1 + (tan(π f Δt)/tan(π f_c Δt))^(2N)), −3 dB at f_c)
//   sampling   every m-th fine sample: the recorder's uniform rate f_s = 1/(m Δt)
//   additive   offset + drift · t + AR(1) noise n_j = ρ n_{j−1} + σ √(1 − ρ²) ξ_j (stationary rms σ,
//              lag-one correlation ρ: coloured, as amplifier and mains pick-up are)
//   ADC        quantisation to the step q: y = q · round(y/q)
//
// `instrument` in the catalogue is a gain and a pure delay of the accelerometer channel in
// (4.2.3); here the same mechanism — a sensor that misreads scale and time — is a load cell's
// gain error and first-order lag.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace tribo::gap::independent {

struct ChannelChain {
  double gain = 1.0;
  double delay_s = 0.0;
  double sensor_time_constant_s = 0.0;
  double offset = 0.0;         // in the channel's unit, at t = 0
  double drift_per_s = 0.0;    // unit per second
  double noise_rms = 0.0;      // σ of the AR(1) noise
  double noise_correlation = 0.0;  // ρ per recorded sample, in [0, 1)
  double quantum = 0.0;        // ADC step q (0: none)
};

struct Recorder {
  double rate_Hz = 1000.0;
  int anti_alias_order = 4;               // N, even
  double anti_alias_cutoff_fraction = 0.4;  // f_c as a fraction of the Nyquist frequency f_s/2
};

// Second-order sections of a digital Butterworth low-pass (order N even) at sample spacing Δt.
class ButterworthLowPass {
 public:
  ButterworthLowPass(int order, double cutoff_Hz, double step_s);
  // Filters a record, starting from the steady state of its first value (DC gain 1).
  std::vector<double> apply(const std::vector<double>& u) const;
  // |H| of the digital filter at frequency f (closed form of the design).
  double gain_at(double frequency_Hz) const;

 private:
  struct Section { double b0, b1, b2, a1, a2; };
  std::vector<Section> sections_;
  int order_;
  double k_, step_s_;
};

// Samples a fine, uniform record (spacing `step_s`, starting at t = 0) through the chain at the
// recorder's rate; returns the recorded values and their times.
std::vector<double> record_channel(const std::vector<double>& fine, double step_s, const ChannelChain& chain, const Recorder& recorder,
                                   std::mt19937_64& rng, std::vector<double>* times_s);

// AR(1) noise of stationary rms σ and lag-one correlation ρ, started from its stationary law.
std::vector<double> ar1_noise(std::size_t n, double rms, double correlation, std::mt19937_64& rng);

inline double quantise(double y, double quantum) { return quantum > 0.0 ? quantum * std::round(y / quantum) : y; }

}  // namespace tribo::gap::independent
