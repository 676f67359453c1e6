// The parameter variance of a fitted model (gap/laplace.h) against the textbook predictive of
// linear least squares: for y = a + b x fitted to n points with noise σ, the variance of the fitted
// line at x is σ² (1/n + (x − x̄)² / S_xx) (e.g. Draper & Smith, Applied Regression Analysis, §3.1),
// to which the box prior's 12 I adds a relative correction of order 12 σ² / (n, S_xx) — made
// negligible here by a small σ.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "gap/laplace.h"

namespace tribo::gap {
namespace {

TEST(Laplace, ParameterVarianceIsTheLeastSquaresLinesPredictiveVariance) {
  const std::vector<double> x{0.0, 0.5, 1.0, 1.5, 2.0, 1.0, 4.0};  // the last two held out
  const std::vector<bool> train{true, true, true, true, true, false, false};
  const double sigma = 1e-3;
  Eigen::MatrixXd J(7, 2);
  for (int i = 0; i < 7; ++i) J(i, 0) = 1.0, J(i, 1) = x[static_cast<std::size_t>(i)];
  const std::vector<double> v = parameter_variance(J, std::vector<double>(7, sigma), train);
  const double n = 5.0, mean = 1.0, sxx = 2.5;
  for (int i = 0; i < 7; ++i) {
    const double d = x[static_cast<std::size_t>(i)] - mean;
    const double expected = sigma * sigma * (1.0 / n + d * d / sxx);
    EXPECT_NEAR(v[static_cast<std::size_t>(i)], expected, 1e-4 * expected) << "x = " << x[static_cast<std::size_t>(i)];
  }
  // Extrapolating to x = 4, twice the data's span beyond their centre, the variance is 19 times
  // that at the centre: (1/5 + 9/2.5) / (1/5).
  EXPECT_NEAR(v[6] / v[5], 19.0, 1e-3);
}

// A direction the training items do not fix at all is bounded by the prior on the box: a
// coordinate only the held-out item depends on has variance 1/12, so v = J² / 12.
TEST(Laplace, ADirectionNoTrainingItemFixesIsBoundedByTheBox) {
  Eigen::MatrixXd J(3, 2);
  J << 1.0, 0.0,  //
      1.0, 0.0,   //
      0.0, 0.6;   // held out, depends on the second coordinate alone
  const std::vector<double> v = parameter_variance(J, {0.01, 0.01, 0.01}, {true, true, false});
  EXPECT_NEAR(v[2], 0.36 / 12.0, 1e-12);
  EXPECT_NEAR(v[0], 1.0 / (2.0 / 1e-4 + 12.0), 1e-15);
  // A slope across a feature that appears (a qualitative miss, residual 1) is capped at 1.
  J(2, 1) = 100.0;
  EXPECT_EQ(parameter_variance(J, {0.01, 0.01, 0.01}, {true, true, false})[2], 1.0);
}

}  // namespace
}  // namespace tribo::gap
