// Restarted GMRES with right preconditioning — SUNDIALS' SPGMR (sunlinsol_spgmr.h) on Eigen vectors,
// for linear systems that are applied rather than stored (the EHL point contact's Newton steps:
// a sparse film stencil times the FFT elastic operator, lubrication/ehl_point.h).
//
// Stops when the true residual, unpreconditioned and unscaled, satisfies
//     ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂
// (right preconditioning leaves SPGMR's residual the true one), or after max_restarts restarts of
// Krylov dimension krylov_dimension. Every SUNDIALS return code is checked; a solve that stops
// short returns converged = false with its iterate in x, the iterations and the residual reached.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <string>

namespace tribo::numerics {

struct GmresOptions {
  double relative_tolerance = 1e-8;
  int krylov_dimension = 60;  // basis vectors before a restart
  int max_restarts = 4;
};

struct GmresSummary {
  bool converged = false;
  int iterations = 0;               // Krylov iterations, restarts included
  double relative_residual = 0.0;   // ‖b − A x‖₂ / ‖b‖₂ as SPGMR reports it at return
  std::string message;              // the SUNDIALS flag when not converged
};

// y = A v and z ≈ M⁻¹ r (the preconditioner; identity when empty). Each returns false on failure,
// which stops the solve with that message.
using LinearMap = std::function<bool(const Eigen::VectorXd& in, Eigen::VectorXd& out)>;

// Solves A x = b from x = 0. Throws std::invalid_argument for an empty b or non-positive options.
GmresSummary gmres(const LinearMap& apply, const LinearMap& precondition, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   const GmresOptions& options = {});

}  // namespace tribo::numerics
