// Uses the installed tribo libraries through their installed headers (root <prefix>/include/tribo)
// and checks each result against a closed form, so a wrong or half-linked library fails here.
// Prints "consumer: ok" and exits 0 when every check passes.
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Core>

#include "contact/grid.h"
#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/reference/hertz.h"
#include "contact/surface.h"
#include "lubrication/geometry.h"
#include "lubrication/reference/squeeze_film.h"
#include "lubrication/reynolds.h"
#include "rig/parameters.h"

namespace {

int failures = 0;

void check(const char* what, double value, double expected, double relative_tolerance) {
  const double error = std::abs(value / expected - 1.0);
  const bool ok = error <= relative_tolerance;
  std::printf("%-40s %.6g (expected %.6g, error %.2e, tolerance %.1e) %s\n", what, value, expected, error,
              relative_tolerance, ok ? "ok" : "FAILED");
  failures += ok ? 0 : 1;
}

}  // namespace

int main() {
  namespace contact = tribo::contact;
  namespace lub = tribo::lubrication;

  // A sinusoid z = A cos(2π x / L) sampled over whole periods has rms height A/√2 exactly.
  const int n = 64;
  const double side = 1e-3, amplitude = 1e-6;
  Eigen::ArrayXXd z(n, n);
  for (int i = 0; i < n; ++i) z.row(i).setConstant(amplitude * std::cos(2.0 * std::numbers::pi * i / n));
  check("surface rms height (m)", contact::surface_statistics(z, side, side).rq_m, amplitude / std::sqrt(2.0), 1e-12);

  // Hertz: a sphere on a non-periodic 128² grid, contact radius ≈ 32 cells (the library's own
  // test asks 2.5 % at this resolution).
  const double e_star = 1e11, radius = 0.01, a_target = 0.25e-3;
  const double load = 4.0 * e_star * std::pow(a_target, 3) / (3.0 * radius);
  const contact::Grid grid = contact::Grid::patch(128, 128, side, side);
  contact::ElasticHalfSpace hs(grid, e_star, /*periodic=*/false);
  const contact::NormalContactResult r = contact::solve_normal_load(hs, contact::sphere_gap(grid, radius), load);
  if (!r.summary.converged) {
    std::printf("Hertz solve did not converge: %s\n", r.summary.message.c_str());
    ++failures;
  }
  check("Hertz contact radius (m)", std::sqrt(r.real_area_m2 / std::numbers::pi),
        contact::reference::hertz_contact_radius_m(load, radius, e_star), 0.025);

  // Squeeze film between parallel discs (a sparse direct Reynolds solve) against the closed form.
  const double disc = 4.7625e-3, gap = 1e-6, rate = -1e-6, eta = 0.05;
  const lub::ReynoldsSolution s = lub::solve_reynolds(lub::parallel_discs_problem(disc, gap, rate, eta, 0.0, 65));
  check("squeeze-film load (N)", s.load_N, lub::squeeze_film_load_N(eta, disc, gap, rate), 0.02);

  // The thesis rig (Appendix I): damped natural frequency 101.9 rad/s.
  check("rig damped frequency (rad/s)", tribo::rig::RigParameters{}.damped_frequency_rad_per_s(), 101.9, 1e-3);

  std::printf("consumer: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures == 0 ? 0 : 1;
}
