#include "rig/kinetic_laws.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tribo::rig {
namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("friction: " + what);
}
bool finite_non_negative(double v) { return std::isfinite(v) && v >= 0.0; }
}  // namespace

ConstantCurve::ConstantCurve(double mu_k) : mu_k_(mu_k) {
  require(finite_non_negative(mu_k), "mu_k must be finite and non-negative");
}

StribeckCurve::StribeckCurve(const StribeckParameters& p) : p_(p) {
  require(finite_non_negative(p.mu_coulomb), "stribeck mu_coulomb must be non-negative");
  require(finite_non_negative(p.mu_breakaway), "stribeck mu_breakaway must be non-negative");
  require(std::isfinite(p.stribeck_speed_m_per_s) && p.stribeck_speed_m_per_s > 0.0, "stribeck speed must be positive");
  require(std::isfinite(p.exponent) && p.exponent > 0.0, "stribeck exponent must be positive");
  require(finite_non_negative(p.viscous_per_m_per_s), "stribeck viscous coefficient must be non-negative");
}

double StribeckCurve::mu(double u) const {
  return p_.mu_coulomb + (p_.mu_breakaway - p_.mu_coulomb) * std::exp(-std::pow(u / p_.stribeck_speed_m_per_s, p_.exponent)) +
         p_.viscous_per_m_per_s * u;
}

double StribeckCurve::slope_per_m_per_s(double u) const {
  if (u <= 0.0) return p_.exponent == 1.0 ? -(p_.mu_breakaway - p_.mu_coulomb) / p_.stribeck_speed_m_per_s + p_.viscous_per_m_per_s
                                          : p_.viscous_per_m_per_s;
  const double r = u / p_.stribeck_speed_m_per_s;
  return -(p_.mu_breakaway - p_.mu_coulomb) * std::exp(-std::pow(r, p_.exponent)) * p_.exponent * std::pow(r, p_.exponent - 1.0) /
             p_.stribeck_speed_m_per_s +
         p_.viscous_per_m_per_s;
}

TabulatedCurve::TabulatedCurve(std::vector<double> u, std::vector<double> mu) : u_(std::move(u)), mu_(std::move(mu)) {
  require(u_.size() >= 2 && u_.size() == mu_.size(), "kinetic table needs at least two (speed, mu) pairs of equal length");
  for (std::size_t i = 0; i < u_.size(); ++i) {
    require(finite_non_negative(u_[i]), "kinetic table speed " + std::to_string(i) + " must be finite and non-negative");
    require(finite_non_negative(mu_[i]), "kinetic table mu " + std::to_string(i) + " must be finite and non-negative");
    require(i == 0 || u_[i] > u_[i - 1], "kinetic table speeds must increase strictly (entry " + std::to_string(i) + ")");
  }
}

double TabulatedCurve::mu(double u) const {
  if (u <= u_.front()) return mu_.front();
  if (u >= u_.back()) return mu_.back();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(u_.begin(), u_.end(), u) - u_.begin()) - 1;
  const double w = (u - u_[i]) / (u_[i + 1] - u_[i]);
  return (1.0 - w) * mu_[i] + w * mu_[i + 1];
}

double TabulatedCurve::slope_per_m_per_s(double u) const {
  if (u < u_.front() || u >= u_.back()) return 0.0;
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(u_.begin(), u_.end(), u) - u_.begin()) - 1;
  return (mu_[i + 1] - mu_[i]) / (u_[i + 1] - u_[i]);
}

KineticCurveLaw::KineticCurveLaw(double mu_s, std::shared_ptr<const KineticCurve> kinetic)
    : mu_s_(mu_s), kinetic_(std::move(kinetic)) {
  require(finite_non_negative(mu_s), "mu_s must be finite and non-negative");
  require(kinetic_ != nullptr, "kinetic curve missing");
}

std::unique_ptr<KineticCurveLaw> make_coulomb(double mu_s, double mu_k) {
  require(finite_non_negative(mu_s) && finite_non_negative(mu_k), "mu_s and mu_k must be finite and non-negative");
  require(mu_k <= mu_s, "mu_k must not exceed mu_s");
  return std::make_unique<KineticCurveLaw>(mu_s, std::make_shared<ConstantCurve>(mu_k));
}

}  // namespace tribo::rig
