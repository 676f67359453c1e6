#include "numerics/dense_solve.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" void dgesv_(const int* n, const int* nrhs, double* a, const int* lda, int* ipiv, double* b, const int* ldb, int* info);

namespace tribo::numerics {

bool dense_solve(Eigen::MatrixXd& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (a.rows() != a.cols() || a.rows() != b.size())
    throw std::logic_error("dense_solve: a " + std::to_string(a.rows()) + " × " + std::to_string(a.cols()) + " matrix with " +
                           std::to_string(b.size()) + " right-hand sides");
  const int n = static_cast<int>(a.rows()), one = 1, lda = std::max(1, n);
  std::vector<int> pivots(static_cast<std::size_t>(n));
  x = b;
  int info = 0;
  dgesv_(&n, &one, a.data(), &lda, pivots.data(), x.data(), &lda, &info);
  if (info < 0) throw std::logic_error("dense_solve: LAPACK dgesv rejected its argument " + std::to_string(-info));
  return info == 0;
}

}  // namespace tribo::numerics
