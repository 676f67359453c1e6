#include "homogenise/ball_film.h"

#include <omp.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "numerics/format.h"
#include "rig/ball_film.h"

namespace tribo::homogenise {

BallFilmTable ball_film(const HomogeniseOptions& o, double thinnest_film_m) {
  if (o.pin.shape != PinShape::ball || !o.micro_ehl) throw std::invalid_argument("ball_film: the options describe no ball with [micro_ehl]");
  BallFilmTable t;
  t.hertz_radius_m = nominal_contact_radius_m(o);
  t.thinnest_film_m = thinnest_film_m;
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
  std::vector<int> skipped(speeds, 0);
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::size_t k = 1; k < speeds; ++k) {  // ηU = 0 has no film
    const double u = t.eta_u_Pa_m[k] / oil.viscosity_Pa_s;
    int usable = 0;
    double last_film_m = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n_s; ++j) {
      // The films thin as the share grows: past two usable (each thinner than the last, rig/ball_film.h),
      // one thinner than thinnest_film_m ends the speed.
      if (usable >= 2 && last_film_m < thinnest_film_m) {
        skipped[k] = static_cast<int>(n_s - j);
        break;
      }
      const double s = t.share[j];
      const lubrication::EhlPointContact c{s * w, o.pin.radius_m, s * 2.0 * o.e_star_Pa, 0.5 * u};
      try {
        const lubrication::EhlPointResult film = lubrication::solve_ehl_point(c, oil, film_options);
        if (!film.converged) {
          why[k * n_s + j] = film.message;
          continue;
        }
        const lubrication::EhlPointTraction f = lubrication::ehl_point_traction(film, oil, u, o.micro_ehl->eyring_stress_Pa, s * w);
        t.central_film_m[k][j] = film.central_film_m;
        t.traction_N[k][j] = f.force_N;
        if (film.central_film_m < last_film_m) last_film_m = film.central_film_m, ++usable;  // as the rig inverts them
      } catch (const std::exception& e) {
        why[k * n_s + j] = e.what();
      }
    }
  }
  for (int n : skipped) t.not_needed += n;
  for (std::size_t q = 0; q < why.size(); ++q)
    if (!why[q].empty()) {
      ++t.unconverged;
      t.messages.push_back("ball film at U = " + numerics::shortest(t.eta_u_Pa_m[q / n_s] / oil.viscosity_Pa_s) +
                           " m/s, share " + numerics::shortest(t.share[q % n_s]) + ": " + why[q]);
    }

  for (std::size_t k = 1; k < speeds; ++k) {  // the rig inverts every node's films (rig/ball_film.h)
    try {
      rig::BallFilmCurve(t.share, t.central_film_m[k], t.traction_N[k]);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error("ball film at U = " + numerics::shortest(t.eta_u_Pa_m[k] / oil.viscosity_Pa_s) + " m/s: " + e.what() +
                               " (the others did not converge: law.json unconverged); raise [micro_ehl] min_speed_m_per_s or [pin] film_grid");
    }
  }
  return t;
}

}  // namespace tribo::homogenise
