// The CVODE wrapper (numerics/cvode.h): a closed-form solution within its tolerance, and a failure
// reported through advance()'s flag with CVODE's own message kept, not printed.
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

}  // namespace
}  // namespace tribo::numerics
