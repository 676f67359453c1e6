// numerics/gmres.h (SUNDIALS SPGMR) on systems whose answer is known: the 1-D convection–diffusion
// operator, non-symmetric, with and without a preconditioner.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <stdexcept>

#include "numerics/gmres.h"

namespace tribo::numerics {
namespace {

// tridiag(−1 − c, 2, −1 + c) of order n (central convection–diffusion at cell Péclet number c):
// non-symmetric, condition ≈ n² for small c. b = A·(1, …, n).
Eigen::MatrixXd convection_diffusion(int n, double c) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) = 2.0;
    if (i > 0) a(i, i - 1) = -1.0 - c;
    if (i + 1 < n) a(i, i + 1) = -1.0 + c;
  }
  return a;
}

LinearMap product(const Eigen::MatrixXd& a) {
  return [&a](const Eigen::VectorXd& v, Eigen::VectorXd& y) {
    y = a * v;
    return true;
  };
}

// Without a preconditioner and without restarts (a basis as large as the system) GMRES converges
// within n iterations: the answer to 1e-6 relative at tolerance 1e-10 (condition ≈ 4·10³ turns the
// residual's 1e-10 into ≤ 4e-7 on x). Restarted at 60 it stagnates near 1e-5 — the next test's case.
TEST(Gmres, ConvectionDiffusionSolvesToTheKnownAnswer) {
  const int n = 101;
  const Eigen::MatrixXd a = convection_diffusion(n, 0.3);
  const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(n, 1.0, n);
  Eigen::VectorXd x;
  GmresOptions o;
  o.relative_tolerance = 1e-10;
  o.krylov_dimension = n;
  o.max_restarts = 0;
  const GmresSummary s = gmres(product(a), {}, a * expected, x, o);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_LE(s.relative_residual, 1e-10);
  EXPECT_LT((a * x - a * expected).norm() / (a * expected).norm(), 1e-9);  // the true residual, recomputed
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>() / n, 1e-6);
  EXPECT_GT(s.iterations, 1);
}

// With the exact inverse as right preconditioner the first Krylov vector is the answer: one
// iteration.
TEST(Gmres, ExactPreconditionerConvergesInOneIteration) {
  const int n = 64;
  const Eigen::MatrixXd a = convection_diffusion(n, 0.3);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
  const LinearMap inverse = [&lu](const Eigen::VectorXd& r, Eigen::VectorXd& z) {
    z = lu.solve(r);
    return true;
  };
  const Eigen::VectorXd expected = Eigen::VectorXd::LinSpaced(n, 1.0, n);
  Eigen::VectorXd x;
  const GmresSummary s = gmres(product(a), inverse, a * expected, x);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_EQ(s.iterations, 1);
  EXPECT_LT((x - expected).lpNorm<Eigen::Infinity>() / n, 1e-10);
}

// Too small a Krylov space and no restarts: it must say it stopped, with the residual it reached.
// (Restarted GMRES stagnates on this operator; 5 iterations leave most of the residual.)
TEST(Gmres, StoppingShortIsReportedWithItsResidual) {
  const int n = 101;
  const Eigen::MatrixXd a = convection_diffusion(n, 0.0);
  Eigen::VectorXd x;
  GmresOptions o;
  o.krylov_dimension = 5;
  o.max_restarts = 0;
  const GmresSummary s = gmres(product(a), {}, a * Eigen::VectorXd::LinSpaced(n, 1.0, n), x, o);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations, 5);
  EXPECT_GT(s.relative_residual, 1e-3);
  EXPECT_NE(s.message.find("5 iterations"), std::string::npos) << s.message;
}

// A failing operator stops the solve and is reported, not returned as an answer.
TEST(Gmres, FailingOperatorStopsTheSolve) {
  const LinearMap failing = [](const Eigen::VectorXd&, Eigen::VectorXd&) { return false; };
  Eigen::VectorXd x;
  EXPECT_FALSE(gmres(failing, {}, Eigen::VectorXd::Ones(10), x).converged);
  EXPECT_THROW(gmres(failing, {}, Eigen::VectorXd(), x), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::numerics
