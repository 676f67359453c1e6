// The Stribeck curve `tribo homogenise` writes into law.json (issue 38 item 1, no silent answer):
// a steady-sliding point that did not converge is left out and listed with its reason, and the
// curve stops, saying so, where the film would leave the table.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "apps/homogenise_run.h"

namespace tribo::cli {
namespace {

rig::SteadySliding point(double u, bool converged) {
  rig::SteadySliding s;
  s.speed_m_per_s = u;
  s.mu = 0.1 * u;
  s.converged = converged;
  if (!converged) s.message = "force balance residual 3e-2 N after 60 iterations";
  return s;
}

TEST(StribeckCurve, AnUnconvergedPointIsLeftOutAndListedWithItsReason) {
  const StribeckCurve c = stribeck_curve({1.0, 2.0, 3.0, 4.0, 5.0}, [](double u) {
    if (u == 4.0) throw std::out_of_range("lift carries W above the largest separation");
    return point(u, u != 2.0);
  });
  ASSERT_EQ(c.points.size(), 2u);  // 1 and 3: not 2 (unconverged), nothing from 4 on
  EXPECT_EQ(c.points[0].speed_m_per_s, 1.0);
  EXPECT_EQ(c.points[1].speed_m_per_s, 3.0);
  ASSERT_EQ(c.unconverged.size(), 2u);
  EXPECT_EQ(c.unconverged[0]["U_m_per_s"].get<double>(), 2.0);
  EXPECT_EQ(c.unconverged[0]["reason"].get<std::string>(), "force balance residual 3e-2 N after 60 iterations");
  EXPECT_EQ(c.unconverged[1]["U_m_per_s"].get<double>(), 4.0);
  EXPECT_NE(c.unconverged[1]["reason"].get<std::string>().find("the curve stops here"), std::string::npos);
}

TEST(StribeckCurve, AllConvergedListsNothing) {
  const StribeckCurve c = stribeck_curve({1.0, 2.0}, [](double u) { return point(u, true); });
  EXPECT_EQ(c.points.size(), 2u);
  EXPECT_TRUE(c.unconverged.empty());
}

}  // namespace
}  // namespace tribo::cli
