// The EHL point contact (lubrication/ehl_point.h) against a published numerical solution: the
// smooth ball-on-disc contact of Mourier, Mazuyer, Lubrecht & Donnet (Tribol. Int. 39, 2006),
// whose centre lines — film and pressure along the rolling direction — are in
// tests/lubrication/data/mourier-2006/ as digitised from the paper (SOURCE.md there), beside their
// interferometric measurement of the same contact's film.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "lubrication/ehl_point.h"
#include "lubrication/reference/ehl_point_film.h"
#include "rig/csv_table.h"

namespace tribo::lubrication {
namespace {

struct CurvePoint {
  double x_m, value;
};

// Column `value` against x_m of a CSV in data/mourier-2006/, read by the project's CSV reader.
std::vector<CurvePoint> read_curve(const std::string& name, const std::string& value) {
  std::vector<std::string> warnings;
  const rig::CsvTable table = rig::read_csv_table(
      std::filesystem::path(TRIBO_SOURCE_DIR) / "tests/lubrication/data/mourier-2006" / name, {"x_m", value}, warnings);
  const int x = table.required("x_m"), v = table.required(value);
  std::vector<CurvePoint> curve;
  for (const auto& [line, row] : table.rows) curve.push_back({table.number(line, row, x), table.number(line, row, v)});
  return curve;
}

// The paper's case: R = 12.5 mm, E' = 110 GPa, 15 N, u_m = 0.09 m/s, η0 = 0.25 Pa s, α = 22 /GPa,
// Roelands and Dowson–Higginson (SOURCE.md), on 257² nodes; solved once per test process.
const EhlPointResult& mourier_case() {
  static const EhlPointResult r = [] {
    const EhlPointContact contact{15.0, 12.5e-3, 110e9, 0.09};
    PiezoviscousLubricant oil;
    oil.viscosity_Pa_s = 0.25;
    oil.pressure_viscosity_per_Pa = 22e-9;
    oil.law = PressureViscosityLaw::roelands;
    oil.compressible = true;
    EhlPointOptions options;
    options.nodes_x = options.nodes_y = 257;
    return solve_ehl_point(contact, oil, options);
  }();
  return r;
}

// A field along the line y = 0 (the node nearest it), x ascending.
std::vector<double> centre_line(const EhlPointResult& r, const std::vector<double>& field) {
  const auto nx = r.x_m.size();
  std::size_t centre = 0;
  for (std::size_t j = 1; j < r.y_m.size(); ++j) {
    if (std::abs(r.y_m[j]) < std::abs(r.y_m[centre])) centre = j;
  }
  return {field.begin() + static_cast<std::ptrdiff_t>(centre * nx), field.begin() + static_cast<std::ptrdiff_t>((centre + 1) * nx)};
}

// Linear interpolation of (x, f) at x0 inside the grid.
double at(const std::vector<double>& x, const std::vector<double>& f, double x0) {
  const auto k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), x0) - x.begin());
  if (k == 0 || k == x.size()) throw std::out_of_range("point outside the solved domain");
  const double t = (x0 - x[k - 1]) / (x[k] - x[k - 1]);
  return (1.0 - t) * f[k - 1] + t * f[k];
}

// Film. Their central film (the flat plateau) is 209 nm, the outlet constriction on the centre line
// 175 nm at x = 0.92 a. Measured on 257²: 211.4 nm, 175.5 nm at 0.95 a (129²: 208.5, 173.9 nm — the
// grid moves them by ≈ 1 %); the film at their 28 points differs by 5.9 nm rms, most of it at the
// steep inlet and outlet, where a micrometre of x (the digitising) is several nanometres of film;
// over their plateau (|x| ≤ 100 µm) by 2.7 nm rms, 4.2 nm at most. Tolerances: 3 % on the films
// (digitising ≈ 1 %, our grid ≈ 1 %), 0.05 a on the constriction's position (their points near it
// are 6–15 µm = 0.04–0.1 a apart), rms 4 % of h_c over all points and 3 % at most on the plateau.
// What fails them (measured): Barus instead of Roelands (h_c 219.6 nm, +5 %), an incompressible film
// (233.5 nm, +12 %); a load or kernel off by a few percent fails the pressures below (p ∝ W^{1/3}).
TEST(EhlPointPublished, FilmAlongTheCentreLineMatchesMourierEtAl2006) {
  const EhlPointResult& r = mourier_case();
  ASSERT_TRUE(r.converged) << r.message;
  const double a = reference::hertz_point_radius_m(15.0, 12.5e-3, 110e9);
  const std::vector<double> h = centre_line(r, r.film_m);
  const auto outlet = std::min_element(h.begin() + static_cast<std::ptrdiff_t>(std::lower_bound(r.x_m.begin(), r.x_m.end(), 0.0) - r.x_m.begin()), h.end());
  const double x_outlet = r.x_m[static_cast<std::size_t>(outlet - h.begin())];
  std::printf("h_c %.1f nm (theirs 209.3), centre-line minimum %.1f nm at %.3f a (theirs 175.3 at 0.923 a)\n", r.central_film_m * 1e9,
              *outlet * 1e9, x_outlet / a);
  EXPECT_NEAR(r.central_film_m / 209.3e-9, 1.0, 0.03);
  EXPECT_NEAR(*outlet / 175.3e-9, 1.0, 0.03);
  EXPECT_NEAR(x_outlet / a, 126.2e-6 / a, 0.05);

  double sum2 = 0.0, plateau_max = 0.0;
  const std::vector<CurvePoint> theirs = read_curve("film_centre_line.csv", "film_m");
  for (const CurvePoint& q : theirs) {
    const double d = at(r.x_m, h, q.x_m) - q.value;
    sum2 += d * d;
    if (std::abs(q.x_m) <= 100e-6) plateau_max = std::max(plateau_max, std::abs(d));
  }
  const double rms = std::sqrt(sum2 / static_cast<double>(theirs.size()));
  std::printf("film: %.1f nm rms over %zu points, %.1f nm at most on the plateau\n", rms * 1e9, theirs.size(), plateau_max * 1e9);
  EXPECT_LT(rms, 0.04 * r.central_film_m);
  EXPECT_LT(plateau_max, 0.03 * r.central_film_m);
}

// The measurement: the same contact's film by optical interferometry (the paper's experiment;
// film_centre_line_measured.csv). Over the plateau (|x| ≤ 100 µm) its 17 points average 211.6 nm
// with a scatter of 2.6 nm (standard error 0.6 nm); our film at those points, 213.6 nm (+0.9 %).
// Tolerance 2 %: our grid's ≈ 1 % and an interferometer's calibration of about as much. Not
// asserted, said in docs/lubrication.md: the measured constriction is 167.7 nm at 0.96 a, ours (and
// their solution's) 175.5 nm — 4.7 % thicker than measured.
TEST(EhlPointPublished, PlateauFilmMatchesTheInterferometricMeasurement) {
  const EhlPointResult& r = mourier_case();
  ASSERT_TRUE(r.converged) << r.message;
  const std::vector<double> h = centre_line(r, r.film_m);
  double ours = 0.0, measured = 0.0;
  int count = 0;
  for (const CurvePoint& q : read_curve("film_centre_line_measured.csv", "film_m")) {
    if (std::abs(q.x_m) > 100e-6) continue;
    ours += at(r.x_m, h, q.x_m);
    measured += q.value;
    ++count;
  }
  std::printf("plateau over %d measured points: ours %.1f nm, measured %.1f nm\n", count, ours / count * 1e9, measured / count * 1e9);
  EXPECT_EQ(count, 17);
  EXPECT_NEAR(ours / measured, 1.0, 0.02);
}

// Pressure. Theirs: 388 MPa at the centre (dry Hertz 383 MPa) and the outlet spike, a second
// maximum of 284 MPa at x = 0.78 a. Measured on 257²: 386 MPa; the spike 284 MPa at 0.82 a (129²:
// 278 MPa at 0.80 a — a spike's height grows as the grid resolves it, so 5 %). Their points near the
// spike are 5–10 µm (0.04–0.08 a) apart: 0.05 a on its position. Over the Hertzian part
// (|x| ≤ 0.7 a, where the digitised x matters little) the pressure within 3 % of p_H rms.
TEST(EhlPointPublished, PressureAndOutletSpikeMatchMourierEtAl2006) {
  const EhlPointResult& r = mourier_case();
  ASSERT_TRUE(r.converged) << r.message;
  const double a = reference::hertz_point_radius_m(15.0, 12.5e-3, 110e9);
  const double p_h = reference::hertz_point_peak_pressure_Pa(15.0, 12.5e-3, 110e9);
  const std::vector<double> p = centre_line(r, r.pressure_Pa);
  // The spike: the largest local maximum of the centre line beyond x = 0.5 a.
  std::size_t spike = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    if (r.x_m[i] > 0.5 * a && p[i] > p[i - 1] && p[i] >= p[i + 1] && (spike == 0 || p[i] > p[spike])) spike = i;
  }
  ASSERT_NE(spike, 0u) << "no pressure spike at the outlet";
  std::printf("p_max %.1f MPa (theirs 388.5), spike %.1f MPa at %.3f a (theirs 284.1 at 0.781 a)\n", r.max_pressure_Pa * 1e-6,
              p[spike] * 1e-6, r.x_m[spike] / a);
  EXPECT_NEAR(r.max_pressure_Pa / 388.5e6, 1.0, 0.02);
  EXPECT_NEAR(p[spike] / 284.1e6, 1.0, 0.05);
  EXPECT_NEAR(r.x_m[spike] / a, 106.9e-6 / a, 0.05);

  double sum2 = 0.0;
  int count = 0;
  for (const CurvePoint& q : read_curve("pressure_centre_line.csv", "pressure_Pa")) {
    if (std::abs(q.x_m) > 0.7 * a) continue;
    const double d = at(r.x_m, p, q.x_m) - q.value;
    sum2 += d * d;
    ++count;
  }
  const double rms = std::sqrt(sum2 / count);
  std::printf("pressure within 0.7 a: %.1f MPa rms over %d points\n", rms * 1e-6, count);
  EXPECT_LT(rms, 0.03 * p_h);
}

}  // namespace
}  // namespace tribo::lubrication
