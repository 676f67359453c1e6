// A Ceres cost function whose numeric Jacobian evaluates its columns side by side.
//
// ceres::DynamicNumericDiffCostFunction differentiates one parameter after another; in a gap fit
// each column is a whole prediction of the bundle (seconds of ODE integration), and a prediction's
// own parallel loop over its runs balances badly (one long slow run and a few short ones), so a
// fit that runs alone — the calibration, the pair, a re-calibration — used little more than one
// core. Here the columns are the parallel loop (numerics/parallel.h): 2n equal predictions for central
// differences, n for forward ones, and each column's prediction runs serially in its thread.
//
// The steps and the arithmetic are Ceres's own (ceres/internal/numeric_diff.h, 2.1): for column j,
// δ = max(√ε, |x_j| · relative_step_size); central (r(x + δ e_j) − r(x − δ e_j)) · ((1/δ)/2),
// forward (r(x + δ e_j) − r(x)) · (1/δ); the Jacobian row-major. A fit therefore takes the same
// steps to the bit (tests/gap/parallel_numeric_diff_test.cpp compares the two Jacobians exactly),
// and whatever the number of threads: the columns do not depend on each other.
#pragma once

#include <ceres/cost_function.h>
#include <ceres/numeric_diff_options.h>
#include <ceres/types.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "numerics/parallel.h"

namespace tribo::gap {

// Functor: bool operator()(double const* const* parameters, double* residuals) const, thread-safe
// (called from several threads at once), one parameter block.
template <class Functor, ceres::NumericDiffMethodType kMethod>
class ParallelNumericDiffCostFunction final : public ceres::CostFunction {
  static_assert(kMethod == ceres::CENTRAL || kMethod == ceres::FORWARD, "central or forward differences");

 public:
  ParallelNumericDiffCostFunction(std::unique_ptr<const Functor> functor, int parameters, int residuals,
                                  const ceres::NumericDiffOptions& options = {})
      : functor_(std::move(functor)), relative_step_size_(options.relative_step_size) {
    mutable_parameter_block_sizes()->push_back(parameters);
    set_num_residuals(residuals);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    if (!(*functor_)(parameters, residuals)) return false;
    if (jacobians == nullptr || jacobians[0] == nullptr) return true;
    const auto n = static_cast<std::size_t>(parameter_block_sizes()[0]), m = static_cast<std::size_t>(num_residuals());
    const double* x = parameters[0];
    const double min_step_size = std::sqrt(std::numeric_limits<double>::epsilon());
    std::vector<char> ok(n, 1);
    numerics::parallel_for(n, [&](std::size_t j) {
      omp_set_num_threads(1);  // the column's prediction in this thread: the columns are the parallel work
      std::vector<double> shifted(x, x + n), plus(m), minus(m);
      const double* block = shifted.data();
      const auto at = [&](double xj, std::vector<double>& r) {
        shifted[j] = xj;
        return (*functor_)(&block, r.data());
      };
      const double delta = std::max(min_step_size, std::abs(x[j]) * relative_step_size_);
      double one_over_delta = 1.0 / delta;
      if (!at(x[j] + delta, plus) || (kMethod == ceres::CENTRAL && !at(x[j] - delta, minus))) {
        ok[j] = 0;
        return;
      }
      if constexpr (kMethod == ceres::CENTRAL) {
        for (std::size_t i = 0; i < m; ++i) plus[i] -= minus[i];
        one_over_delta /= 2;
      } else {
        for (std::size_t i = 0; i < m; ++i) plus[i] -= residuals[i];
      }
      for (std::size_t i = 0; i < m; ++i) jacobians[0][i * n + j] = plus[i] * one_over_delta;
    });
    return std::all_of(ok.begin(), ok.end(), [](char c) { return c != 0; });
  }

 private:
  std::unique_ptr<const Functor> functor_;
  double relative_step_size_;
};

}  // namespace tribo::gap
