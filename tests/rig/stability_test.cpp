// Steady sliding on a negatively sloped kinetic curve: small oscillations grow iff −W dμk/dU > r
// (thesis Appendix II; rig/reference/closed_forms.h gives the linear growth rate).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "rig/kinetic_laws.h"
#include "rig/reference/closed_forms.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

// Linear kinetic curve μk = μ0 + s U around the drive speed (a two-point table).
double measured_growth_rate(double slope_ratio) {
  const RigParameters rig;  // r = 1.7338 N s/m, W = 93.857 N
  const double v = 0.1, mu_v = 0.15;
  const double slope = -slope_ratio * rig.damping_N_s_per_m / rig.normal_load_N;  // dμk/dU
  auto curve = std::make_shared<TabulatedCurve>(std::vector<double>{0.0, 1.0},
                                                std::vector<double>{mu_v - slope * v, mu_v + slope * (1.0 - v)});
  KineticCurveLaw law(0.5, curve);
  // Start on the steady-sliding equilibrium k x = μk(v) W − r v... perturbed by 10 µm/s.
  SimulationOptions opt;
  opt.duration_s = 6.0;
  opt.start_slipping = true;
  opt.initial_velocity_m_per_s = 1e-5;
  opt.initial_displacement_m = (mu_v * rig.normal_load_N) / rig.stiffness_N_per_m;
  const SimulationResult r = simulate(rig, Drive::constant(v), law, opt);
  EXPECT_TRUE(r.summary.completed) << r.summary.message;
  EXPECT_EQ(r.events.size(), 0u) << "the perturbation must stay small: no velocity match";
  // Envelope of ẋ: peak speeds in the first and last second.
  double early = 0.0, late = 0.0;
  for (const Sample& s : r.samples) {
    if (s.t_s >= 1.0 && s.t_s < 2.0) early = std::max(early, std::abs(s.xdot_m_per_s));
    if (s.t_s >= 5.0) late = std::max(late, std::abs(s.xdot_m_per_s));
  }
  return std::log(late / early) / 4.0;  // peaks of the windows are 4 s apart (± a period)
}

TEST(NegativeSlope, OscillationGrowsOnlyWhenSlopeExceedsDamping) {
  const RigParameters rig;
  for (double ratio : {0.5, 0.9, 1.1, 2.0}) {
    const double slope = -ratio * rig.damping_N_s_per_m / rig.normal_load_N;
    const double expected = reference::steady_sliding_growth_rate_per_s(rig, slope);
    const double sigma = measured_growth_rate(ratio);
    EXPECT_EQ(sigma > 0.0, ratio > 1.0) << "ratio " << ratio;
    // Peaks are sampled once per 2π/(200 ω_n) and the windows' peaks sit up to one period
    // from their nominal 4 s spacing: |Δσ| ≤ |σ| T/4 s + 1e-4/4 s — 0.02 1/s covers both.
    EXPECT_NEAR(sigma, expected, 0.02) << "ratio " << ratio;
  }
}

}  // namespace
}  // namespace tribo::rig
