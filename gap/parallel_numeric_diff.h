// A Ceres cost function whose numeric Jacobian evaluates its columns side by side.
//
// ceres::DynamicNumericDiffCostFunction differentiates one parameter after another; in a gap fit
// each column is a whole prediction of the bundle (seconds of ODE integration), and a prediction's
// own parallel loop over its runs balances badly (one long slow run and a few short ones), so a
// fit that runs alone — the calibration, the pair, a re-calibration — used little more than one
// core. Here the columns are the parallel loop (parallel.h): 2n equal predictions for central
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

#include "gap/parallel.h"

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
    const int n = parameter_block_sizes()[0], m = num_residuals();
    const double* x = parameters[0];
    const double min_step_size = std::sqrt(std::numeric_limits<double>::epsilon());
    std::vector<char> ok(static_cast<std::size_t>(n), 1);
    parallel_for(static_cast<std::size_t>(n), [&](std::size_t j) {
      omp_set_num_threads(1);  // the column's prediction in this thread: the columns are the parallel work
      std::vector<double> shifted(x, x + n), plus(static_cast<std::size_t>(m)), minus;
      const double* block = shifted.data();
      const double delta = std::max(min_step_size, std::abs(x[j]) * relative_step_size_);
      shifted[j] = x[j] + delta;
      if (!(*functor_)(&block, plus.data())) {
        ok[j] = 0;
        return;
      }
      double one_over_delta = 1.0 / delta;
      if constexpr (kMethod == ceres::CENTRAL) {
        minus.resize(static_cast<std::size_t>(m));
        shifted[j] = x[j] - delta;
        if (!(*functor_)(&block, minus.data())) {
          ok[j] = 0;
          return;
        }
        for (int i = 0; i < m; ++i) plus[static_cast<std::size_t>(i)] -= minus[static_cast<std::size_t>(i)];
        one_over_delta /= 2;
      } else {
        for (int i = 0; i < m; ++i) plus[static_cast<std::size_t>(i)] -= residuals[i];
      }
      for (int i = 0; i < m; ++i) jacobians[0][static_cast<std::size_t>(i) * static_cast<std::size_t>(n) + j] = plus[static_cast<std::size_t>(i)] * one_over_delta;
    });
    return std::all_of(ok.begin(), ok.end(), [](char c) { return c != 0; });
  }

 private:
  std::unique_ptr<const Functor> functor_;
  double relative_step_size_;
};

}  // namespace tribo::gap
