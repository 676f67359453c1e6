#include "lubrication/geometry.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace tribo::lubrication {

ReynoldsProblem parallel_discs_problem(double radius_m, double gap_m, double gap_rate_m_per_s, double viscosity_Pa_s,
                                       double sliding_speed_m_per_s, int n) {
  if (n < 5) throw std::invalid_argument("parallel discs: grid n must be >= 5 (got " + std::to_string(n) + ")");
  if (!(std::isfinite(radius_m) && radius_m > 0))
    throw std::invalid_argument("parallel discs: radius_m must be finite and > 0");
  ReynoldsProblem pr;
  const double d = 2.0 * radius_m / (n - 3);
  pr.grid = contact::Grid{n, n, d, d};
  pr.gap_m = pr.grid.field(gap_m);
  pr.gap_rate_m_per_s = pr.grid.field(gap_rate_m_per_s);
  pr.viscosity_Pa_s = viscosity_Pa_s;
  pr.sliding_speed_m_per_s = sliding_speed_m_per_s;
  const double c = 0.5 * (n - 1) * d;
  pr.disc = DiscDomain{c, c, radius_m};
  return pr;
}

namespace {

// Mean of a field, summed in storage order.
double mean(const Eigen::ArrayXXd& f) {
  return std::accumulate(f.data(), f.data() + f.size(), 0.0) / static_cast<double>(f.size());
}

}  // namespace

Eigen::ArrayXXd rough_pair_gap_m(const Eigen::ArrayXXd& upper, const Eigen::ArrayXXd& lower, double mean_gap_m,
                                 double min_gap_m, std::size_t* contact_nodes) {
  if (upper.rows() != lower.rows() || upper.cols() != lower.cols() || upper.size() == 0)
    throw std::invalid_argument("rough pair: the two surfaces must be non-empty and on the same grid");
  if (!(std::isfinite(mean_gap_m) && mean_gap_m > 0)) throw std::invalid_argument("rough pair: mean_gap_m must be > 0");
  if (!(std::isfinite(min_gap_m) && min_gap_m > 0 && min_gap_m < mean_gap_m))
    throw std::invalid_argument("rough pair: min_gap_m must be in (0, mean_gap_m)");
  if (!upper.allFinite() || !lower.allFinite()) throw std::invalid_argument("rough pair: non-finite height");
  const double mu = mean(upper), ml = mean(lower);
  Eigen::ArrayXXd h(upper.rows(), upper.cols());
  std::size_t touching = 0;
  for (Eigen::Index k = 0; k < h.size(); ++k) {
    h(k) = mean_gap_m + (upper(k) - mu) - (lower(k) - ml);
    if (h(k) < min_gap_m) {
      h(k) = min_gap_m;
      ++touching;
    }
  }
  if (contact_nodes) *contact_nodes = touching;
  return h;
}

ReynoldsProblem periodic_film_cell(const Eigen::ArrayXXd& film, double size_m) {
  const Eigen::Index n = film.rows();
  if (n < 3 || film.cols() != n)
    throw std::invalid_argument("periodic film cell: the film must be n x n with n >= 3 (got " +
                                std::to_string(film.rows()) + " x " + std::to_string(film.cols()) + ")");
  if (!(std::isfinite(size_m) && size_m > 0)) throw std::invalid_argument("periodic film cell: size_m must be > 0");
  ReynoldsProblem pr;
  pr.grid = contact::Grid{n + 1, n, size_m / static_cast<double>(n), size_m / static_cast<double>(n)};
  pr.gap_m.resize(n + 1, n);
  pr.gap_m.topRows(n) = film;
  pr.gap_m.row(n) = film.row(0);
  pr.boundary_y = BoundaryY::periodic;
  return pr;
}

bool RoughPairFilmOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& m) {
    if (why) *why = m;
    return false;
  };
  if (mean_gap_m.has_value() == normal_load_N.has_value())
    return fail("give exactly one of mean_gap_m (rigid surfaces) and normal_load_N (deformed by contact)");
  if (mean_gap_m && !(std::isfinite(*mean_gap_m) && *mean_gap_m > 0)) return fail("mean_gap_m must be finite and > 0");
  if (normal_load_N && !(std::isfinite(*normal_load_N) && *normal_load_N > 0))
    return fail("normal_load_N must be finite and > 0");
  if (!(std::isfinite(composite_modulus_Pa) && composite_modulus_Pa > 0))
    return fail("composite_modulus_Pa must be finite and > 0");
  if (!(hardness_Pa > 0)) return fail("hardness_Pa must be > 0 (infinity for elastic contact)");
  if (!(contact_gap_fraction > 0 && contact_gap_fraction <= 0.5)) return fail("contact_gap_fraction must be in (0, 0.5]");
  if (normal_load_N) {
    contact::NormalContactOptions c = contact;
    c.pressure_cap_Pa = hardness_Pa;
    std::string reason;
    if (!c.is_valid(&reason)) return fail("contact options: " + reason);
  }
  return true;
}

RoughPairFilm rough_pair_film(const Eigen::ArrayXXd& upper, const Eigen::ArrayXXd& lower, double size_m,
                              const RoughPairFilmOptions& o) {
  auto bad = [](const std::string& m) { throw std::invalid_argument("rough pair film: " + m); };
  std::string why;
  if (!o.is_valid(&why)) bad(why);
  const Eigen::Index n = lower.rows();
  if (n < 3 || lower.cols() != n || upper.rows() != n || upper.cols() != n)
    bad("upper and lower must be the same n x n grid with n >= 3 (got " + std::to_string(upper.rows()) + " x " +
        std::to_string(upper.cols()) + " and " + std::to_string(lower.rows()) + " x " + std::to_string(lower.cols()) +
        ")");
  if (!upper.allFinite() || !lower.allFinite()) bad("non-finite height");
  if (!(std::isfinite(size_m) && size_m > 0)) bad("size_m must be finite and > 0");
  auto rq = [](const Eigen::ArrayXXd& z) { return std::sqrt((z - z.mean()).square().mean()); };
  RoughPairFilm film;
  film.composite_rms_height_m = std::hypot(rq(upper), rq(lower));
  film.floor_m = o.contact_gap_fraction * film.composite_rms_height_m;
  if (!(film.floor_m > 0)) bad("both surfaces are flat: the film floor (a fraction of the rms height) is zero");
  // The film h on the n × n surface grid.
  Eigen::ArrayXXd h;
  if (o.mean_gap_m) {
    if (!(*o.mean_gap_m > film.floor_m)) bad("mean_gap_m must exceed the film floor contact_gap_fraction * sigma");
    h = rough_pair_gap_m(upper, lower, *o.mean_gap_m, film.floor_m, &film.contact_nodes);
  } else {
    // Separation s = const + upper − lower; as a rigid profile against a flat its initial gap is
    // s − min s, i.e. gap_from_heights(lower − upper).
    contact::ElasticHalfSpace halfspace(contact::Grid::patch(n, n, size_m, size_m), o.composite_modulus_Pa, true);
    contact::NormalContactOptions copt = o.contact;
    copt.pressure_cap_Pa = o.hardness_Pa;
    const Eigen::ArrayXXd gap0 = contact::gap_from_heights(lower - upper);
    film.contact = contact::solve_normal_load(halfspace, gap0, *o.normal_load_N, copt);
    const Eigen::ArrayXXd& g = film.contact->gap_m;
    h = g.max(film.floor_m);
    film.contact_nodes = static_cast<std::size_t>((g < film.floor_m).count());
  }
  film.mean_film_m = mean(h);
  film.problem = periodic_film_cell(h, size_m);
  return film;
}

}  // namespace tribo::lubrication
