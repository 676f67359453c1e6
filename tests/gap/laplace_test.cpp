// The parameter variance of a fitted model (gap/laplace.h) against the textbook predictive of
// linear least squares: for y = a + b x fitted to n points with noise σ, the variance of the fitted
// line at x is σ² (1/n + (x − x̄)² / S_xx) (e.g. Draper & Smith, Applied Regression Analysis, §3.1),
// to which the box prior's 12 I adds a relative correction of order 12 σ² / (n, S_xx) — made
// negligible here by a small σ.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "gap/laplace.h"
#include "gap/verdict.h"

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

// The predictive (verdict.h) with the parameter term is calibrated where the model is right: a
// line fitted by least squares to six items at x ∈ [0, 1] with noise s, predicting two held-out
// items at x = 2 and 3. Over 4000 redraws of the noise the held-out residuals' mean z² = r²/σ² is
// 1 with σ² = s² + τ² + v (its standard error √(2/4000) = 0.022; tolerance 0.1, 4.5 of those).
// Without v the predictive claims the noise alone and the held-out z² averages
// 1 + v/s² ≈ 1 + (1/6 + (x − ½)²/0.7) — 5.5 at x = 2, 10.1 at x = 3.
TEST(Laplace, PredictiveWithTheParameterTermIsCalibratedOnExtrapolatedItems) {
  const std::vector<double> x{0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 2.0, 3.0};
  const std::vector<bool> train{true, true, true, true, true, true, false, false};
  const double s = 0.01, a = 0.3, b = -0.1;
  std::vector<Item> items(x.size());
  for (Item& it : items) it.observable = "mu_peak";
  Eigen::MatrixXd J(8, 2), Jt(6, 2);
  for (int i = 0; i < 8; ++i) J(i, 0) = 1.0, J(i, 1) = x[static_cast<std::size_t>(i)];
  Jt = J.topRows(6);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, s);
  double with = 0.0, without = 0.0;
  int n = 0;
  for (int draw = 0; draw < 4000; ++draw) {
    Eigen::VectorXd y(8);
    for (int i = 0; i < 8; ++i) y(i) = a + b * x[static_cast<std::size_t>(i)] + noise(rng);
    const Eigen::Vector2d fit = Jt.colPivHouseholderQr().solve(y.head(6));
    const Eigen::VectorXd r = J * fit - y;
    const std::vector<double> res(r.data(), r.data() + r.size()), sd(8, s);
    const Predictive bare = predictive(items, res, sd, train);
    const Predictive full = predictive(items, res, sd, train, parameter_variance(J, bare.sd, train));
    for (int i = 6; i < 8; ++i, ++n) {
      with += std::pow(r(i) / full.sd[static_cast<std::size_t>(i)], 2);
      without += std::pow(r(i) / bare.sd[static_cast<std::size_t>(i)], 2);
    }
  }
  EXPECT_NEAR(with / n, 1.0, 0.1);
  EXPECT_GT(without / n, 5.0);
}

}  // namespace
}  // namespace tribo::gap
