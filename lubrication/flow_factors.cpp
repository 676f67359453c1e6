#include "lubrication/flow_factors.h"

#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"

#include <omp.h>

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tribo::lubrication {
namespace {

[[noreturn]] void bad_cell_input(const std::string& what) { throw std::invalid_argument("homogenisation: " + what); }

// Reynolds cell over one period of the surface (periodic_film_cell) on the film
// max(h + z, floor). `transposed` swaps the surface axes (flow along the surface's y).
ReynoldsProblem cell_problem(const Eigen::ArrayXXd& z, double size_m, double nominal_gap_m, double floor_m,
                             bool transposed, double viscosity_Pa_s, std::size_t* touching) {
  const Eigen::ArrayXXd h = nominal_gap_m + (transposed ? Eigen::ArrayXXd(z.transpose()) : z);
  if (touching) *touching = static_cast<std::size_t>((h <= floor_m).count());
  ReynoldsProblem pr = periodic_film_cell(h.max(floor_m), size_m);
  pr.viscosity_Pa_s = viscosity_Pa_s;
  return pr;
}

// Mean local film h̄_T over one period (the wrapped column counted once).
double mean_film_m(const ReynoldsProblem& pr) {
  double sum = 0;
  for (Eigen::Index j = 0; j < pr.grid.ny; ++j)
    for (Eigen::Index i = 0; i + 1 < pr.grid.nx; ++i) sum += pr.gap_m(i, j);
  return sum / static_cast<double>((pr.grid.nx - 1) * pr.grid.ny);
}

// Mean shears on the stationary (rough) wall of a solved cell, over the n × n surface nodes (the
// wrapped column once), contact nodes (film at the floor) contributing nothing. The x-flow q̄ of
// node i is the mean of its two x-face flows (the face before node 0 is the face before the wrap
// node n), and the local 1-D relation q̄ = −h_T³p'/(12η) + (U/2)h_T gives the nodal gradient
//     (h_T/2) p' = 6η((U/2) h_T − q̄)/h_T².
struct WallShear {
  double couette_Pa = 0;   // Σ ηU/h_T / N
  double pressure_Pa = 0;  // Σ (h_T/2) p' / N
};

WallShear stationary_wall_shear(const ReynoldsProblem& pr, const ReynoldsSolution& s, double floor_m) {
  const contact::Grid& g = pr.grid;
  const Eigen::Index n = g.nx - 1;
  const Eigen::ArrayXXd q = x_face_flow_m2_per_s(pr, s);
  const double eta = pr.viscosity_Pa_s, u = pr.sliding_speed_m_per_s;
  WallShear w;
  for (Eigen::Index j = 0; j < g.ny; ++j)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double h = pr.gap_m(i, j);
      if (h <= floor_m) continue;
      const double qbar = 0.5 * (q((i + n - 1) % n, j) + q(i, j));
      w.couette_Pa += eta * u / h;
      w.pressure_Pa += 6.0 * eta * (0.5 * u * h - qbar) / (h * h);
    }
  const double cells = static_cast<double>(n) * g.ny;
  w.couette_Pa /= cells;
  w.pressure_Pa /= cells;
  return w;
}

struct PatirChengPressure {
  double gamma, c, r;
};
struct PatirChengShear {
  double gamma, a1, alpha1, alpha2, alpha3, a2;
};
// Patir & Cheng 1978, Table 1 (pressure flow factor) and 1979, Table 1 (shear flow factor).
constexpr std::array<PatirChengPressure, 7> kPressureFits{{{1.0 / 9, 1.48, 0.42},
                                                           {1.0 / 6, 1.38, 0.42},
                                                           {1.0 / 3, 1.18, 0.42},
                                                           {1.0, 0.90, 0.56},
                                                           {3.0, 0.225, 1.5},
                                                           {6.0, 0.520, 1.5},
                                                           {9.0, 0.870, 1.5}}};
constexpr std::array<PatirChengShear, 7> kShearFits{{{1.0 / 9, 2.046, 1.12, 0.78, 0.03, 1.856},
                                                     {1.0 / 6, 1.962, 1.08, 0.77, 0.03, 1.754},
                                                     {1.0 / 3, 1.858, 1.01, 0.76, 0.03, 1.561},
                                                     {1.0, 1.899, 0.98, 0.92, 0.05, 1.126},
                                                     {3.0, 1.560, 0.85, 1.13, 0.08, 0.556},
                                                     {6.0, 1.290, 0.62, 1.09, 0.08, 0.388},
                                                     {9.0, 1.011, 0.54, 1.07, 0.08, 0.295}}};

bool same_gamma(double a, double b) { return std::abs(a / b - 1.0) < 1e-6; }

}  // namespace

Estimate estimate(const std::vector<double>& v) {
  Estimate e;
  if (v.empty()) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  for (double x : v) e.mean += x;
  e.mean /= static_cast<double>(v.size());
  if (v.size() < 2) return e;
  double ss = 0;
  for (double x : v) ss += (x - e.mean) * (x - e.mean);
  e.standard_error = std::sqrt(ss / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
  return e;
}

double patir_cheng_phi_x(double h, double gamma) {
  if (!(h >= 0.5)) return std::numeric_limits<double>::quiet_NaN();
  for (const auto& f : kPressureFits)
    if (same_gamma(f.gamma, gamma)) return gamma <= 1.0 ? 1.0 - f.c * std::exp(-f.r * h) : 1.0 + f.c * std::pow(h, -f.r);
  return std::numeric_limits<double>::quiet_NaN();
}

double patir_cheng_phi_y(double h, double gamma) { return patir_cheng_phi_x(h, 1.0 / gamma); }

double patir_cheng_phi_f(double h, double contact_gap_fraction) {
  if (!(h > 0) || !(contact_gap_fraction > 0)) return std::numeric_limits<double>::quiet_NaN();
  const double z = h / 3.0, eps = contact_gap_fraction / 3.0, a = 1.0 - z * z, a3 = a * a * a;
  if (z <= 1.0)
    return 35.0 / 32.0 * z *
           (a3 * std::log((z + 1.0) / eps) +
            (-55.0 + z * (132.0 + z * (345.0 + z * (-160.0 + z * (-405.0 + z * (60.0 + 147.0 * z)))))) / 60.0);
  return 35.0 / 32.0 * z * (a3 * std::log((z + 1.0) / (z - 1.0)) + z / 15.0 * (66.0 + z * z * (30.0 * z * z - 80.0)));
}

double patir_cheng_shear_factor(double h, double gamma) {
  if (!(h > 0.5)) return std::numeric_limits<double>::quiet_NaN();
  for (const auto& f : kShearFits)
    if (same_gamma(f.gamma, gamma))
      return h <= 5.0 ? f.a1 * std::pow(h, f.alpha1) * std::exp(-f.alpha2 * h + f.alpha3 * h * h)
                      : f.a2 * std::exp(-0.25 * h);
  return std::numeric_limits<double>::quiet_NaN();
}

void validate(const HomogenisationOptions& o) {
  contact::validate(o.surface);
  if (!(o.surface.rms_height_m > 0)) bad_cell_input("surface.rms_height_m (σ) must be > 0");
  if (o.surface.grid < 8) bad_cell_input("surface.grid must be >= 8");
  if (o.gap_ratios.empty()) bad_cell_input("gap_ratios must not be empty");
  for (double h : o.gap_ratios)
    if (!(std::isfinite(h) && h > 0)) bad_cell_input("gap_ratios must be finite and > 0");
  if (o.realisations < 1) bad_cell_input("realisations must be >= 1");
  if (!(std::isfinite(o.viscosity_Pa_s) && o.viscosity_Pa_s > 0)) bad_cell_input("viscosity_Pa_s must be finite and > 0");
  if (!(std::isfinite(o.sliding_speed_m_per_s) && o.sliding_speed_m_per_s != 0))
    bad_cell_input("sliding_speed_m_per_s must be finite and non-zero");
  if (!(std::isfinite(o.pressure_drop_Pa) && o.pressure_drop_Pa > 0)) bad_cell_input("pressure_drop_Pa must be finite and > 0");
  if (!(o.contact_gap_fraction > 0 && o.contact_gap_fraction <= 0.5)) bad_cell_input("contact_gap_fraction must be in (0, 0.5]");
  if (o.threads < 0) bad_cell_input("threads must be >= 0");
  if (o.heights_m) {
    if (o.realisations != 1) bad_cell_input("given heights are one realisation: realisations must be 1");
    if (o.heights_m->rows() != o.surface.grid || o.heights_m->cols() != o.surface.grid)
      bad_cell_input("given heights are " + std::to_string(o.heights_m->rows()) + "x" + std::to_string(o.heights_m->cols()) +
                     ", surface.grid is " + std::to_string(o.surface.grid));
    if (!o.heights_m->allFinite()) bad_cell_input("given heights must be finite");
  }
}

namespace {

// Runs `per_realisation(k, solver, surface)` for every realisation in parallel; one solver per
// realisation keeps the symbolic analyses reused across the gap ratios of that realisation.
// The cells' Reynolds options: the defaults, with more Newton steps. From the full film, Newton on a
// contact-floored rough cell moves its many cavitation fronts about a node per damped step before
// it turns quadratic: on the thesis preset (128², seed 1) 32 steps at h/σ = 0.5 and 62 at 0.25,
// where the default limit of 60 (set for bearings, 3–9 steps) dropped the cell unconverged. A cell
// that would not converge costs the same steps either way, so the limit only buys convergence.
ReynoldsOptions cell_solver_options() {
  ReynoldsOptions o;
  o.max_newton_iterations = 200;
  return o;
}

template <class F>
void for_each_realisation(const HomogenisationOptions& o, F per_realisation) {
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  std::string error;
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (int k = 0; k < o.realisations; ++k) {
    try {
      contact::GaussianSurfaceParams p = o.surface;
      p.seed = o.first_seed + static_cast<std::uint64_t>(k);
      const Eigen::ArrayXXd z = o.heights_m ? *o.heights_m : contact::gaussian_surface(p);
      ReynoldsSolver solver(cell_solver_options());
      per_realisation(k, solver, z);
    } catch (const std::exception& e) {
#pragma omp critical(tribo_homogenisation_error)
      error = e.what();
    }
  }
  if (!error.empty()) throw std::runtime_error("homogenisation: " + error);
}

}  // namespace

std::vector<FlowFactorRow> flow_factors(const HomogenisationOptions& o) {
  validate(o);
  const std::size_t nh = o.gap_ratios.size();
  const double sigma = o.surface.rms_height_m, size = o.surface.size_m, eta = o.viscosity_Pa_s;
  const auto r = static_cast<std::size_t>(o.realisations);
  // Per (gap ratio, realisation): NaN marks an unconverged solve.
  std::vector<std::vector<double>> px(nh, std::vector<double>(r)), py = px, ps = px, film = px, touch = px;
  std::vector<std::vector<double>> pf = px, pfs = px, pfp = px, couette = px;
  for_each_realisation(o, [&](int k, ReynoldsSolver& solver, const Eigen::ArrayXXd& z) {
    const double cells = static_cast<double>(z.size());
    for (std::size_t m = 0; m < nh; ++m) {
      const double h = o.gap_ratios[m] * sigma, floor_m = o.contact_gap_fraction * sigma;
      const double smooth_flow = h * h * h * o.pressure_drop_Pa / (12.0 * eta * size);
      std::size_t touching = 0;
      for (int axis = 0; axis < 2; ++axis) {
        ReynoldsProblem pr = cell_problem(z, size, h, floor_m, axis == 1, eta, &touching);
        pr.inlet_pressure_Pa = o.pressure_drop_Pa;
        const ReynoldsSolution s = solver.solve(pr);
        const double q = film_flow(pr, s).inflow_x0_m3_per_s / size;
        (axis == 0 ? px : py)[m][k] = s.summary.converged ? q / smooth_flow : std::nan("");
        if (axis == 0) {  // φfp = ⟨(h_T/2)p'⟩ / ((h/2)∂p̄/∂x), ∂p̄/∂x = −Δp/L
          const double mean_gradient = -o.pressure_drop_Pa / size;
          pfp[m][k] = s.summary.converged ? stationary_wall_shear(pr, s, floor_m).pressure_Pa / (0.5 * h * mean_gradient)
                                          : std::nan("");
        }
      }
      ReynoldsProblem pr = cell_problem(z, size, h, floor_m, false, eta, &touching);
      pr.sliding_speed_m_per_s = o.sliding_speed_m_per_s;
      const ReynoldsSolution s = solver.solve(pr);
      const double u = o.sliding_speed_m_per_s, q = film_flow(pr, s).inflow_x0_m3_per_s / size;
      const double ht = mean_film_m(pr);
      ps[m][k] = s.summary.converged ? (0.5 * u * ht - q) / (0.5 * u * sigma) : std::nan("");
      film[m][k] = ht / sigma;
      // Stationary-wall shear τ = ηU/h_T − (h_T/2)p' in units of ηU/h: φf − φfs.
      const WallShear w = stationary_wall_shear(pr, s, floor_m);
      const double scale = eta * u / h;
      pf[m][k] = w.couette_Pa / scale;
      pfs[m][k] = s.summary.converged ? w.pressure_Pa / scale : std::nan("");
      couette[m][k] = s.summary.converged ? (w.couette_Pa - w.pressure_Pa) / scale : std::nan("");
      touch[m][k] = static_cast<double>(touching) / cells;
    }
  });
  std::vector<FlowFactorRow> rows(nh);
  for (std::size_t m = 0; m < nh; ++m) {
    auto finite = [&](const std::vector<double>& v) {
      std::vector<double> out;
      for (double x : v)
        if (std::isfinite(x)) out.push_back(x);
      return out;
    };
    FlowFactorRow& row = rows[m];
    row.h_over_sigma = o.gap_ratios[m];
    row.phi_x = estimate(finite(px[m]));
    row.phi_y = estimate(finite(py[m]));
    row.phi_s = estimate(finite(ps[m]));
    row.phi_f = estimate(pf[m]);
    row.phi_fs = estimate(finite(pfs[m]));
    row.phi_fp = estimate(finite(pfp[m]));
    row.couette_shear_factor = estimate(finite(couette[m]));
    row.mean_film_over_sigma = estimate(film[m]);
    row.contact_fraction = estimate(touch[m]);
    row.unconverged = static_cast<int>(3 * r - finite(px[m]).size() - finite(py[m]).size() - finite(ps[m]).size());
  }
  return rows;
}

std::vector<LiftRow> rugosity_lift(const HomogenisationOptions& o) {
  validate(o);
  const std::size_t nh = o.gap_ratios.size();
  const double sigma = o.surface.rms_height_m, size = o.surface.size_m;
  const auto r = static_cast<std::size_t>(o.realisations);
  std::vector<std::vector<double>> cav(nh, std::vector<double>(r)), full = cav, frac = cav, iters = cav;
  for_each_realisation(o, [&](int k, ReynoldsSolver& solver, const Eigen::ArrayXXd& z) {
    for (std::size_t m = 0; m < nh; ++m) {
      ReynoldsProblem pr = cell_problem(z, size, o.gap_ratios[m] * sigma, o.contact_gap_fraction * sigma, false,
                                        o.viscosity_Pa_s, nullptr);
      pr.sliding_speed_m_per_s = o.sliding_speed_m_per_s;
      full[m][k] = solver.solve(pr).load_N / (size * size);
      pr.cavitation = Cavitation::mass_conserving;
      const ReynoldsSolution s = solver.solve(pr);
      cav[m][k] = s.summary.converged ? s.load_N / (size * size) : std::nan("");
      frac[m][k] = s.cavitated_fraction;
      iters[m][k] = s.summary.iterations;
    }
  });
  std::vector<LiftRow> rows(nh);
  const double eta_u = o.viscosity_Pa_s * o.sliding_speed_m_per_s;
  for (std::size_t m = 0; m < nh; ++m) {
    std::vector<double> ok, per;
    for (double x : cav[m])
      if (std::isfinite(x)) {
        ok.push_back(x);
        per.push_back(x / eta_u);
      }
    LiftRow& row = rows[m];
    row.h_over_sigma = o.gap_ratios[m];
    row.mean_pressure_Pa = estimate(ok);
    row.mean_pressure_per_eta_u = estimate(per);
    row.mean_pressure_full_film_Pa = estimate(full[m]);
    row.cavitated_fraction = estimate(frac[m]);
    row.newton_iterations = estimate(iters[m]);
    row.unconverged = static_cast<int>(r - ok.size());
  }
  return rows;
}

}  // namespace tribo::lubrication
