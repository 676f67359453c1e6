// The EHL line contact (lubrication/ehl_line.h), the checks fast enough for the sanitizer build:
// the dry Hertz pressure at high load, bad input and a reported non-convergence. The film against
// Martin's closed form and the published fits is ehl_line_slow_test.cpp (dense Newton steps take
// minutes without optimisation).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "lubrication/ehl_line.h"
#include "lubrication/reference/ehl_film.h"
#include "steel_roller_pair.h"

namespace tribo::lubrication {
namespace {

using namespace steel_rollers;

// At a high load (W = w/(E'R) = 1.3e-3, p_H ≈ 3.3 GPa) the film is thin against the deflection and
// the pressure is the dry contact's: Hertz's semi-ellipse inside the contact to 3 % of p_H (the
// film's pressure departs from it only at the inlet and at the outlet spike).
TEST(EhlLine, HighLoadPressureIsHertzian) {
  const double w = 3e6;
  const EhlLineResult r = solve_ehl_line({w, kRadius_m, kModulus_Pa, kSpeed_m_per_s}, mineral_oil());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.hertz_pressure_Pa, reference::hertz_line_peak_pressure_Pa(w, kRadius_m, kModulus_Pa), 1e-9 * r.hertz_pressure_Pa);
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  int inside = 0;
  for (std::size_t i = 0; i < r.x_m.size(); ++i) {
    const double x = r.x_m[i] / r.hertz_half_width_m;
    if (std::abs(x) > 0.7) continue;
    ++inside;
    EXPECT_NEAR(r.pressure_Pa[i] / r.hertz_pressure_Pa, std::sqrt(1.0 - x * x), 0.03) << "x/b = " << x;
  }
  EXPECT_GT(inside, 50);
  // The film is nearly parallel there: the minimum (at the outlet constriction) within 25 % of the
  // central film (all the fits put it 10–20 % below).
  EXPECT_LT(r.minimum_film_m, r.central_film_m);
  EXPECT_GT(r.minimum_film_m, 0.75 * r.central_film_m);
}

TEST(EhlLine, BadInputIsRejectedAndNonConvergenceIsReported) {
  EXPECT_THROW(solve_ehl_line({-1.0, kRadius_m, kModulus_Pa, kSpeed_m_per_s}, mineral_oil()), std::invalid_argument);
  EhlLineOptions narrow;
  narrow.inlet_over_half_width = -0.5;  // inside the Hertz contact
  EXPECT_THROW(solve_ehl_line({3e5, kRadius_m, kModulus_Pa, kSpeed_m_per_s}, mineral_oil(), narrow), std::invalid_argument);
  PiezoviscousLubricant bad = mineral_oil();
  bad.viscosity_Pa_s = 0.0;
  EXPECT_THROW(solve_ehl_line({3e5, kRadius_m, kModulus_Pa, kSpeed_m_per_s}, bad), std::invalid_argument);
  EhlLineOptions starved;
  starved.max_newton_iterations = 1;
  starved.max_continuation_steps = 0;
  const EhlLineResult r = solve_ehl_line({3e5, kRadius_m, kModulus_Pa, kSpeed_m_per_s}, mineral_oil(), starved);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, starved.tolerance);
  EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace tribo::lubrication
