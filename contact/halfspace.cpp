#include "contact/halfspace.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "contact/vector_clones.h"
#include "numerics/huge_pages.h"

namespace tribo::contact {
namespace {

// Love's displacement at (x, y) from unit pressure on the cell [−a, a] × [−b, b] (see header).
double love_influence(double x, double y, double a, double b, double e_star) {
  auto term = [](double c, double t1, double t2) {
    // c (asinh(t1/|c|) − asinh(t2/|c|)); → 0 as c → 0, the limit of c ln(…) terms.
    const double ac = std::abs(c);
    return ac == 0.0 ? 0.0 : c * (std::asinh(t1 / ac) - std::asinh(t2 / ac));
  };
  const double s = term(x + a, y + b, y - b) + term(y + b, x + a, x - a) + term(x - a, y - b, y + b) +
                   term(y - b, x - a, x + a);
  return s / (std::numbers::pi * e_star);
}

// The padded FFT length for n nodes: the smallest even m ≥ 2n − 2 with no prime factor above 5.
// The circular convolution is the linear one on the patch when no two offsets within ±(n − 1)
// share an index mod m; at m = 2n − 2 only +(n − 1) and −(n − 1) do, and the kernel is even, so
// its values there are equal. Small prime factors let FFTW run its fast codelets: 2n for a power
// of two n, and 2ⁿ⁺¹ for 2ⁿ + 1 nodes — 512 for 257 (an r2c + c2r pair on 514² took four times
// as long as on 540², the smallest 5-smooth length ≥ 2n, and 540² is 11 % more points than 512²).
Eigen::Index padded_length(Eigen::Index n) {
  for (Eigen::Index m = std::max<Eigen::Index>(2, 2 * n - 2);; m += 2) {
    Eigen::Index r = m;
    for (const Eigen::Index f : {2, 3, 5})
      while (r % f == 0) r /= f;
    if (r == 1) return m;
  }
}

// The column stage of displacement_by_rows moves one block of kb = RowColumnFftOf::kColumns columns
// (nb ≤ kb of them real) between the half spectrum, whose lines are `stride` complex values apart,
// and the block, whose columns are contiguous (value j of column c at c·ny + j). Each line gives
// nb neighbouring values, one to each column. Fixed-length moves the compiler keeps inline (a
// library memmove per line took 9 % of a 1024² solve), with the lines ahead prefetched (the
// spectrum's are more than a page apart, beyond the hardware prefetcher).
constexpr Eigen::Index kPrefetchLines = 16;

// A block's line of the half spectrum: kb values, two 64-byte cache lines in double precision and
// one in single.
template <class Real>
inline void prefetch_line(const std::complex<Real>* line, bool write) {
  constexpr std::size_t kBytes = RowColumnFftOf<Real>::kColumns * sizeof(std::complex<Real>);
  const char* p = reinterpret_cast<const char*>(line);
  for (std::size_t at = 0; at < kBytes; at += 64) {
    if (write) {
      __builtin_prefetch(p + at, 1);
    } else {
      __builtin_prefetch(p + at);
    }
  }
}

template <class Real>
TRIBO_VECTOR_CLONES void gather_block(const std::complex<Real>* spectrum, Eigen::Index stride, std::complex<Real>* block,
                                      Eigen::Index ny, Eigen::Index nb) {
  constexpr Eigen::Index kb = RowColumnFftOf<Real>::kColumns;
  for (Eigen::Index j = 0; j < ny; ++j) {
    const std::complex<Real>* line = spectrum + j * stride;
    if (j + kPrefetchLines < ny) prefetch_line(line + kPrefetchLines * stride, false);
    if (nb == kb) {
      for (Eigen::Index c = 0; c < kb; ++c) block[c * ny + j] = line[c];
    } else {
      for (Eigen::Index c = 0; c < nb; ++c) block[c * ny + j] = line[c];
    }
  }
}

template <class Real>
TRIBO_VECTOR_CLONES void scatter_block(const std::complex<Real>* block, std::complex<Real>* spectrum, Eigen::Index stride,
                                       Eigen::Index ny, Eigen::Index nb) {
  constexpr Eigen::Index kb = RowColumnFftOf<Real>::kColumns;
  for (Eigen::Index j = 0; j < ny; ++j) {
    std::complex<Real>* line = spectrum + j * stride;
    if (j + kPrefetchLines < ny) prefetch_line(line + kPrefetchLines * stride, true);
    if (nb == kb) {
      for (Eigen::Index c = 0; c < kb; ++c) line[c] = block[c * ny + j];
    } else {
      for (Eigen::Index c = 0; c < nb; ++c) line[c] = block[c * ny + j];
    }
  }
}

// The block's first nb transformed columns times the kernel (`kernel`: the block's columns in
// turn, ny values each, as the block), returning Σ weight K |x|² (weight 1 for the k = 0 and
// Nyquist columns, which have no mirror image in the half spectrum, 2 for the others).
template <class Real>
TRIBO_VECTOR_CLONES double multiply_block(std::complex<Real>* block, const Real* kernel, Eigen::Index ny, Eigen::Index nb,
                                          const double* weight) {
  double e = 0.0;
  for (Eigen::Index c = 0; c < nb; ++c) {
    Real* __restrict x = reinterpret_cast<Real*>(block + c * ny);
    const Real* __restrict k = kernel + c * ny;
    double part = 0.0;
#pragma omp simd reduction(+ : part)
    for (Eigen::Index j = 0; j < ny; ++j) {
      const Real re = x[2 * j], im = x[2 * j + 1], kj = k[j];
      if constexpr (std::is_same_v<Real, double>) {
        part += kj * (re * re + im * im);
      } else {
        part += (kj * re) * re + (kj * im) * im;  // |x|² alone can pass FLT_MAX on a large grid
      }
      x[2 * j] = re * kj;
      x[2 * j + 1] = im * kj;
    }
    e += weight[c] * part;
  }
  return e;
}

// FFTW threads pay off only on large transforms; below 128² points one thread is faster.
int fft_threads(const Grid& g, bool periodic, int requested) {
  const Eigen::Index points = (periodic ? 1 : 4) * g.nx * g.ny;
  return requested == 0 && points < 128 * 128 ? 1 : requested;
}

}  // namespace

double composite_modulus_Pa(double e1, double nu1, double e2, double nu2) {
  auto compliance = [](double e, double nu, const char* which) {
    if (!(e > 0.0) || std::isnan(e)) throw std::invalid_argument(std::string("Young's modulus of ") + which + " must be positive");
    if (!(nu >= 0.0 && nu < 0.5)) throw std::invalid_argument(std::string("Poisson's ratio of ") + which + " must lie in [0, 0.5)");
    return std::isinf(e) ? 0.0 : (1.0 - nu * nu) / e;
  };
  const double c = compliance(e1, nu1, "body 1") + compliance(e2, nu2, "body 2");
  if (c == 0.0) throw std::invalid_argument("both bodies rigid: the composite modulus is infinite");
  return 1.0 / c;
}

ElasticHalfSpace::ElasticHalfSpace(const Grid& grid, double e_star_Pa, bool periodic, int threads, bool measure_fft)
    : grid_((validate(grid), grid)),
      e_star_Pa_(e_star_Pa),
      periodic_(periodic),
      fft_(periodic ? grid.nx : padded_length(grid.nx), periodic ? grid.ny : padded_length(grid.ny),
           fft_threads(grid, periodic, threads), measure_fft),
      one_thread_(threads == 1) {
  if (!(std::isfinite(e_star_Pa) && e_star_Pa > 0.0)) {
    throw std::invalid_argument("composite modulus e_star_Pa must be positive and finite");
  }
  const Eigen::Index mx = fft_.nx(), my = fft_.ny(), mxh = fft_.nx_half();
  const double inv_size = 1.0 / static_cast<double>(mx * my);
  kernel_.resize(mxh * my);
  numerics::advise_huge_pages(kernel_.data(), sizeof(double) * static_cast<std::size_t>(kernel_.size()));
  if (periodic) {
    const double dqx = 2.0 * std::numbers::pi / grid.period_x_m(), dqy = 2.0 * std::numbers::pi / grid.period_y_m();
    for (Eigen::Index j = 0; j < my; ++j) {
      const double qy = dqy * static_cast<double>(signed_frequency(j, my));
      for (Eigen::Index k = 0; k < mxh; ++k) {
        const double q = std::hypot(dqx * static_cast<double>(k), qy);
        kernel_[j * mxh + k] = q > 0.0 ? 2.0 / (e_star_Pa * q) * inv_size : 0.0;
      }
    }
    // Self-compliance = mean of the multiplier over all modes (the diagonal of a circulant).
    double sum = 0.0;
    for (Eigen::Index j = 0; j < my; ++j) {
      for (Eigen::Index k = 0; k < mxh; ++k) {
        const int weight = (k == 0 || 2 * k == mx) ? 1 : 2;
        sum += weight * kernel_[j * mxh + k];
      }
    }
    self_compliance_ = sum;
    make_lines(lines_);
  } else {
    const double a = 0.5 * grid.dx_m, b = 0.5 * grid.dy_m;
    auto real = fft_.real();
    // Wrapped offsets: index i ↔ offset i up to m/2, i − m above (m the padded length ≥ 2nx − 2);
    // offsets beyond ±(nx − 1) are never reached by a convolution restricted to the nx × ny patch.
    for (Eigen::Index j = 0; j < my; ++j) {
      const double y = grid.dy_m * static_cast<double>(signed_frequency(j, my));
      for (Eigen::Index i = 0; i < mx; ++i) {
        const double x = grid.dx_m * static_cast<double>(signed_frequency(i, mx));
        real(i, j) = love_influence(x, y, a, b, e_star_Pa);
      }
    }
    self_compliance_ = real(0, 0);
    fft_.forward();
    // The kernel is even in x and y, so its transform is real (imaginary parts are round-off).
    for (Eigen::Index m = 0; m < mxh * my; ++m) kernel_[m] = fft_.spectrum()[m].real() * inv_size;
  }
}

void ElasticHalfSpace::displacement(const Eigen::ArrayXXd& p, Eigen::ArrayXXd& u) {
  if (u.rows() != grid_.nx || u.cols() != grid_.ny) u.resize(grid_.nx, grid_.ny);
  displacement_and_energy(p, u);
}

double ElasticHalfSpace::displacement_and_energy(const Eigen::ArrayXXd& p, Eigen::ArrayXXd& u) {
  const Eigen::Index nx = grid_.nx, ny = grid_.ny;
  assert(p.rows() == nx && p.cols() == ny && "pressure field does not match the half-space grid");
  assert(u.rows() == nx && u.cols() == ny && "displacement field does not match the half-space grid");
  assert(p.data() != u.data() && "displacement_and_energy cannot work in place");
  if (periodic_) {
    fft_.forward(p.data());
  } else {
    // The c2r of the previous product filled the padding; the zero padding is what makes the
    // circular convolution the linear one.
    auto real = fft_.real();
    real.topLeftCorner(nx, ny) = p;
    real.bottomRows(fft_.nx() - nx).leftCols(ny).setZero();
    real.rightCols(fft_.ny() - ny).setZero();
    fft_.forward();
  }
  // Multiply by the kernel and sum the energy Σ_q K(q) |p̂(q)|² over the full spectrum: the half
  // spectrum counts its k = 0 and Nyquist columns once and the others twice (Hermitian symmetry).
  std::complex<double>* s = fft_.spectrum();
  const Eigen::Index mxh = fft_.nx_half(), my = fft_.ny();
  const bool even_x = fft_.nx() % 2 == 0;
  double energy = 0.0;
#pragma omp parallel for if (!one_thread_ && mxh * my >= kParallelMinCells) reduction(+ : energy) schedule(static)
  for (Eigen::Index j = 0; j < my; ++j) {
    std::complex<double>* col = s + j * mxh;
    const double* k = kernel_.data() + j * mxh;
    // The k = 0 and (even nx) Nyquist bins have no mirror image: counted once, the rest twice.
    double edge = k[0] * std::norm(col[0]);
    if (even_x && mxh > 1) edge += k[mxh - 1] * std::norm(col[mxh - 1]);
    double e = 0.0;
    for (Eigen::Index m = 0; m < mxh; ++m) {
      e += k[m] * std::norm(col[m]);
      col[m] *= k[m];
    }
    e = 2.0 * e - edge;
    energy += e;
  }
  if (periodic_) {
    fft_.inverse(u.data());
  } else {
    fft_.inverse();
    u = fft_.real().topLeftCorner(nx, ny);
  }
  return energy;
}

int ElasticHalfSpace::row_threads() const {
  return one_thread_ || grid_.nx * grid_.ny < kParallelMinCells ? 1 : std::max(1, omp_get_max_threads());
}

template <class Real>
void ElasticHalfSpace::make_lines(Lines<Real>& lines) {
  const Eigen::Index mx = fft_.nx(), my = fft_.ny(), mxh = fft_.nx_half();
  lines.fft = std::make_unique<RowColumnFftOf<Real>>(mx, my);
  // A single-precision line of the half spectrum is 8 bytes a value: an even stride keeps every
  // line on FFTW's 16-byte alignment.
  lines.stride = std::is_same_v<Real, double> ? mxh : mxh + mxh % 2;
  // The kernel in the order the column stage reads it (a block's columns in turn, ny values
  // each; 0 past the last column): read a line stride apart, as the half spectrum is laid out,
  // every value was a cache miss (the multiply took 10 % of a 1024² solve, 2.5 % now).
  constexpr Eigen::Index kb = RowColumnFftOf<Real>::kColumns;
  const Eigen::Index blocks = (mxh + kb - 1) / kb;
  lines.block_kernel.reserve(static_cast<std::size_t>(blocks * my * kb));
  numerics::advise_huge_pages(lines.block_kernel.data(), sizeof(Real) * lines.block_kernel.capacity());
  lines.block_kernel.assign(static_cast<std::size_t>(blocks * my * kb), Real{0});
  for (Eigen::Index b = 0; b < blocks; ++b) {
    for (Eigen::Index c = 0; c < kb && b * kb + c < mxh; ++c) {
      for (Eigen::Index j = 0; j < my; ++j) {
        lines.block_kernel[static_cast<std::size_t>((b * kb + c) * my + j)] = static_cast<Real>(kernel_[j * mxh + b * kb + c]);
      }
    }
  }
}

double ElasticHalfSpace::displacement_by_rows(double* s, double* u, const RowPass& make_row,
                                              const std::function<bool(double)>& decide, const UseRow& use_row,
                                              Precision precision) {
  if (!periodic_) throw std::logic_error("displacement_by_rows needs a periodic half-space");
  assert(s != u && "displacement_by_rows cannot work in place");
  if (precision == Precision::full) return rows_product(lines_, fft_.spectrum(), s, u, make_row, decide, use_row);
  if (!lines_single_.fft) make_lines(lines_single_);
  // fft_'s half spectrum is idle during the product, and fftw_malloc's alignment suits both.
  return rows_product(lines_single_, reinterpret_cast<std::complex<float>*>(fft_.spectrum()), s, u, make_row, decide,
                      use_row);
}

template <class Real>
double ElasticHalfSpace::rows_product(Lines<Real>& lines, std::complex<Real>* spectrum, double* s, double* u,
                                      const RowPass& make_row, const std::function<bool(double)>& decide,
                                      const UseRow& use_row) {
  using F = RowColumnFftOf<Real>;
  constexpr bool kFull = std::is_same_v<Real, double>;
  const Eigen::Index nx = grid_.nx, ny = grid_.ny, mxh = lines.fft->nx_half(), stride = lines.stride;
  constexpr Eigen::Index kb = F::kColumns;
  const F& f = *lines.fft;
  const int threads = row_threads();
  // Per thread: two blocks of columns (the column transforms go from one to the other), a line of
  // nx values of the transforms' precision — for lines of s and u that do not have the plans'
  // alignment (odd nx: every other line), or in single precision for each line of s and u — and
  // in single precision a line of nx doubles, for the lines of u when u is not kept. An even
  // length keeps each thread's share 16-byte aligned.
  const Eigen::Index line_values = nx / 2 + 1, scratch_raw = 2 * kb * ny + line_values + (kFull ? 0 : nx);
  const Eigen::Index scratch = scratch_raw + scratch_raw % 2;
  lines.scratch.resize(static_cast<std::size_t>(threads * scratch));
  const bool even_x = nx % 2 == 0;
  auto line_buffer = [&](int t) { return reinterpret_cast<Real*>(lines.scratch.data() + t * scratch + 2 * kb * ny); };
  auto wide_buffer = [&](int t) {
    if constexpr (kFull) return line_buffer(t);
    else return reinterpret_cast<double*>(lines.scratch.data() + t * scratch + 2 * kb * ny + line_values);
  };

  // 1. Lines of s, each transformed along x as soon as it is made.
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), m = omp_get_num_threads();
    for (Eigen::Index j = ny * t / m; j < ny * (t + 1) / m; ++j) {
      make_row(t, j);
      const double* made = s + j * nx;
      const Real* line;
      if constexpr (kFull) {
        line = F::aligned(made) ? made : std::copy_n(made, nx, line_buffer(t)) - nx;
      } else {
        line = std::transform(made, made + nx, line_buffer(t), [](double x) { return static_cast<Real>(x); }) - nx;
      }
      f.row_forward(line, spectrum + j * stride);
    }
  }
  // 2. Blocks of kb columns: gathered, along y into the second block, times the kernel (with the
  // energy, the k = 0 and Nyquist columns counted once and the others twice by Hermitian
  // symmetry), back into the first, and scattered.
  const Eigen::Index blocks = (mxh + kb - 1) / kb;
  std::vector<double> part(static_cast<std::size_t>(threads), 0.0);
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), m = omp_get_num_threads();
    std::complex<Real>* block = lines.scratch.data() + t * scratch;
    std::complex<Real>* transformed = block + kb * ny;
    double e = 0.0;
    for (Eigen::Index b = blocks * t / m; b < blocks * (t + 1) / m; ++b) {
      const Eigen::Index k0 = b * kb, nb = std::min(kb, mxh - k0);
      gather_block(spectrum + k0, stride, block, ny, nb);
      f.columns_forward(block, transformed, nb);
      std::array<double, kb> weight{};
      for (Eigen::Index c = 0; c < nb; ++c) weight[c] = k0 + c == 0 || (even_x && k0 + c == mxh - 1) ? 1.0 : 2.0;
      e += multiply_block(transformed, lines.block_kernel.data() + b * ny * kb, ny, nb, weight.data());
      f.columns_inverse(transformed, block, nb);
      scatter_block(block, spectrum + k0, stride, ny, nb);
    }
    part[static_cast<std::size_t>(t)] = e;
  }
  double energy = 0.0;
  for (const double e : part) energy += e;
  if (!decide(energy)) return energy;
  // 3. Lines of u, each used as soon as it is transformed back along x.
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), m = omp_get_num_threads();
    for (Eigen::Index j = ny * t / m; j < ny * (t + 1) / m; ++j) {
      double* line = u != nullptr ? u + j * nx : wide_buffer(t);
      if constexpr (kFull) {
        if (F::aligned(line)) {
          f.row_inverse(spectrum + j * stride, line);
        } else {
          f.row_inverse(spectrum + j * stride, line_buffer(t));
          line = std::copy_n(line_buffer(t), nx, line) - nx;
        }
      } else {
        f.row_inverse(spectrum + j * stride, line_buffer(t));
        std::copy_n(line_buffer(t), nx, line);
      }
      use_row(t, j, line);
    }
  }
  return energy;
}

}  // namespace tribo::contact
