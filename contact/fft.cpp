#include "contact/fft.h"

#include <fftw3.h>
#include <omp.h>

#include <algorithm>
#include <cassert>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

#include "numerics/huge_pages.h"

namespace tribo::contact {
namespace detail {
extern const char* const kShippedFftwWisdom;  // contact/fftw_wisdom.txt, compiled in by CMake
}  // namespace detail
namespace {

// FFTW's planner is not thread-safe; all planning and plan destruction goes through this lock.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

bool wisdom_loaded = false;

// Before the first plan: FFTW's threads, and the shipped wisdom (fft.h).
void init_threads_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (fftw_init_threads() == 0) throw std::runtime_error("FFTW: fftw_init_threads failed");
    std::lock_guard<std::mutex> lock(planner_mutex());
    wisdom_loaded = fftw_import_wisdom_from_string(detail::kShippedFftwWisdom) != 0;
  });
}

}  // namespace

bool shipped_fftw_wisdom_loaded() {
  init_threads_once();
  return wisdom_loaded;
}

RealFft2d::RealFft2d(Eigen::Index nx, Eigen::Index ny, int threads, bool measure) : nx_(nx), ny_(ny) {
  if (nx < 1 || ny < 1) {
    throw std::invalid_argument("FFT grid must have at least one point per direction, got " + std::to_string(nx) +
                                " x " + std::to_string(ny));
  }
  if (threads < 0) throw std::invalid_argument("FFT thread count must be >= 0, got " + std::to_string(threads));
  init_threads_once();
  real_ = static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(nx * ny)));
  spectrum_ = reinterpret_cast<std::complex<double>*>(
      fftw_malloc(sizeof(fftw_complex) * static_cast<std::size_t>(spectrum_size())));
  if (real_ == nullptr || spectrum_ == nullptr) {
    release();
    throw std::bad_alloc();
  }
  numerics::advise_huge_pages(real_, sizeof(double) * static_cast<std::size_t>(nx * ny));
  numerics::advise_huge_pages(spectrum_, sizeof(fftw_complex) * static_cast<std::size_t>(spectrum_size()));
  const unsigned flags = measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_plan_with_nthreads(threads == 0 ? omp_get_max_threads() : threads);
    // FFTW dimensions are [ny][nx] because x is contiguous (see fft.h).
    forward_plan_ = fftw_plan_dft_r2c_2d(static_cast<int>(ny), static_cast<int>(nx), real_,
                                         reinterpret_cast<fftw_complex*>(spectrum_), flags);
    inverse_plan_ = fftw_plan_dft_c2r_2d(static_cast<int>(ny), static_cast<int>(nx),
                                         reinterpret_cast<fftw_complex*>(spectrum_), real_, flags);
  }
  if (forward_plan_ == nullptr || inverse_plan_ == nullptr) {
    release();
    throw std::runtime_error("FFTW could not plan a " + std::to_string(nx) + " x " + std::to_string(ny) +
                             " real transform");
  }
  // FFTW_MEASURE overwrites the buffers while planning; start from a defined state.
  real().setZero();
}

RealFft2d::~RealFft2d() { release(); }

RealFft2d::RealFft2d(RealFft2d&& other) noexcept
    : nx_(std::exchange(other.nx_, 0)),
      ny_(std::exchange(other.ny_, 0)),
      real_(std::exchange(other.real_, nullptr)),
      spectrum_(std::exchange(other.spectrum_, nullptr)),
      forward_plan_(std::exchange(other.forward_plan_, nullptr)),
      inverse_plan_(std::exchange(other.inverse_plan_, nullptr)) {}

RealFft2d& RealFft2d::operator=(RealFft2d&& other) noexcept {
  if (this != &other) {
    release();
    nx_ = std::exchange(other.nx_, 0);
    ny_ = std::exchange(other.ny_, 0);
    real_ = std::exchange(other.real_, nullptr);
    spectrum_ = std::exchange(other.spectrum_, nullptr);
    forward_plan_ = std::exchange(other.forward_plan_, nullptr);
    inverse_plan_ = std::exchange(other.inverse_plan_, nullptr);
  }
  return *this;
}

void RealFft2d::release() noexcept {
  if (forward_plan_ != nullptr || inverse_plan_ != nullptr) {
    std::lock_guard<std::mutex> lock(planner_mutex());
    if (forward_plan_ != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
    if (inverse_plan_ != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(inverse_plan_));
  }
  forward_plan_ = inverse_plan_ = nullptr;
  fftw_free(real_);
  fftw_free(spectrum_);
  real_ = nullptr;
  spectrum_ = nullptr;
}

void RealFft2d::forward() {
  assert(forward_plan_ != nullptr && "RealFft2d used after move");
  fftw_execute(static_cast<fftw_plan>(forward_plan_));
}

void RealFft2d::inverse() {
  assert(inverse_plan_ != nullptr && "RealFft2d used after move");
  fftw_execute(static_cast<fftw_plan>(inverse_plan_));
}

void RealFft2d::forward(const double* in) {
  assert(forward_plan_ != nullptr && "RealFft2d used after move");
  // FFTW plans are only valid on arrays with the planning arrays' alignment (fftw3 manual,
  // "New-array Execute Functions"); Eigen's heap arrays usually match fftw_malloc's.
  double* src = const_cast<double*>(in);  // fftw's signature is non-const; r2c out-of-place preserves it
  if (src == real_) {
    forward();
  } else if (fftw_alignment_of(src) == fftw_alignment_of(real_)) {
    fftw_execute_dft_r2c(static_cast<fftw_plan>(forward_plan_), src, reinterpret_cast<fftw_complex*>(spectrum_));
  } else {
    real() = Eigen::Map<const Eigen::ArrayXXd>(in, nx_, ny_);
    forward();
  }
}

void RealFft2d::inverse(double* out) {
  assert(inverse_plan_ != nullptr && "RealFft2d used after move");
  if (out == real_) {
    inverse();
  } else if (fftw_alignment_of(out) == fftw_alignment_of(real_)) {
    fftw_execute_dft_c2r(static_cast<fftw_plan>(inverse_plan_), reinterpret_cast<fftw_complex*>(spectrum_), out);
  } else {
    inverse();
    Eigen::Map<Eigen::ArrayXXd>(out, nx_, ny_) = real();
  }
}

RowColumnFft::RowColumnFft(Eigen::Index nx, Eigen::Index ny, bool measure) : nx_(nx), ny_(ny) {
  if (nx < 1 || ny < 1) {
    throw std::invalid_argument("FFT grid must have at least one point per direction, got " + std::to_string(nx) +
                                " x " + std::to_string(ny));
  }
  init_threads_once();
  // Planning arrays (FFTW_MEASURE overwrites them); the plans then run on the caller's arrays.
  const std::size_t block = static_cast<std::size_t>(kColumns * ny);
  double* r = static_cast<double*>(fftw_malloc(sizeof(double) * static_cast<std::size_t>(nx)));
  fftw_complex* c = static_cast<fftw_complex*>(
      fftw_malloc(sizeof(fftw_complex) * std::max(static_cast<std::size_t>(nx / 2 + 1), block)));
  fftw_complex* d = static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * block));
  if (r == nullptr || c == nullptr || d == nullptr) {
    fftw_free(r);
    fftw_free(c);
    fftw_free(d);
    throw std::bad_alloc();
  }
  const unsigned flags = measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  const int n_y = static_cast<int>(ny), columns = static_cast<int>(kColumns);
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    fftw_plan_with_nthreads(1);
    row_forward_ = fftw_plan_dft_r2c_1d(static_cast<int>(nx), r, c, flags);
    row_inverse_ = fftw_plan_dft_c2r_1d(static_cast<int>(nx), c, r, flags);
    block_forward_ = fftw_plan_many_dft(1, &n_y, columns, c, nullptr, 1, n_y, d, nullptr, 1, n_y, FFTW_FORWARD, flags);
    block_inverse_ = fftw_plan_many_dft(1, &n_y, columns, d, nullptr, 1, n_y, c, nullptr, 1, n_y, FFTW_BACKWARD, flags);
    column_forward_ = fftw_plan_many_dft(1, &n_y, 1, c, nullptr, 1, n_y, d, nullptr, 1, n_y, FFTW_FORWARD, flags);
    column_inverse_ = fftw_plan_many_dft(1, &n_y, 1, d, nullptr, 1, n_y, c, nullptr, 1, n_y, FFTW_BACKWARD, flags);
  }
  fftw_free(r);
  fftw_free(c);
  fftw_free(d);
  for (void* p : {row_forward_, row_inverse_, block_forward_, block_inverse_, column_forward_, column_inverse_}) {
    if (p == nullptr) {
      release();
      throw std::runtime_error("FFTW could not plan the line transforms of a " + std::to_string(nx) + " x " +
                               std::to_string(ny) + " grid");
    }
  }
}

RowColumnFft::~RowColumnFft() { release(); }

void RowColumnFft::release() noexcept {
  std::lock_guard<std::mutex> lock(planner_mutex());
  for (void** p : {&row_forward_, &row_inverse_, &block_forward_, &block_inverse_, &column_forward_, &column_inverse_}) {
    if (*p != nullptr) fftw_destroy_plan(static_cast<fftw_plan>(*p));
    *p = nullptr;
  }
}

bool RowColumnFft::aligned(const void* p) {
  // fftw_alignment_of is p's offset from FFTW's SIMD alignment; fftw_malloc's arrays have 0.
  return fftw_alignment_of(static_cast<double*>(const_cast<void*>(p))) == 0;
}

void RowColumnFft::row_forward(const double* in, std::complex<double>* out) const {
  assert(aligned(in) && aligned(out));
  // fftw's signature is non-const; an out-of-place r2c preserves its input.
  fftw_execute_dft_r2c(static_cast<fftw_plan>(row_forward_), const_cast<double*>(in),
                       reinterpret_cast<fftw_complex*>(out));
}

void RowColumnFft::row_inverse(std::complex<double>* in, double* out) const {
  assert(aligned(in) && aligned(out));
  fftw_execute_dft_c2r(static_cast<fftw_plan>(row_inverse_), reinterpret_cast<fftw_complex*>(in), out);
}

namespace {
void run_columns(void* block_plan, void* column_plan, const std::complex<double>* in, std::complex<double>* out,
                 Eigen::Index ny, Eigen::Index count) {
  assert(count >= 0 && count <= RowColumnFft::kColumns && in != out);
  // fftw's signature is non-const; an out-of-place complex transform preserves its input.
  auto* i = reinterpret_cast<fftw_complex*>(const_cast<std::complex<double>*>(in));
  auto* o = reinterpret_cast<fftw_complex*>(out);
  if (count == RowColumnFft::kColumns) {
    fftw_execute_dft(static_cast<fftw_plan>(block_plan), i, o);
    return;
  }
  for (Eigen::Index k = 0; k < count; ++k) fftw_execute_dft(static_cast<fftw_plan>(column_plan), i + k * ny, o + k * ny);
}
}  // namespace

void RowColumnFft::columns_forward(const std::complex<double>* in, std::complex<double>* out, Eigen::Index count) const {
  run_columns(block_forward_, column_forward_, in, out, ny_, count);
}

void RowColumnFft::columns_inverse(const std::complex<double>* in, std::complex<double>* out, Eigen::Index count) const {
  run_columns(block_inverse_, column_inverse_, in, out, ny_, count);
}

}  // namespace tribo::contact
