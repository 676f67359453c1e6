#include "numerics/cvode.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace tribo::numerics {
namespace {
void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE: ") + call + " failed with " + Cvode::describe(flag));
}
template <class T>
T* check_ptr(T* p, const char* call) {
  if (p == nullptr) throw std::runtime_error(std::string("CVODE: ") + call + " returned null (out of memory?)");
  return p;
}
}  // namespace

std::string Cvode::describe(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS
  std::string text = name != nullptr ? std::string(name) : std::string("unknown flag");
  std::free(name);
  return text + " (" + std::to_string(flag) + ")";
}

Cvode::Cvode(CVRhsFn rhs, void* user_data, const CvodeSettings& settings, double t0, std::span<const double> y0)
    : size_(settings.absolute_tolerances.size()) {
  if (size_ == 0 || y0.size() != size_) {
    throw std::invalid_argument("CVODE: the initial state and the absolute tolerances must have the same, non-zero size");
  }
  try {
    check(SUNContext_Create(nullptr, &ctx_), "SUNContext_Create");
    const auto n = static_cast<sunindextype>(size_);
    y_ = check_ptr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    abstol_ = check_ptr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    dense_ = check_ptr(N_VNew_Serial(n, ctx_), "N_VNew_Serial");
    for (std::size_t i = 0; i < size_; ++i) {
      NV_Ith_S(y_, i) = y0[i];
      NV_Ith_S(abstol_, i) = settings.absolute_tolerances[i];
    }
    mem_ = check_ptr(CVodeCreate(settings.method == CvodeSettings::Method::adams ? CV_ADAMS : CV_BDF, ctx_), "CVodeCreate");
    check(CVodeInit(mem_, rhs, t0, y_), "CVodeInit");
    check(CVodeSetUserData(mem_, user_data), "CVodeSetUserData");
    check(CVodeSetErrHandlerFn(mem_, &Cvode::keep_message, this), "CVodeSetErrHandlerFn");
    check(CVodeSVtolerances(mem_, settings.relative_tolerance, abstol_), "CVodeSVtolerances");
    matrix_ = check_ptr(SUNDenseMatrix(n, n, ctx_), "SUNDenseMatrix");
    solver_ = check_ptr(SUNLinSol_Dense(y_, matrix_, ctx_), "SUNLinSol_Dense");
    check(CVodeSetLinearSolver(mem_, solver_, matrix_), "CVodeSetLinearSolver");
    check(CVodeSetMaxNumSteps(mem_, settings.max_steps), "CVodeSetMaxNumSteps");
    // A restart at an event sits exactly on the root that fired: expected, not worth a warning.
    check(CVodeSetNoInactiveRootWarn(mem_), "CVodeSetNoInactiveRootWarn");
  } catch (...) {
    release();
    throw;
  }
}

Cvode::~Cvode() { release(); }

void Cvode::keep_message(int, const char*, const char*, char* message, void* self) {
  static_cast<Cvode*>(self)->last_message_ = message != nullptr ? message : "";
}

void Cvode::release() {
  if (mem_) CVodeFree(&mem_);
  if (solver_) SUNLinSolFree(solver_);
  if (matrix_) SUNMatDestroy(matrix_);
  if (abstol_) N_VDestroy(abstol_);
  if (dense_) N_VDestroy(dense_);
  if (y_) N_VDestroy(y_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr, solver_ = nullptr, matrix_ = nullptr, abstol_ = nullptr, dense_ = nullptr, y_ = nullptr, ctx_ = nullptr;
}

void Cvode::restart(double t, std::span<const double> y) {
  for (std::size_t i = 0; i < size_; ++i) NV_Ith_S(y_, i) = y[i];
  check(CVodeReInit(mem_, t, y_), "CVodeReInit");
}

void Cvode::set_roots(CVRootFn roots, std::span<const int> directions) {
  root_count_ = directions.size();
  check(CVodeRootInit(mem_, static_cast<int>(root_count_), roots), "CVodeRootInit");
  std::vector<int> dirs(directions.begin(), directions.end());  // CVODE takes a non-const pointer
  check(CVodeSetRootDirection(mem_, dirs.data()), "CVodeSetRootDirection");
}

void Cvode::set_stop_time(double t_stop_s) { check(CVodeSetStopTime(mem_, t_stop_s), "CVodeSetStopTime"); }

int Cvode::advance(double t_out, double& t_reached) { return CVode(mem_, t_out, y_, &t_reached, CV_NORMAL); }

int Cvode::step(double t_out, double& t_reached) { return CVode(mem_, t_out, y_, &t_reached, CV_ONE_STEP); }

void Cvode::interpolate(double t, std::span<double> y) {
  check(CVodeGetDky(mem_, t, 0, dense_), "CVodeGetDky");
  const double* d = N_VGetArrayPointer(dense_);
  std::copy(d, d + size_, y.begin());
}

std::span<double> Cvode::state() { return {N_VGetArrayPointer(y_), size_}; }

std::vector<int> Cvode::roots_found() const {
  std::vector<int> found(root_count_, 0);
  check(CVodeGetRootInfo(mem_, found.data()), "CVodeGetRootInfo");
  return found;
}

long Cvode::steps() const {
  long n = 0;
  check(CVodeGetNumSteps(mem_, &n), "CVodeGetNumSteps");
  return n;
}

}  // namespace tribo::numerics
