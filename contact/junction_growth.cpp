#include "contact/junction_growth.h"

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "numerics/cvode.h"
#include "numerics/format.h"

namespace tribo::contact {
namespace {

void require_ramp(bool ok, const char* what) {  // literal: nothing built unless it fails
  if (!ok) throw std::invalid_argument(std::string("junction ramp: ") + what);
}

// Dimensionless problem (see header): aⁿ da/ds = √(1 + α f²) − a, f = f0 + r s, root f − a/S.
struct Scaled {
  double alpha, n, f0, r, s_ratio;
  double f(double s) const { return f0 + r * s; }
  double rate(double s, double a) const { return (std::sqrt(1.0 + alpha * f(s) * f(s)) - a) / std::pow(a, n); }
};

int rhs(sunrealtype s, N_Vector y, N_Vector ydot, void* data) {
  const auto* p = static_cast<const Scaled*>(data);
  const double a = NV_Ith_S(y, 0);
  if (!(a > 0.0)) return 1;  // recoverable: CVODE retries with a smaller step
  NV_Ith_S(ydot, 0) = p->rate(s, a);
  return 0;
}

int slip_root(sunrealtype s, N_Vector y, sunrealtype* g, void* data) {
  const auto* p = static_cast<const Scaled*>(data);
  g[0] = p->f(s) - NV_Ith_S(y, 0) / p->s_ratio;
  return 0;
}

// Advances to s_out or to the slip root; returns true at the root.
bool advance(numerics::Cvode& cv, double s_out, double& s) {
  const int flag = cv.advance(s_out, s);
  if (flag < 0) {
    throw std::runtime_error("junction ramp: CVODE failed at s = " + numerics::shortest(s) + " with " + numerics::Cvode::describe(flag) + ": " + cv.last_message());
  }
  return flag == CV_ROOT_RETURN;
}

}  // namespace

double damping_from_location(double w, double sigma0, double n, double location) {
  require_ramp(std::isfinite(w) && w > 0.0, "normal load must be positive");
  require_ramp(std::isfinite(sigma0) && sigma0 > 0.0, "hardness must be positive");
  require_ramp(std::isfinite(n) && n >= 0.0, "n must be non-negative");
  require_ramp(std::isfinite(location) && location > 0.0, "location parameter must be positive");
  return std::pow(sigma0, 1.0 + n) / (std::pow(w, n) * location);
}

JunctionRampResult integrate_junction_ramp(const JunctionRampParams& p) {
  require_ramp(std::isfinite(p.normal_load_N) && p.normal_load_N > 0.0, "normal_load_N must be positive");
  require_ramp(std::isfinite(p.hardness_Pa) && p.hardness_Pa > 0.0, "hardness_Pa must be positive");
  require_ramp(std::isfinite(p.alpha) && p.alpha >= 0.0, "alpha must be non-negative");
  require_ramp(std::isfinite(p.interface_shear_strength_Pa) && p.interface_shear_strength_Pa > 0.0 &&
                   std::pow(p.hardness_Pa / p.interface_shear_strength_Pa, 2) > p.alpha,
               "interface_shear_strength_Pa must be positive with (sigma0/tau_i)^2 > alpha (3.1.23)");
  require_ramp(std::isfinite(p.n) && p.n >= 0.0, "n must be non-negative");
  require_ramp(std::isfinite(p.damping_b) && p.damping_b > 0.0, "damping_b must be positive");
  require_ramp(std::isfinite(p.load_rate_N_per_s) && p.load_rate_N_per_s > 0.0, "load_rate_N_per_s must be positive");
  require_ramp(std::isfinite(p.initial_tangential_load_N) && p.initial_tangential_load_N >= 0.0,
               "initial_tangential_load_N must be non-negative");
  require_ramp(p.relative_tolerance > 0.0 && p.relative_tolerance < 1e-2, "relative_tolerance must lie in (0, 1e-2)");
  require_ramp(p.trajectory_samples >= 0, "trajectory_samples must be >= 0");

  const double w = p.normal_load_N, sigma0 = p.hardness_Pa;
  const double location = std::pow(sigma0, 1.0 + p.n) / (std::pow(w, p.n) * p.damping_b);  // L, 1/s
  Scaled sc{p.alpha, p.n, p.initial_tangential_load_N / w, p.load_rate_N_per_s / (w * location),
            sigma0 / p.interface_shear_strength_Pa};
  const double mu_max = 1.0 / std::sqrt(sc.s_ratio * sc.s_ratio - sc.alpha);  // (3.1.23)
  const double a0 = std::sqrt(1.0 + sc.alpha * sc.f0 * sc.f0);
  JunctionRampResult out;
  out.load_rate_per_s = p.load_rate_N_per_s / w;
  auto finish = [&](double s, double a) {
    out.slipped = true;
    out.slip_time_s = s / location;
    out.tangential_load_at_slip_N = w * sc.f(s);
    out.static_friction = sc.f(s);
    out.area_at_slip_m2 = a * w / sigma0;
    out.area_rate_at_slip_m2_per_s = sc.rate(s, a) * location * w / sigma0;
    out.phi_dot_at_slip_per_s = p.interface_shear_strength_Pa * out.area_rate_at_slip_m2_per_s / w;  // (3.1.21)
  };
  if (sc.f0 >= a0 / sc.s_ratio) {
    finish(0.0, a0);
    out.message = "slips at once: F0 >= tau_i A(0)";
    return out;
  }
  // Slip must occur by f = μs,max (the area never exceeds its equilibrium, see header); a little
  // beyond it bounds the integration.
  const double s_end = (mu_max * (1.0 + 1e-6) - sc.f0) / sc.r;
  // BDF: a slow ramp is stiff — a relaxes to its equilibrium within s ~ aⁿ, the ramp lasts s ~ μs,max / r.
  const numerics::CvodeSettings settings{numerics::CvodeSettings::Method::bdf, p.relative_tolerance, {p.relative_tolerance * a0}, 100000};
  numerics::Cvode cv(rhs, &sc, settings, 0.0, std::span<const double>(&a0, 1));
  const int up = 1;  // stick → slip: F − τ_i A crosses zero upwards
  cv.set_roots(slip_root, std::span<const int>(&up, 1));
  double s = 0.0;
  bool root = false;
  if (p.trajectory_samples > 0) {
    out.time_s.push_back(0.0);
    out.area_m2.push_back(a0 * w / sigma0);
    out.tangential_load_N.push_back(w * sc.f0);
    for (int k = 1; k <= p.trajectory_samples && !root; ++k) {
      root = advance(cv, s_end * k / p.trajectory_samples, s);
      out.time_s.push_back(s / location);
      out.area_m2.push_back(cv.state()[0] * w / sigma0);
      out.tangential_load_N.push_back(w * sc.f(s));
    }
  } else {
    root = advance(cv, s_end, s);
  }
  out.steps = cv.steps();
  if (!root) {
    out.message = "no slip before F/W reached the upper asymptote mu_s,max = " + numerics::shortest(mu_max);
    return out;
  }
  finish(s, cv.state()[0]);
  out.message = "slip at t = " + numerics::shortest(out.slip_time_s) + " s, mu_s = " + numerics::shortest(out.static_friction);
  return out;
}

}  // namespace tribo::contact
