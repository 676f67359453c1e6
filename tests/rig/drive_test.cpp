// Drive histories: exact displacement of piecewise-linear speed, a stuck slider following a
// velocity step (load-rate change at the step, thesis 3.1.20 φ̇ = k v / W while stuck), one
// breaking away just before a hold, and a slipping one re-locked by a step.
#include <gtest/gtest.h>

#include <cmath>

#include "rig/drive.h"
#include "rig/kinetic_laws.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

TEST(Drive, DisplacementIsTheExactIntegralOfPiecewiseLinearSpeed) {
  const Drive d = Drive::table({0.0, 1.0, 3.0}, {0.0, 2.0, 0.0});
  EXPECT_DOUBLE_EQ(d.displacement_m(1.0), 1.0);   // triangle ½·1·2
  EXPECT_DOUBLE_EQ(d.displacement_m(3.0), 3.0);   // + ½·2·2
  EXPECT_DOUBLE_EQ(d.displacement_m(5.0), 3.0);   // speed 0 beyond the table
  EXPECT_DOUBLE_EQ(d.speed_m_per_s(2.0), 1.0);
  EXPECT_DOUBLE_EQ(d.acceleration_m_per_s2(2.0), -1.0);
}

TEST(Drive, SlideHoldSlideStopsTheDriveDuringTheHold) {
  const Drive d = Drive::slide_hold_slide(1e-3, 2.0, 3.0);
  EXPECT_DOUBLE_EQ(d.speed_m_per_s(3.0), 0.0);
  EXPECT_DOUBLE_EQ(d.displacement_m(6.0), 1e-3 * 3.0);
}

TEST(Drive, RejectsNegativeSpeedAndUnorderedTimes) {
  EXPECT_THROW(Drive::constant(-1e-3), std::invalid_argument);
  EXPECT_THROW(Drive::steps({0.0, 2.0, 1.0}, {1.0, 2.0, 3.0}), std::invalid_argument);
  EXPECT_THROW(Drive::steps({0.5}, {1.0}), std::invalid_argument);
}

TEST(Drive, StuckSliderBreaksAwayWhenTheSpringReachesMuSW) {
  // Steps 1 → 3 mm/s at t = 0.5 s; breakaway at k x + r v = μs W, x = ∫v dt.
  const RigParameters rig;
  const Drive d = Drive::steps({0.0, 0.5}, {1e-3, 3e-3});
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions opt;
  opt.duration_s = 2.0;
  const SimulationResult r = simulate(rig, d, *law, opt);
  ASSERT_TRUE(r.summary.completed);
  ASSERT_FALSE(r.events.empty());
  const Event& e = r.events.front();
  ASSERT_EQ(e.kind, EventKind::breakaway);
  const double x_s = (0.3 * rig.normal_load_N - rig.damping_N_s_per_m * 3e-3) / rig.stiffness_N_per_m;
  const double t_expected = 0.5 + (x_s - 0.5e-3) / 3e-3;
  EXPECT_NEAR(e.t_s, t_expected, 1e-8);
  EXPECT_NEAR(e.load_rate_per_s, rig.stiffness_N_per_m * 3e-3 / rig.normal_load_N, 1e-12);
}

// The spring reaches k x + r v = μs W shortly before a hold; from the hold on the damper's r v is
// gone and k x alone stays below μs W. The breakaway is at the closed-form time all the same: the
// integrator's last step of the slide ends on the hold's start, where the event functions see the
// slide's drive (its left limit), not the hold's. One output instant per run, so that no output
// instant inside the slide finds the crossing instead.
TEST(Drive, AStuckSliderBreaksAwayJustBeforeAHoldThatWouldHaveHeldIt) {
  const RigParameters rig;
  const double v = 1e-3, mu_s = 0.3;
  const double x_s = (mu_s * rig.normal_load_N - rig.damping_N_s_per_m * v) / rig.stiffness_N_per_m;
  const double t_break = x_s / v, t_hold = t_break + 0.5 * rig.damping_N_s_per_m / rig.stiffness_N_per_m;
  ASSERT_LT(rig.stiffness_N_per_m * v * t_hold, mu_s * rig.normal_load_N);  // the hold alone would hold it
  const Drive d = Drive::slide_hold_slide(v, t_hold, 1.0);
  auto law = make_coulomb(mu_s, 0.2);
  SimulationOptions opt;
  opt.duration_s = t_hold + 0.5;
  opt.stick_samples_per_run = 1;
  const SimulationResult r = simulate(rig, d, *law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  ASSERT_FALSE(r.events.empty());
  EXPECT_EQ(r.events.front().kind, EventKind::breakaway);
  EXPECT_NEAR(r.events.front().t_s, t_break, 1e-8);
  // By the segment's formula at its end: the slide's speed, at the breakpoint and in it.
  EXPECT_DOUBLE_EQ(d.speed_m_per_s(t_hold, d.segment_at(0.0)), v);
  EXPECT_DOUBLE_EQ(d.speed_m_per_s(t_hold), 0.0);
}

// A re-attachment that falls on a velocity step: the drive steps 1 → 2 mm/s where a run at 1 mm/s
// first re-attaches, give or take a few times the root finder's tolerance, so that some of these
// runs locate the event on CVODE's stop time itself. The slider then sticks and must move with the
// new speed, as after any step: every stuck sample after the step has ẋ = v(t).
TEST(Drive, AStuckSliderFollowsAVelocityStepThatFallsOnItsReattachment) {
  const RigParameters rig;
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions opt;
  opt.duration_s = 3.0;
  const SimulationResult at_one_speed = simulate(rig, Drive::constant(1e-3), *law, opt);
  double t_reattach = -1.0;
  for (const Event& e : at_one_speed.events)
    if (e.kind == EventKind::reattach) {
      t_reattach = e.t_s;
      break;
    }
  ASSERT_GT(t_reattach, 0.0);
  for (int k = -8; k <= 8; ++k) {
    const double t_step = t_reattach * (1.0 + 2e-15 * k);
    const SimulationResult r = simulate(rig, Drive::steps({0.0, t_step}, {1e-3, 2e-3}), *law, opt);
    ASSERT_TRUE(r.summary.completed) << r.summary.message;
    int stuck_after = 0, off = 0;
    for (const Sample& s : r.samples) {
      if (s.phase != Phase::stick || !(s.t_s > t_step)) continue;
      ++stuck_after;
      off += std::abs(s.xdot_m_per_s - 2e-3) > 1e-12 ? 1 : 0;
    }
    EXPECT_GT(stuck_after, 100) << "step at t_reattach × (1 + " << 2e-15 * k << ")";
    EXPECT_EQ(off, 0) << "step at t_reattach × (1 + " << 2e-15 * k << ")";
  }
}

// SimulationOptions::relock_at_drive_steps: sliding steadily at 0.1 m/s, the drive steps to 0.2 m/s
// at t = 1 s; the contact re-locks there (event `relock` at the step), the slider moves with the
// drive, x = x(1) + v₂ (t − 1), and breaks away where k x + r v₂ = μs W — the same closed form as
// a stuck start. Without the option the slider slips on through the step.
TEST(Drive, RelockAtADriveStepSticksUntilTheSpringReachesMuSW) {
  const RigParameters rig;
  const Drive d = Drive::steps({0.0, 1.0}, {0.1, 0.2});
  auto law = make_coulomb(0.3, 0.2);
  SimulationOptions opt;
  opt.duration_s = 1.5;
  opt.start_in_steady_sliding = true;
  opt.relock_at_drive_steps = true;
  const SimulationResult r = simulate(rig, d, *law, opt);
  ASSERT_TRUE(r.summary.completed) << r.summary.message;
  ASSERT_GE(r.events.size(), 2u);
  const Event& relock = r.events[0];
  ASSERT_EQ(relock.kind, EventKind::relock);
  EXPECT_DOUBLE_EQ(relock.t_s, 1.0);
  EXPECT_NEAR(relock.mu, 0.2, 1e-12);  // it was slipping on the kinetic level
  const Event& breakaway = r.events[1];
  ASSERT_EQ(breakaway.kind, EventKind::breakaway);
  const double x_s = (0.3 * rig.normal_load_N - rig.damping_N_s_per_m * 0.2) / rig.stiffness_N_per_m;
  EXPECT_NEAR(breakaway.t_s, 1.0 + (x_s - relock.x_m) / 0.2, 1e-8);

  opt.relock_at_drive_steps = false;
  for (const Event& e : simulate(rig, d, *law, opt).events) EXPECT_NE(e.kind, EventKind::relock);
}

}  // namespace
}  // namespace tribo::rig
