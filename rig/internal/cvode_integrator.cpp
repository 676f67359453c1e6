#include "rig/internal/cvode_integrator.h"

#include <stdexcept>
#include <string>

namespace tribo::rig::internal {
namespace {
void check(int flag, const char* fn) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE: ") + fn + " failed with code " + std::to_string(flag));
}
template <class T>
T* check_ptr(T* p, const char* fn) {
  if (!p) throw std::runtime_error(std::string("CVODE: ") + fn + " returned null");
  return p;
}
}  // namespace

CvodeIntegrator::CvodeIntegrator(std::size_t size, CVRhsFn rhs, CVRootFn roots, void* user_data,
                                 double relative_tolerance, std::span<const double> absolute_tolerances)
    : roots_(roots), size_(size) {
  try {
    check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
    const auto n = static_cast<sunindextype>(size);
    y_ = check_ptr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    abstol_ = check_ptr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    for (std::size_t i = 0; i < size; ++i) {
      NV_Ith_S(y_, i) = 0.0;
      NV_Ith_S(abstol_, i) = absolute_tolerances[i];
    }
    // Adams–Moulton: the rig is a lightly damped oscillator, non-stiff; Newton with a dense
    // Jacobian (by difference quotients) keeps the corrector robust across friction jumps.
    mem_ = check_ptr(CVodeCreate(CV_ADAMS, ctx_), "CVodeCreate");
    check(CVodeInit(mem_, rhs, 0.0, y_), "CVodeInit");
    check(CVodeSetUserData(mem_, user_data), "CVodeSetUserData");
    check(CVodeSVtolerances(mem_, relative_tolerance, abstol_), "CVodeSVtolerances");
    matrix_ = check_ptr(SUNDenseMatrix(n, n, ctx_), "SUNDenseMatrix");
    solver_ = check_ptr(SUNLinSol_Dense(y_, matrix_, ctx_), "SUNLinSol_Dense");
    check(CVodeSetLinearSolver(mem_, solver_, matrix_), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem_, 200000), "CVodeSetMaxNumSteps");
    check(CVodeSetNoInactiveRootWarn(mem_), "CVodeSetNoInactiveRootWarn");
  } catch (...) {
    release();
    throw;
  }
}

CvodeIntegrator::~CvodeIntegrator() { release(); }

void CvodeIntegrator::release() {
  if (mem_) CVodeFree(&mem_);
  if (solver_) SUNLinSolFree(solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  if (abstol_) N_VDestroy(abstol_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr, solver_ = nullptr, matrix_ = nullptr, abstol_ = nullptr, y_ = nullptr, ctx_ = nullptr;
}

void CvodeIntegrator::restart(double t, std::span<const double> y, std::span<const int> directions, double stop_time) {
  for (std::size_t i = 0; i < size_; ++i) NV_Ith_S(y_, i) = y[i];
  check(CVodeReInit(mem_, t, y_), "CVodeReInit");
  check(CVodeRootInit(mem_, static_cast<int>(directions.size()), roots_), "CVodeRootInit");
  std::vector<int> dirs(directions.begin(), directions.end());
  check(CVodeSetRootDirection(mem_, dirs.data()), "CVodeSetRootDirection");
  check(CVodeSetStopTime(mem_, stop_time), "CVodeSetStopTime");
  initialised_ = true;
}

int CvodeIntegrator::advance(double t_out, double& t_reached) {
  return CVode(mem_, t_out, y_, &t_reached, CV_NORMAL);
}

std::span<double> CvodeIntegrator::state() { return {N_VGetArrayPointer(y_), size_}; }

std::vector<int> CvodeIntegrator::roots_found(std::size_t n) const {
  std::vector<int> found(n, 0);
  check(CVodeGetRootInfo(mem_, found.data()), "CVodeGetRootInfo");
  return found;
}

long CvodeIntegrator::steps() const {
  long n = 0;
  check(CVodeGetNumSteps(mem_, &n), "CVodeGetNumSteps");
  return n;
}

}  // namespace tribo::rig::internal
