#include "rig/reference/closed_forms.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

namespace tribo::rig::reference {
namespace {

// First t in (t0, t1] where f changes sign from `from_sign`, scanned on n steps, then bisected.
double first_crossing(const std::function<double(double)>& f, double t0, double t1, int n, int from_sign) {
  double a = t0, fa = f(t0 + 1e-12 * (t1 - t0));
  for (int i = 1; i <= n; ++i) {
    double b = t0 + (t1 - t0) * i / n;
    const double fb = f(b);
    if (from_sign * fa > 0.0 && from_sign * fb <= 0.0) {
      for (int k = 0; k < 200 && b - a > 1e-15 * b; ++k) {
        const double m = 0.5 * (a + b);
        (from_sign * f(m) > 0.0 ? a : b) = m;
      }
      return 0.5 * (a + b);
    }
    a = b, fa = fb;
  }
  throw std::logic_error("closed_forms: no crossing found in the scanned interval");
}

}  // namespace

StickSlipCycle coulomb_stick_slip(const RigParameters& rig, double mu_s, double mu_k, double v) {
  validate(rig);
  if (!(mu_s > mu_k) || !(mu_k >= 0.0)) throw std::invalid_argument("stick-slip reference: needs mu_s > mu_k >= 0");
  if (!(v > 0.0)) throw std::invalid_argument("stick-slip reference: needs a positive drive speed");
  const double k = rig.stiffness_N_per_m, W = rig.normal_load_N, r = rig.damping_N_s_per_m;
  const double beta = rig.decay_rate_per_s(), wd = rig.damped_frequency_rad_per_s();
  const double x_eq = mu_k * W / k;
  const double x_s = (mu_s * W - r * v) / k;                    // stick ends: k x + r v = μs W
  // Slip: ξ = x − x_eq, ξ(0) = x_s − x_eq, ξ̇(0) = v; ξ = e^{−βt}(A cos ω_d t + B sin ω_d t).
  const double A = x_s - x_eq, B = (v + beta * A) / wd;
  auto xi = [&](double t) { return std::exp(-beta * t) * (A * std::cos(wd * t) + B * std::sin(wd * t)); };
  auto xidot = [&](double t) {
    return std::exp(-beta * t) * ((wd * B - beta * A) * std::cos(wd * t) - (wd * A + beta * B) * std::sin(wd * t));
  };
  const double Td = 2.0 * std::numbers::pi / wd;
  const int n = 20000;
  const double t_max = first_crossing(xidot, 0.0, 1.5 * Td, n, +1);                             // ẋ: + → −
  const double t_min = first_crossing(xidot, t_max, 1.5 * Td, n, -1);                           // ẋ: − → +
  const double t_slip = first_crossing([&](double t) { return v - xidot(t); }, t_min, 1.5 * Td, n, +1);  // ẋ reaches v
  StickSlipCycle c;
  c.slip_start_displacement_m = x_s;
  c.max_displacement_m = x_eq + xi(t_max);
  c.min_displacement_m = x_eq + xi(t_min);
  c.peak_to_peak_m = c.max_displacement_m - c.min_displacement_m;
  c.slip_time_s = t_slip;
  c.stick_time_s = (x_s - (x_eq + xi(t_slip))) / v;
  c.period_s = c.slip_time_s + c.stick_time_s;
  return c;
}

double coulomb_amplitude_loss_per_cycle_m(const RigParameters& rig, double mu_k) {
  return 4.0 * mu_k * rig.normal_load_N / rig.stiffness_N_per_m;
}

double steady_sliding_growth_rate_per_s(const RigParameters& rig, double dmu_dU) {
  return -(rig.damping_N_s_per_m + rig.normal_load_N * dmu_dU) / (2.0 * rig.mass_kg);
}

}  // namespace tribo::rig::reference
