// The one regime classification (rig/observables.h) read from a recorded slider displacement:
// hand-built traces whose regime is known by construction, and simulated stick-slip, which the
// stepper's events classify, recorded as a uniform sampler with sensor noise would record it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "rig/kinetic_laws.h"
#include "rig/observables.h"
#include "rig/reference/closed_forms.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

constexpr double kV = 1e-3;  // drive speed, m/s

struct Trace {
  std::vector<double> t, x;
};

// Samples f(t) every dt over [0, duration).
template <class F>
Trace sample(F f, double duration_s, double dt) {
  Trace tr;
  for (double t = 0.0; t < duration_s; t += dt) tr.t.push_back(t), tr.x.push_back(f(t));
  return tr;
}

std::string regime_of(const RigParameters& rig, const Trace& tr) {
  return classify_regime(rig, recorded_regime_evidence(rig, tr.t, tr.x, kV, analysis_start_s(tr.t.front(), tr.t.back())));
}

// Slipping at a constant offset: no events, no oscillation.
TEST(RecordedRegime, ConstantOffsetIsSteadySliding) {
  RigParameters rig;
  const Trace tr = sample([](double) { return 2e-5; }, 1.0, 1e-3);
  const RegimeEvidence e = recorded_regime_evidence(rig, tr.t, tr.x, kV, 0.5);
  EXPECT_EQ(e.breakaways + e.reattachments + e.reversals, 0);
  EXPECT_FALSE(e.sticks);  // u = V throughout: slipping
  EXPECT_EQ(classify_regime(rig, e), "steady_sliding");
}

// x = A sin(ωt) with Aω = 0.5 V: the sliding speed u = V(1 − 0.5 cos ωt) stays in [0.5 V, 1.5 V],
// never near the 5 % stick threshold, and the amplitude persists: quasi-harmonic. The same
// oscillation decaying with e^{−t/τ}, τ = 0.2 s, loses 92 % between the window's halves: steady.
TEST(RecordedRegime, PersistentOscillationWithoutStickIsQuasiHarmonic) {
  RigParameters rig;
  const double w = 2.0 * std::numbers::pi * 20.0, a = 0.5 * kV / w;
  EXPECT_EQ(regime_of(rig, sample([&](double t) { return a * std::sin(w * t); }, 2.0, 2e-4)), "quasi_harmonic");
  EXPECT_EQ(regime_of(rig, sample([&](double t) { return a * std::exp(-t / 0.2) * std::sin(w * t); }, 2.0, 2e-4)),
            "steady_sliding");
}

// A hand-built sawtooth: 0.3 s stuck (x rises with the drive, ẋ = V), then a 0.02 s slip back at
// 16 V. Every cycle is one breakaway and one re-attachment, the slip far shorter than the rig's
// damped period (0.062 s): stick-slip; a 0.2 s slip lasts over 1.5 periods: multi-cycle slip.
TEST(RecordedRegime, SawtoothIsStickSlipAndLongSlipsAreMultiCycle) {
  RigParameters rig;
  auto sawtooth = [](double stick_s, double slip_s) {
    const double rise = kV * stick_s, period = stick_s + slip_s;
    return [=](double t) {
      const double p = std::fmod(t, period);
      return p < stick_s ? kV * p : rise * (1.0 - (p - stick_s) / slip_s);
    };
  };
  const Trace tr = sample(sawtooth(0.3, 0.02), 6.4, 1e-3);
  const RegimeEvidence e = recorded_regime_evidence(rig, tr.t, tr.x, kV, 3.2);
  // 3.2 s of window at 0.32 s per cycle: 10 cycles (± one cut by the window's edges).
  EXPECT_NEAR(e.breakaways, 10, 1);
  EXPECT_NEAR(e.reattachments, 10, 1);
  EXPECT_EQ(e.reversals, 0);
  EXPECT_NEAR(e.longest_slip_s, 0.02, 0.004);  // ± the ±T_d/40 = 1.5 ms chord at each end
  EXPECT_EQ(classify_regime(rig, e), "stick_slip");
  EXPECT_EQ(regime_of(rig, sample(sawtooth(0.3, 0.2), 10.0, 1e-3)), "multi_cycle_slip");
}

// Held still while the drive moves (u = V): slipping, not stuck. Moving with the drive throughout
// (ẋ = V, u = 0): stuck, no events.
TEST(RecordedRegime, MovingWithTheDriveIsStuck) {
  RigParameters rig;
  EXPECT_EQ(regime_of(rig, sample([](double t) { return kV * t; }, 1.0, 1e-3)), "stuck");
}

// Coulomb stick-slip simulated by the rig (the closed-form case of stick_slip_test.cpp), recorded
// at a uniform 2 kHz — not the stepper's event-aligned samples — with white noise on x whose
// speed error over the ±T_d/40 chord is 2 % of the drive speed (σ = 0.02 V · 2h/√2 ≈ 44 nm): the
// recorded evidence gives the regime and the event counts the stepper's events give, within one
// cycle cut by the window's edges.
TEST(RecordedRegime, SimulatedStickSlipRecordedWithNoiseKeepsItsRegime) {
  RigParameters rig;
  const double mu_s = 0.3, mu_k = 0.2;
  const auto ref = reference::coulomb_stick_slip(rig, mu_s, mu_k, kV);
  SimulationOptions opt;
  opt.duration_s = 12.5 * ref.period_s;
  auto law = make_coulomb(mu_s, mu_k);
  const SimulationResult r = simulate(rig, Drive::constant(kV), *law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  const double t0 = analysis_start_s(0.0, r.summary.end_time_s);
  const RunObservables o = summarise(rig, r.samples, r.events, t0);
  ASSERT_EQ(o.regime, "stick_slip");

  Trace tr;
  std::mt19937_64 rng(7);
  const double h = std::numbers::pi / (20.0 * rig.damped_frequency_rad_per_s());
  std::normal_distribution<double> noise(0.0, 0.02 * kV * 2.0 * h / std::sqrt(2.0));
  std::size_t j = 0;
  for (double t = 0.0; t < r.summary.end_time_s; t += 5e-4) {
    while (j + 2 < r.samples.size() && r.samples[j + 1].t_s <= t) ++j;
    const Sample &a = r.samples[j], &b = r.samples[j + 1];
    const double f = b.t_s > a.t_s ? (t - a.t_s) / (b.t_s - a.t_s) : 0.0;
    tr.t.push_back(t);
    tr.x.push_back(a.x_m + f * (b.x_m - a.x_m) + noise(rng));
  }
  const RegimeEvidence e = recorded_regime_evidence(rig, tr.t, tr.x, kV, t0);
  EXPECT_EQ(classify_regime(rig, e), "stick_slip");
  EXPECT_NEAR(e.breakaways, o.breakaways, 1);
  EXPECT_NEAR(e.reattachments, o.reattachments, 1);
  EXPECT_EQ(e.reversals, 0);
}

}  // namespace
}  // namespace tribo::rig
