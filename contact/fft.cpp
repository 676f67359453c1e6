#include "contact/fft.h"

#include <fftw3.h>
#include <omp.h>

#include <algorithm>
#include <cassert>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "numerics/huge_pages.h"

namespace tribo::contact {
namespace detail {
extern const char* const kShippedFftwWisdom;   // contact/fftw_wisdom.txt, compiled in by CMake
extern const char* const kShippedFftwfWisdom;  // contact/fftwf_wisdom.txt: single precision
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
    const bool double_loaded = fftw_import_wisdom_from_string(detail::kShippedFftwWisdom) != 0;
    const bool single_loaded = fftwf_import_wisdom_from_string(detail::kShippedFftwfWisdom) != 0;
    wisdom_loaded = double_loaded && single_loaded;
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

namespace {

// FFTW's double (fftw_) and single-precision (fftwf_) interfaces under one name each.
template <class Real>
struct Fftw;

template <>
struct Fftw<double> {
  using Plan = fftw_plan;
  using Cx = fftw_complex;
  static void* malloc(std::size_t bytes) { return fftw_malloc(bytes); }
  static void free(void* p) { fftw_free(p); }
  static int alignment_of(double* p) { return fftw_alignment_of(p); }
  static Plan r2c(int n, double* r, Cx* c, unsigned f) { return fftw_plan_dft_r2c_1d(n, r, c, f); }
  static Plan c2r(int n, Cx* c, double* r, unsigned f) { return fftw_plan_dft_c2r_1d(n, c, r, f); }
  static Plan many(int n, int howmany, Cx* in, Cx* out, int sign, unsigned f) {
    return fftw_plan_many_dft(1, &n, howmany, in, nullptr, 1, n, out, nullptr, 1, n, sign, f);
  }
  static void destroy(void* p) { fftw_destroy_plan(static_cast<Plan>(p)); }
  static void execute_r2c(void* p, double* in, Cx* out) { fftw_execute_dft_r2c(static_cast<Plan>(p), in, out); }
  static void execute_c2r(void* p, Cx* in, double* out) { fftw_execute_dft_c2r(static_cast<Plan>(p), in, out); }
  static void execute_dft(void* p, Cx* in, Cx* out) { fftw_execute_dft(static_cast<Plan>(p), in, out); }
  // The plans are single-threaded whatever RealFft2d's last plan asked (the planner is shared).
  static void one_thread() { fftw_plan_with_nthreads(1); }
};

template <>
struct Fftw<float> {
  using Plan = fftwf_plan;
  using Cx = fftwf_complex;
  static void* malloc(std::size_t bytes) { return fftwf_malloc(bytes); }
  static void free(void* p) { fftwf_free(p); }
  static int alignment_of(float* p) { return fftwf_alignment_of(p); }
  static Plan r2c(int n, float* r, Cx* c, unsigned f) { return fftwf_plan_dft_r2c_1d(n, r, c, f); }
  static Plan c2r(int n, Cx* c, float* r, unsigned f) { return fftwf_plan_dft_c2r_1d(n, c, r, f); }
  static Plan many(int n, int howmany, Cx* in, Cx* out, int sign, unsigned f) {
    return fftwf_plan_many_dft(1, &n, howmany, in, nullptr, 1, n, out, nullptr, 1, n, sign, f);
  }
  static void destroy(void* p) { fftwf_destroy_plan(static_cast<Plan>(p)); }
  static void execute_r2c(void* p, float* in, Cx* out) { fftwf_execute_dft_r2c(static_cast<Plan>(p), in, out); }
  static void execute_c2r(void* p, Cx* in, float* out) { fftwf_execute_dft_c2r(static_cast<Plan>(p), in, out); }
  static void execute_dft(void* p, Cx* in, Cx* out) { fftwf_execute_dft(static_cast<Plan>(p), in, out); }
  // fftwf's threads are never initialised: its plans are single-threaded.
  static void one_thread() {}
};

}  // namespace

template <class Real>
RowColumnFftOf<Real>::RowColumnFftOf(Eigen::Index nx, Eigen::Index ny, bool measure) : nx_(nx), ny_(ny) {
  using F = Fftw<Real>;
  using Cx = typename F::Cx;
  if (nx < 1 || ny < 1) {
    throw std::invalid_argument("FFT grid must have at least one point per direction, got " + std::to_string(nx) +
                                " x " + std::to_string(ny));
  }
  init_threads_once();
  // Planning arrays (FFTW_MEASURE overwrites them); the plans then run on the caller's arrays.
  const std::size_t block = static_cast<std::size_t>(kColumns * ny);
  Real* r = static_cast<Real*>(F::malloc(sizeof(Real) * static_cast<std::size_t>(nx)));
  Cx* c = static_cast<Cx*>(F::malloc(sizeof(Cx) * std::max(static_cast<std::size_t>(nx / 2 + 1), block)));
  Cx* d = static_cast<Cx*>(F::malloc(sizeof(Cx) * block));
  if (r == nullptr || c == nullptr || d == nullptr) {
    F::free(r);
    F::free(c);
    F::free(d);
    throw std::bad_alloc();
  }
  const unsigned flags = measure ? FFTW_MEASURE : FFTW_ESTIMATE;
  const int n_y = static_cast<int>(ny), columns = static_cast<int>(kColumns);
  {
    std::lock_guard<std::mutex> lock(planner_mutex());
    F::one_thread();
    row_forward_ = F::r2c(static_cast<int>(nx), r, c, flags);
    row_inverse_ = F::c2r(static_cast<int>(nx), c, r, flags);
    block_forward_ = F::many(n_y, columns, c, d, FFTW_FORWARD, flags);
    block_inverse_ = F::many(n_y, columns, d, c, FFTW_BACKWARD, flags);
    column_forward_ = F::many(n_y, 1, c, d, FFTW_FORWARD, flags);
    column_inverse_ = F::many(n_y, 1, d, c, FFTW_BACKWARD, flags);
  }
  F::free(r);
  F::free(c);
  F::free(d);
  for (void* p : {row_forward_, row_inverse_, block_forward_, block_inverse_, column_forward_, column_inverse_}) {
    if (p == nullptr) {
      release();
      throw std::runtime_error("FFTW could not plan the line transforms of a " + std::to_string(nx) + " x " +
                               std::to_string(ny) + " grid");
    }
  }
}

template <class Real>
RowColumnFftOf<Real>::~RowColumnFftOf() {
  release();
}

template <class Real>
void RowColumnFftOf<Real>::release() noexcept {
  std::lock_guard<std::mutex> lock(planner_mutex());
  for (void** p : {&row_forward_, &row_inverse_, &block_forward_, &block_inverse_, &column_forward_, &column_inverse_}) {
    if (*p != nullptr) Fftw<Real>::destroy(*p);
    *p = nullptr;
  }
}

template <class Real>
bool RowColumnFftOf<Real>::aligned(const void* p) {
  // fftw_alignment_of is p's offset from FFTW's SIMD alignment; fftw_malloc's arrays have 0.
  return Fftw<Real>::alignment_of(static_cast<Real*>(const_cast<void*>(p))) == 0;
}

template <class Real>
void RowColumnFftOf<Real>::row_forward(const Real* in, Complex* out) const {
  assert(aligned(in) && aligned(out));
  // fftw's signature is non-const; an out-of-place r2c preserves its input.
  Fftw<Real>::execute_r2c(row_forward_, const_cast<Real*>(in), reinterpret_cast<typename Fftw<Real>::Cx*>(out));
}

template <class Real>
void RowColumnFftOf<Real>::row_inverse(Complex* in, Real* out) const {
  assert(aligned(in) && aligned(out));
  Fftw<Real>::execute_c2r(row_inverse_, reinterpret_cast<typename Fftw<Real>::Cx*>(in), out);
}

namespace {
template <class Real>
void run_columns(void* block_plan, void* column_plan, const std::complex<Real>* in, std::complex<Real>* out,
                 Eigen::Index ny, Eigen::Index count) {
  using Cx = typename Fftw<Real>::Cx;
  assert(count >= 0 && count <= RowColumnFftOf<Real>::kColumns && in != out);
  // fftw's signature is non-const; an out-of-place complex transform preserves its input.
  auto* i = reinterpret_cast<Cx*>(const_cast<std::complex<Real>*>(in));
  auto* o = reinterpret_cast<Cx*>(out);
  // A single-precision column of odd length ends 8 bytes off FFTW's 16-byte alignment, so every
  // other column of a block is misaligned for the one-column plan (planned on aligned arrays). The
  // block plan knows its columns' offsets: a partial block is transformed whole, its unused
  // columns holding whatever the scratch held (finite values, never scattered back).
  constexpr bool kSingle = std::is_same_v<Real, float>;
  if (count == RowColumnFftOf<Real>::kColumns || (kSingle && ny % 2 == 1)) {
    Fftw<Real>::execute_dft(block_plan, i, o);
    return;
  }
  for (Eigen::Index k = 0; k < count; ++k) {
    assert(RowColumnFftOf<Real>::aligned(i + k * ny) && RowColumnFftOf<Real>::aligned(o + k * ny));
    Fftw<Real>::execute_dft(column_plan, i + k * ny, o + k * ny);
  }
}
}  // namespace

template <class Real>
void RowColumnFftOf<Real>::columns_forward(const Complex* in, Complex* out, Eigen::Index count) const {
  run_columns<Real>(block_forward_, column_forward_, in, out, ny_, count);
}

template <class Real>
void RowColumnFftOf<Real>::columns_inverse(const Complex* in, Complex* out, Eigen::Index count) const {
  run_columns<Real>(block_inverse_, column_inverse_, in, out, ny_, count);
}

template class RowColumnFftOf<double>;
template class RowColumnFftOf<float>;

}  // namespace tribo::contact
