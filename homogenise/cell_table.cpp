#include "homogenise/cell_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tribo::homogenise {
namespace {

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

// Removes the nodes where any column's mean is NaN (no realisation converged there), keeping
// their separations in dropped_separation_m.
void drop_unresolved_nodes(CellTable& t) {
  std::vector<std::vector<Estimate>*> columns = {&t.solid_pressure_Pa, &t.area_fraction, &t.phi_x, &t.phi_y,
                                                 &t.phi_s, &t.film_over_sigma, &t.phi_f, &t.couette_shear_factor,
                                                 &t.phi_fp, &t.contact_fraction, &t.lift_per_eta_u_per_m};
  std::vector<double> kept_separation;
  std::vector<std::vector<Estimate>> kept(columns.size());
  for (std::size_t m = 0; m < t.separation_m.size(); ++m) {
    bool finite = true;
    for (const auto* c : columns) finite = finite && std::isfinite((*c)[m].mean);
    if (!finite) {
      t.dropped_separation_m.push_back(t.separation_m[m]);
      continue;
    }
    kept_separation.push_back(t.separation_m[m]);
    for (std::size_t c = 0; c < columns.size(); ++c) kept[c].push_back((*columns[c])[m]);
  }
  if (kept_separation.size() < 2)
    throw std::invalid_argument("homogenise: fewer than two separations have a converged solve in every column");
  t.separation_m = kept_separation;
  for (std::size_t c = 0; c < columns.size(); ++c) *columns[c] = std::move(kept[c]);
}

}  // namespace

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
  t.phi_x = column(patches, &PatchResult::phi_x);
  t.phi_y = column(patches, &PatchResult::phi_y);
  t.phi_s = column(patches, &PatchResult::phi_s);
  t.film_over_sigma = column(patches, &PatchResult::film_over_sigma);
  t.phi_f = column(patches, &PatchResult::phi_f);
  t.couette_shear_factor = column(patches, &PatchResult::couette_shear_factor);
  t.phi_fp = column(patches, &PatchResult::phi_fp);
  t.contact_fraction = column(patches, &PatchResult::contact_fraction);
  t.lift_per_eta_u_per_m = column(patches, &PatchResult::lift_per_eta_u_per_m);
  std::vector<double> mus, mub;
  for (const PatchResult& p : patches) {
    mus.push_back(p.mu_s_max);
    mub.push_back(p.mu_boundary);
    t.first_contact_separation_m = std::max(t.first_contact_separation_m, p.first_contact_separation_m);
    t.unconverged += p.unconverged;
  }
  t.mu_s_max = finite_estimate(mus);
  t.mu_boundary = finite_estimate(mub);
  drop_unresolved_nodes(t);
  return t;
}

}  // namespace tribo::homogenise
