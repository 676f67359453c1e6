// Surfaces and the BEM normal (and tangential) contact solve.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"
#include "contact/surface_io.h"
#include "contact/tangential.h"
#include "python/common.h"

namespace tribo::python {
namespace {

using Eigen::ArrayXXd;

contact::SpectrumKind spectrum_kind(const std::string& name) {
  if (name == "self_affine") return contact::SpectrumKind::self_affine;
  if (name == "gaussian_acf") return contact::SpectrumKind::gaussian_acf;
  throw std::invalid_argument("spectrum: '" + name + "' is not one of self_affine, gaussian_acf");
}

ArrayXXd gaussian_surface(Eigen::Index grid, double size_m, const std::string& spectrum,
                          std::optional<double> rms_height_m, std::optional<double> rms_slope, std::uint64_t seed,
                          double hurst, double rolloff_wavelength_m, double cutoff_wavelength_m,
                          double correlation_length_m, double correlation_length_across_m, double peklenik_gamma) {
  contact::GaussianSurfaceParams p;
  p.grid = grid;
  p.size_m = size_m;
  p.kind = spectrum_kind(spectrum);
  // Exactly one target: the height unless only a slope is given (the library checks "exactly one").
  p.rms_slope = rms_slope.value_or(0.0);
  p.rms_height_m = rms_height_m.value_or(rms_slope ? 0.0 : 1e-6);
  p.seed = seed;
  p.hurst = hurst;
  p.rolloff_wavelength_m = rolloff_wavelength_m;
  p.cutoff_wavelength_m = cutoff_wavelength_m;
  p.correlation_length_m = correlation_length_m;
  p.correlation_length_across_m = correlation_length_across_m;
  p.peklenik_gamma = peklenik_gamma;
  contact::validate(p);
  py::gil_scoped_release release;
  return contact::gaussian_surface(p);
}

py::dict statistics(const ArrayXXd& heights_m, double lx_m, std::optional<double> ly_m) {
  if (heights_m.size() == 0) throw std::invalid_argument("heights_m: empty array");
  const contact::SurfaceStatistics s = contact::surface_statistics(heights_m, lx_m, ly_m.value_or(lx_m));
  py::dict d;
  d["mean_m"] = s.mean_m;
  d["rq_m"] = s.rq_m;
  d["ra_m"] = s.ra_m;
  d["rms_slope"] = s.rms_slope;
  d["rms_curvature_per_m"] = s.rms_curvature_per_m;
  d["skewness"] = s.skewness;
  d["kurtosis"] = s.kurtosis;
  d["min_m"] = s.min_m;
  d["max_m"] = s.max_m;
  return d;
}

py::dict radial_psd(const ArrayXXd& heights_m, double lx_m, std::optional<double> ly_m) {
  const contact::RadialPsd r = contact::radial_psd(heights_m, lx_m, ly_m.value_or(lx_m));
  py::dict d;
  d["q_per_m"] = py::array(py::cast(r.q_per_m));
  d["psd_m4"] = py::array(py::cast(r.psd_m4));
  d["modes"] = py::array(py::cast(r.modes));
  return d;
}

py::dict read_topography(const std::filesystem::path& path, double height_scale) {
  const contact::Topography t = contact::read_topography(path, height_scale);
  py::dict d;
  d["heights_m"] = t.heights_m;
  d["lx_m"] = t.lx_m;
  d["ly_m"] = t.ly_m;
  return d;
}

py::dict contact_summary(const contact::NormalContactSummary& s) {
  py::dict d;
  d["converged"] = s.converged;
  d["iterations"] = s.iterations;
  d["residual"] = s.residual;
  d["fft_pairs"] = s.fft_pairs;
  d["single_pairs"] = s.single_pairs;
  d["message"] = s.message;
  return d;
}

py::dict contact_result(const contact::NormalContactResult& r) {
  py::dict d;
  d["pressure_Pa"] = r.pressure_Pa;
  d["gap_m"] = r.gap_m;
  d["displacement_m"] = r.displacement_m;
  d["plastic_increment_m"] = r.plastic_increment_m;
  d["normal_load_N"] = r.normal_load_N;
  d["approach_m"] = r.approach_m;
  d["real_area_m2"] = r.real_area_m2;
  d["plastic_area_m2"] = r.plastic_area_m2;
  d["area_fraction"] = r.area_fraction;
  d["max_pressure_Pa"] = r.max_pressure_Pa;
  d["mean_gap_m"] = r.mean_gap_m;
  d["summary"] = contact_summary(r.summary);
  return d;
}

// One solve as `tribo contact` runs it (apps/cmd_contact.cpp): a half-space on the profile's grid,
// then a load-, approach- or mean-gap-controlled elastic(-plastic) solve, or with a tangential
// load the junction-growth fixed point of contact/tangential.h.
py::dict solve_contact(const ArrayXXd& gap0_m, double size_m, std::optional<double> size_y_m, double e_star_Pa,
                       std::optional<double> normal_load_N, std::optional<double> approach_m,
                       std::optional<double> mean_gap_m, bool periodic, std::optional<double> hardness_Pa,
                       double tangential_load_N, double alpha, std::optional<double> interface_shear_strength_Pa,
                       double tolerance, int max_iterations, double single_precision_above, int threads) {
  if (gap0_m.rows() < 1 || gap0_m.cols() < 1) throw std::invalid_argument("gap0_m: empty array");
  const int controls = int(normal_load_N.has_value()) + int(approach_m.has_value()) + int(mean_gap_m.has_value());
  if (controls != 1) throw std::invalid_argument("give exactly one of normal_load_N, approach_m, mean_gap_m");
  if (tangential_load_N > 0.0 && (!normal_load_N || !hardness_Pa))
    throw std::invalid_argument("tangential_load_N: junction growth needs normal_load_N and hardness_Pa");
  // Side along y: the profile's aspect ratio at the x spacing unless given (square cells).
  const double ly_m = size_y_m.value_or(size_m * double(gap0_m.cols()) / double(gap0_m.rows()));
  const contact::Grid grid = contact::Grid::patch(gap0_m.rows(), gap0_m.cols(), size_m, ly_m);
  contact::validate(grid);
  contact::NormalContactOptions options;
  options.tolerance = tolerance;
  options.max_iterations = max_iterations;
  options.single_precision_above = single_precision_above;
  if (std::string why; !options.is_valid(&why)) throw std::invalid_argument(why);

  py::dict d;
  contact::NormalContactResult r;
  {
    py::gil_scoped_release release;
    contact::ElasticHalfSpace hs(grid, e_star_Pa, periodic, threads);
    if (tangential_load_N > 0.0) {
      contact::TangentialContactOptions t;
      t.hardness_Pa = *hardness_Pa;
      t.alpha = alpha;
      t.interface_shear_strength_Pa = interface_shear_strength_Pa.value_or(std::numeric_limits<double>::infinity());
      t.normal = options;
      const contact::TangentialContactResult tr = contact::solve_tangential_load(hs, gap0_m, *normal_load_N,
                                                                                 tangential_load_N, t);
      r = tr.contact;
      py::gil_scoped_acquire acquire;
      py::dict j;
      j["tangential_load_N"] = tr.tangential_load_N;
      j["shear_stress_Pa"] = tr.shear_stress_Pa;
      j["pressure_cap_Pa"] = tr.pressure_cap_Pa;
      j["slipped"] = tr.slipped;
      j["converged"] = tr.converged;
      j["outer_iterations"] = tr.outer_iterations;
      j["inner_iterations"] = tr.inner_iterations;
      j["message"] = tr.message;
      d["junction"] = j;
    } else {
      if (hardness_Pa) options.pressure_cap_Pa = *hardness_Pa;
      if (normal_load_N) r = contact::solve_normal_load(hs, gap0_m, *normal_load_N, options);
      else if (approach_m) r = contact::solve_approach(hs, gap0_m, *approach_m, options);
      else r = contact::solve_mean_gap(hs, gap0_m, *mean_gap_m, options);
    }
  }
  for (auto item : contact_result(r)) d[item.first] = item.second;
  if (d.contains("junction")) {
    // As the CLI reports it: CG iterations over all the solves, and converged only if the
    // junction's fixed point converged too.
    py::dict s = d["summary"];
    s["iterations"] = d["junction"]["inner_iterations"];
    s["converged"] = py::bool_(r.summary.converged && d["junction"]["converged"].cast<bool>());
  }
  return d;
}

ArrayXXd sphere_gap(Eigen::Index grid, double size_m, double radius_m) {
  const contact::Grid g = contact::Grid::patch(grid, grid, size_m, size_m);
  contact::validate(g);
  if (!(radius_m > 0)) throw std::invalid_argument("radius_m: must be > 0");
  return contact::sphere_gap(g, radius_m);
}

}  // namespace

void bind_contact(py::module_& m) {
  using namespace pybind11::literals;
  m.def("gaussian_surface", &gaussian_surface,
        R"(Periodic Gaussian random rough surface (contact/surface.h), heights in m.

Returns a float64 array of shape (grid, grid), a[i, j] = h(x_i, y_j), x_i = i * size_m / grid,
mean zero, scaled so its rms height Rq (m) or its rms slope (1) equals the target exactly.

grid: points per side n.  size_m: side L of the periodic square (m).
spectrum: "self_affine" (Hurst exponent `hurst` in (0, 1], roll-off wavelength
  `rolloff_wavelength_m`, short-wavelength cut-off `cutoff_wavelength_m`, 0 = none; a lay by
  `peklenik_gamma`, features that many times longer along x than across, 1 = isotropic) or
  "gaussian_acf" (correlation length `correlation_length_m` along x, the lay, and
  `correlation_length_across_m` along y, 0 = isotropic).
rms_height_m or rms_slope: exactly one (default Rq = 1e-6 m).
seed: same seed, same surface on any thread count. Bad parameters raise ValueError.)",
        "grid"_a = 256, "size_m"_a = 1e-3, "spectrum"_a = "self_affine", "rms_height_m"_a = py::none(),
        "rms_slope"_a = py::none(), "seed"_a = 1, "hurst"_a = 0.8, "rolloff_wavelength_m"_a = 0.0,
        "cutoff_wavelength_m"_a = 0.0, "correlation_length_m"_a = 0.0, "correlation_length_across_m"_a = 0.0,
        "peklenik_gamma"_a = 1.0);
  m.def("surface_statistics", &statistics,
        R"(Statistics of a height field (m) on a periodic patch lx_m x ly_m (ly_m defaults to lx_m):
dict mean_m, rq_m, ra_m (m), rms_slope (1), rms_curvature_per_m (1/m), skewness, kurtosis, min_m, max_m.)",
        "heights_m"_a, "lx_m"_a, "ly_m"_a = py::none());
  m.def("radial_psd", &radial_psd,
        R"(Radially averaged 2-D PSD of a height field (m) on lx_m x ly_m: dict of arrays
q_per_m (rad/m, bin centres), psd_m4 (C(q), m^4), modes (Fourier amplitudes per bin).)",
        "heights_m"_a, "lx_m"_a, "ly_m"_a = py::none());
  m.def("read_topography", &read_topography,
        R"(Read a measured surface: .npy, .xyz (x y z columns) or an ASCII matrix (rows along x).
Heights are multiplied by height_scale (e.g. 1e-6 for a file in um) to give metres.
Returns dict heights_m (array (nx, ny), m), lx_m, ly_m (m; 0 when the format carries no size).
A missing or malformed file raises ValueError naming it.)",
        "path"_a, "height_scale"_a = 1.0);
  m.def("gap_from_heights", &contact::gap_from_heights,
        "Initial gap (m) of a rigid rough surface with heights z (m) against a flat: max(z) - z.", "heights_m"_a);
  m.def("sphere_gap", &sphere_gap,
        "Initial gap (m) of a sphere of radius radius_m centred on a grid x grid patch of side size_m: r^2/(2R).",
        "grid"_a, "size_m"_a, "radius_m"_a);
  m.def("composite_modulus_Pa", &contact::composite_modulus_Pa,
        "Composite modulus E* (Pa): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (moduli in Pa).", "e1_Pa"_a, "nu1"_a,
        "e2_Pa"_a, "nu2"_a);
  m.def("solve_contact", &solve_contact,
        R"(BEM normal contact of a rigid profile on an elastic(-plastic) half-space (contact/normal_contact.h).

gap0_m: initial gap h (m), array (nx, ny) on cells of size_m / nx (size_y_m defaults to square cells).
e_star_Pa: composite modulus E* (Pa).  periodic: periodic half-space (rough patches) or isolated
(a sphere).  hardness_Pa: pressure cap sigma0 (Pa) of surface plasticity; None = elastic.
Control, exactly one of: normal_load_N (N), approach_m (rigid approach, m), mean_gap_m (m, periodic only).
tangential_load_N > 0 (N, with normal_load_N and hardness_Pa): junction growth under the Tabor cap
sqrt(sigma0^2 - alpha tau^2) with alpha and interface_shear_strength_Pa (tau_i, Pa; None = never slips)
as `tribo contact` does; the extra dict "junction" then reports it.
tolerance: relative complementarity residual; max_iterations 0 = automatic; single_precision_above: the
products in single precision while the residual is above it (periodic), 0 = double throughout;
threads 0 = all OpenMP threads.

Returns dict: pressure_Pa, gap_m, displacement_m, plastic_increment_m (arrays (nx, ny));
normal_load_N, approach_m, real_area_m2, plastic_area_m2, area_fraction, max_pressure_Pa, mean_gap_m;
summary {converged, iterations, residual, fft_pairs, single_pairs, message}. Non-convergence is reported there,
not raised; bad input raises ValueError.)",
        "gap0_m"_a, "size_m"_a, "size_y_m"_a = py::none(), "e_star_Pa"_a = 1.137e11, "normal_load_N"_a = py::none(),
        "approach_m"_a = py::none(), "mean_gap_m"_a = py::none(), "periodic"_a = true, "hardness_Pa"_a = py::none(),
        "tangential_load_N"_a = 0.0, "alpha"_a = 25.0, "interface_shear_strength_Pa"_a = py::none(),
        "tolerance"_a = 1e-8, "max_iterations"_a = 0, "single_precision_above"_a = 1e-6, "threads"_a = 0);
}

}  // namespace tribo::python
