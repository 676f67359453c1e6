// The linearised refit (gap/refit.h) against the exact least-squares refit of a straight line,
// where the Gauss–Newton step from the optimum is the whole refit.
#include "gap/refit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

namespace tribo::gap {
namespace {

// Residuals of a line a + b x against measured y: r_i = a + b x_i − y_i. Six points, the first
// four train (weights 1, 2, 1, 2), the last two held out (weight 0).
struct Line {
  std::vector<double> x{0.0, 1.0, 2.0, 3.0, 4.0, 5.0}, y{0.1, 0.9, 2.2, 2.8, 4.1, 5.2}, w{1.0, 2.0, 1.0, 2.0, 0.0, 0.0};
  Eigen::MatrixXd jacobian() const {
    Eigen::MatrixXd J(6, 2);
    for (int i = 0; i < 6; ++i) J(i, 0) = 1.0, J(i, 1) = x[static_cast<std::size_t>(i)];
    return J;
  }
  // Weighted least squares on the training points for measurements y − shift (residual r + shift).
  Eigen::Vector2d fit(const std::vector<double>& shift) const {
    Eigen::MatrixXd A(4, 2);
    Eigen::VectorXd b(4);
    for (int i = 0; i < 4; ++i) {
      const auto k = static_cast<std::size_t>(i);
      A(i, 0) = w[k], A(i, 1) = w[k] * x[k], b(i) = w[k] * (y[k] - shift[k]);
    }
    return A.colPivHouseholderQr().solve(b);
  }
  std::vector<double> residuals(const Eigen::Vector2d& p, const std::vector<double>& shift) const {
    std::vector<double> r;
    for (std::size_t i = 0; i < 6; ++i) r.push_back(p(0) + p(1) * x[i] - y[i] + (i < 4 ? shift[i] : 0.0));
    return r;
  }
};

TEST(LinearisedRefit, OnALineItIsTheExactWeightedLeastSquaresRefit) {
  const Line line;
  const std::vector<double> none(6, 0.0), shift{0.05, -0.03, 0.02, 0.04, 0.7, -0.9};  // held-out entries not read
  const Eigen::Vector2d p0 = line.fit(none), p1 = line.fit(shift);
  const LinearisedRefit refit(line.jacobian(), line.residuals(p0, none), line.w, {10.0, 10.0}, {10.0, 10.0});
  const Eigen::VectorXd step = refit.step(shift);
  EXPECT_NEAR(step(0), p1(0) - p0(0), 1e-12);
  EXPECT_NEAR(step(1), p1(1) - p0(1), 1e-12);
  // On the held-out points the refitted residuals are the refitted line's (without the shift,
  // which the bootstrap adds to held-out items itself).
  const std::vector<double> r = refit.residuals(shift), exact = line.residuals(p1, none);
  EXPECT_NEAR(r[4], exact[4], 1e-12);
  EXPECT_NEAR(r[5], exact[5], 1e-12);
  EXPECT_GT(std::abs(r[5] - line.residuals(p0, none)[5]), 1e-3);  // and the refit moved them
}

// A coordinate at its bound moves only into the box; a coordinate the data do not fix (a zero
// column) does not move at all (minimum-norm solution).
TEST(LinearisedRefit, StepsStayInTheBoxAndLeaveUnfixedCoordinatesAlone) {
  const Line line;
  const std::vector<double> up(6, -0.1);  // measured higher: the intercept must rise by 0.1
  const Eigen::Vector2d p0 = line.fit(std::vector<double>(6, 0.0));
  const LinearisedRefit free(line.jacobian(), line.residuals(p0, std::vector<double>(6, 0.0)), line.w, {1.0, 1.0}, {1.0, 1.0});
  EXPECT_NEAR(free.step(up)(0), 0.1, 1e-12);
  EXPECT_NEAR(free.step(up)(1), 0.0, 1e-12);
  const LinearisedRefit capped(line.jacobian(), line.residuals(p0, std::vector<double>(6, 0.0)), line.w, {1.0, 1.0}, {0.04, 1.0});
  EXPECT_NEAR(capped.step(up)(0), 0.04, 1e-15);

  Eigen::MatrixXd J(6, 2);
  J.col(0) = line.jacobian().col(0);
  J.col(1).setZero();
  const LinearisedRefit flat(J, std::vector<double>(6, 0.0), line.w, {1.0, 1.0}, {1.0, 1.0});
  EXPECT_NEAR(flat.step(up)(0), 0.1, 1e-12);
  EXPECT_EQ(flat.step(up)(1), 0.0);
}

// The spread of a redraw's step along each direction is the least-squares covariance
// (W J_t)⁺ W Σ W (W J_t)⁺ᵀ projected on it; a dropped direction takes no part in any step.
TEST(LinearisedRefit, StepSpreadIsTheLeastSquaresCovarianceAndDroppedDirectionsStayPut) {
  const Line line;
  const std::vector<double> noise{0.1, 0.05, 0.2, 0.1, 0.3, 0.3};
  LinearisedRefit refit(line.jacobian(), std::vector<double>(6, 0.0), line.w, {10.0, 10.0}, {10.0, 10.0});
  Eigen::MatrixXd WJ(4, 2);
  Eigen::VectorXd ws(4);
  for (int i = 0; i < 4; ++i) {
    WJ.row(i) = line.w[static_cast<std::size_t>(i)] * line.jacobian().row(i);
    ws(i) = line.w[static_cast<std::size_t>(i)] * noise[static_cast<std::size_t>(i)];
  }
  const Eigen::MatrixXd P = WJ.completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::MatrixXd cov = P * ws.cwiseAbs2().asDiagonal() * P.transpose();
  const Eigen::VectorXd sd = refit.step_std(noise);
  for (Eigen::Index k = 0; k < 2; ++k) {
    const Eigen::VectorXd v = refit.directions().col(k);
    EXPECT_NEAR(sd(k), std::sqrt(v.dot(cov * v)), 1e-12);
  }
  const std::vector<double> shift{0.05, -0.03, 0.02, 0.04, 0.0, 0.0};
  refit.drop(0);
  EXPECT_NEAR(refit.directions().col(0).dot(refit.step(shift)), 0.0, 1e-14);
  EXPECT_GT(std::abs(refit.directions().col(1).dot(refit.step(shift))), 1e-4);
  EXPECT_EQ(refit.step_std(noise)(0), 0.0);
}

}  // namespace
}  // namespace tribo::gap
