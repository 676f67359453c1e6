#include "gap/independent/measuring_chain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tribo::gap::independent {

ButterworthLowPass::ButterworthLowPass(int order, double cutoff_Hz, double step_s) : order_(order), step_s_(step_s) {
  if (order < 2 || order % 2 != 0) throw std::invalid_argument("Butterworth low-pass: order must be even and >= 2");
  if (!(cutoff_Hz > 0.0) || !(cutoff_Hz * step_s < 0.5)) throw std::invalid_argument("Butterworth low-pass: cut-off must lie below the Nyquist frequency");
  // Pre-warped analogue cut-off: K = tan(π f_c Δt) = Ω_c Δt / 2.
  k_ = std::tan(M_PI * cutoff_Hz * step_s);
  // Normalised Butterworth polynomial = Π (s² + β_j s + 1), β_j = 2 sin((2j − 1)π / 2N), each
  // section mapped by s = (2/Δt)(1 − z⁻¹)/(1 + z⁻¹).
  for (int j = 1; j <= order / 2; ++j) {
    const double beta = 2.0 * std::sin((2.0 * j - 1.0) * M_PI / (2.0 * order));
    const double norm = 1.0 / (1.0 + beta * k_ + k_ * k_);
    Section s;
    s.b0 = k_ * k_ * norm, s.b1 = 2.0 * s.b0, s.b2 = s.b0;
    s.a1 = 2.0 * (k_ * k_ - 1.0) * norm;
    s.a2 = (1.0 - beta * k_ + k_ * k_) * norm;
    sections_.push_back(s);
  }
}

std::vector<double> ButterworthLowPass::apply(const std::vector<double>& u) const {
  std::vector<double> y = u;
  if (y.empty()) return y;
  for (const Section& s : sections_) {
    const double x0 = y.front();
    double x1 = x0, x2 = x0, y1 = x0, y2 = x0;  // steady state: DC gain (b0 + b1 + b2)/(1 + a1 + a2) = 1
    for (double& v : y) {
      const double out = s.b0 * v + s.b1 * x1 + s.b2 * x2 - s.a1 * y1 - s.a2 * y2;
      x2 = x1, x1 = v, y2 = y1, y1 = out;
      v = out;
    }
  }
  return y;
}

double ButterworthLowPass::gain_at(double f) const {
  return 1.0 / std::sqrt(1.0 + std::pow(std::tan(M_PI * f * step_s_) / k_, 2.0 * order_));
}

std::vector<double> ar1_noise(std::size_t n, double rms, double rho, std::mt19937_64& rng) {
  std::normal_distribution<double> xi(0.0, 1.0);
  std::vector<double> e(n, 0.0);
  if (rms <= 0.0) return e;
  double prev = rms * xi(rng);
  const double innovation = rms * std::sqrt(1.0 - rho * rho);
  for (std::size_t j = 0; j < n; ++j) {
    e[j] = j == 0 ? prev : rho * prev + innovation * xi(rng);
    prev = e[j];
  }
  return e;
}

std::vector<double> record_channel(const std::vector<double>& fine, double dt, const ChannelChain& c, const Recorder& r, std::mt19937_64& rng,
                                   std::vector<double>* times_s) {
  const int m = static_cast<int>(std::lround(1.0 / (r.rate_Hz * dt)));
  if (m < 1) throw std::invalid_argument("measuring chain: recorder rate above the simulation rate");
  std::vector<double> y(fine.size());
  // Sensor: delay (linear interpolation, held before t = 0), first-order lag (exact for a signal
  // constant over a step), gain.
  const double shift = c.delay_s / dt;
  double lagged = 0.0;
  const double alpha = c.sensor_time_constant_s > 0.0 ? 1.0 - std::exp(-dt / c.sensor_time_constant_s) : 1.0;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const double at = static_cast<double>(i) - shift;
    double u;
    if (at <= 0.0) {
      u = fine.front();
    } else {
      const std::size_t k = static_cast<std::size_t>(at);
      const double w = at - static_cast<double>(k);
      u = k + 1 < fine.size() ? (1.0 - w) * fine[k] + w * fine[k + 1] : fine.back();
    }
    lagged = i == 0 ? u : lagged + alpha * (u - lagged);
    y[i] = c.gain * lagged;
  }
  const ButterworthLowPass aa(r.anti_alias_order, r.anti_alias_cutoff_fraction * 0.5 * r.rate_Hz, dt);
  y = aa.apply(y);
  std::vector<double> out, t;
  for (std::size_t i = 0; i < y.size(); i += static_cast<std::size_t>(m)) out.push_back(y[i]), t.push_back(static_cast<double>(i) * dt);
  const std::vector<double> noise = ar1_noise(out.size(), c.noise_rms, c.noise_correlation, rng);
  for (std::size_t j = 0; j < out.size(); ++j) out[j] = quantise(out[j] + c.offset + c.drift_per_s * t[j] + noise[j], c.quantum);
  if (times_s) *times_s = std::move(t);
  return out;
}

}  // namespace tribo::gap::independent
