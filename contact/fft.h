// Move-only owner of a pair of FFTW plans for a real 2-D grid (r2c forward, c2r inverse).
//
// Layout: a field on an nx × ny grid is an Eigen::ArrayXXd with nx rows (x, index i) and ny
// columns (y, index j), column-major, so x is the contiguous index (contact/grid.h). FFTW sees
// it as a row-major array [ny][nx]; the r2c spectrum is therefore [ny][nx/2 + 1]:
//   spectrum[j * (nx/2 + 1) + k] = Σ_{i,j'} f(i, j') exp(−2πi (k i / nx + j j' / ny))
// with wavenumbers q_x = 2π k / L_x (k = 0..nx/2) and q_y = 2π j̃ / L_y, j̃ = j for j ≤ ny/2,
// j − ny otherwise. Neither direction is normalised: inverse(forward(f)) = nx · ny · f.
#pragma once

#include <Eigen/Core>

#include <complex>
#include <cstddef>

namespace tribo::contact {

// FFTW's thread count for new plans: 0 means "as many as OpenMP offers" (omp_get_max_threads()).
class RealFft2d {
 public:
  // Plans both transforms on buffers owned by this object. `threads` = 1 gives transforms whose
  // bits do not depend on the machine's thread count (used for seeded surface synthesis).
  // `measure` asks FFTW to time candidate algorithms (slower to plan, faster to run).
  RealFft2d(Eigen::Index nx, Eigen::Index ny, int threads = 0, bool measure = false);
  ~RealFft2d();
  RealFft2d(RealFft2d&& other) noexcept;
  RealFft2d& operator=(RealFft2d&& other) noexcept;
  RealFft2d(const RealFft2d&) = delete;
  RealFft2d& operator=(const RealFft2d&) = delete;

  Eigen::Index nx() const { return nx_; }
  Eigen::Index ny() const { return ny_; }
  // Complex points along x in the half spectrum, nx/2 + 1.
  Eigen::Index nx_half() const { return nx_ / 2 + 1; }
  Eigen::Index spectrum_size() const { return nx_half() * ny_; }

  // The real buffer (nx × ny) and the half spectrum (spectrum_size() values).
  Eigen::Map<Eigen::ArrayXXd> real() { return {real_, nx_, ny_}; }
  std::complex<double>* spectrum() { return spectrum_; }

  void forward();  // real() → spectrum()
  void inverse();  // spectrum() → real(); overwrites spectrum() (FFTW c2r destroys its input)
  // The same transforms on caller-owned nx × ny arrays (x contiguous), saving the copy into and
  // out of real(): FFTW's new-array execute when `in`/`out` share real()'s SIMD alignment, a copy
  // through real() otherwise. `in` is left unchanged (out-of-place r2c preserves its input).
  void forward(const double* in);
  void inverse(double* out);

 private:
  void release() noexcept;

  Eigen::Index nx_ = 0, ny_ = 0;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  void* forward_plan_ = nullptr;  // fftw_plan; kept opaque so users need not include fftw3.h
  void* inverse_plan_ = nullptr;
};

// The 1-D transforms of the same nx × ny real 2-D FFT taken line by line, for a caller that fuses
// its own work into the stages (ElasticHalfSpace::displacement_by_rows): r2c along x of one
// x-line (nx values → nx/2 + 1 complex values), and the complex transforms along y of a block
// of kColumns columns of that half spectrum, each column contiguous (value j of column c at
// block[c·ny + j]), from one block into another: so FFTW transforms the columns where they lie.
// (Interleaved columns, or a transform in place, made FFTW copy every column into a buffer of
// its own and back: a quarter of the column stage, bench/README.md.) The composition is
// RealFft2d's transform (same unnormalised convention). Single-threaded plans, executed through
// FFTW's new-array interface, which is safe from several threads at once (each thread owns its
// buffers); the arrays must be SIMD-aligned (aligned()). Planned as RealFft2d (estimate, or
// measure; the shipped wisdom holds measured plans for square grids 64² … 4096²).
// Real = double (FFTW) or float (FFTW's single-precision library, fftwf_: the normal solve's
// products far from its tolerance, normal_contact.h).
template <class Real>
class RowColumnFftOf {
 public:
  using Complex = std::complex<Real>;
  static constexpr Eigen::Index kColumns = 8;

  RowColumnFftOf(Eigen::Index nx, Eigen::Index ny, bool measure = false);
  ~RowColumnFftOf();
  RowColumnFftOf(const RowColumnFftOf&) = delete;
  RowColumnFftOf& operator=(const RowColumnFftOf&) = delete;

  Eigen::Index nx() const { return nx_; }
  Eigen::Index ny() const { return ny_; }
  Eigen::Index nx_half() const { return nx_ / 2 + 1; }
  // Whether an array has the alignment the plans were made for (fftw_malloc's).
  static bool aligned(const void* p);

  void row_forward(const Real* in, Complex* out) const;  // in: nx values, preserved
  void row_inverse(Complex* in, Real* out) const;        // in: nx/2 + 1, destroyed
  // The first `count` ≤ kColumns columns of a block of ny · kColumns values (column c at c·ny),
  // from `in` into `out` (distinct blocks; `in` is left unchanged).
  void columns_forward(const Complex* in, Complex* out, Eigen::Index count) const;
  void columns_inverse(const Complex* in, Complex* out, Eigen::Index count) const;

 private:
  void release() noexcept;

  Eigen::Index nx_, ny_;
  void* row_forward_ = nullptr;  // fftw_plan or fftwf_plan
  void* row_inverse_ = nullptr;
  void* block_forward_ = nullptr;  // kColumns contiguous columns, out of place
  void* block_inverse_ = nullptr;
  void* column_forward_ = nullptr;  // one of them
  void* column_inverse_ = nullptr;
};
using RowColumnFft = RowColumnFftOf<double>;
using RowColumnFftSingle = RowColumnFftOf<float>;

// FFTW wisdom shipped with tribo (contact/fftw_wisdom.txt, made by build/bench/fftw_wisdom): the
// plans FFTW_MEASURE chose for RealFft2d on square grids 64² … 4096² on 1 and 2 threads, and for
// RowColumnFft's line transforms on the same grids; and (contact/fftwf_wisdom.txt) for
// RowColumnFftSingle's on those grids. It is imported before the first plan, and
// FFTW then builds a covered problem's plan from it, without measuring: the same plan in every
// run and process, so results stay reproducible to the bit (a measured plan can differ from run
// to run), at the measured plan's speed — an r2c + c2r pair on 2048² on one thread took 31 ms
// against the estimated plan's 61 ms (bench/README.md). False when FFTW rejected either wisdom
// (another FFTW version): every plan is then FFTW's estimate — slower, the same results to
// round-off.
bool shipped_fftw_wisdom_loaded();

// Signed wavenumber index of FFT bin j on an n-point axis: j for j ≤ n/2, j − n otherwise.
inline Eigen::Index signed_frequency(Eigen::Index j, Eigen::Index n) { return j <= n / 2 ? j : j - n; }

}  // namespace tribo::contact
