#include "lubrication/mixed_line.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "lubrication/reference/ehl_film.h"
#include "numerics/format.h"

namespace tribo::lubrication {
namespace {

[[noreturn]] void bad_mixed_input(const std::string& what) { throw std::invalid_argument("mixed line contact: " + what); }

// The film solved at share s = e^{ln_share}, the summits at its separation, and the load balance
// g(s)/w they leave.
struct Trial {
  double ln_share = 0.0, balance = 0.0, asperity_load_N_per_m = 0.0;
  EhlLineResult film;
  contact::GwState summits;
};

}  // namespace

MixedLineResult solve_mixed_line(const MixedLineContact& c, const PiezoviscousLubricant& lubricant, const MixedLineOptions& o) {
  const EhlLineContact& f = c.film;
  for (double v : {f.load_per_length_N_per_m, f.reduced_radius_m, f.reduced_modulus_Pa})
    if (!(std::isfinite(v) && v > 0.0)) bad_mixed_input("load, radius and modulus must be finite and > 0");
  contact::validate(c.asperities);
  const double e_star_Pa = 0.5 * f.reduced_modulus_Pa;
  if (!(std::abs(c.asperities.e_star_Pa - e_star_Pa) <= 1e-9 * e_star_Pa))
    bad_mixed_input("the summits' E* (" + numerics::shortest(c.asperities.e_star_Pa) + " Pa) must be E'/2 = " + numerics::shortest(e_star_Pa) +
                    " Pa, the bodies' own");
  if (!(std::isfinite(c.summit_height_m) && c.summit_height_m >= 0.0))
    bad_mixed_input("summit height y_s must be finite and >= 0, got " + numerics::shortest(c.summit_height_m) + " m");
  if (!(std::isfinite(c.boundary_friction_coefficient) && c.boundary_friction_coefficient >= 0.0))
    bad_mixed_input("boundary friction coefficient must be finite and >= 0, got " + numerics::shortest(c.boundary_friction_coefficient));
  if (!(o.tolerance > 0.0 && o.min_share > 0.0 && o.min_share < 1.0 && o.max_film_solves >= 2))
    bad_mixed_input("options: tolerance > 0, 0 < min_share < 1 and max_film_solves >= 2 are required");

  const double w = f.load_per_length_N_per_m;
  const double half_width_m = reference::hertz_line_half_width_m(w, f.reduced_radius_m, f.reduced_modulus_Pa);
  MixedLineResult out;
  const auto at = [&](double ln_share) {
    const double s = std::exp(ln_share);
    EhlLineContact scaled = f;
    scaled.load_per_length_N_per_m = s * w;
    scaled.reduced_modulus_Pa = s * f.reduced_modulus_Pa;
    Trial t{ln_share, 0.0, 0.0, solve_ehl_line(scaled, lubricant, o.film), {}};
    ++out.film_solves;
    if (t.film.converged) {
      t.summits = contact::gw_at_separation(c.asperities, t.film.central_film_m - c.summit_height_m);
      t.asperity_load_N_per_m = 2.0 * half_width_m * t.summits.pressure_Pa;
      t.balance = (s * w + t.asperity_load_N_per_m - w) / w;
    }
    return t;
  };
  const auto unconverged_film = [&](const Trial& t) {
    out.film = t.film;
    out.film_share = std::exp(t.ln_share);
    out.message = "the film solve at share " + numerics::shortest(out.film_share) + " did not converge: " + t.film.message;
    return out;
  };

  // g(1) ≥ 0 (the asperities' load on top of the whole load); g(min_share) < 0 is the bracket.
  // Where the whole load's film is too thin for the film solver (a slow, heavily loaded contact,
  // deep in the boundary regime), the upper end steps down in fourths until a film solves: the
  // root lies where the film's share is small and its film thicker.
  const double ln_min = std::log(o.min_share);
  Trial full = at(0.0);
  while (!full.film.converged && full.ln_share - std::log(4.0) > ln_min && out.film_solves < o.max_film_solves)
    full = at(full.ln_share - std::log(4.0));
  if (!full.film.converged) return unconverged_film(full);
  if (full.balance < -o.tolerance) {
    out.film = full.film;
    out.film_share = std::exp(full.ln_share);
    out.residual = std::abs(full.balance);
    out.message = "the root lies above the film share " + numerics::shortest(out.film_share) + ", where the film solve did not converge";
    return out;
  }
  Trial found = full;
  if (full.balance > o.tolerance) {
    Trial low = at(ln_min);
    if (!low.film.converged) return unconverged_film(low);
    if (!(low.balance < 0.0)) {
      out.film = low.film;
      out.film_share = o.min_share;
      out.residual = std::abs(low.balance);
      out.message = "the asperities carry more than the whole load even at the smallest film share " + numerics::shortest(o.min_share) +
                    " (load balance " + numerics::shortest(low.balance) + "): no root in (min_share, 1]";
      return out;
    }
    // Regula falsi in ln s with the Illinois halving of the retained end's value.
    double a = low.ln_share, fa = low.balance, b = full.ln_share, fb = full.balance;
    int kept = 0;  // −1: a was kept last time, +1: b was
    found = std::move(low);
    while (std::abs(found.balance) > o.tolerance && out.film_solves < o.max_film_solves) {
      Trial t = at((a * fb - b * fa) / (fb - fa));
      if (!t.film.converged) return unconverged_film(t);
      if (t.balance < 0.0) {
        a = t.ln_share, fa = t.balance;
        if (kept == 1) fb *= 0.5;
        kept = 1;
      } else {
        b = t.ln_share, fb = t.balance;
        if (kept == -1) fa *= 0.5;
        kept = -1;
      }
      found = std::move(t);
    }
  }

  const double s = std::exp(found.ln_share);
  out.film_share = s;
  out.film_load_per_length_N_per_m = s * w;
  out.asperity_load_per_length_N_per_m = found.asperity_load_N_per_m;
  out.central_film_m = found.film.central_film_m;
  out.separation_m = found.summits.separation_m;
  out.film_parameter = found.film.central_film_m / c.asperities.summit_std_m;
  out.asperity_area_fraction = found.summits.area_fraction;
  out.film = std::move(found.film);
  out.traction = ehl_line_traction(out.film, lubricant, c.sliding_speed_m_per_s, c.eyring_stress_Pa, s * w, c.heating);
  out.boundary_friction_N_per_m = c.boundary_friction_coefficient * out.asperity_load_per_length_N_per_m;
  out.film_friction_N_per_m = out.traction.force_per_length_N_per_m;
  out.friction_coefficient = (out.boundary_friction_N_per_m + out.film_friction_N_per_m) / w;
  out.residual = std::abs(found.balance);
  out.converged = out.residual <= o.tolerance;
  out.message = out.converged ? "converged: load balance " + numerics::shortest(out.residual) + " of the load"
                              : "the load balance stayed at " + numerics::shortest(out.residual) + " of the load after " +
                                    std::to_string(out.film_solves) + " film solves";
  return out;
}

}  // namespace tribo::lubrication
