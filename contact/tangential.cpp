#include "contact/tangential.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tribo::contact {

TangentialContactResult solve_tangential_load(ElasticHalfSpace& hs, const Eigen::ArrayXXd& gap0, double w, double f,
                                              const TangentialContactOptions& opt) {
  if (!(std::isfinite(opt.hardness_Pa) && opt.hardness_Pa > 0.0)) {
    throw std::invalid_argument("junction growth: hardness must be positive and finite");
  }
  if (!(std::isfinite(opt.alpha) && opt.alpha >= 0.0)) throw std::invalid_argument("junction growth: alpha must be >= 0");
  if (!(opt.interface_shear_strength_Pa > 0.0)) {
    throw std::invalid_argument("junction growth: interface shear strength must be positive");
  }
  if (!(opt.cap_tolerance > 0.0 && opt.cap_tolerance < 1.0) || opt.max_outer_iterations < 1) {
    throw std::invalid_argument("junction growth: cap_tolerance must lie in (0, 1), max_outer_iterations >= 1");
  }
  if (!(std::isfinite(w) && w > 0.0)) throw std::invalid_argument("junction growth: normal load must be positive");
  if (!(std::isfinite(f) && f >= 0.0)) throw std::invalid_argument("junction growth: tangential load must be >= 0");
  const double sigma0 = opt.hardness_Pa, nominal = hs.grid().area_m2();
  if (w * w + opt.alpha * f * f > std::pow(sigma0 * nominal, 2) * (1.0 + 1e-12)) {
    throw std::invalid_argument("junction growth: sqrt(W^2 + alpha F^2) exceeds hardness * domain area; the junction "
                                "would outgrow the domain");
  }

  TangentialContactResult out;
  out.tangential_load_N = f;
  NormalContactOptions normal = opt.normal;
  const Eigen::ArrayXXd* warm = nullptr;
  auto solve_at = [&](double cap) {
    normal.pressure_cap_Pa = cap;
    out.contact = solve_normal_load(hs, gap0, w, normal, warm);
    out.inner_iterations += out.contact.summary.iterations;
    warm = &out.contact.pressure_Pa;
    const double tau = f / out.contact.real_area_m2;
    return cap * cap + opt.alpha * tau * tau - sigma0 * sigma0;
  };

  // ψ(σ0) ≥ 0; the lower end c = W/A_nominal saturates the domain (A = A_nominal), where the
  // check above makes ψ ≤ 0. Regula falsi with the Illinois modification on [c_lo, c_hi].
  double c_hi = sigma0, psi_hi = solve_at(c_hi);
  double c = c_hi, psi = psi_hi;
  int outer = 1;
  bool done = f == 0.0 || psi_hi <= opt.cap_tolerance * sigma0 * sigma0;
  if (!done) {
    double c_lo = w / nominal, psi_lo = c_lo * c_lo + opt.alpha * std::pow(f / nominal, 2) - sigma0 * sigma0;
    int side = 0;
    while (outer < opt.max_outer_iterations) {
      c = (c_lo * psi_hi - c_hi * psi_lo) / (psi_hi - psi_lo);
      if (!(c > c_lo && c < c_hi)) c = 0.5 * (c_lo + c_hi);
      psi = solve_at(c);
      ++outer;
      if (std::abs(psi) <= opt.cap_tolerance * sigma0 * sigma0) {
        done = true;
        break;
      }
      if (psi > 0.0) {
        c_hi = c, psi_hi = psi;
        if (side == 1) psi_lo *= 0.5;
        side = 1;
      } else {
        c_lo = c, psi_lo = psi;
        if (side == -1) psi_hi *= 0.5;
        side = -1;
      }
      if (c_hi - c_lo <= opt.cap_tolerance * sigma0) {
        // A(c) jumps by whole cells: settle on the admissible side, p² + α τ² ≤ σ0².
        if (psi > 0.0) psi = solve_at(c_lo), c = c_lo;
        done = true;
        break;
      }
    }
  }
  out.outer_iterations = outer;
  out.pressure_cap_Pa = c;
  out.shear_stress_Pa = f / out.contact.real_area_m2;
  out.slipped = out.shear_stress_Pa >= opt.interface_shear_strength_Pa;
  out.converged = done && out.contact.summary.converged;
  std::ostringstream msg;
  msg << (out.converged ? "converged" : "not converged") << " after " << outer << " elastic-plastic solves: cap "
      << c << " Pa, tau " << out.shear_stress_Pa << " Pa, consistency residual " << psi / (sigma0 * sigma0)
      << "; last solve: " << out.contact.summary.message;
  if (out.slipped) msg << "; the junction slips (tau >= tau_i)";
  out.message = msg.str();
  return out;
}

}  // namespace tribo::contact
