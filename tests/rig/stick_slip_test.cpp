// Classic stick-slip with constant μs > μk at constant drive speed, against the closed form
// (rig/reference/closed_forms.h), and the energy balance over a cycle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "rig/friction_model.h"
#include "rig/kinetic_laws.h"
#include "rig/observables.h"
#include "rig/reference/closed_forms.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

struct Case {
  double damping_N_s_per_m;
  double drive_speed_m_per_s;
};

class StickSlipClosedForm : public ::testing::TestWithParam<Case> {};

TEST_P(StickSlipClosedForm, AmplitudePeriodAndStickTimeMatch) {
  RigParameters rig;
  rig.damping_N_s_per_m = GetParam().damping_N_s_per_m;
  const double v = GetParam().drive_speed_m_per_s, mu_s = 0.3, mu_k = 0.2;
  const auto ref = reference::coulomb_stick_slip(rig, mu_s, mu_k, v);
  SimulationOptions opt;
  opt.duration_s = 6.5 * ref.period_s;
  auto law = make_coulomb(mu_s, mu_k);
  const SimulationResult r = simulate(rig, Drive::constant(v), *law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  // From the first breakaway on, every cycle is the steady one.
  const RunObservables o = summarise(rig, r.samples, r.events, r.events.front().t_s);
  EXPECT_EQ(o.regime, "stick_slip");
  // Period and stick time come from located events (≈1e-9 relative); the peak-to-peak is read
  // off samples spaced 2π/(200 ω_n), whose error at an extremum is ≤ (π/200)²/2 ≈ 1.2e-4.
  EXPECT_NEAR(o.period_s, ref.period_s, 1e-6 * ref.period_s);
  EXPECT_NEAR(o.stick_time_s, ref.stick_time_s, 1e-6 * ref.stick_time_s);
  EXPECT_NEAR(o.slip_time_s, ref.slip_time_s, 1e-6 * ref.slip_time_s);
  EXPECT_NEAR(o.peak_to_peak_m, ref.peak_to_peak_m, 2e-4 * ref.peak_to_peak_m);
  EXPECT_NEAR(o.mu_s_mean, mu_s, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(UndampedAndThesisDamping, StickSlipClosedForm,
                         ::testing::Values(Case{0.0, 1e-3}, Case{0.0, 2e-2}, Case{1.7338, 1e-3}, Case{1.7338, 5e-3}));

TEST(StickSlip, UndampedClosedFormIsTheTextbookFormula) {
  // The formula: peak-to-peak 2Δ, period 2Δ/v + (π + 2 atan(v/(ω_n Δ)))/ω_n, Δ = (μs−μk)W/k.
  RigParameters rig;
  rig.damping_N_s_per_m = 0.0;
  const double v = 1e-3, W = rig.normal_load_N, k = rig.stiffness_N_per_m, wn = rig.natural_frequency_rad_per_s();
  const double delta = 0.1 * W / k;
  const auto ref = reference::coulomb_stick_slip(rig, 0.3, 0.2, v);
  EXPECT_NEAR(ref.period_s, 2 * delta / v + (M_PI + 2 * std::atan(v / (wn * delta))) / wn, 1e-10);
  EXPECT_NEAR(ref.peak_to_peak_m, 2 * std::hypot(delta, v / wn), 1e-12);
  EXPECT_NEAR(ref.peak_to_peak_m, 2 * delta, 1e-4 * 2 * delta);  // v/(ω_n Δ) = 0.011 here
}

TEST(StickSlip, FrictionWorkEqualsDampingDissipationOverACycle) {
  // Energy E = ½Mẋ² + ½kx² returns to its value after a full cycle, so ∮F ẋ dt = ∮r ẋ² dt.
  RigParameters rig;
  rig.damping_N_s_per_m = 20.0;  // larger than the thesis rig so the balance is not trivially small
  const double v = 5e-3;
  const auto ref = reference::coulomb_stick_slip(rig, 0.3, 0.2, v);
  SimulationOptions opt;
  opt.duration_s = 4.5 * ref.period_s;
  opt.samples_per_period = 2000;
  opt.stick_samples_per_run = 20000;
  auto law = make_coulomb(0.3, 0.2);
  const SimulationResult r = simulate(rig, Drive::constant(v), *law, opt);
  ASSERT_TRUE(r.summary.completed);
  std::vector<double> breakaways;
  for (const Event& e : r.events) {
    if (e.kind == EventKind::breakaway) breakaways.push_back(e.t_s);
  }
  ASSERT_GE(breakaways.size(), 3u);
  const double t0 = breakaways[1], t1 = breakaways[2];
  double friction_work = 0.0, damping_work = 0.0, gross = 0.0;
  for (std::size_t i = 1; i < r.samples.size(); ++i) {
    const Sample &a = r.samples[i - 1], &b = r.samples[i];
    if (a.t_s < t0 || b.t_s > t1) continue;
    const double dt = b.t_s - a.t_s;
    // A sample at an event holds the state before the switch; on [a, b] the new phase's force acts:
    // constant μk W in a Coulomb slip, k x + r v on entering a stick.
    const double fa = a.phase == b.phase          ? a.friction_N
                      : b.phase == Phase::slip    ? b.friction_N
                                                  : rig.stiffness_N_per_m * a.x_m + rig.damping_N_s_per_m * v;
    friction_work += 0.5 * (fa * a.xdot_m_per_s + b.friction_N * b.xdot_m_per_s) * dt;
    damping_work += 0.5 * rig.damping_N_s_per_m * (a.xdot_m_per_s * a.xdot_m_per_s + b.xdot_m_per_s * b.xdot_m_per_s) * dt;
    gross += 0.5 * std::abs(fa * a.xdot_m_per_s + b.friction_N * b.xdot_m_per_s) * dt;
  }
  // Trapezoid error with 2000 samples per period: (2π/2000)²/12 ≈ 1e-6 of the gross work.
  EXPECT_NEAR(friction_work, damping_work, 1e-5 * gross);
  EXPECT_GT(damping_work, 1e-3 * gross);
}

// SimulationOptions::stop_after_events ends a run, completed, at its tenth event — the fifth
// re-attachment, one slip time after the fifth breakaway: the first breakaway when spring and
// damper, stuck at ẋ = v from x = 0, reach μs W (k v t + c v = μs W), then one closed-form period
// per cycle — and what it
// simulated is the whole run's prefix to the bit (the integration is causal).
TEST(StickSlip, ARunStoppedAfterItsEventsIsThePrefixOfTheWholeRun) {
  const RigParameters rig;
  const double v = 5e-3, mu_s = 0.3, mu_k = 0.2;
  const auto ref = reference::coulomb_stick_slip(rig, mu_s, mu_k, v);
  auto law = make_coulomb(mu_s, mu_k);
  SimulationOptions whole;
  whole.duration_s = 20.0 * ref.period_s;
  SimulationOptions stopped = whole;
  stopped.stop_after_events = 10;
  const SimulationResult full = simulate(rig, Drive::constant(v), *law, whole);
  const SimulationResult part = simulate(rig, Drive::constant(v), *law, stopped);
  ASSERT_TRUE(full.summary.completed) << full.summary.message;
  ASSERT_TRUE(part.summary.completed) << part.summary.message;
  ASSERT_EQ(part.events.size(), 10u);
  EXPECT_EQ(part.events.back().kind, EventKind::reattach);
  const double t_first = (mu_s * rig.normal_load_N - rig.damping_N_s_per_m * v) / (rig.stiffness_N_per_m * v);
  // Events are located to CVODE's root tolerance, ≈ 1e-9 of a period (the closed-form test above).
  EXPECT_NEAR(part.summary.end_time_s, t_first + 4.0 * ref.period_s + ref.slip_time_s, 1e-6 * ref.period_s);
  EXPECT_EQ(part.summary.end_time_s, part.events.back().t_s);
  ASSERT_LT(part.samples.size(), full.samples.size());
  for (std::size_t i = 0; i < part.samples.size(); ++i) {
    ASSERT_EQ(part.samples[i].t_s, full.samples[i].t_s) << "sample " << i;
    ASSERT_EQ(part.samples[i].x_m, full.samples[i].x_m) << "sample " << i;
    ASSERT_EQ(part.samples[i].friction_N, full.samples[i].friction_N) << "sample " << i;
  }
  EXPECT_GT(full.samples[part.samples.size()].t_s, part.summary.end_time_s);
}

// SimulationOptions::settle_window_periods: after the breakaway a viscous slope c damps the swing
// at (r + c)/2M ≈ 21 1/s; the first window of 20 natural periods (1.2 s) still holds it (its mean
// friction is c Δx / window ≈ 0.04 N off the steady level, Δx the spring's relaxation), the second
// and third agree to e^{−25}, so the run settles when the third window closes: three windows after
// the first slip sample, on the slip grid. Stopped there, the run is the whole run's prefix to the
// bit, and the whole run reports the same instant; the level is the steady μk W + c v.
TEST(SteadySliding, ARunEndsWhereItSettledAndIsThePrefixOfTheWholeRun) {
  const RigParameters rig;
  const double v = 0.05, c = 40.0;
  FrictionModel model = coulomb(0.3, 0.15);
  model.set("viscous_friction", "coefficient_N_s_per_m", c);
  const auto law = make_friction_law(model);
  SimulationOptions whole;
  whole.duration_s = 20.0;
  whole.settle_window_periods = 20.0;
  SimulationOptions stopped = whole;
  stopped.stop_when_settled = true;
  const SimulationResult full = simulate(rig, Drive::constant(v), *law, whole);
  const SimulationResult part = simulate(rig, Drive::constant(v), *law, stopped);
  ASSERT_TRUE(full.summary.completed) << full.summary.message;
  ASSERT_TRUE(part.summary.completed) << part.summary.message;
  ASSERT_EQ(full.events.size(), 1u);
  const double period = 2.0 * std::numbers::pi / rig.natural_frequency_rad_per_s();
  const double dt = period / whole.samples_per_period, window = 20.0 * period;
  const double first_slip_sample = full.events[0].t_s + dt;
  EXPECT_GE(part.summary.settled_at_s, first_slip_sample + 3.0 * window - 1e-9);
  EXPECT_LE(part.summary.settled_at_s, first_slip_sample + 3.0 * window + 3.0 * dt);  // a window closes on a sample
  EXPECT_EQ(full.summary.settled_at_s, part.summary.settled_at_s);
  EXPECT_EQ(part.summary.end_time_s, part.summary.settled_at_s);
  EXPECT_NE(part.summary.message.find("settled"), std::string::npos) << part.summary.message;
  ASSERT_LT(part.samples.size(), full.samples.size());
  for (std::size_t i = 0; i < part.samples.size(); ++i) {
    ASSERT_EQ(part.samples[i].t_s, full.samples[i].t_s) << "sample " << i;
    ASSERT_EQ(part.samples[i].friction_N, full.samples[i].friction_N) << "sample " << i;
  }
  // The swing is e^{−21 × 3.6} of its 12-N start by then: the steady level to CVODE's tolerance.
  EXPECT_NEAR(part.samples.back().friction_N, 0.15 * rig.normal_load_N + c * v, 1e-6 * rig.normal_load_N);
}

// Stick-slip never settles, however long its stick: here 18 s of stick (2(μs − μk)W/(k v)) against
// a 1.2-s window, and slips of half a period. A run asked to stop when settled runs its duration.
TEST(SteadySliding, SlowStickSlipNeverCountsAsSettled) {
  const RigParameters rig;
  const double v = 1e-4, mu_s = 0.3, mu_k = 0.2;
  auto law = make_coulomb(mu_s, mu_k);
  SimulationOptions o;
  o.duration_s = 100.0;
  o.settle_window_periods = 20.0;
  o.stop_when_settled = true;
  const SimulationResult r = simulate(rig, Drive::constant(v), *law, o);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  EXPECT_GE(r.events.size(), 8u);  // 5 cycles of ≈ 18 s after the first breakaway at ≈ 27 s
  EXPECT_TRUE(std::isnan(r.summary.settled_at_s));
  EXPECT_EQ(r.summary.end_time_s, o.duration_s);
}

TEST(StickSlip, EventRateOptionsAreChecked) {
  const RigParameters rig;
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions o;
  o.max_event_rate_per_s = -1.0;
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
  o.max_event_rate_per_s = std::numeric_limits<double>::infinity();
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
  o.max_event_rate_per_s = 10.0;
  o.events_before_rate_limit = -1;
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
}

// The integrator's work between two output instants is bounded: a run that would need more steps
// than max_steps_per_output to reach the next one stops, says CV_TOO_MUCH_WORK and where, and is
// not completed. A slip on the thesis rig takes tens of steps between slip samples at 200 a period
// (samples_per_period); four is too few. The bound itself is checked.
TEST(StickSlip, ARunThatCrawlsBetweenOutputInstantsStopsAndSaysSo) {
  const RigParameters rig;
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions o;
  o.duration_s = 2.0;
  o.max_steps_per_output = 4;
  const SimulationResult r = simulate(rig, Drive::constant(1e-2), *law, o);
  EXPECT_FALSE(r.summary.completed);
  EXPECT_NE(r.summary.message.find("CV_TOO_MUCH_WORK"), std::string::npos) << r.summary.message;
  EXPECT_NE(r.summary.message.find("4 steps without reaching the next output instant"), std::string::npos) << r.summary.message;
  EXPECT_LT(r.summary.end_time_s, o.duration_s);
  o.max_steps_per_output = 200'000;
  EXPECT_TRUE(simulate(rig, Drive::constant(1e-2), *law, o).summary.completed);
  o.max_steps_per_output = 0;
  EXPECT_THROW(simulate(rig, Drive::constant(1e-2), *law, o), std::invalid_argument);
}

TEST(SteadySliding, SettleOptionsAreChecked) {
  const RigParameters rig;
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions o;
  o.stop_when_settled = true;  // without a window
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
  o.settle_window_periods = -1.0;
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
  o.settle_window_periods = 10.0;
  o.settle_tolerance_fraction = 0.0;
  EXPECT_THROW(simulate(rig, Drive::constant(1e-3), *law, o), std::invalid_argument);
}

// At a re-attachment the friction drops from μk W to the spring's pull, (2μk − μs) W undamped
// (the slider swings symmetrically about μk W/k), and rises at k v in the stick that follows. The
// first stick sample comes one slip spacing (2π/ω_n / samples_per_period) after the event, so the
// sampled trough is that pull to within k v times the spacing — before, the interpolant from the
// event's own sample (μk W) spread the drop over a whole stick spacing (duration / stick samples:
// here 20 periods / 400, about 60 slip spacings).
TEST(StickSlip, TheFirstStickSampleReadsTheSpringsPullAtTheReattachment) {
  RigParameters rig;
  rig.damping_N_s_per_m = 0.0;
  const double v = 5e-3, mu_s = 0.3, mu_k = 0.2, W = rig.normal_load_N, k = rig.stiffness_N_per_m;
  const auto ref = reference::coulomb_stick_slip(rig, mu_s, mu_k, v);
  SimulationOptions opt;
  opt.duration_s = 20.0 * ref.period_s;
  opt.stick_samples_per_run = 400;
  auto law = make_coulomb(mu_s, mu_k);
  const SimulationResult r = simulate(rig, Drive::constant(v), *law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  const double dt_slip = 2.0 * M_PI / rig.natural_frequency_rad_per_s() / opt.samples_per_period;
  ASSERT_GT(opt.duration_s / opt.stick_samples_per_run, 50.0 * dt_slip);  // a stick spacing far coarser
  int reattachments = 0;
  for (const Event& e : r.events) {
    if (e.kind != EventKind::reattach) continue;
    const auto next = std::upper_bound(r.samples.begin(), r.samples.end(), e.t_s, [](double t, const Sample& s) { return t < s.t_s; });
    ASSERT_NE(next, r.samples.end());
    EXPECT_NEAR(next->t_s - e.t_s, dt_slip, 1e-9 * ref.period_s);
    EXPECT_EQ(next->phase, Phase::stick);
    // The pull at the event, plus k v over the spacing; CVODE's error ≈ 1e-10 of W here.
    EXPECT_NEAR(next->friction_N, (2.0 * mu_k - mu_s) * W + k * v * dt_slip, 1e-6 * W) << "t = " << e.t_s;
    ++reattachments;
  }
  EXPECT_GE(reattachments, 19);
}

// A recorder's instants (SimulationOptions::output_times_s) replace the output grid and leave the
// solution alone: samples only at listed instants and events; in every stick the slider rides
// the surface, x = x_reattach + v (t − t_reattach) exactly; and listing more instants moves no
// shared sample beyond CVODE's interpolation error (≈ 1e-9 of the stick-slip amplitude here).
TEST(StickSlip, RecorderInstantsReplaceTheGridWithoutMovingTheSolution) {
  const RigParameters rig;
  const double v = 5e-3;
  const auto ref = reference::coulomb_stick_slip(rig, 0.3, 0.2, v);
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions opt;
  opt.duration_s = 3.5 * ref.period_s;
  for (double t = 0.0; t <= opt.duration_s; t += 7e-3) opt.output_times_s.push_back(t);  // 7 ms: no multiple of the cycle
  const SimulationResult coarse = simulate(rig, Drive::constant(v), *law, opt);
  ASSERT_TRUE(coarse.summary.completed) << coarse.summary.message;
  std::vector<double> event_times;
  for (const Event& e : coarse.events) event_times.push_back(e.t_s);
  ASSERT_GE(event_times.size(), 5u);
  int in_stick = 0;
  double t_reattach = -1.0, x_reattach = 0.0;
  for (const Sample& s : coarse.samples) {
    const bool listed = std::binary_search(opt.output_times_s.begin(), opt.output_times_s.end(), s.t_s);
    const bool at_event = std::count(event_times.begin(), event_times.end(), s.t_s) > 0;
    EXPECT_TRUE(listed || at_event || s.t_s == opt.duration_s) << "sample at t = " << s.t_s;
    if (at_event && s.phase == Phase::slip) t_reattach = s.t_s, x_reattach = s.x_m;  // the state before the switch to stick
    if (listed && s.phase == Phase::stick && t_reattach >= 0.0) {
      EXPECT_NEAR(s.x_m, x_reattach + v * (s.t_s - t_reattach), 1e-12 * ref.peak_to_peak_m) << "t = " << s.t_s;
      ++in_stick;
    }
  }
  EXPECT_GT(in_stick, 80);  // 103 of the 7-ms instants fall in sticks

  SimulationOptions finer = opt;
  for (double t = 3.3e-3; t <= opt.duration_s; t += 7e-3) finer.output_times_s.push_back(t);
  std::sort(finer.output_times_s.begin(), finer.output_times_s.end());
  const SimulationResult fine = simulate(rig, Drive::constant(v), *law, finer);
  ASSERT_TRUE(fine.summary.completed);
  ASSERT_EQ(fine.events.size(), coarse.events.size());
  for (std::size_t i = 0; i < coarse.events.size(); ++i) EXPECT_NEAR(fine.events[i].t_s, coarse.events[i].t_s, 1e-9 * ref.period_s);
  int shared = 0;
  for (const Sample& s : coarse.samples) {
    const auto it = std::find_if(fine.samples.begin(), fine.samples.end(), [&](const Sample& f) { return f.t_s == s.t_s; });
    if (it == fine.samples.end()) continue;
    EXPECT_NEAR(it->x_m, s.x_m, 1e-9 * ref.peak_to_peak_m) << "t = " << s.t_s;
    ++shared;
  }
  EXPECT_GE(shared, static_cast<int>(opt.output_times_s.size()));

  opt.output_times_s = {0.1, 0.05};
  try {
    simulate(rig, Drive::constant(v), *law, opt);
    FAIL() << "decreasing output times accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("output_times_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::rig
