#include "gap/laplace.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "numerics/parallel.h"

namespace tribo::gap {

std::vector<double> residuals_at(const Comparison& c, const FitPoint& fit, const std::vector<double>& u, std::uint64_t seed) {
  FitSetup s = fit.setup;
  apply(fit.space, u, s);
  try {
    return c.residuals(c.predict(s.rig, s.model, seed));
  } catch (const std::invalid_argument&) {
    return {};
  }
}

std::vector<Linearisation> linearise(const Comparison& c, const std::vector<FitPoint>& fits, std::uint64_t seed) {
  std::vector<Linearisation> out(fits.size());
  std::vector<std::pair<std::size_t, std::size_t>> tasks;  // (fit, coordinate); coordinate = size: the fit itself
  for (std::size_t f = 0; f < fits.size(); ++f) {
    out[f].u = coordinates(fits[f].space, fits[f].setup, false);
    out[f].step.assign(out[f].u.size(), 0.0);
    for (std::size_t j = 0; j <= fits[f].space.size(); ++j) tasks.emplace_back(f, j);
  }
  std::vector<std::vector<double>> at(tasks.size());
  numerics::parallel_for(tasks.size(), [&](std::size_t t) {
    const auto [f, j] = tasks[t];
    std::vector<double> u = out[f].u;
    if (j < u.size()) {
      out[f].step[j] = u[j] + kSearchStep <= 2.0 ? kSearchStep : -kSearchStep;
      u[j] += out[f].step[j];
    }
    at[t] = residuals_at(c, fits[f], u, seed);  // empty: the column stays 0
  });
  std::size_t t = 0;
  for (std::size_t f = 0; f < fits.size(); ++f) {
    const std::size_t p = fits[f].space.size();
    Linearisation& l = out[f];
    l.centre = at[t + p];
    const std::size_t n = c.items().size();
    l.jacobian = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(p));
    for (std::size_t j = 0; j < p; ++j)
      if (l.centre.size() == n && at[t + j].size() == n)
        for (std::size_t i = 0; i < n; ++i)
          if (const double d = (at[t + j][i] - l.centre[i]) / l.step[j]; std::isfinite(d))
            l.jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = d;
    t += p + 1;
  }
  return out;
}

double rms_parameter_sd(const std::vector<double>& v, const std::vector<bool>& mask) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (mask[i]) sum += v[i], ++n;
  return n > 0 ? std::sqrt(sum / n) : 0.0;
}

std::vector<double> parameter_variance(const Eigen::MatrixXd& J, const std::vector<double>& sd, const std::vector<bool>& train) {
  assert(static_cast<std::size_t>(J.rows()) == sd.size() && sd.size() == train.size());
  constexpr double kPriorPrecision = 12.0;  // 1 / variance of a uniform coordinate on [1, 2]
  const Eigen::Index p = J.cols();
  Eigen::MatrixXd information = kPriorPrecision * Eigen::MatrixXd::Identity(p, p);
  for (Eigen::Index i = 0; i < J.rows(); ++i)
    if (train[static_cast<std::size_t>(i)]) {
      const double w = 1.0 / sd[static_cast<std::size_t>(i)];
      information.noalias() += (w * w) * J.row(i).transpose() * J.row(i);
    }
  const Eigen::LLT<Eigen::MatrixXd> chol(information);  // positive definite: the prior's 12 I at least
  assert(chol.info() == Eigen::Success);
  std::vector<double> v(sd.size(), 0.0);
  for (Eigen::Index i = 0; i < J.rows(); ++i) {
    const Eigen::VectorXd g = J.row(i).transpose();
    v[static_cast<std::size_t>(i)] = std::min(1.0, g.dot(chol.solve(g)));
  }
  return v;
}

}  // namespace tribo::gap
