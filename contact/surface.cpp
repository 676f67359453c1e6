#include "contact/surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "contact/fft.h"

namespace tribo::contact {
namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("gaussian surface: " + what);
}

// SplitMix64 (Steele, Lea & Flood 2014): a fixed, portable stream, unlike the
// implementation-defined std::normal_distribution, so a seed names the same surface everywhere.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // Uniform in (0, 1]: 53 random bits, never 0 so that log() below is finite.
  double uniform() { return (static_cast<double>(next() >> 11) + 1.0) * 0x1.0p-53; }

 private:
  std::uint64_t state_;
};

// Periodic forward-difference rms gradient, the definition used by surface_statistics.
double fd_rms_slope(const Eigen::ArrayXXd& h, double dx, double dy) {
  const Eigen::Index nx = h.rows(), ny = h.cols();
  double sum = 0.0;
  for (Eigen::Index j = 0; j < ny; ++j) {
    const Eigen::Index jp = (j + 1) % ny;
    for (Eigen::Index i = 0; i < nx; ++i) {
      const Eigen::Index ip = (i + 1) % nx;
      const double sx = nx > 1 ? (h(ip, j) - h(i, j)) / dx : 0.0;
      const double sy = ny > 1 ? (h(i, jp) - h(i, j)) / dy : 0.0;
      sum += sx * sx + sy * sy;
    }
  }
  return std::sqrt(sum / static_cast<double>(h.size()));
}

}  // namespace

void validate(const GaussianSurfaceParams& p) {
  require(p.grid >= 2, "grid must be at least 2 points per side, got " + std::to_string(p.grid));
  require(std::isfinite(p.size_m) && p.size_m > 0.0, "size_m must be positive and finite");
  require(std::isfinite(p.rms_height_m) && p.rms_height_m >= 0.0, "rms_height_m must be non-negative");
  require(std::isfinite(p.rms_slope) && p.rms_slope >= 0.0, "rms_slope must be non-negative");
  require((p.rms_height_m > 0.0) != (p.rms_slope > 0.0), "give exactly one of rms_height_m and rms_slope");
  if (p.kind == SpectrumKind::self_affine) {
    require(std::isfinite(p.hurst) && p.hurst > 0.0 && p.hurst <= 1.0, "hurst must lie in (0, 1]");
    require(std::isfinite(p.rolloff_wavelength_m) && p.rolloff_wavelength_m >= 0.0 &&
                p.rolloff_wavelength_m <= p.size_m,
            "rolloff_wavelength_m must lie in [0, size_m]");
    require(std::isfinite(p.cutoff_wavelength_m) && p.cutoff_wavelength_m >= 0.0,
            "cutoff_wavelength_m must be non-negative");
    const double rolloff = p.rolloff_wavelength_m > 0.0 ? p.rolloff_wavelength_m : p.size_m;
    require(p.cutoff_wavelength_m < rolloff, "cutoff_wavelength_m must be shorter than the roll-off wavelength");
    require(std::isfinite(p.peklenik_gamma) && p.peklenik_gamma > 0.0, "peklenik_gamma must be positive and finite");
  } else {
    require(p.peklenik_gamma == 1.0, "peklenik_gamma is for the self-affine spectrum (a Gaussian ACF's lay: correlation_length_across_m)");
    require(std::isfinite(p.correlation_length_m) && p.correlation_length_m > 0.0,
            "correlation_length_m must be positive");
    require(std::isfinite(p.correlation_length_across_m) && p.correlation_length_across_m >= 0.0,
            "correlation_length_across_m must be non-negative");
  }
}

double psd_shape(const GaussianSurfaceParams& p, double qx, double qy) {
  const double q = std::hypot(qx, qy);
  if (q == 0.0) return 0.0;
  if (p.kind == SpectrumKind::gaussian_acf) {
    const double lx = p.correlation_length_m;
    const double ly = p.correlation_length_across_m > 0.0 ? p.correlation_length_across_m : lx;
    return std::exp(-0.25 * (qx * qx * lx * lx + qy * qy * ly * ly));
  }
  const double two_pi = 2.0 * std::numbers::pi;
  const double q_r = two_pi / (p.rolloff_wavelength_m > 0.0 ? p.rolloff_wavelength_m : p.size_m);
  const double g = p.peklenik_gamma;
  const double q_lay = g == 1.0 ? q : std::sqrt(g * qx * qx + qy * qy / g);
  if (p.cutoff_wavelength_m > 0.0 && q_lay > two_pi / p.cutoff_wavelength_m) return 0.0;
  if (q_lay < q_r) return 1.0;
  return std::pow(q_lay / q_r, -2.0 * (1.0 + p.hurst));
}

Eigen::ArrayXXd gaussian_surface(const GaussianSurfaceParams& p) {
  validate(p);
  const Eigen::Index n = p.grid;
  RealFft2d fft(n, n, /*threads=*/1);
  SplitMix64 rng(p.seed);
  auto noise = fft.real();
  // Box–Muller pairs, filled in memory order: the stream is independent of any threading.
  for (Eigen::Index k = 0; k < noise.size(); k += 2) {
    const double r = std::sqrt(-2.0 * std::log(rng.uniform()));
    const double phi = 2.0 * std::numbers::pi * rng.uniform();
    noise.data()[k] = r * std::cos(phi);
    if (k + 1 < noise.size()) noise.data()[k + 1] = r * std::sin(phi);
  }
  fft.forward();
  const double dq = 2.0 * std::numbers::pi / p.size_m;
  std::complex<double>* s = fft.spectrum();
  for (Eigen::Index j = 0; j < n; ++j) {
    const double qy = dq * static_cast<double>(signed_frequency(j, n));
    for (Eigen::Index k = 0; k < fft.nx_half(); ++k) {
      s[j * fft.nx_half() + k] *= std::sqrt(psd_shape(p, dq * static_cast<double>(k), qy));
    }
  }
  fft.inverse();
  Eigen::ArrayXXd h = fft.real();
  h -= h.mean();
  const double dx = p.size_m / static_cast<double>(n);
  const double current = p.rms_height_m > 0.0 ? std::sqrt(h.square().mean()) : fd_rms_slope(h, dx, dx);
  if (!(current > 0.0)) {
    throw std::invalid_argument("gaussian surface: the requested spectrum has no mode on a " + std::to_string(n) +
                                "² grid (cut-off or correlation length too short for the grid?)");
  }
  h *= (p.rms_height_m > 0.0 ? p.rms_height_m : p.rms_slope) / current;
  return h;
}

Eigen::ArrayXXd fourier_refine(const Eigen::ArrayXXd& h, int factor) {
  if (factor < 1) throw std::invalid_argument("fourier_refine: factor must be >= 1, got " + std::to_string(factor));
  if (h.size() == 0) throw std::invalid_argument("fourier_refine: empty height field");
  if (factor == 1) return h;
  const Eigen::Index nx = h.rows(), ny = h.cols(), mx = factor * nx, my = factor * ny;
  RealFft2d coarse(nx, ny, /*threads=*/1), fine(mx, my, /*threads=*/1);
  coarse.forward(h.data());
  std::complex<double>* c = coarse.spectrum();
  std::complex<double>* f = fine.spectrum();
  std::fill(f, f + fine.spectrum_size(), std::complex<double>(0.0, 0.0));
  // Unnormalised transforms: h = (1/(nx ny)) Σ C e^{iq·x}, so the fine coefficients are C scaled
  // by (mx my)/(nx ny) = factor², halved on each Nyquist line of an even axis.
  const double scale = static_cast<double>(factor) * static_cast<double>(factor);
  for (Eigen::Index j = 0; j < ny; ++j) {
    const Eigen::Index ky = signed_frequency(j, ny);
    const bool y_nyquist = 2 * ky == ny;
    for (Eigen::Index k = 0; k < coarse.nx_half(); ++k) {
      const double w = scale * (2 * k == nx ? 0.5 : 1.0) * (y_nyquist ? 0.5 : 1.0);
      const std::complex<double> v = w * c[j * coarse.nx_half() + k];
      f[(ky >= 0 ? ky : my + ky) * fine.nx_half() + k] += v;
      if (y_nyquist) f[(my - ky) * fine.nx_half() + k] += v;  // the −q_N half of the cosine
    }
  }
  Eigen::ArrayXXd out(mx, my);
  fine.inverse(out.data());
  return out / static_cast<double>(mx * my);
}

SurfaceStatistics surface_statistics(const Eigen::ArrayXXd& h, double lx_m, double ly_m) {
  if (h.size() == 0) throw std::invalid_argument("surface statistics: empty height field");
  if (!(lx_m > 0.0 && ly_m > 0.0 && std::isfinite(lx_m) && std::isfinite(ly_m))) {
    throw std::invalid_argument("surface statistics: side lengths must be positive");
  }
  SurfaceStatistics s;
  const double n = static_cast<double>(h.size());
  s.mean_m = h.mean();
  const Eigen::ArrayXXd d = h - s.mean_m;
  s.rq_m = std::sqrt(d.square().mean());
  s.ra_m = d.abs().mean();
  if (s.rq_m > 0.0) {
    s.skewness = d.cube().mean() / std::pow(s.rq_m, 3);
    s.kurtosis = d.square().square().mean() / std::pow(s.rq_m, 4);
  }
  s.min_m = h.minCoeff();
  s.max_m = h.maxCoeff();
  const Eigen::Index nx = h.rows(), ny = h.cols();
  const double dx = lx_m / static_cast<double>(nx), dy = ly_m / static_cast<double>(ny);
  s.rms_slope = fd_rms_slope(h, dx, dy);
  double curv = 0.0;
  for (Eigen::Index j = 0; j < ny; ++j) {
    const Eigen::Index jp = (j + 1) % ny, jm = (j + ny - 1) % ny;
    for (Eigen::Index i = 0; i < nx; ++i) {
      const Eigen::Index ip = (i + 1) % nx, im = (i + nx - 1) % nx;
      const double lap = (nx > 2 ? (h(ip, j) - 2.0 * h(i, j) + h(im, j)) / (dx * dx) : 0.0) +
                         (ny > 2 ? (h(i, jp) - 2.0 * h(i, j) + h(i, jm)) / (dy * dy) : 0.0);
      curv += 0.25 * lap * lap;
    }
  }
  s.rms_curvature_per_m = std::sqrt(curv / n);
  return s;
}

RadialPsd radial_psd(const Eigen::ArrayXXd& h, double lx_m, double ly_m) {
  if (h.size() == 0) throw std::invalid_argument("radial PSD: empty height field");
  if (!(lx_m > 0.0 && ly_m > 0.0)) throw std::invalid_argument("radial PSD: side lengths must be positive");
  const Eigen::Index nx = h.rows(), ny = h.cols();
  RealFft2d fft(nx, ny, 1);
  fft.real() = h - h.mean();
  fft.forward();
  const double two_pi = 2.0 * std::numbers::pi;
  const double dqx = two_pi / lx_m, dqy = two_pi / ly_m, dq = std::min(dqx, dqy);
  // Largest full circle: the Nyquist wavenumber of the coarser direction.
  const double q_max = std::min(nx > 1 ? dqx * static_cast<double>(nx / 2) : 0.0,
                                ny > 1 ? dqy * static_cast<double>(ny / 2) : 0.0);
  const auto bins = static_cast<std::size_t>(std::max(0.0, std::floor(q_max / dq + 0.5)));
  RadialPsd out;
  std::vector<double> sum(bins + 1, 0.0);
  std::vector<int> count(bins + 1, 0);
  const double norm = 1.0 / (static_cast<double>(h.size()) * static_cast<double>(h.size()));
  const double to_psd = lx_m * ly_m / (two_pi * two_pi);
  for (Eigen::Index j = 0; j < ny; ++j) {
    const double qy = dqy * static_cast<double>(signed_frequency(j, ny));
    for (Eigen::Index k = 0; k < fft.nx_half(); ++k) {
      const double q = std::hypot(dqx * static_cast<double>(k), qy);
      const auto b = static_cast<std::size_t>(std::floor(q / dq + 0.5));
      if (b == 0 || b > bins) continue;
      // One entry per independent complex amplitude (its conjugate at −q carries no new
      // information), so `modes` sets the sampling scatter 1/√modes of the bin average.
      sum[b] += std::norm(fft.spectrum()[j * fft.nx_half() + k]) * norm * to_psd;
      count[b] += 1;
    }
  }
  for (std::size_t b = 1; b <= bins; ++b) {
    if (count[b] == 0) continue;
    out.q_per_m.push_back(dq * static_cast<double>(b));
    out.psd_m4.push_back(sum[b] / count[b]);
    out.modes.push_back(count[b]);
  }
  return out;
}

HeightHistogram height_histogram(const Eigen::ArrayXXd& h, int bins) {
  if (bins < 1) throw std::invalid_argument("height histogram: bins must be >= 1");
  if (h.size() == 0) throw std::invalid_argument("height histogram: empty height field");
  const double lo = h.minCoeff(), hi = h.maxCoeff();
  const double width = hi > lo ? (hi - lo) / bins : 1.0;
  std::vector<double> counts(static_cast<std::size_t>(bins), 0.0);
  for (Eigen::Index k = 0; k < h.size(); ++k) {
    const int b = std::min(bins - 1, static_cast<int>((h.data()[k] - lo) / width));
    counts[static_cast<std::size_t>(b)] += 1.0;
  }
  HeightHistogram out;
  for (int b = 0; b < bins; ++b) {
    out.bin_centre_m.push_back(lo + (b + 0.5) * width);
    out.density_per_m.push_back(counts[static_cast<std::size_t>(b)] / (static_cast<double>(h.size()) * width));
  }
  return out;
}

}  // namespace tribo::contact
