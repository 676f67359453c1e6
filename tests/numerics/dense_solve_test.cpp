// numerics/dense_solve.h (LAPACK dgesv) against systems whose answer is known in closed form.
#include <gtest/gtest.h>

#include <stdexcept>

#include "numerics/dense_solve.h"

namespace tribo::numerics {
namespace {

// The 1-D Laplacian tridiag(−1, 2, −1) of order n with b = A·(1, 2, …, n): the solution is
// 1…n. Its condition number grows as n², ≈ 4·10⁴ at n = 127 (odd: no symmetry to hide a
// pivoting error), so the answer holds to ≈ 1e-16 × 4e4 × n relative — 1e-9 leaves room.
TEST(DenseSolve, LaplacianSystemReturnsTheKnownSolution) {
  const int n = 127;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2.0;
    if (i > 0) a(i, i - 1) = -1.0;
    if (i + 1 < n) a(i, i + 1) = -1.0;
  }
  const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(n, 1.0, n);
  const Eigen::VectorXd b = a * expected;
  Eigen::VectorXd x;
  ASSERT_TRUE(dense_solve(a, b, x));
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>() / n, 1e-9);
}

// A row permutation needs the pivoting: [[0, 1], [1, 0]] x = (3, 5) gives x = (5, 3) exactly.
TEST(DenseSolve, ZeroLeadingEntryIsPivotedAway) {
  Eigen::MatrixXd a(2, 2);
  a << 0.0, 1.0, 1.0, 0.0;
  Eigen::VectorXd x;
  ASSERT_TRUE(dense_solve(a, Eigen::Vector2d(3.0, 5.0), x));
  EXPECT_EQ(x(0), 5.0);
  EXPECT_EQ(x(1), 3.0);
}

TEST(DenseSolve, SingularMatrixIsReportedAndMismatchedSizesAreABug) {
  Eigen::MatrixXd a(3, 3);
  a << 1, 2, 3, 2, 4, 6, 0, 1, 1;  // the second row twice the first: an exact zero pivot
  Eigen::VectorXd x;
  EXPECT_FALSE(dense_solve(a, Eigen::Vector3d(1.0, 2.0, 3.0), x));
  Eigen::MatrixXd b = Eigen::MatrixXd::Identity(3, 3);
  EXPECT_THROW(dense_solve(b, Eigen::Vector2d(1.0, 2.0), x), std::logic_error);
}

}  // namespace
}  // namespace tribo::numerics
