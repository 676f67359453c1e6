// The parallel numeric Jacobian of the gap fits (gap/parallel_numeric_diff.h) against the reference
// it must reproduce: Ceres's own DynamicNumericDiffCostFunction, column for column to the bit — so a
// fit takes the same Levenberg–Marquardt steps as before the columns ran side by side.
#include "gap/parallel_numeric_diff.h"

#include <ceres/dynamic_numeric_diff_cost_function.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

// Five residuals of four parameters, nonlinear in each (so that every column differs from its
// neighbours and the step size matters), of very different magnitudes.
struct Curved {
  bool operator()(double const* const* p, double* r) const {
    const double* x = p[0];
    r[0] = std::exp(0.3 * x[0]) - x[1] * x[1];
    r[1] = std::sin(x[1] * x[2]) + 1e-3 * x[3];
    r[2] = 1e4 * x[0] * x[3] - std::log1p(x[2] * x[2]);
    r[3] = std::atan(x[3] - x[0]) * 1e-6;
    r[4] = x[0] * x[1] * x[2] * x[3];
    return true;
  }
};

// Refuses points with x[1] above 1.5: a column whose step crosses it fails the whole evaluation.
struct Bounded {
  bool operator()(double const* const* p, double* r) const {
    r[0] = p[0][0] + p[0][1];
    return p[0][1] <= 1.5;
  }
};

template <ceres::NumericDiffMethodType kMethod>
void expect_same_jacobian_as_ceres(const std::vector<double>& x, double relative_step) {
  ceres::NumericDiffOptions options;
  options.relative_step_size = relative_step;
  ceres::DynamicNumericDiffCostFunction<Curved, kMethod> reference(new Curved, ceres::TAKE_OWNERSHIP, options);
  reference.AddParameterBlock(4);
  reference.SetNumResiduals(5);
  tribo::gap::ParallelNumericDiffCostFunction<Curved, kMethod> parallel(std::make_unique<const Curved>(), 4, 5, options);

  const double* block = x.data();
  std::vector<double> r_ref(5), r_par(5), j_ref(20), j_par(20);
  double* jr = j_ref.data();
  double* jp = j_par.data();
  ASSERT_TRUE(reference.Evaluate(&block, r_ref.data(), &jr));
  ASSERT_TRUE(parallel.Evaluate(&block, r_par.data(), &jp));
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r_par[i], r_ref[i]) << "residual " << i;
  for (int k = 0; k < 20; ++k) EXPECT_EQ(j_par[k], j_ref[k]) << "row " << k / 4 << ", column " << k % 4;
}

TEST(ParallelNumericDiff, CentralJacobianEqualsCeresToTheBit) {
  expect_same_jacobian_as_ceres<ceres::CENTRAL>({1.3, 1.7, 1.1, 1.9}, 0.002);  // the refinement's step
  expect_same_jacobian_as_ceres<ceres::CENTRAL>({0.0, -2.5, 1e-9, 3e3}, 0.002);  // x = 0: the √ε floor
}

TEST(ParallelNumericDiff, ForwardJacobianEqualsCeresToTheBit) {
  expect_same_jacobian_as_ceres<ceres::FORWARD>({1.3, 1.7, 1.1, 1.9}, 0.01);  // the search's step
  expect_same_jacobian_as_ceres<ceres::FORWARD>({0.0, -2.5, 1e-9, 3e3}, 0.01);
}

TEST(ParallelNumericDiff, AFailedColumnFailsTheEvaluation) {
  tribo::gap::ParallelNumericDiffCostFunction<Bounded, ceres::CENTRAL> cost(std::make_unique<const Bounded>(), 2, 1);
  const std::vector<double> inside{1.0, 1.0}, at_edge{1.0, 1.5};
  std::vector<double> r(1), jac(2);
  double* j = jac.data();
  const double* block = inside.data();
  ASSERT_TRUE(cost.Evaluate(&block, r.data(), &j));
  // d(x0 + x1)/dx0 = 1 up to the rounding of x ± δ: ε |x| / δ ≈ 2e-10 at Ceres's default step 1e-6.
  EXPECT_NEAR(jac[0], 1.0, 1e-9);
  block = at_edge.data();         // the residual itself is fine; the column x1 + δ is refused
  EXPECT_FALSE(cost.Evaluate(&block, r.data(), &j));
  EXPECT_TRUE(cost.Evaluate(&block, r.data(), nullptr));  // no Jacobian asked: the point alone
}

}  // namespace
