// The EHL point contact (lubrication/ehl_point.h), the checks fast enough for the sanitizer build:
// the dry Hertz pressure at a high load, the load balance, bad input and a reported
// non-convergence. The film against the published fits and its grid convergence are in
// ehl_point_slow_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "lubrication/reference/ehl_point_film.h"
#include "tests/lubrication/ball_on_disc.h"

namespace tribo::lubrication {
namespace {

using namespace ball_on_disc;

// At 20 N (p_H = 0.83 GPa, Moes M ≈ 100) the film is thin against the deflection and the pressure
// is the dry contact's: Hertz's semi-ellipsoid across the flow through the centre, to 4 % of p_H
// within 0.7 a (31² nodes put 6 of them there; the film departs from Hertz at the inlet and the
// outlet's constriction, along x).
TEST(EhlPoint, HighLoadPressureIsHertzianAcrossTheFlow) {
  const double load = 20.0;
  const EhlPointResult r = solve_ehl_point(contact(load, 0.5), oil(), grid(31));
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.hertz_pressure_Pa, reference::hertz_point_peak_pressure_Pa(load, kRadius_m, kModulus_Pa), 1e-12 * r.hertz_pressure_Pa);
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  const std::size_t nx = r.x_m.size();
  std::size_t centre = 0;  // the column nearest x = 0
  for (std::size_t i = 0; i < nx; ++i)
    if (std::abs(r.x_m[i]) < std::abs(r.x_m[centre])) centre = i;
  ASSERT_LT(std::abs(r.x_m[centre]) / r.hertz_radius_m, 0.1);
  int inside = 0;
  for (std::size_t j = 0; j < r.y_m.size(); ++j) {
    const double y = r.y_m[j] / r.hertz_radius_m, x = r.x_m[centre] / r.hertz_radius_m;
    if (std::abs(y) > 0.7) continue;
    ++inside;
    EXPECT_NEAR(r.pressure_Pa[centre + nx * j] / r.hertz_pressure_Pa, std::sqrt(1.0 - x * x - y * y), 0.04) << "y/a = " << y;
  }
  EXPECT_GE(inside, 6);
  // The horseshoe: the minimum film lies below the central one.
  EXPECT_LT(r.minimum_film_m, r.central_film_m);
}

TEST(EhlPoint, BadInputIsRejectedAndNonConvergenceIsReported) {
  EXPECT_THROW(solve_ehl_point(contact(-1.0, 0.5), oil(), grid(21)), std::invalid_argument);
  EhlPointOptions narrow = grid(21);
  narrow.side_over_radius = 0.8;  // the Hertz circle does not fit
  EXPECT_THROW(solve_ehl_point(contact(2.0, 0.5), oil(), narrow), std::invalid_argument);
  EXPECT_THROW(solve_ehl_point(contact(2.0, 0.5), oil(), grid(9)), std::invalid_argument);
  EhlPointOptions starved = grid(21);
  starved.max_newton_iterations = 1;
  starved.max_continuation_steps = 0;
  const EhlPointResult r = solve_ehl_point(contact(2.0, 0.5), oil(), starved);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, starved.tolerance);
  EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace tribo::lubrication
