// Move-only owner of a SUNDIALS CVODE integrator (context, vector, dense linear solver) with
// root finding. Every CVODE return code is checked; failures throw std::runtime_error with the
// function name and code, except CVode() itself whose outcome is returned to the caller.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <span>
#include <vector>

namespace tribo::rig::internal {

class CvodeIntegrator {
 public:
  CvodeIntegrator(std::size_t size, CVRhsFn rhs, CVRootFn roots, void* user_data,
                  double relative_tolerance, std::span<const double> absolute_tolerances);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // Restart at (t, y) — after every event or drive breakpoint, since the right-hand side jumps.
  // `directions[i]` = −1 reports only decreasing crossings of root i, +1 increasing, 0 both.
  void restart(double t, std::span<const double> y, std::span<const int> directions, double stop_time);

  // Advances towards t_out; returns CV_SUCCESS, CV_ROOT_RETURN, CV_TSTOP_RETURN or a negative code.
  int advance(double t_out, double& t_reached);

  std::span<double> state();
  // Which roots fired at the last CV_ROOT_RETURN (non-zero entries).
  std::vector<int> roots_found(std::size_t n) const;
  long steps() const;

 private:
  void release();

  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector abstol_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
  void* mem_ = nullptr;
  CVRootFn roots_;
  std::size_t size_;
  bool initialised_ = false;
};

}  // namespace tribo::rig::internal
