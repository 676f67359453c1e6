#include "rig/ball_film.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rig/internal/exact_decimal.h"

namespace tribo::rig {
namespace {

// x^(1−w) y^w for w in [0, 1], without 0·∞ at the ends or where a value is 0.
double geometric_blend(double x, double y, double w) {
  if (w <= 0.0 || x == y) return x;
  if (w >= 1.0) return y;
  if (x == 0.0 || y == 0.0) return 0.0;
  return std::exp((1.0 - w) * std::log(x) + w * std::log(y));
}

}  // namespace

BallFilmCurve::BallFilmCurve(const std::vector<double>& share, const std::vector<double>& central_film_m, const std::vector<double>& traction_N) {
  if (central_film_m.size() != share.size() || traction_N.size() != share.size())
    throw std::invalid_argument("ball film: the films and tractions must have one entry per share");
  for (std::size_t j = 0; j < share.size(); ++j) {
    const double hc = central_film_m[j], f = traction_N[j];
    if (!(std::isfinite(hc) && hc > 0.0 && std::isfinite(f) && f > 0.0 && share[j] > 0.0)) continue;
    if (!ln_h_.empty() && !(std::log(hc) < ln_h_.back())) continue;
    ln_s_.push_back(std::log(share[j]));
    ln_h_.push_back(std::log(hc));
    ln_f_.push_back(std::log(f));
  }
  if (ln_s_.size() < 2)
    throw std::invalid_argument("ball film: fewer than two shares have a film (each thinner than the smaller shares' films)");
}

BallFilmAt BallFilmCurve::at(double h) const {
  if (!(h > 0.0)) throw std::invalid_argument("ball film: the separation must be > 0, got " + internal::exact_decimal(h));
  const double x = std::log(h);
  // The interval holding ln h (h_c falls with j), the end intervals continued beyond.
  std::size_t j = 0;
  while (j + 2 < ln_h_.size() && x < ln_h_[j + 1]) ++j;
  const auto along = [&](const std::vector<double>& y, double t) { return y[j] + t * (y[j + 1] - y[j]); };
  const double t = (x - ln_h_[j]) / (ln_h_[j + 1] - ln_h_[j]);
  const double cap = std::log(kBallFilmMaxShare);
  if (along(ln_s_, t) >= cap) return {kBallFilmMaxShare, std::exp(along(ln_f_, (cap - ln_s_[j]) / (ln_s_[j + 1] - ln_s_[j]))), 0.0};
  return {std::exp(along(ln_s_, t)), std::exp(along(ln_f_, t)), (ln_s_[j + 1] - ln_s_[j]) / (ln_h_[j + 1] - ln_h_[j])};
}

double BallFilmCurve::traction_at_share_N(double share) const {
  const double x = std::log(share);
  std::size_t j = 0;  // ln s increases with j
  while (j + 2 < ln_s_.size() && x > ln_s_[j + 1]) ++j;
  return std::exp(ln_f_[j] + (x - ln_s_[j]) / (ln_s_[j + 1] - ln_s_[j]) * (ln_f_[j + 1] - ln_f_[j]));
}

BallFilm::BallFilm(const std::vector<double>& share, std::vector<double> eta_u_Pa_m, const std::vector<std::vector<double>>& central_film_m,
                   const std::vector<std::vector<double>>& traction_N, double normal_load_N)
    : eta_u_(std::move(eta_u_Pa_m)), normal_load_N_(normal_load_N) {
  if (eta_u_.size() < 2 || eta_u_.front() != 0.0 || central_film_m.size() != eta_u_.size() || traction_N.size() != eta_u_.size())
    throw std::invalid_argument("ball film: needs an ηU axis from 0 and one row of films and tractions per node");
  for (std::size_t k = 1; k < eta_u_.size(); ++k) {
    if (!(eta_u_[k] > eta_u_[k - 1])) throw std::invalid_argument("ball film: the ηU axis must increase strictly");
    try {
      nodes_.emplace_back(share, central_film_m[k], traction_N[k]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string(e.what()) + " at ηU node " + std::to_string(k) + " (" + internal::exact_decimal(eta_u_[k]) + " Pa m)");
    }
  }
}

BallFilm::Film BallFilm::at(double h, double eta_u) const {
  if (!(eta_u >= 0.0 && eta_u <= eta_u_.back()))
    throw std::out_of_range("ball film: eta_u_Pa_m = " + internal::exact_decimal(eta_u) + " lies outside the table's [0, " +
                            internal::exact_decimal(eta_u_.back()) + "]; homogenise with a larger [micro_ehl] max_speed_m_per_s");
  if (eta_u == 0.0) return {};
  // Node k (1-based on eta_u_) at or below ηU, the one above; below the first, the first alone.
  const auto upper = std::upper_bound(eta_u_.begin() + 1, eta_u_.end(), eta_u);
  const std::size_t hi = std::min<std::size_t>(static_cast<std::size_t>(upper - eta_u_.begin()), eta_u_.size() - 1);
  const std::size_t lo = std::max<std::size_t>(hi - 1, 1);
  const double w = hi == lo ? 1.0 : std::log(eta_u / eta_u_[lo]) / std::log(eta_u_[hi] / eta_u_[lo]);
  const auto read = [&](std::size_t k) { return nodes_[k - 1].at(h * std::pow(eta_u_[k] / eta_u, kBallFilmSpeedExponent)); };
  const BallFilmAt a = read(lo), b = hi == lo ? a : read(hi);
  const double share = geometric_blend(a.share, b.share, w);
  if (!(share > 0.0)) return {};  // far below the first node the film's power law underflows
  const double traction = geometric_blend(nodes_[lo - 1].traction_at_share_N(share), nodes_[hi - 1].traction_at_share_N(share), w);
  const double load = share * normal_load_N_;
  // Both nodes are read at separations proportional to h̄: d ln W_f / d ln h̄ is their slopes' blend.
  return {load, traction, load / h * ((1.0 - w) * a.log_slope + w * b.log_slope)};
}

}  // namespace tribo::rig
