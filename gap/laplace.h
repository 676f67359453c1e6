// What a fitted model does not know about its own parameters, carried into its predictive
// (verdict.h predictive). A fit leaves its parameters as well fixed as its training items fix
// them; where the held-out items depend on a combination the training items leave loose — a speed
// outside the training speeds, a stiffness they did not vary — its prediction there is that much
// less certain, whatever its training misfit. To first order about the fit u* (a Laplace
// approximation of the posterior):
//     Σ_u = (Σ_train J_iᵀ J_i / σ_i² + 12 I)⁻¹,   v_i = J_i Σ_u J_iᵀ,
// J_i the residual's gradient in the fit's coordinates u ∈ [1, 2] (fit.h), σ_i the model's
// predictive scale without this term, and 12 I the precision of the uniform prior on the box
// (variance 1/12 per coordinate), which bounds a direction the training items do not fix at all.
// v_i adds to σ_i² (verdict.h predictive), capped at 1: a residual of 1 is a qualitative miss
// (fit.h FitResult::missing_items), the most a prediction can be off by, and a difference
// across a feature that appears or vanishes would otherwise read as an unbounded slope.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "gap/compare.h"
#include "gap/fit.h"

namespace tribo::gap {

// A fit to linearise: its search coordinates and where it stopped.
struct FitPoint {
  std::vector<FitParameter> space;
  FitSetup setup;
};

// The residuals of `fit`'s model on every item with its coordinates set to `u`; empty where it
// cannot be simulated there.
std::vector<double> residuals_at(const Comparison& c, const FitPoint& fit, const std::vector<double>& u, std::uint64_t seed);

// A fit's residuals on every item at its coordinates u and their Jacobian ∂r_i/∂u_j by forward
// differences of kSearchStep (backward at the upper bound) — the step the search takes, coarse
// enough to see through the small jumps of event-based observables. A column whose simulation
// fails is 0; where the fit itself cannot be simulated `centre` is empty and J is 0.
struct Linearisation {
  std::vector<double> u, centre, step;
  Eigen::MatrixXd jacobian;
};
// Every fit's linearisation, the simulations of all of them side by side (numerics/parallel.h).
std::vector<Linearisation> linearise(const Comparison& c, const std::vector<FitPoint>& fits, std::uint64_t seed);

// √(mean v_i) over the items of `mask` (0 for none or an empty v): how far a model's parameter
// uncertainty reaches on them, in gap units (gap_report.json `heldout_parameter_sd`).
double rms_parameter_sd(const std::vector<double>& v, const std::vector<bool>& mask);

// v_i above for every item, from the Jacobian `J` (rows: items) and the predictive scale `sd` on
// the items of `train`.
std::vector<double> parameter_variance(const Eigen::MatrixXd& J, const std::vector<double>& sd, const std::vector<bool>& train);

}  // namespace tribo::gap
