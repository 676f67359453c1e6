#include "homogenise/cell_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "homogenise/solid_contact.h"

namespace tribo::homogenise {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean ± standard error of the finite values (NaN marks an unconverged solve).
Estimate finite_estimate(const std::vector<double>& values) {
  std::vector<double> v;
  for (double x : values)
    if (std::isfinite(x)) v.push_back(x);
  return lubrication::estimate(v);
}

std::vector<Estimate> column(const std::vector<PatchResult>& patches, std::vector<double> PatchResult::*field) {
  const std::size_t nodes = (patches.front().*field).size();
  std::vector<Estimate> out;
  for (std::size_t m = 0; m < nodes; ++m) {
    std::vector<double> v;
    for (const PatchResult& p : patches) v.push_back((p.*field)[m]);
    out.push_back(finite_estimate(v));
  }
  return out;
}

// A node × ηU column: mean ± standard error over the realisations at every entry (empty when the
// patches have none).
std::vector<std::vector<Estimate>> column_2d(const std::vector<PatchResult>& patches,
                                             std::vector<std::vector<double>> PatchResult::*field) {
  std::vector<std::vector<Estimate>> out((patches.front().*field).size());
  for (std::size_t m = 0; m < out.size(); ++m)
    for (std::size_t k = 0; k < (patches.front().*field)[m].size(); ++k) {
      std::vector<double> v;
      for (const PatchResult& p : patches) v.push_back((p.*field).at(m).at(k));
      out[m].push_back(finite_estimate(v));
    }
  return out;
}

// Removes the nodes where any tabulated column's mean is NaN (no realisation converged there),
// keeping their separations in dropped_separation_m; the coarse solid columns (for the
// discretisation error alone: NaN there leaves the error unknown, not the node) follow.
void drop_unresolved_nodes(CellTable& t) {
  const std::vector<std::vector<Estimate>*> tabulated = {&t.solid_pressure_Pa, &t.area_fraction, &t.phi_x, &t.phi_y,
                                                         &t.phi_s, &t.film_over_sigma, &t.phi_f, &t.couette_shear_factor,
                                                         &t.phi_fp, &t.contact_fraction, &t.lift_per_eta_u_per_m};
  std::vector<std::vector<Estimate>*> columns = tabulated;
  columns.push_back(&t.solid_pressure_coarse_Pa);
  columns.push_back(&t.area_fraction_coarse);
  const std::vector<std::vector<std::vector<Estimate>>*> rows_2d = {&t.spot_shear_Pa, &t.spot_shear_coarse_Pa, &t.spot_film_share};
  std::vector<std::vector<std::vector<Estimate>>> kept_2d(rows_2d.size());
  std::vector<double> kept_separation;
  std::vector<std::vector<Estimate>> kept(columns.size());
  for (std::size_t m = 0; m < t.separation_m.size(); ++m) {
    bool finite = true;
    for (const auto* c : tabulated) finite = finite && std::isfinite((*c)[m].mean);
    if (!finite) {
      t.dropped_separation_m.push_back(t.separation_m[m]);
      continue;
    }
    kept_separation.push_back(t.separation_m[m]);
    for (std::size_t c = 0; c < columns.size(); ++c) kept[c].push_back((*columns[c])[m]);
    for (std::size_t c = 0; c < rows_2d.size(); ++c)
      if (!rows_2d[c]->empty()) kept_2d[c].push_back((*rows_2d[c])[m]);
  }
  if (kept_separation.size() < 2)
    throw std::invalid_argument("homogenise: fewer than two separations have a converged solve in every column");
  t.separation_m = kept_separation;
  for (std::size_t c = 0; c < columns.size(); ++c) *columns[c] = std::move(kept[c]);
  for (std::size_t c = 0; c < rows_2d.size(); ++c) *rows_2d[c] = std::move(kept_2d[c]);
}

}  // namespace

std::vector<double> discretisation_error(const std::vector<Estimate>& fine, const std::vector<Estimate>& coarse) {
  if (coarse.size() != fine.size())
    throw std::invalid_argument("homogenise: a coarse column has " + std::to_string(coarse.size()) + " nodes, its fine one " +
                                std::to_string(fine.size()));
  std::vector<double> e;
  for (std::size_t m = 0; m < fine.size(); ++m) e.push_back(error_from_refinement(coarse[m].mean, fine[m].mean));
  return e;
}

CellTable aggregate(const HomogeniseOptions& o, const std::vector<PatchResult>& patches) {
  if (patches.empty()) throw std::invalid_argument("homogenise: no realisation to average");
  const std::vector<double>& nodes = patches.front().separation_m;
  for (const PatchResult& p : patches)
    if (p.separation_m != nodes)
      throw std::invalid_argument("homogenise: realisation seed " + std::to_string(p.seed) +
                                  " was tabulated at other separations (a stale cache?)");
  CellTable t;
  t.sigma_m = o.surface.rms_height_m;
  t.separation_m = nodes;
  t.realisations = static_cast<int>(patches.size());
  t.solid_pressure_Pa = column(patches, &PatchResult::solid_pressure_Pa);
  t.area_fraction = column(patches, &PatchResult::area_fraction);
  t.solid_pressure_coarse_Pa = column(patches, &PatchResult::solid_pressure_coarse_Pa);
  t.area_fraction_coarse = column(patches, &PatchResult::area_fraction_coarse);
  t.phi_x = column(patches, &PatchResult::phi_x);
  t.phi_y = column(patches, &PatchResult::phi_y);
  t.phi_s = column(patches, &PatchResult::phi_s);
  t.film_over_sigma = column(patches, &PatchResult::film_over_sigma);
  t.phi_f = column(patches, &PatchResult::phi_f);
  t.couette_shear_factor = column(patches, &PatchResult::couette_shear_factor);
  t.phi_fp = column(patches, &PatchResult::phi_fp);
  t.contact_fraction = column(patches, &PatchResult::contact_fraction);
  t.lift_per_eta_u_per_m = column(patches, &PatchResult::lift_per_eta_u_per_m);
  t.spot_shear_Pa = column_2d(patches, &PatchResult::spot_shear_Pa);
  t.spot_shear_coarse_Pa = column_2d(patches, &PatchResult::spot_shear_coarse_Pa);
  t.spot_film_share = column_2d(patches, &PatchResult::spot_film_share);
  // The junction per realisation on its three grids (NaN where a solve failed on any of them).
  struct Levels {
    std::vector<double> finest, coarse, coarser;
  } mus, mub;
  const auto push = [](Levels& l, double finest, double coarse, double coarser) {
    const bool both = std::isfinite(finest) && std::isfinite(coarse);
    l.finest.push_back(std::isfinite(finest) ? finest : kNaN);
    l.coarse.push_back(both ? coarse : kNaN);
    l.coarser.push_back(both ? coarser : kNaN);
  };
  for (const PatchResult& p : patches) {
    if (p.contact_grid != patches.front().contact_grid || p.junction_grid != patches.front().junction_grid)
      throw std::invalid_argument("homogenise: realisation seed " + std::to_string(p.seed) + " was solved on another contact grid (a stale cache?)");
    push(mus, p.mu_s_max, p.mu_s_max_coarse, p.mu_s_max_coarser);
    push(mub, p.mu_boundary, p.mu_boundary_coarse, p.mu_boundary_coarser);
    t.first_contact_separation_m = std::max(t.first_contact_separation_m, p.first_contact_separation_m);
    t.unconverged += p.unconverged;
  }
  // Reported: the extrapolation from the two finest grids, over the realisations solved on both;
  // its error: the realisations' mean change of their extrapolation from the two coarsest to the
  // two finest — not the change of the mean, in which realisations moving apart cancel (on the
  // 32² – 128² grids of a tiny config μs,max's did, exactly, the areas being few whole cells).
  // Where the coarsest solve failed, the extrapolation's own correction (from the middle grid's
  // value) stands in for that change: twice the grid values' change, on the safe side.
  // Both kept above their fully plastic values τ_i/p_cap (solid_contact.h: extrapolate_above).
  const auto extrapolate = [](const Levels& l, double plastic, double& error) {
    std::vector<double> fine, change;
    for (std::size_t k = 0; k < l.finest.size(); ++k)
      if (std::isfinite(l.coarse[k])) {
        fine.push_back(extrapolate_above(l.coarse[k], l.finest[k], plastic));
        const double below = extrapolate_above(l.coarser[k], l.coarse[k], plastic);
        change.push_back(error_from_refinement(std::isfinite(below) ? below : l.coarse[k], fine.back()));
      }
    error = change.empty() ? kNaN : lubrication::estimate(change).mean;
    return finite_estimate(fine);
  };
  const double tau = o.interface_shear_strength_Pa;
  t.mu_s_max = extrapolate(mus, tau / std::sqrt(o.hardness_Pa * o.hardness_Pa - o.alpha * tau * tau), t.mu_s_max_discretisation_error);  // (3.1.5)
  t.mu_boundary = extrapolate(mub, tau / o.hardness_Pa, t.mu_boundary_discretisation_error);
  t.mu_s_max_on_junction_grid = finite_estimate(mus.finest);
  t.mu_boundary_on_junction_grid = finite_estimate(mub.finest);
  t.junction_grid = patches.front().junction_grid;
  t.contact_grid = patches.front().contact_grid;
  drop_unresolved_nodes(t);
  return t;
}

}  // namespace tribo::homogenise
