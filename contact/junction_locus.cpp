#include "contact/junction_locus.h"
#include "numerics/format.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <stdexcept>
#include <string>

namespace tribo::contact {
namespace {

// The message is a literal, so a check that passes allocates nothing: the rig's event functions
// ask for μs on the locus at every integrator step.
void require_locus(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("junction model: ") + what);
}

// Shape factor g(μ) = μ^{-n} S^{-(1+n)} [√(1+αμ²) − Sμ] of (3.1.24); φ̇ = L g(μ).
// Strictly decreasing on (0, μs,max] because S > √α makes the bracket decrease.
double shape(const JunctionLocus& l, double mu) {
  const double s = l.sigma0_over_tau_i;
  return std::pow(mu, -l.n) * std::pow(s, -(1.0 + l.n)) * (std::sqrt(1.0 + l.alpha * mu * mu) - s * mu);
}

// With σ0 = κ φ̇^m, φ̇ = L_ref (φ̇/φ̇_ref)^{m(1+n)} g(μ); returns the exponent m(1+n).
double hardening_exponent(const JunctionLocus& l) { return l.strain_rate_index_m * (1.0 + l.n); }

}  // namespace

void validate(const JunctionLocus& l) {
  require_locus(std::isfinite(l.alpha) && l.alpha > 0.0, "alpha must be positive (thesis: 10..25)");
  require_locus(std::isfinite(l.n) && l.n >= 0.0, "n must be non-negative (thesis: 1..1.5)");
  require_locus(std::isfinite(l.sigma0_over_tau_i) && l.sigma0_over_tau_i * l.sigma0_over_tau_i > l.alpha,
                "sigma0/tau_i squared must exceed alpha (3.1.23), otherwise there is no upper asymptote");
  require_locus(std::isfinite(l.location_per_s) && l.location_per_s > 0.0, "location parameter must be positive");
  require_locus(std::isfinite(l.strain_rate_index_m) && l.strain_rate_index_m >= 0.0 && hardening_exponent(l) < 1.0,
                "strain-rate index m must satisfy 0 <= m (1 + n) < 1");
  require_locus(std::isfinite(l.reference_load_rate_per_s) && l.reference_load_rate_per_s > 0.0,
                "reference load rate must be positive");
}

double sigma0_over_tau_i_from_upper_asymptote(double mu_s_max, double alpha) {
  require_locus(std::isfinite(mu_s_max) && mu_s_max > 0.0, "upper asymptote mu_s_max must be positive");
  require_locus(std::isfinite(alpha) && alpha > 0.0, "alpha must be positive");
  return std::sqrt(1.0 / (mu_s_max * mu_s_max) + alpha);  // thesis (3.1.23)
}

double upper_asymptote(const JunctionLocus& l) {
  validate(l);
  return 1.0 / std::sqrt(l.sigma0_over_tau_i * l.sigma0_over_tau_i - l.alpha);
}

double load_rate_at_static_friction_per_s(const JunctionLocus& l, double mu_s) {
  const double mu_max = upper_asymptote(l);
  if (!(std::isfinite(mu_s) && mu_s > 0.0 && mu_s <= mu_max))
    throw std::invalid_argument("junction model: mu_s must lie in (0, " + numerics::shortest(mu_max) + "]");
  const double g = shape(l, mu_s);
  if (g <= 0.0) return 0.0;
  // φ̇^{1−m(1+n)} = L_ref φ̇_ref^{−m(1+n)} g(μ)   — (3.1.24) with (5.1.2)
  const double e = hardening_exponent(l);
  return std::pow(l.location_per_s * std::pow(l.reference_load_rate_per_s, -e) * g, 1.0 / (1.0 - e));
}

namespace {

double solve_static_friction(const JunctionLocus& l, double phi_dot_per_s) {
  const double mu_max = upper_asymptote(l);
  require_locus(std::isfinite(phi_dot_per_s) && phi_dot_per_s >= 0.0, "load rate must be finite and non-negative");
  if (phi_dot_per_s == 0.0) return mu_max;
  // (3.1.24) with (5.1.2) in logarithms: F(μ) = ln q(μ) − n ln μ − c = 0, q = √(1+αμ²) − Sμ and
  // c = ln(φ̇^{1−m(1+n)} φ̇_ref^{m(1+n)} S^{1+n} / L_ref). q falls from 1 at μ = 0 to 0 at μs,max, so
  // F falls from +∞ to −∞ and the root is unique. q is written as (1 − μ²/μs,max²)/(√(1+αμ²) + Sμ),
  // which has no cancellation near the asymptote.
  const double s = l.sigma0_over_tau_i, e = hardening_exponent(l);
  const double c = (1.0 - e) * std::log(phi_dot_per_s) + e * std::log(l.reference_load_rate_per_s) + (1.0 + l.n) * std::log(s) -
                   std::log(l.location_per_s);
  // F and dF/d(ln μ) at μ.
  auto residual = [&](double mu) {
    const double r = std::sqrt(1.0 + l.alpha * mu * mu), x = mu / mu_max;
    const double q = (1.0 - x) * (1.0 + x) / (r + s * mu);
    return std::make_pair(std::log(q) - l.n * std::log(mu) - c, mu * (l.alpha * mu / r - s) / q - l.n);
  };
  // Since q ≤ 1, F(μ) ≤ −n ln μ − c: the root lies at or below e^{−c/n}, which is the root itself
  // where q ≈ 1 (fast loading, small μs). Newton's method in ln μ from that side, where F is
  // concave, approaches the root monotonically; a step out of the bracket bisects instead.
  if (l.n == 0.0 && c >= 0.0) return 0.0;  // without anelastic damping, loading at φ̇ ≥ L_ref/S slips at once
  double lo = 0.0, hi = mu_max;
  if (l.n > 0.0) hi = std::min(hi, std::exp(-c / l.n));
  if (!(hi > 0.0)) return 0.0;  // φ̇ so large that μs underflows
  double mu = hi == mu_max ? 0.5 * mu_max : hi;
  for (int i = 0; i < 200; ++i) {
    const auto [f, slope] = residual(mu);
    if (f == 0.0) return mu;
    (f > 0.0 ? lo : hi) = mu;
    double next = mu * std::exp(-f / slope);
    if (std::abs(next - mu) <= 4e-16 * mu) return next;  // before the bracket: at the root, roundoff puts it on a bound
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo <= 4e-16 * hi) return next;
    mu = next;
  }
  throw std::logic_error("junction model: static friction root not found for load rate " + numerics::shortest(phi_dot_per_s) + " 1/s");
}

// Every field compared: a field added to JunctionLocus must be added here (the assertion fails).
static_assert(sizeof(JunctionLocus) == 6 * sizeof(double), "same_locus compares every field of JunctionLocus");
bool same_locus(const JunctionLocus& a, const JunctionLocus& b) {
  return a.alpha == b.alpha && a.n == b.n && a.sigma0_over_tau_i == b.sigma0_over_tau_i && a.location_per_s == b.location_per_s &&
         a.strain_rate_index_m == b.strain_rate_index_m && a.reference_load_rate_per_s == b.reference_load_rate_per_s;
}

}  // namespace

double static_friction_from_load_rate(const JunctionLocus& l, double phi_dot_per_s) {
  // A rig asks at one load rate again and again while its contact is stuck (a constant drive loads
  // the spring at a constant rate): each thread keeps its last answer, the same bits as solving again.
  struct Last {
    JunctionLocus locus;
    double phi_dot_per_s = std::numeric_limits<double>::quiet_NaN(), mu_s = 0.0;
  };
  thread_local Last last;
  if (phi_dot_per_s == last.phi_dot_per_s && same_locus(l, last.locus)) return last.mu_s;
  const double mu_s = solve_static_friction(l, phi_dot_per_s);
  last = {l, phi_dot_per_s, mu_s};
  return mu_s;
}

double location_through_point_per_s(const JunctionLocus& shape_params, double phi_dot_per_s, double mu_s) {
  JunctionLocus l = shape_params;
  l.location_per_s = 1.0;
  const double mu_max = upper_asymptote(l);
  require_locus(std::isfinite(mu_s) && mu_s > 0.0 && mu_s < mu_max, "mu_s must lie below the upper asymptote");
  require_locus(std::isfinite(phi_dot_per_s) && phi_dot_per_s > 0.0, "load rate must be positive");
  const double e = hardening_exponent(l);
  return std::pow(phi_dot_per_s, 1.0 - e) * std::pow(l.reference_load_rate_per_s, e) / shape(l, mu_s);
}

double tabor_area_m2(double normal_load_N, double tangential_load_N, double alpha, double sigma0_Pa) {
  require_locus(std::isfinite(normal_load_N) && normal_load_N >= 0.0, "normal load must be non-negative");
  require_locus(std::isfinite(tangential_load_N), "tangential load must be finite");
  require_locus(std::isfinite(alpha) && alpha >= 0.0, "alpha must be non-negative");
  require_locus(std::isfinite(sigma0_Pa) && sigma0_Pa > 0.0, "flow stress sigma0 must be positive");
  return std::sqrt(normal_load_N * normal_load_N + alpha * tangential_load_N * tangential_load_N) / sigma0_Pa;  // (3.1.9)
}

}  // namespace tribo::contact
