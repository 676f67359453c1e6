#include "homogenise/pin.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <optional>
#include <vector>

#include "homogenise/ball_film.h"
#include "homogenise/solid_contact.h"
#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"
#include "rig/law_table.h"
#include "numerics/format.h"

namespace tribo::homogenise {
namespace {

// A cell column as a function of the local film h; smooth-film value above the last node.
class Column {
 public:
  Column(const CellTable& t, const std::vector<Estimate>& c, double smooth, double scale = 1.0)
      : last_(t.separation_m.back()), smooth_(smooth), curve_(t.separation_m, means(c, scale), "separation_m") {}
  double operator()(double h) const { return h > last_ ? smooth_ : curve_.value(h); }
  double slope(double h) const { return h > last_ ? 0.0 : curve_.slope(h); }

 private:
  static std::vector<double> means(const std::vector<Estimate>& c, double scale) {
    std::vector<double> v;
    for (const Estimate& e : c) v.push_back(e.mean * scale);
    return v;
  }
  double last_, smooth_;
  rig::MonotoneTable curve_;
};

// The separation at which the asperities alone carry W (linear between the table's nodes; the
// first separation if they carry less there).
double rest_separation_m(const std::vector<double>& separation_m, const std::vector<double>& solid_load_N, double w) {
  for (std::size_t m = 0; m + 1 < separation_m.size(); ++m)
    if (solid_load_N[m] >= w && solid_load_N[m + 1] < w)
      return separation_m[m] + (separation_m[m + 1] - separation_m[m]) * (solid_load_N[m] - w) / (solid_load_N[m] - solid_load_N[m + 1]);
  return separation_m.front();
}

}  // namespace

double face_drop_m(const Pin& pin) {
  const double theta = pin.tilt_rad, r = pin.radius_m;
  if (pin.shape != PinShape::spherical) return theta * r;  // a ball is untilted
  const double rc = pin.crown_radius_m;
  return theta * rc <= r ? 0.5 * theta * theta * rc : theta * r - r * r / (2.0 * rc);
}

PinTable pin_scale(const HomogeniseOptions& o, const CellTable& t) {
  const bool ball = o.pin.shape == PinShape::ball;
  // A ball's face is its Hertz circle, the film over it uniform (ball_film.h).
  const double sigma = t.sigma_m, radius = nominal_contact_radius_m(o);
  PinTable pin;
  pin.nominal_area_m2 = M_PI * radius * radius;
  const double drop = face_drop_m(o.pin);
  for (double s : t.separation_m) pin.separation_m.push_back(s + drop);
  const Column ps(t, t.solid_pressure_Pa, 0.0), ar(t, t.area_fraction, 0.0);
  std::vector<Estimate> ps_se, ar_se;
  for (const Estimate& e : t.solid_pressure_Pa) ps_se.push_back({e.standard_error, 0});
  for (const Estimate& e : t.area_fraction) ar_se.push_back({e.standard_error, 0});
  const Column ps_err(t, ps_se, 0.0), ar_err(t, ar_se, 0.0);
  const Column ps_coarse(t, t.solid_pressure_coarse_Pa, 0.0), ar_coarse(t, t.area_fraction_coarse, 0.0);
  const Column phix(t, t.phi_x, 1.0), phiy(t, t.phi_y, 1.0), phis(t, t.phi_s, 0.0), phif(t, t.phi_f, 1.0);
  const Column phifp(t, t.phi_fp, 1.0), lift(t, t.lift_per_eta_u_per_m, 0.0);
  const Column film(t, t.film_over_sigma, 0.0, sigma);  // h̄_T in m; above the last node h̄_T = h (slope 1)
  const auto mean_film = [&](double h) { return h > t.separation_m.back() ? h : film(h); };
  const auto film_slope = [&](double h) { return h > t.separation_m.back() ? 1.0 : film.slope(h); };

  // Per ηU node, a column over h: the spots' shear (τ_i above the last node), its standard error,
  // its value on half the contact grid, and the share the films separate (0 above the last node).
  pin.eta_u_Pa_m = micro_ehl_eta_u_Pa_m(o);
  const auto per_eta_u = [&](const std::vector<std::vector<Estimate>>& cells, double smooth, bool error) {
    std::vector<Column> out;
    for (std::size_t k = 0; k < pin.eta_u_Pa_m.size(); ++k) {
      std::vector<Estimate> c;
      for (const auto& row : cells) c.push_back(error ? Estimate{row[k].standard_error, 0} : row[k]);
      out.emplace_back(t, c, smooth);
    }
    return out;
  };
  const double tau_i = o.interface_shear_strength_Pa;
  const std::vector<Column> tau = per_eta_u(t.spot_shear_Pa, tau_i, false), tau_se = per_eta_u(t.spot_shear_Pa, 0.0, true),
                            tau_coarse = per_eta_u(t.spot_shear_coarse_Pa, tau_i, false),
                            separated = per_eta_u(t.spot_film_share, 0.0, false);

  const int n = o.pin_grid;
  lubrication::ReynoldsSolver solver;
  for (double centre : pin.separation_m) {
    lubrication::ReynoldsProblem pr = lubrication::parallel_discs_problem(radius, centre, 0.0, 1.0, 1.0, n);
    const contact::Grid& g = pr.grid;
    const double cx = pr.disc->centre_x_m, cy = pr.disc->centre_y_m;
    Eigen::ArrayXXd h = g.field();
    pr.pressure_flow_factor_x = g.field();
    pr.pressure_flow_factor_y = g.field();
    pr.couette_film_m = g.field();
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const double x = i * g.dx_m - cx, r2 = x * x + std::pow(j * g.dy_m - cy, 2);
        const double film = centre + (o.pin.shape == PinShape::spherical ? r2 / (2.0 * o.pin.crown_radius_m) : 0.0) -
                            o.pin.tilt_rad * x;
        // On the face the drop keeps the film on the table (up to round-off at the rim); only the
        // grid's outer ring, off the face, can fall below it — held at the first separation there.
        assert(r2 > radius * radius || film >= t.separation_m.front() - 1e-9 * centre);
        h(i, j) = std::max(film, t.separation_m.front());
        pr.pressure_flow_factor_x(i, j) = phix(h(i, j));
        pr.pressure_flow_factor_y(i, j) = phiy(h(i, j));
        pr.couette_film_m(i, j) = std::max(mean_film(h(i, j)) - sigma * phis(h(i, j)), 0.0);
      }
    pr.gap_m = h;
    // Squeeze: U = 0, ∂h̄_T/∂t = (dh̄_T/dh) ḣ with ḣ = −1 m/s, full film.
    lubrication::ReynoldsProblem sq = pr;
    sq.sliding_speed_m_per_s = 0.0;
    sq.cavitation = lubrication::Cavitation::none;
    sq.gap_rate_m_per_s = h.unaryExpr([&](double hk) { return -film_slope(hk); });
    const auto solved = [&](const lubrication::ReynoldsProblem& problem) {
      lubrication::ReynoldsSolution s = solver.solve(problem);
      if (!s.summary.converged) {
        ++pin.reynolds_unconverged;
        pin.messages += "pin-face Reynolds at h = " + numerics::shortest(centre) + " m: " + s.summary.message + "; ";
      }
      return s;
    };
    const lubrication::ReynoldsSolution squeeze = solved(sq);
    // Wedge: steady sliding at ηU = 1 with cavitation. Not for a ball: its fluid is its EHL film
    // (ball_film), and the rigid circle's lift and Petroff shear would count it twice.
    std::optional<lubrication::ReynoldsSolution> wedge;
    if (!ball) {
      pr.cavitation = lubrication::Cavitation::mass_conserving;
      wedge = solved(pr);
    }

    // Face integrals over the wetted nodes (the disc's, the same in both solves), weights scaled so
    // they sum to πR² exactly.
    const Eigen::ArrayXX<bool>& wetted = squeeze.wetted;
    const double w = pin.nominal_area_m2 / static_cast<double>(wetted.count());
    double ns = 0, ns_se = 0, ns_coarse = 0, a = 0, a_se = 0, a_coarse = 0, rug = 0, shear = 0;
    const std::size_t speeds = pin.eta_u_Pa_m.size();
    std::vector<double> spot_force(speeds, 0.0), spot_force_se(speeds, 0.0), spot_force_coarse(speeds, 0.0), film_area(speeds, 0.0);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        if (!wetted(i, j)) continue;
        const double hk = h(i, j);
        ns += w * ps(hk);
        ns_se += w * ps_err(hk);
        ns_coarse += w * ps_coarse(hk);
        a += w * ar(hk);
        a_se += w * ar_err(hk);
        a_coarse += w * ar_coarse(hk);
        for (std::size_t k = 0; k < speeds; ++k) {
          spot_force[k] += w * ar(hk) * tau[k](hk);
          spot_force_se[k] += w * ar(hk) * tau_se[k](hk);
          spot_force_coarse[k] += w * ar_coarse(hk) * tau_coarse[k](hk);
          film_area[k] += w * ar(hk) * separated[k](hk);
        }
        if (!wedge) continue;
        rug += w * lift(hk);
        // Central difference of the wedge pressure (ambient 0 beyond the rim).
        const auto p_at = [&](int ii) { return ii >= 0 && ii < g.nx && wetted(ii, j) ? wedge->pressure_Pa(ii, j) : 0.0; };
        const double dpdx = (p_at(i + 1) - p_at(i - 1)) / (2.0 * g.dx_m);
        shear += w * (phif(hk) / hk - phifp(hk) * 0.5 * hk * dpdx);
      }
    pin.solid_load_N.push_back(ns);
    pin.solid_load_standard_error_N.push_back(ns_se);
    pin.solid_load_coarse_N.push_back(ns_coarse);
    pin.solid_load_discretisation_error_N.push_back(error_from_refinement(ns_coarse, ns));
    pin.real_area_m2.push_back(a);
    pin.real_area_standard_error_m2.push_back(a_se);
    pin.real_area_coarse_m2.push_back(a_coarse);
    pin.real_area_discretisation_error_m2.push_back(error_from_refinement(a_coarse, a));
    pin.wedge_lift_per_eta_u_m.push_back(wedge ? wedge->load_N : 0.0);
    pin.rugosity_lift_per_eta_u_m.push_back(rug);
    pin.squeeze_per_eta_m.push_back(squeeze.load_N);
    pin.shear_per_eta_u_m.push_back(shear);
    if (speeds > 0) {
      const auto per_area = [&](double force, double area) { return area > 0.0 ? force / area : tau_i; };
      std::vector<double> tau_row, se_row, error_row, coarse_row, film_row;
      for (std::size_t k = 0; k < speeds; ++k) {
        tau_row.push_back(per_area(spot_force[k], a));
        se_row.push_back(a > 0.0 ? spot_force_se[k] / a : 0.0);
        coarse_row.push_back(per_area(spot_force_coarse[k], a_coarse));
        film_row.push_back(a > 0.0 ? film_area[k] / a : 0.0);
        error_row.push_back(error_from_refinement(coarse_row.back(), tau_row.back()));
      }
      pin.solid_shear_coarse_Pa.push_back(coarse_row);
      pin.film_share.push_back(film_row);
      pin.solid_shear_Pa.push_back(tau_row);
      pin.solid_shear_standard_error_Pa.push_back(se_row);
      pin.solid_shear_discretisation_error_Pa.push_back(error_row);
    }
  }
  return pin;
}

void add_ball_film(const HomogeniseOptions& o, PinTable& pin, const BallFilmStore& store) {
  pin.ball = ball_film(o, 0.5 * rest_separation_m(pin.separation_m, pin.solid_load_N, o.pin.normal_load_N), store);
}

}  // namespace tribo::homogenise
