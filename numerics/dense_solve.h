// The dense linear solve of the EHL Newton steps (lubrication/ehl_newton.h): LU with partial
// pivoting by LAPACK's dgesv, which on Debian is OpenBLAS's (libopenblas-openmp-dev: its kernels
// chosen for the CPU at run time, its threads OpenMP's, so a solve inside a parallel region runs
// on one). Eigen's own PartialPivLU runs the baseline x86-64 instruction set this library is
// compiled for; at the point contact's 1.5–3.5 k unknowns it took most of a solve.
#pragma once

#include <Eigen/Dense>

namespace tribo::numerics {

// Solves A x = b, overwriting A with its LU factors. Returns false when A is exactly singular
// (dgesv's info > 0: a zero pivot); x is then unspecified. An argument dgesv rejects (info < 0)
// is a bug here and throws std::logic_error.
bool dense_solve(Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x);

}  // namespace tribo::numerics
