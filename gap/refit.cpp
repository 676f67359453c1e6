#include "gap/refit.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace tribo::gap {

LinearisedRefit::LinearisedRefit(Eigen::MatrixXd jacobian, std::vector<double> residuals, const std::vector<double>& train_weights,
                                 std::vector<double> room_below, std::vector<double> room_above)
    : jacobian_(std::move(jacobian)), residuals_(std::move(residuals)), room_below_(std::move(room_below)), room_above_(std::move(room_above)) {
  assert(static_cast<std::size_t>(jacobian_.rows()) == residuals_.size() && residuals_.size() == train_weights.size());
  assert(static_cast<std::size_t>(jacobian_.cols()) == room_below_.size() && room_below_.size() == room_above_.size());
  for (std::size_t i = 0; i < train_weights.size(); ++i)
    if (train_weights[i] > 0.0) train_.push_back(static_cast<int>(i));
  const auto rows = static_cast<Eigen::Index>(train_.size());
  train_weights_.resize(rows);
  Eigen::MatrixXd weighted(rows, jacobian_.cols());
  for (Eigen::Index k = 0; k < rows; ++k) {
    train_weights_(k) = train_weights[static_cast<std::size_t>(train_[static_cast<std::size_t>(k)])];
    weighted.row(k) = train_weights_(k) * jacobian_.row(train_[static_cast<std::size_t>(k)]);
  }
  if (rows == 0 || jacobian_.cols() == 0) {  // nothing to refit on, or nothing to refit
    left_.resize(rows, 0), directions_.resize(jacobian_.cols(), 0);
    return;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(weighted, Eigen::ComputeThinU | Eigen::ComputeThinV);
  left_ = svd.matrixU();
  directions_ = svd.matrixV();
  singular_ = svd.singularValues();
  // Numerically zero singular values: directions the training data do not fix at all.
  const double tiny = singular_.size() > 0 ? 1e-12 * singular_(0) : 0.0;
  for (Eigen::Index k = 0; k < singular_.size(); ++k) kept_.push_back(singular_(k) > tiny);
}

Eigen::VectorXd LinearisedRefit::step_std(const std::vector<double>& noise) const {
  Eigen::VectorXd scaled(left_.rows());
  for (Eigen::Index k = 0; k < scaled.size(); ++k)
    scaled(k) = train_weights_(k) * noise[static_cast<std::size_t>(train_[static_cast<std::size_t>(k)])];
  Eigen::VectorXd out = Eigen::VectorXd::Zero(singular_.size());
  for (Eigen::Index k = 0; k < singular_.size(); ++k)
    if (kept(k)) out(k) = left_.col(k).cwiseProduct(scaled).norm() / singular_(k);
  return out;
}

double LinearisedRefit::train_norm(const Eigen::VectorXd& change) const {
  double s = 0.0;
  for (std::size_t k = 0; k < train_.size(); ++k) s += std::pow(train_weights_(static_cast<Eigen::Index>(k)) * change(train_[k]), 2);
  return std::sqrt(s);
}

Eigen::VectorXd LinearisedRefit::step(const std::vector<double>& shift) const {
  Eigen::VectorXd ws(left_.rows());
  for (Eigen::Index k = 0; k < ws.size(); ++k) ws(k) = train_weights_(k) * shift[static_cast<std::size_t>(train_[static_cast<std::size_t>(k)])];
  Eigen::VectorXd du = Eigen::VectorXd::Zero(jacobian_.cols());
  for (Eigen::Index k = 0; k < singular_.size(); ++k)
    if (kept(k)) du -= directions_.col(k) * (left_.col(k).dot(ws) / singular_(k));
  for (Eigen::Index j = 0; j < du.size(); ++j)
    du(j) = std::clamp(du(j), -room_below_[static_cast<std::size_t>(j)], room_above_[static_cast<std::size_t>(j)]);
  return du;
}

std::vector<double> LinearisedRefit::residuals(const std::vector<double>& shift) const {
  const Eigen::VectorXd moved = jacobian_ * step(shift);
  std::vector<double> r = residuals_;
  for (std::size_t i = 0; i < r.size(); ++i) r[i] += moved(static_cast<Eigen::Index>(i));
  return r;
}

}  // namespace tribo::gap
