#include "homogenise/solid_contact.h"

#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/contact_spots.h"
#include "contact/grid.h"
#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "lubrication/micro_ehl.h"
#include "numerics/format.h"
#include "numerics/huge_pages.h"

namespace tribo::homogenise {
namespace {

// A coarse cell's pressure on each of the 2 × 2 fine cells it covers (empty stays empty).
Eigen::ArrayXXd spread_to_finer(const Eigen::ArrayXXd& coarse, Eigen::Index rows, Eigen::Index cols) {
  if (coarse.size() == 0) return {};
  assert(2 * coarse.rows() == rows && 2 * coarse.cols() == cols);
  Eigen::ArrayXXd fine(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) fine(i, j) = coarse(i / 2, j / 2);
  return fine;
}

// The rigid film h̄ + z against a flat: gap0 = z − min z, on huge pages (numerics/huge_pages.h),
// as every pass of every solve on this surface reads it.
Eigen::ArrayXXd gap_at_first_contact(const Eigen::ArrayXXd& z) {
  Eigen::ArrayXXd gap0 = numerics::huge_page_array(z.rows(), z.cols());
  gap0 = z - z.minCoeff();
  return gap0;
}

// A solve from `warm` (empty: cold), and from cold once more if the warm start did not converge:
// a start is only a shortcut, and from some the CG stalls (the thesis-like surface H 1.0, λ_s
// 31.25 µm at h̄/σ 1.75 on 512²: residual 0.13 after 3048 iterations from the neighbouring node's
// pressure, converged in 175 from cold). `iterations` gets both attempts'.
template <class Solve>
contact::NormalContactResult solve_with_fallback(const Eigen::ArrayXXd& warm, int& iterations, Solve&& solve) {
  contact::NormalContactResult c = solve(warm.size() ? &warm : nullptr);
  iterations += c.summary.iterations;
  if (!c.summary.converged && warm.size()) {
    c = solve(nullptr);
    iterations += c.summary.iterations;
  }
  return c;
}

// The junction at the pin's nominal pressure (solid_contact.h "static" and "dry"): two capped
// solves, each started from `coarse`'s field for it (spread to this grid) when given; their
// pressures into `keep`. Adds to r's μs,max, μ_b, iterations and failures.
void solve_junction(const HomogeniseOptions& o, contact::ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0,
                    const contact::NormalContactOptions& bem, const SolidPressures* coarse, SolidPressures* keep, SolidContact& r) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const double side = o.surface.size_m, patch_area = side * side;
  const double pin_area = M_PI * std::pow(nominal_contact_radius_m(o), 2);  // a ball's: its Hertz circle
  const double load = o.pin.normal_load_N / pin_area * patch_area;  // the pin's nominal pressure on the patch
  const double tau = o.interface_shear_strength_Pa;
  const auto area_at_cap = [&](double cap, const Eigen::ArrayXXd* coarse_field, Eigen::ArrayXXd* kept) {
    contact::NormalContactOptions capped = bem;
    capped.pressure_cap_Pa = cap;
    const Eigen::ArrayXXd w = coarse_field ? spread_to_finer(*coarse_field, gap0.rows(), gap0.cols()) : Eigen::ArrayXXd();
    const contact::NormalContactResult c = solve_with_fallback(w, r.bem_iterations, [&](const Eigen::ArrayXXd* start) {
      return contact::solve_normal_load(halfspace, gap0, load, capped, start);
    });
    if (!c.summary.converged) {
      ++r.unconverged;
      r.messages += "BEM (" + std::to_string(gap0.rows()) + "²) at the pin load with cap " + numerics::shortest(cap) +
                    " Pa: " + c.summary.message + "; ";
      return kNaN;
    }
    if (kept) *kept = c.pressure_Pa;
    return c.real_area_m2;
  };
  r.mu_s_max = tau *
               area_at_cap(std::sqrt(o.hardness_Pa * o.hardness_Pa - o.alpha * tau * tau), coarse ? &coarse->at_slip_cap : nullptr,
                           keep ? &keep->at_slip_cap : nullptr) /
               load;  // thesis (3.1.5)
  r.mu_boundary = tau * area_at_cap(o.hardness_Pa, coarse ? &coarse->at_hardness_cap : nullptr, keep ? &keep->at_hardness_cap : nullptr) / load;
}

contact::NormalContactOptions bem_options(const HomogeniseOptions& o) {
  contact::NormalContactOptions bem;
  bem.tolerance = o.bem_tolerance;
  bem.pressure_cap_Pa = o.hardness_Pa;
  bem.full_fields = false;  // the pressure (spots, warm starts) and the scalars are all this file reads
  return bem;
}

}  // namespace

SolidContact solid_contact(const HomogeniseOptions& o, const Eigen::ArrayXXd& z, const SolidPressures* coarse, SolidPressures* keep) {
  if (coarse && (coarse->at_node.size() != o.separation_ratios.size()))
    throw std::invalid_argument("solid_contact: the coarse pressures are for another table");
  const auto start = [&](const Eigen::ArrayXXd& coarse_field, const Eigen::ArrayXXd& fallback) {
    Eigen::ArrayXXd w = coarse ? spread_to_finer(coarse_field, z.rows(), z.cols()) : Eigen::ArrayXXd();
    return w.size() ? w : fallback;
  };
  if (keep) *keep = SolidPressures{std::vector<Eigen::ArrayXXd>(o.separation_ratios.size()), {}, {}};
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  SolidContact r;
  const double sigma = o.surface.rms_height_m, side = o.surface.size_m, patch_area = side * side;
  const std::string grid_name = std::to_string(z.rows()) + "²";
  const contact::Grid grid = contact::Grid::patch(z.rows(), z.cols(), side, side);
  contact::ElasticHalfSpace halfspace(grid, o.e_star_Pa, true, 1);
  const Eigen::ArrayXXd gap0 = gap_at_first_contact(z);
  r.first_contact_separation_m = -z.minCoeff();
  const contact::NormalContactOptions bem = bem_options(o);
  const auto failed = [&](const std::string& where, const contact::NormalContactResult& c) {
    ++r.unconverged;
    r.messages += "BEM (" + grid_name + ") " + where + ": " + c.summary.message + "; ";
  };

  const std::size_t nodes = o.separation_ratios.size();
  r.solid_pressure_Pa.assign(nodes, 0.0);
  r.area_fraction.assign(nodes, 0.0);
  const std::vector<double> eta_u = micro_ehl_eta_u_Pa_m(o);
  const lubrication::MicroEhlOptions films = o.micro_ehl ? micro_ehl_options(o) : lubrication::MicroEhlOptions{};
  if (o.micro_ehl) {
    r.spot_shear_Pa.assign(nodes, std::vector<double>(eta_u.size(), o.interface_shear_strength_Pa));
    r.spot_film_share.assign(nodes, std::vector<double>(eta_u.size(), 0.0));
  }
  Eigen::ArrayXXd warm;
  for (std::size_t m = nodes; m-- > 0;) {  // from light to heavy contact, warm-started
    const double approach = r.first_contact_separation_m - o.separation_ratios[m] * sigma;
    if (approach <= 0.0) continue;
    const Eigen::ArrayXXd w = start(coarse ? coarse->at_node[m] : Eigen::ArrayXXd(), warm);
    const contact::NormalContactResult c = solve_with_fallback(w, r.bem_iterations, [&](const Eigen::ArrayXXd* start) {
      return contact::solve_approach(halfspace, gap0, approach, bem, start);
    });
    if (!c.summary.converged) {
      failed("at h/σ = " + numerics::shortest(o.separation_ratios[m]), c);
      r.solid_pressure_Pa[m] = r.area_fraction[m] = kNaN;
      if (o.micro_ehl) r.spot_shear_Pa[m].assign(eta_u.size(), kNaN), r.spot_film_share[m].assign(eta_u.size(), kNaN);
      continue;
    }
    if (o.micro_ehl) {
      const std::vector<contact::ContactSpot> spots = contact::contact_spots(c.pressure_Pa, grid, o.e_star_Pa);
      for (std::size_t k = 0; k < eta_u.size(); ++k) {
        const lubrication::SpotFilms f = lubrication::mean_spot_films(spots, eta_u[k], films);
        r.spot_shear_Pa[m][k] = f.shear_Pa;
        r.spot_film_share[m][k] = f.film_share;
      }
    }
    r.solid_pressure_Pa[m] = c.normal_load_N / patch_area;
    r.area_fraction[m] = c.area_fraction;
    warm = c.pressure_Pa;
    if (keep) keep->at_node[m] = c.pressure_Pa;
  }

  solve_junction(o, halfspace, gap0, bem, coarse, keep, r);
  return r;
}

SolidContact junction_contact(const HomogeniseOptions& o, const Eigen::ArrayXXd& z, const SolidPressures* coarse, SolidPressures* keep) {
  if (keep) *keep = SolidPressures{};
  SolidContact r;
  const double side = o.surface.size_m;
  contact::ElasticHalfSpace halfspace(contact::Grid::patch(z.rows(), z.cols(), side, side), o.e_star_Pa, true, 1);
  r.first_contact_separation_m = -z.minCoeff();
  solve_junction(o, halfspace, gap_at_first_contact(z), bem_options(o), coarse, keep, r);
  return r;
}

}  // namespace tribo::homogenise
