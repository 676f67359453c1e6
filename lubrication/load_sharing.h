// The film's share of the load in a mixed contact by load sharing (Johnson, Greenwood & Poon 1972;
// mixed_line.h, mixed_point.h): the root s of g(s) = s W + W_c(h_c(s)) − W in (min_share, 1],
// bracketed in ln s and found by regula falsi with the Illinois modification, each evaluation a
// full EHL film solve. Internal to lubrication/: `at(ln s)` returns a Trial with members
// ln_share, balance (g(s)/W) and film (an EHL result with converged and message).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact/greenwood_williamson.h"
#include "lubrication/ehl_traction.h"
#include "numerics/format.h"

namespace tribo::lubrication::load_sharing {

struct Options {
  double tolerance = 1e-6;  // |g(s)|/W
  double min_share = 1e-6;
  int max_film_solves = 60;
};

// The film's heating with the summits' boundary friction heat f_c p_GW |Δu| entering the surfaces
// over the contact (half-width b of a line, radius a of a point), when their flash temperature is
// on (ehl_traction.h); unchanged without it.
inline FilmHeating with_summits_heat(FilmHeating heating, double boundary_friction_coefficient, double summit_pressure_Pa,
                                     double sliding_speed_m_per_s, double contact_half_width_m) {
  if (heating.surfaces) {
    heating.interface_heat_W_per_m2 = boundary_friction_coefficient * summit_pressure_Pa * std::abs(sliding_speed_m_per_s);
    heating.interface_heat_half_width_m = contact_half_width_m;
  }
  return heating;
}

// The inputs a mixed contact shares, checked: summits whose E* is the bodies' E'/2, y_s ≥ 0,
// f_c ≥ 0, and the options. Throws std::invalid_argument starting with `what` ("mixed line
// contact: …").
inline void check_inputs(const std::string& what, const contact::GreenwoodWilliamson& asperities, double reduced_modulus_Pa,
                         double summit_height_m, double boundary_friction_coefficient, const Options& o) {
  const auto bad = [&](const std::string& why) { throw std::invalid_argument(what + ": " + why); };
  contact::validate(asperities);
  const double e_star_Pa = 0.5 * reduced_modulus_Pa;
  if (!(std::abs(asperities.e_star_Pa - e_star_Pa) <= 1e-9 * e_star_Pa))
    bad("the summits' E* (" + numerics::shortest(asperities.e_star_Pa) + " Pa) must be E'/2 = " + numerics::shortest(e_star_Pa) +
        " Pa, the bodies' own");
  if (!(std::isfinite(summit_height_m) && summit_height_m >= 0.0))
    bad("summit height y_s must be finite and >= 0, got " + numerics::shortest(summit_height_m) + " m");
  if (!(std::isfinite(boundary_friction_coefficient) && boundary_friction_coefficient >= 0.0))
    bad("boundary friction coefficient must be finite and >= 0, got " + numerics::shortest(boundary_friction_coefficient));
  if (!(o.tolerance > 0.0 && o.min_share > 0.0 && o.min_share < 1.0 && o.max_film_solves >= 2))
    bad("options: tolerance > 0, 0 < min_share < 1 and max_film_solves >= 2 are required");
}

template <class Trial>
struct Outcome {
  Trial found;          // the last trial: the root's when `failure` is empty
  std::string failure;  // why no root could be searched for (a film that did not solve, no bracket)
  int film_solves = 0;
};

// g(1) ≥ 0 (the asperities' load on top of the whole load); g(min_share) < 0 is the bracket. Where
// the whole load's film is too thin for the film solver (a slow, heavily loaded contact, deep in
// the boundary regime), the upper end steps down in fourths until a film solves: the root lies
// where the film's share is small and its film thicker.
template <class Trial, class At>
Outcome<Trial> find_film_share(const At& at, const Options& o) {
  Outcome<Trial> out;
  const auto trial = [&](double ln_share) {
    ++out.film_solves;
    return at(ln_share);
  };
  const auto unsolved = [&](Trial t) {
    out.failure = "the film solve at share " + numerics::shortest(std::exp(t.ln_share)) + " did not converge: " + t.film.message;
    out.found = std::move(t);
    return out;
  };
  const double ln_min = std::log(o.min_share);
  Trial full = trial(0.0);
  while (!full.film.converged && full.ln_share - std::log(4.0) > ln_min && out.film_solves < o.max_film_solves)
    full = trial(full.ln_share - std::log(4.0));
  if (!full.film.converged) return unsolved(std::move(full));
  if (full.balance < -o.tolerance) {
    out.failure = "the root lies above the film share " + numerics::shortest(std::exp(full.ln_share)) + ", where the film solve did not converge";
    out.found = std::move(full);
    return out;
  }
  out.found = std::move(full);
  if (out.found.balance <= o.tolerance) return out;
  Trial low = trial(ln_min);
  if (!low.film.converged) return unsolved(std::move(low));
  if (!(low.balance < 0.0)) {
    out.failure = "the asperities carry more than the whole load even at the smallest film share " + numerics::shortest(o.min_share) +
                  " (load balance " + numerics::shortest(low.balance) + "): no root in (min_share, 1]";
    out.found = std::move(low);
    return out;
  }
  // Regula falsi in ln s with the Illinois halving of the retained end's value.
  double a = low.ln_share, fa = low.balance, b = out.found.ln_share, fb = out.found.balance;
  int kept = 0;  // −1: a was kept last time, +1: b was
  out.found = std::move(low);
  while (std::abs(out.found.balance) > o.tolerance && out.film_solves < o.max_film_solves) {
    Trial t = trial((a * fb - b * fa) / (fb - fa));
    if (!t.film.converged) return unsolved(std::move(t));
    if (t.balance < 0.0) {
      a = t.ln_share, fa = t.balance;
      if (kept == 1) fb *= 0.5;
      kept = 1;
    } else {
      b = t.ln_share, fb = t.balance;
      if (kept == -1) fa *= 0.5;
      kept = -1;
    }
    out.found = std::move(t);
  }
  return out;
}

// What a mixed result (MixedLineResult, MixedPointResult) takes from the search whatever its
// geometry: the film solves, the share and the load balance's residual, and the film found; on
// success its central film, the summits' separation, area fraction and film parameter Λ = h_c/σ_s,
// and whether the balance met the tolerance. Returns false when the search failed (`message` why);
// the caller then has nothing more to fill.
template <class Result, class Trial>
bool take_outcome(Result& out, Outcome<Trial>& searched, double summit_std_m, double tolerance) {
  Trial& found = searched.found;
  out.film_solves = searched.film_solves;
  out.film_share = std::exp(found.ln_share);
  out.residual = std::abs(found.balance);
  if (!searched.failure.empty()) {
    out.film = std::move(found.film);
    out.message = searched.failure;
    return false;
  }
  out.central_film_m = found.film.central_film_m;
  out.separation_m = found.summits.separation_m;
  out.film_parameter = found.film.central_film_m / summit_std_m;
  out.asperity_area_fraction = found.summits.area_fraction;
  out.film = std::move(found.film);
  out.converged = out.residual <= tolerance;
  out.message = out.converged ? "converged: load balance " + numerics::shortest(out.residual) + " of the load"
                              : "the load balance stayed at " + numerics::shortest(out.residual) + " of the load after " +
                                    std::to_string(out.film_solves) + " film solves";
  return true;
}

}  // namespace tribo::lubrication::load_sharing
