// The one regime classification (rig/observables.h) read from a recorded slider displacement:
// hand-built traces whose regime is known by construction, and simulated stick-slip,
// quasi-harmonic oscillation and steady sliding, which the stepper's events classify, read from
// the stepper's samples and as a uniform sampler with sensor noise would record them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
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
// x of a sawtooth: `stick_s` moving with the drive (ẋ = V), then a linear slip back to 0 in `slip_s`.
double sawtooth_x(double t, double stick_s, double slip_s) {
  const double p = std::fmod(t, stick_s + slip_s);
  return p < stick_s ? kV * p : kV * stick_s * (1.0 - (p - stick_s) / slip_s);
}

TEST(RecordedRegime, SawtoothIsStickSlipAndLongSlipsAreMultiCycle) {
  RigParameters rig;
  auto sawtooth = [](double stick_s, double slip_s) { return [=](double t) { return sawtooth_x(t, stick_s, slip_s); }; };
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

// The same sawtooth recorded with white noise on x whose speed error over the ±T_d/40 chord of one
// sample each side at 1 kHz is 35 % of the drive speed (σ = 0.35 V Δt √2 = 0.49 µm at 1 mm/s; the
// independent generator's slowest run of seed 301 records as much): the chord would flicker
// across the ±20 % stick band and read reversals, with no stick at all. The least-squares slope
// over the span the noise needs (here ±6 ms ≈ T_d/10) reads the ten cycles as recorded; the slip
// reads longer by up to the span at each end.
TEST(RecordedRegime, NoisySlowSawtoothIsStickSlipWithOneBreakawayPerCycle) {
  RigParameters rig;
  std::mt19937_64 gen(7);
  std::normal_distribution<double> noise(0.0, 0.35 * kV * 1e-3 * std::sqrt(2.0));
  const Trace tr = sample([&](double t) { return sawtooth_x(t, 0.3, 0.02) + noise(gen); }, 6.4, 1e-3);
  const RegimeEvidence e = recorded_regime_evidence(rig, tr.t, tr.x, kV, 3.2);
  EXPECT_NEAR(e.breakaways, 10, 1);
  EXPECT_NEAR(e.reattachments, 10, 1);
  EXPECT_EQ(e.reversals, 0);
  EXPECT_NEAR(e.longest_slip_s, 0.02, 0.013);  // ± the ±6 ms span at each end and a sample
  EXPECT_EQ(classify_regime(rig, e), "stick_slip");
}

// The same sawtooth recorded by an encoder of step q = 1.085 V Δt (the independent generator's
// slowest runs: ±10 mm over 12 bits, 4.9 µm, at 4.5 mm/s and 1 kHz). Most chord deviations are
// then exactly 0, so the median sees no noise, but the rounding flickers the ±1-sample chord by up
// to q/(2Δt) = 54 % of V, across the ±20 % stick band. The rounding counted as noise widens the
// slope as noise would.
TEST(RecordedRegime, QuantisedSlowSawtoothIsStickSlipWithOneBreakawayPerCycle) {
  RigParameters rig;
  const double q = 1.085 * kV * 1e-3;
  const Trace tr = sample([&](double t) { return q * std::round(sawtooth_x(t, 0.3, 0.02) / q); }, 6.4, 1e-3);
  const RegimeEvidence e = recorded_regime_evidence(rig, tr.t, tr.x, kV, 3.2);
  EXPECT_NEAR(e.breakaways, 10, 1);
  EXPECT_NEAR(e.reattachments, 10, 1);
  EXPECT_EQ(e.reversals, 0);
  EXPECT_NEAR(e.longest_slip_s, 0.02, 0.013);  // ± the widened span at each end and a sample
  EXPECT_EQ(classify_regime(rig, e), "stick_slip");
}

// Held still while the drive moves (u = V): slipping, not stuck. Moving with the drive throughout
// (ẋ = V, u = 0): stuck, no events.
TEST(RecordedRegime, MovingWithTheDriveIsStuck) {
  RigParameters rig;
  EXPECT_EQ(regime_of(rig, sample([](double t) { return kV * t; }, 1.0, 1e-3)), "stuck");
}

// A simulated run and its two recordings: the stepper's own samples (non-uniform: denser while
// slipping) and a uniform sampler at 2 kHz with white noise on x whose speed error over the
// ±T_d/40 chord is 2 % of the drive speed (σ = 0.02 V · 2h/√2; 44 nm at 1 mm/s).
struct SimulatedRun {
  RunObservables observables;  // the stepper's events and phases (summarise)
  double window_start_s = 0.0;
  Trace stepper, recorded;
};

SimulatedRun simulate_and_record(const RigParameters& rig, const FrictionLaw& law, double v, const SimulationOptions& opt) {
  SimulatedRun out;
  const SimulationResult r = simulate(rig, Drive::constant(v), law, opt);
  EXPECT_TRUE(r.summary.completed) << r.summary.message;
  out.window_start_s = analysis_start_s(0.0, r.summary.end_time_s);
  out.observables = summarise(rig, r.samples, r.events, out.window_start_s);
  for (const Sample& s : r.samples) out.stepper.t.push_back(s.t_s), out.stepper.x.push_back(s.x_m);
  std::mt19937_64 rng(7);
  const double h = std::numbers::pi / (20.0 * rig.damped_frequency_rad_per_s());
  std::normal_distribution<double> noise(0.0, 0.02 * v * 2.0 * h / std::sqrt(2.0));
  std::size_t j = 0;
  for (double t = 0.0; t < r.summary.end_time_s; t += 5e-4) {
    while (j + 2 < r.samples.size() && r.samples[j + 1].t_s <= t) ++j;
    const Sample &a = r.samples[j], &b = r.samples[j + 1];
    const double f = b.t_s > a.t_s ? (t - a.t_s) / (b.t_s - a.t_s) : 0.0;
    out.recorded.t.push_back(t);
    out.recorded.x.push_back(a.x_m + f * (b.x_m - a.x_m) + noise(rng));
  }
  return out;
}

// A run that never sticks, read from both recordings: no events, no stick, and `regime`.
void expect_continuous_slip_read_as(const RigParameters& rig, const SimulatedRun& run, double v, const char* regime) {
  for (const Trace* tr : {&run.stepper, &run.recorded}) {
    const RegimeEvidence e = recorded_regime_evidence(rig, tr->t, tr->x, v, run.window_start_s);
    EXPECT_EQ(e.breakaways + e.reattachments + e.reversals, 0);
    EXPECT_FALSE(e.sticks);
    EXPECT_EQ(classify_regime(rig, e), regime);
  }
}

// Coulomb stick-slip (the closed-form case of stick_slip_test.cpp): both recordings give the
// regime and the event counts the stepper's events give, within one cycle cut by the window's
// edges.
TEST(RecordedRegime, SimulatedStickSlipKeepsItsRegime) {
  RigParameters rig;
  const double mu_s = 0.3, mu_k = 0.2;
  SimulationOptions opt;
  opt.duration_s = 12.5 * reference::coulomb_stick_slip(rig, mu_s, mu_k, kV).period_s;
  const SimulatedRun run = simulate_and_record(rig, *make_coulomb(mu_s, mu_k), kV, opt);
  ASSERT_EQ(run.observables.regime, "stick_slip");
  for (const Trace* tr : {&run.stepper, &run.recorded}) {
    const RegimeEvidence e = recorded_regime_evidence(rig, tr->t, tr->x, kV, run.window_start_s);
    EXPECT_EQ(classify_regime(rig, e), "stick_slip");
    EXPECT_NEAR(e.breakaways, run.observables.breakaways, 1);
    EXPECT_NEAR(e.reattachments, run.observables.reattachments, 1);
    EXPECT_EQ(e.reversals, 0);
  }
}

// A kinetic curve falling at 3 r/W within ±5 mm/s of V = 0.1 m/s and flat beyond (thesis
// Appendix II: unstable steady sliding) grows an oscillation that saturates where the falling
// band no longer feeds it — a speed amplitude of ≈ 12/π × 5 mm/s ≈ 0.02 m/s (describing function),
// started there. u stays in ≈ [0.08, 0.12] m/s, never near the stick threshold: no events, and a
// persistent oscillation of ≈ 0.4 mm peak-to-peak, far above the noise floor (12 σ ≈ 50 µm).
TEST(RecordedRegime, SimulatedQuasiHarmonicOscillationKeepsItsRegime) {
  RigParameters rig;
  const double v = 0.1, band = 0.005, mu0 = 0.15;
  const double dmu = 3.0 * rig.damping_N_s_per_m / rig.normal_load_N * band;
  KineticCurveLaw law(0.5, std::make_shared<TabulatedCurve>(std::vector<double>{v - band, v + band},
                                                            std::vector<double>{mu0 + dmu, mu0 - dmu}));
  SimulationOptions opt;
  opt.duration_s = 10.0;
  opt.start_slipping = true;
  opt.initial_velocity_m_per_s = 0.02;
  opt.initial_displacement_m = mu0 * rig.normal_load_N / rig.stiffness_N_per_m;
  const SimulatedRun run = simulate_and_record(rig, law, v, opt);
  ASSERT_EQ(run.observables.regime, "quasi_harmonic");
  expect_continuous_slip_read_as(rig, run, v, "quasi_harmonic");
}

// Coulomb friction at 0.1 m/s, released onto the disc in steady sliding with a 0.1 mm/s kick: the
// kick decays at r/2M = 0.87 1/s, to 11 % between the window's halves. From the stepper's samples
// the decay decides (late < 90 % of early); on the noisy recording both halves are noise (the
// kick's ≈ 1 µm amplitude is down to ≈ 13 nm by the window), whose peak-to-peak persists but
// stays under the 12 σ floor — without the floor it would read as quasi-harmonic.
TEST(RecordedRegime, SimulatedSteadySlidingKeepsItsRegime) {
  RigParameters rig;
  const double v = 0.1;
  SimulationOptions opt;
  opt.duration_s = 10.0;
  opt.start_in_steady_sliding = true;
  const SimulatedRun run = simulate_and_record(rig, *make_coulomb(0.3, 0.2), v, opt);
  ASSERT_EQ(run.observables.regime, "steady_sliding");
  expect_continuous_slip_read_as(rig, run, v, "steady_sliding");
}

// White noise alone on a steady slider: its peak-to-peak is the same in both halves of the window
// (late ≥ 90 % of early about half the time), so only the noise floor keeps it steady sliding —
// in every one of 20 seeds. σ = 0.2 µm is a speed error of 9 % of V over the ±T_d/40 chord, clear
// of the 5 % / 20 % stick thresholds about u = V. The same noise on the quasi-harmonic sine of the
// test above (8 µm peak-to-peak, 40 σ) leaves it quasi-harmonic: the floor (12 σ) sits at the noise.
TEST(RecordedRegime, SensorNoiseIsNotAnOscillation) {
  RigParameters rig;
  const double sigma = 0.2e-6, w = 2.0 * std::numbers::pi * 20.0, a = 0.5 * kV / w;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    EXPECT_EQ(regime_of(rig, sample([&](double) { return 2e-5 + noise(rng); }, 2.0, 2e-4)), "steady_sliding") << "seed " << seed;
    EXPECT_EQ(regime_of(rig, sample([&](double t) { return a * std::sin(w * t) + noise(rng); }, 2.0, 2e-4)), "quasi_harmonic")
        << "seed " << seed;
  }
}

}  // namespace
}  // namespace tribo::rig
