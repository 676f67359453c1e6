#include "homogenise/ball_film.h"

#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "numerics/format.h"
#include "numerics/json_numbers.h"
#include "numerics/parallel.h"
#include "rig/ball_film.h"

namespace tribo::homogenise {
namespace {

// Node k's films: the shares in increasing order until two usable films (each thinner than the
// last, as the rig inverts them, rig/ball_film.h) and the last thinner than thinnest_film_m — the
// larger shares' films are thinner still.
BallFilmNode solve_node(const HomogeniseOptions& o, const lubrication::PiezoviscousLubricant& oil,
                        const lubrication::EhlPointOptions& film_options, const std::vector<double>& shares,
                        double eta_u_Pa_m, double thinnest_film_m) {
  const std::size_t n_s = shares.size();
  const double nan = std::numeric_limits<double>::quiet_NaN(), w = o.pin.normal_load_N;
  const double u = eta_u_Pa_m / oil.viscosity_Pa_s;
  BallFilmNode node{eta_u_Pa_m, thinnest_film_m, std::vector<double>(n_s, nan), std::vector<double>(n_s, nan),
                    std::vector<std::string>(n_s), 0};
  int usable = 0;
  double last_film_m = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < n_s; ++j) {
    if (usable >= 2 && last_film_m < thinnest_film_m) {
      node.not_needed = static_cast<int>(n_s - j);
      break;
    }
    const double s = shares[j];
    const lubrication::EhlPointContact c{s * w, o.pin.radius_m, s * 2.0 * o.e_star_Pa, 0.5 * u};
    try {
      const lubrication::EhlPointResult film = lubrication::solve_ehl_point(c, oil, film_options);
      if (!film.converged) {
        node.left_out[j] = film.message;
        continue;
      }
      const lubrication::EhlPointTraction f = lubrication::ehl_point_traction(film, oil, u, o.micro_ehl->eyring_stress_Pa, s * w, {},
                                                                                 o.micro_ehl->limiting_shear);
      node.central_film_m[j] = film.central_film_m;
      node.traction_N[j] = f.force_N;
      if (film.central_film_m < last_film_m) last_film_m = film.central_film_m, ++usable;
    } catch (const std::exception& e) {
      node.left_out[j] = e.what();
    }
  }
  return node;
}

bool belongs_to(const BallFilmNode& node, double eta_u_Pa_m, double thinnest_film_m, std::size_t shares) {
  return node.eta_u_Pa_m == eta_u_Pa_m && node.thinnest_film_m == thinnest_film_m && node.central_film_m.size() == shares &&
         node.traction_N.size() == shares && node.left_out.size() == shares && node.not_needed >= 0;
}

}  // namespace

nlohmann::json to_json(const BallFilmNode& node) {
  return {{"eta_u_Pa_m", node.eta_u_Pa_m},
          {"thinnest_film_m", node.thinnest_film_m},
          {"central_film_m", numerics::finite_or_null(node.central_film_m)},
          {"traction_N", numerics::finite_or_null(node.traction_N)},
          {"left_out", node.left_out},
          {"not_needed", node.not_needed}};
}

BallFilmNode ball_film_node_from_json(const nlohmann::json& j) {
  return {j.at("eta_u_Pa_m").get<double>(), j.at("thinnest_film_m").get<double>(), numerics::doubles_with_nans(j.at("central_film_m")),
          numerics::doubles_with_nans(j.at("traction_N")), j.at("left_out").get<std::vector<std::string>>(), j.at("not_needed").get<int>()};
}

BallFilmTable ball_film(const HomogeniseOptions& o, double thinnest_film_m, const BallFilmStore& store) {
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
  std::vector<std::optional<BallFilmNode>> nodes(speeds);
  std::vector<std::size_t> to_solve;
  for (std::size_t k = 1; k < speeds; ++k) {  // ηU = 0 has no film
    if (store.load) nodes[k] = store.load(k);
    if (!nodes[k] || !belongs_to(*nodes[k], t.eta_u_Pa_m[k], thinnest_film_m, n_s)) {
      nodes[k].reset();
      to_solve.push_back(k);
    } else if (store.finished) {
      store.finished(k, *nodes[k], true);
    }
  }
  // Passed to the store one at a time, under a lock a throwing store releases; after a store that
  // threw, no later node is passed on (numerics::parallel_for rethrows the first failure after the
  // running solves and starts no more).
  std::mutex keep;
  bool store_failed = false;
  numerics::parallel_for(
      to_solve.size(),
      [&](std::size_t q) {
        const std::size_t k = to_solve[q];
        nodes[k] = solve_node(o, oil, film_options, t.share, t.eta_u_Pa_m[k], thinnest_film_m);
        if (!store.finished) return;
        const std::lock_guard lock(keep);
        if (store_failed) return;
        try {
          store.finished(k, *nodes[k], false);
        } catch (...) {
          store_failed = true;
          throw;
        }
      },
      o.threads);

  const double nan = std::numeric_limits<double>::quiet_NaN();
  t.central_film_m.assign(1, std::vector<double>(n_s, nan));
  t.traction_N = t.central_film_m;
  for (std::size_t k = 1; k < speeds; ++k) {
    const BallFilmNode& node = *nodes[k];
    t.central_film_m.push_back(node.central_film_m);
    t.traction_N.push_back(node.traction_N);
    t.not_needed += node.not_needed;
    for (std::size_t j = 0; j < n_s; ++j)
      if (!node.left_out[j].empty()) {
        ++t.unconverged;
        t.messages.push_back("ball film at U = " + numerics::shortest(node.eta_u_Pa_m / oil.viscosity_Pa_s) + " m/s, share " +
                             numerics::shortest(t.share[j]) + ": " + node.left_out[j]);
      }
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
