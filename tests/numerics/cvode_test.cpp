// The CVODE wrapper (numerics/cvode.h): a closed-form solution within its tolerance, a failure
// reported through advance()'s flag with CVODE's own message kept, not printed, and one-step
// integration with interpolated output giving what advance() gives.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "numerics/cvode.h"

namespace tribo::numerics {
namespace {

// y' = y², y(0) = 1: y = 1 / (1 − t), which blows up at t = 1.
int blow_up(sunrealtype, N_Vector y, N_Vector ydot, void*) {
  NV_Ith_S(ydot, 0) = NV_Ith_S(y, 0) * NV_Ith_S(y, 0);
  return 0;
}

TEST(Cvode, FollowsTheClosedFormAndKeepsItsMessageWhenTheSolutionBlowsUp) {
  const std::vector<double> y0{1.0};
  Cvode cv(blow_up, nullptr, CvodeSettings{CvodeSettings::Method::bdf, 1e-8, {1e-12}, 5000}, 0.0, y0);
  double t = 0.0;
  ASSERT_EQ(cv.advance(0.5, t), CV_SUCCESS);
  // Local error 1e-8 per step, accumulated over a few hundred steps: 1e-6 relative is generous.
  EXPECT_NEAR(cv.state()[0], 2.0, 2.0 * 1e-6);
  EXPECT_TRUE(cv.last_message().empty()) << cv.last_message();

  const int flag = cv.advance(2.0, t);  // past the singularity
  EXPECT_LT(flag, 0) << Cvode::describe(flag);
  EXPECT_LT(t, 1.0);
  EXPECT_GT(t, 0.99);
  // CVODE's text names where it stopped and why ("At t = 1, mxstep steps taken before reaching tout.").
  EXPECT_EQ(cv.last_message().rfind("At t = ", 0), 0u) << cv.last_message();
  EXPECT_NE(cv.last_message().find("mxstep"), std::string::npos) << cv.last_message();
}

// The undamped oscillator y'' = −y, y(0) = 1, y'(0) = 0: y = cos t, whose first downward zero is
// at π/2.
int oscillator(sunrealtype, N_Vector y, N_Vector ydot, void*) {
  NV_Ith_S(ydot, 0) = NV_Ith_S(y, 1);
  NV_Ith_S(ydot, 1) = -NV_Ith_S(y, 0);
  return 0;
}
int position(sunrealtype, N_Vector y, sunrealtype* g, void*) {
  g[0] = NV_Ith_S(y, 0);
  return 0;
}

TEST(Cvode, OneStepWithInterpolatedOutputGivesWhatAdvanceGivesAndTheSameRoot) {
  const std::vector<double> y0{1.0, 0.0};
  const CvodeSettings settings{CvodeSettings::Method::adams, 1e-9, {1e-12, 1e-12}, 5000};
  const std::vector<int> down{-1};
  const double dt = 0.01;  // output spacing, several to a step at this tolerance
  Cvode normal(oscillator, nullptr, settings, 0.0, y0), stepped(oscillator, nullptr, settings, 0.0, y0);
  normal.set_roots(position, down);
  stepped.set_roots(position, down);

  std::vector<double> by_advance, by_step;
  double t = 0.0, t_root_advance = 0.0;
  for (int k = 1;; ++k) {
    const int flag = normal.advance(k * dt, t);
    ASSERT_GE(flag, 0) << Cvode::describe(flag);
    if (flag == CV_ROOT_RETURN) {
      t_root_advance = t;
      break;
    }
    by_advance.push_back(normal.state()[0]);
  }
  double t_step = 0.0, next = dt, t_root_step = 0.0;
  std::vector<double> y(2);
  long steps = 0;
  for (;;) {
    const int flag = stepped.step(next, t_step);
    ASSERT_GE(flag, 0) << Cvode::describe(flag);
    ++steps;
    const bool root = flag == CV_ROOT_RETURN;
    for (; root ? next < t_step : next <= t_step; next += dt) {
      stepped.interpolate(next, y);
      by_step.push_back(y[0]);
    }
    if (root) {
      t_root_step = t_step;
      break;
    }
  }
  // The same steps (the first bounded by the same first output time), so the same polynomial at
  // each output instant: equal to round-off.
  ASSERT_EQ(by_step.size(), by_advance.size());
  for (std::size_t i = 0; i < by_step.size(); ++i) EXPECT_NEAR(by_step[i], by_advance[i], 1e-14) << "output " << i;
  // Both within the tolerance of cos t (1e-9 per step over a few dozen steps).
  for (std::size_t i = 0; i < by_step.size(); ++i) EXPECT_NEAR(by_step[i], std::cos((static_cast<double>(i) + 1.0) * dt), 1e-7);
  // The root, searched over whole steps instead of output intervals: π/2 within the tolerance.
  EXPECT_NEAR(t_root_step, std::acos(0.0), 1e-7);
  EXPECT_NEAR(t_root_step, t_root_advance, 1e-9);
  // Output denser than the steps is what makes step() pay: fewer steps than output instants.
  EXPECT_LT(steps, static_cast<long>(by_step.size()));
}

}  // namespace
}  // namespace tribo::numerics
