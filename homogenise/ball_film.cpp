#include "homogenise/ball_film.h"

#include <omp.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "numerics/format.h"

namespace tribo::homogenise {

BallFilmAt ball_film_at(const std::vector<double>& share, const std::vector<double>& central_film_m,
                        const std::vector<double>& traction_N, double h) {
  // The solved shares whose film is thinner than every smaller share's: h_c strictly decreasing.
  std::vector<double> ls, lh, lf;
  for (std::size_t j = 0; j < share.size(); ++j) {
    const double hc = central_film_m[j], f = traction_N[j];
    if (!(std::isfinite(hc) && hc > 0.0 && std::isfinite(f) && f > 0.0)) continue;
    if (!lh.empty() && !(std::log(hc) < lh.back())) continue;
    ls.push_back(std::log(share[j]));
    lh.push_back(std::log(hc));
    lf.push_back(std::log(f));
  }
  if (ls.size() < 2) throw std::invalid_argument("ball film: fewer than two shares with a film thinner than the last");
  const double x = std::log(h);
  // The interval holding ln h (h_c falls with j), the end intervals continued beyond.
  std::size_t j = 0;
  while (j + 2 < lh.size() && x < lh[j + 1]) ++j;
  const auto along = [&](const std::vector<double>& y, double t) { return y[j] + t * (y[j + 1] - y[j]); };
  double t = (x - lh[j]) / (lh[j + 1] - lh[j]);
  const double cap = std::log(kBallFilmMaxShare);
  if (along(ls, t) >= cap) return {kBallFilmMaxShare, std::exp(along(lf, (cap - ls[j]) / (ls[j + 1] - ls[j])))};
  return {std::exp(along(ls, t)), std::exp(along(lf, t))};
}

BallFilmTable ball_film(const HomogeniseOptions& o, const std::vector<double>& separation_m) {
  if (o.pin.shape != PinShape::ball || !o.micro_ehl) throw std::invalid_argument("ball_film: the options describe no ball with [micro_ehl]");
  BallFilmTable t;
  t.hertz_radius_m = nominal_contact_radius_m(o);
  t.eta_u_Pa_m = micro_ehl_eta_u_Pa_m(o);
  const int decades = static_cast<int>(std::lround(-std::log10(kBallFilmMinShare)));
  const int shares = decades * kBallFilmSharesPerDecade;
  for (int j = 0; j <= shares; ++j) t.share.push_back(std::pow(10.0, -decades + static_cast<double>(j) / kBallFilmSharesPerDecade));
  t.share.back() = 1.0;

  lubrication::PiezoviscousLubricant oil;
  oil.viscosity_Pa_s = o.lubricant.viscosity_Pa_s;
  oil.pressure_viscosity_per_Pa = o.lubricant.pressure_viscosity_per_Pa;
  oil.law = o.micro_ehl->pressure_viscosity_law;
  lubrication::EhlPointOptions film_options;
  film_options.nodes_x = film_options.nodes_y = o.pin.film_grid;

  const std::size_t speeds = t.eta_u_Pa_m.size(), n_s = t.share.size();
  const double nan = std::numeric_limits<double>::quiet_NaN(), w = o.pin.normal_load_N;
  t.central_film_m.assign(speeds, std::vector<double>(n_s, nan));
  t.traction_N = t.central_film_m;
  std::vector<std::string> why(speeds * n_s);
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::size_t q = n_s; q < speeds * n_s; ++q) {  // ηU = 0 (q < n_s) has no film
    const std::size_t k = q / n_s, j = q % n_s;
    const double u = t.eta_u_Pa_m[k] / oil.viscosity_Pa_s, s = t.share[j];
    const lubrication::EhlPointContact c{s * w, o.pin.radius_m, s * 2.0 * o.e_star_Pa, 0.5 * u};
    try {
      const lubrication::EhlPointResult film = lubrication::solve_ehl_point(c, oil, film_options);
      if (!film.converged) {
        why[q] = film.message;
        continue;
      }
      const lubrication::EhlPointTraction f = lubrication::ehl_point_traction(film, oil, u, o.micro_ehl->eyring_stress_Pa, s * w);
      t.central_film_m[k][j] = film.central_film_m;
      t.traction_N[k][j] = f.force_N;
    } catch (const std::exception& e) {
      why[q] = e.what();
    }
  }
  for (std::size_t q = 0; q < why.size(); ++q)
    if (!why[q].empty()) {
      ++t.unconverged;
      t.messages.push_back("ball film at U = " + numerics::shortest(t.eta_u_Pa_m[q / n_s] / oil.viscosity_Pa_s) +
                           " m/s, share " + numerics::shortest(t.share[q % n_s]) + ": " + why[q]);
    }

  for (double h : separation_m) {
    std::vector<double> load{0.0}, shear{0.0};
    for (std::size_t k = 1; k < speeds; ++k) {
      BallFilmAt at;
      try {
        at = ball_film_at(t.share, t.central_film_m[k], t.traction_N[k], h);
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error("ball film at U = " + numerics::shortest(t.eta_u_Pa_m[k] / oil.viscosity_Pa_s) + " m/s: " + e.what() +
                                 " converged; raise [micro_ehl] min_speed_m_per_s or [pin] film_grid");
      }
      load.push_back(at.share * w);
      shear.push_back(at.traction_N);
    }
    t.fluid_load_N.push_back(load);
    t.fluid_shear_N.push_back(shear);
  }
  return t;
}

}  // namespace tribo::homogenise
