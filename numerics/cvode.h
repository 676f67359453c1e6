// Move-only owner of a SUNDIALS CVODE integrator (context, state vector, dense linear solver)
// with root finding: the one wrapper the libraries integrate with. Every SUNDIALS return code is
// checked; a failure throws std::runtime_error naming the call and its flag (e.g. CV_ILL_INPUT),
// except CVode() itself (advance), whose outcome the caller decides on.
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <span>
#include <string>
#include <vector>

namespace tribo::numerics {

struct CvodeSettings {
  // Adams–Moulton for non-stiff systems, BDF for stiff ones; both with a Newton corrector on a
  // dense difference-quotient Jacobian.
  enum class Method { adams, bdf } method = Method::bdf;
  double relative_tolerance = 1e-6;
  std::vector<double> absolute_tolerances;  // one per state component: their count is the size
  long max_steps = 500;                     // per advance()
};

class Cvode {
 public:
  // Integrates y' = rhs(t, y) from (t0, y0); `user_data` is handed to rhs and the root function.
  Cvode(CVRhsFn rhs, void* user_data, const CvodeSettings& settings, double t0, std::span<const double> y0);
  ~Cvode();
  Cvode(const Cvode&) = delete;
  Cvode& operator=(const Cvode&) = delete;

  // Restarts at (t, y) — needed wherever the right-hand side jumps (an event, a drive breakpoint).
  void restart(double t, std::span<const double> y);
  // Roots g_i(t, y) = 0 to locate; `directions[i]` = −1 reports only decreasing crossings of
  // root i, +1 only increasing ones, 0 both.
  void set_roots(CVRootFn roots, std::span<const int> directions);
  // advance() never steps past t_stop.
  void set_stop_time(double t_stop_s);

  // Advances towards t_out; returns CV_SUCCESS, CV_ROOT_RETURN, CV_TSTOP_RETURN or a negative
  // CVODE flag (describe() names it).
  int advance(double t_out, double& t_reached);
  // One internal step (CVODE's CV_ONE_STEP), same returns: roots are checked once over the whole
  // step, where advance() checks them again at every t_out inside it — dear when output is denser
  // than the steps. t_out, the next output time, bounds the first step after a restart (as it
  // does for advance()) and is otherwise unused. state() is then the state at t_reached.
  int step(double t_out, double& t_reached);
  // The state at t within the last step, from CVODE's interpolating polynomial (CVodeGetDky).
  void interpolate(double t, std::span<double> y);

  std::span<double> state();
  // Which roots fired at the last CV_ROOT_RETURN (non-zero entries), one entry per root.
  std::vector<int> roots_found() const;
  long steps() const;

  // "CV_ILL_INPUT (-22)": a CVODE return flag by name.
  static std::string describe(int flag);
  // CVODE's own text of its last error or warning ("At t = … the corrector convergence test
  // failed …"); empty if none. CVODE's messages are kept here, not printed: a failure reaches the
  // caller through advance()'s flag, and a fit that probes stalling parameter sets would
  // otherwise fill the terminal with them.
  const std::string& last_message() const { return last_message_; }

 private:
  void release();
  static void keep_message(int error_code, const char* module, const char* function, char* message, void* self);

  SUNContext ctx_ = nullptr;
  N_Vector y_ = nullptr;
  N_Vector abstol_ = nullptr;
  N_Vector dense_ = nullptr;  // interpolate()'s output
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver solver_ = nullptr;
  void* mem_ = nullptr;
  std::size_t size_;
  std::size_t root_count_ = 0;
  std::string last_message_;
};

}  // namespace tribo::numerics
