// Refits in the bootstrap resamples (diagnosis.h step 4), linearised. A fit at its optimum u*
// whose training measurements are taken again — each moved by s_i, its standard error times a
// standard normal — moves, to first order in s, by the Gauss–Newton step from u*:
//     Δu = −(W J_t)⁺ W s_t = −Σ_k v_k (u_kᵀ W s_t) / σ_k,
// J the residuals' Jacobian in the fit's coordinates (the finite differences the fit itself
// steps by), W the fit's residual weights on the training items, u_k σ_k v_kᵀ the singular
// triplets of W J_t. Its residuals on every item then become r + J Δu; the held-out ones are what
// the bootstrap judges. Exact for a model linear in its parameters. For the catalogue's effects
// it holds only as far as the residuals are linear over the step a redraw makes, so each
// direction v_k is checked (pipeline_verdict.cpp): where a probe two standard deviations of the step
// along it does not change the training residuals as J predicts (within half), the direction is
// dropped — a nonlinear refit would not follow a straight line there (the velocity-step record:
// slip_transient's rate weakening, a direction with σ_k/σ_1 = 1.5e-4, moved 19 % of its range on
// one redraw and sent the confidence from 92 % to 44 %, where ten nonlinear refits kept 92 %).
// One Jacobian per fit and a probe per direction, where a nonlinear refit per resample cost 10–40
// simulations (ten redraws of three fits added 75 s to the 4 min 40 s velocity-step diagnosis).
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace tribo::gap {

class LinearisedRefit {
 public:
  // `jacobian`: ∂r_i/∂u_j on every item (rows) for the fit's coordinates (columns);
  // `residuals`: r at u*; `train_weights`: W, 0 off the training items; `room_below`,
  // `room_above`: how far each coordinate may move before a bound (≥ 0).
  LinearisedRefit(Eigen::MatrixXd jacobian, std::vector<double> residuals, const std::vector<double>& train_weights,
                  std::vector<double> room_below, std::vector<double> room_above);
  // The directions v_k in the coordinates (columns), strongest first.
  const Eigen::MatrixXd& directions() const { return directions_; }
  // The standard deviation of the step along each direction for redraws with standard errors
  // `noise` on the items: sqrt(Σ_i (u_ki w_i noise_i)²) / σ_k (0 for a direction left out).
  Eigen::VectorXd step_std(const std::vector<double>& noise) const;
  // The training residuals' change for a coordinate step `du` as J predicts it, and its weighted
  // norm ‖W J du‖ on the training items.
  Eigen::VectorXd predicted_change(const Eigen::VectorXd& du) const { return jacobian_ * du; }
  double train_norm(const Eigen::VectorXd& change) const;
  // Leaves direction k out of every step.
  void drop(Eigen::Index k) { kept_[static_cast<std::size_t>(k)] = false; }
  bool kept(Eigen::Index k) const { return kept_[static_cast<std::size_t>(k)]; }
  // The coordinates' step for training shifts `shift` (entries off the training items are not
  // read), each clipped to its bound.
  Eigen::VectorXd step(const std::vector<double>& shift) const;
  // The refitted residuals on every item: r + J Δu.
  std::vector<double> residuals(const std::vector<double>& shift) const;

 private:
  Eigen::MatrixXd jacobian_, left_, directions_;  // J; u_k and v_k of W J_t
  Eigen::VectorXd singular_;
  std::vector<double> residuals_, room_below_, room_above_;
  std::vector<int> train_;
  Eigen::VectorXd train_weights_;
  std::vector<bool> kept_;
};

}  // namespace tribo::gap
