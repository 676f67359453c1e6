// Linear elastic half-space by FFT: surface displacement u from surface pressure p.
//
//   composite modulus      1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂
//   periodic (Fourier):    ũ(q) = 2 p̃(q) / (E* |q|),  ũ(0) = 0 (the mean displacement of a
//                          periodic half-space is undefined; it is absorbed into the approach)
//   non-periodic:          u = K ∗ p with Love's (1929) influence coefficients for a uniform
//                          pressure on one rectangular cell −a ≤ x ≤ a, −b ≤ y ≤ b:
//     K(x, y) = 1/(π E*) [ (x+a)(ash((y+b)/|x+a|) − ash((y−b)/|x+a|))
//                        + (y+b)(ash((x+a)/|y+b|) − ash((x−a)/|y+b|))
//                        + (x−a)(ash((y−b)/|x−a|) − ash((y+b)/|x−a|))
//                        + (y−b)(ash((x−a)/|y−b|) − ash((x+a)/|y−b|)) ]   (ash = asinh)
//     (Johnson, Contact Mechanics (1985) §3.9, written with asinh to avoid cancellation),
//     evaluated on a grid of at least (2nx − 2) × (2ny − 2) (the next lengths with no prime factor
//     above 5) with the pressure zero-padded, so the circular convolution equals the linear one on
//     the nx × ny patch (Liu, Wang & Liu 2000, DC-FFT; K is even, so the one offset pair that
//     shares an index, ±(n − 1), has equal values).
// u > 0 is displacement into the body (the gap opens); units m from Pa.
#pragma once

#include <Eigen/Core>

#include <complex>
#include <functional>
#include <memory>
#include <vector>

#include "contact/fft.h"
#include "contact/grid.h"

namespace tribo::contact {

// Below this many cells a loop over a grid (the half-space's multiply and line stages, the normal
// solve's passes) costs less than waking a thread team — and on a busy machine far less than a
// descheduled spinning thread — so it runs on one thread.
inline constexpr Eigen::Index kParallelMinCells = Eigen::Index{1} << 15;

// thesis Appendix I materials combine as 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂; a rigid body has E = ∞.
double composite_modulus_Pa(double e1_Pa, double nu1, double e2_Pa, double nu2);

class ElasticHalfSpace {
 public:
  // `threads` as for RealFft2d (0 = all OpenMP threads); 1 keeps the spectrum's product on the
  // caller's thread too (no OpenMP team whose idle threads spin beside a caller's own threads).
  ElasticHalfSpace(const Grid& grid, double e_star_Pa, bool periodic, int threads = 0, bool measure_fft = false);

  const Grid& grid() const { return grid_; }
  double e_star_Pa() const { return e_star_Pa_; }
  bool periodic() const { return periodic_; }
  // Displacement of a cell under unit pressure on itself (m/Pa): the diagonal of the operator.
  double self_compliance_m_per_Pa() const { return self_compliance_; }

  // u = G p on the nx × ny grid. Not const: uses the owned FFT buffers (one instance per thread).
  void displacement(const Eigen::ArrayXXd& pressure_Pa, Eigen::ArrayXXd& displacement_m);
  // The same product, also returning the energy product p·(G p) = Σ_i p_i u_i (m³/Pa · Pa² per
  // cell area, i.e. m·Pa) from the spectrum by Parseval, so a caller that needs it (the CG line
  // step) saves a pass over the grid. On a periodic grid p and u are transformed in place of the
  // FFT buffers (no copies); `u` must already have the grid's shape and must not alias `p`.
  double displacement_and_energy(const Eigen::ArrayXXd& pressure_Pa, Eigen::ArrayXXd& displacement_m);
  // The same product on a periodic grid, taken in the stages of a row–column FFT with the
  // caller's passes fused into them, so that no grid is read or written twice for it:
  //   1. make_row(t, j) writes line j of s, s(0..nx−1, j), and the line is transformed along x
  //      while it is in cache;
  //   2. the columns of the half spectrum are transformed along y, multiplied by the kernel
  //      (summing the energy s·G s) and transformed back, a block of columns at a time;
  //   3. decide(energy) says whether u is wanted; if so each line of u = G s is transformed back
  //      along x and use_row(t, j, u_line) is called on it while it is in cache: u_line is line j
  //      of `u`, or, with u = nullptr, a line buffer of thread t's that the next line overwrites —
  //      for a caller that uses each line once and keeps none (the solve's w: no grid written).
  // Every line j is made and used by the same thread t < row_threads() (its accumulators can be
  // kept per thread and merged in thread order). Returns the energy. `s` and `u` are nx × ny
  // arrays (x contiguous) and must not alias.
  // With Precision::single the lines of s are rounded to float and the transforms, the kernel and
  // the half spectrum are FFTW's single precision: u to a few 1e-7 of max |u| and the energy to
  // 1e-7, in a little over half the time at 1024² (bench/README.md), for an iterative solve far
  // from its tolerance.
  using RowPass = std::function<void(int thread, Eigen::Index line)>;
  using UseRow = std::function<void(int thread, Eigen::Index line, const double* u_line)>;
  enum class Precision { full, single };
  double displacement_by_rows(double* s, double* u, const RowPass& make_row, const std::function<bool(double)>& decide,
                              const UseRow& use_row, Precision precision = Precision::full);
  int row_threads() const;
  // Number of r2c + c2r pairs per displacement() — one on the (padded) FFT grid.
  const RealFft2d& fft() const { return fft_; }

 private:
  Grid grid_;
  double e_star_Pa_;
  bool periodic_;
  RealFft2d fft_;                // nx × ny (periodic) or ≥ (2nx − 2) × (2ny − 2) (padded)
  // displacement_by_rows' transforms, kernel by column block ([block][column][j]), per-thread
  // column blocks and lines, and the stride of its half spectrum's lines (in fft_'s spectrum
  // buffer, which a single-precision one fits in twice over).
  template <class Real>
  struct Lines {
    std::unique_ptr<RowColumnFftOf<Real>> fft;
    std::vector<Real> block_kernel;
    std::vector<std::complex<Real>> scratch;
    Eigen::Index stride = 0;
  };
  template <class Real>
  void make_lines(Lines<Real>& lines);
  template <class Real>
  double rows_product(Lines<Real>& lines, std::complex<Real>* spectrum, double* s, double* u, const RowPass& make_row,
                      const std::function<bool(double)>& decide, const UseRow& use_row);
  Lines<double> lines_;       // periodic; the half spectrum is fft_'s
  Lines<float> lines_single_;  // made at the first single-precision product
  Eigen::ArrayXd kernel_;        // real Fourier multiplier on the half spectrum, 1/(FFT size) folded in
  double self_compliance_ = 0.0;
  bool one_thread_ = false;      // constructed with threads = 1
};

}  // namespace tribo::contact
