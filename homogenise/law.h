// The homogenisation end to end (issue 14): realisations → cell table → pin table → the law file
// the rig reads (`law.json`, format "tribo-law-1", read by rig/law_table.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "homogenise/cell_table.h"
#include "homogenise/options.h"
#include "homogenise/patch.h"
#include "homogenise/pin.h"

namespace tribo::homogenise {

// Solves the realisations not already in `cached` (index k ↔ realisation k), in parallel over
// options.threads; `on_patch` runs (serialised) as each one finishes, so a caller can keep it.
// The first exception from a solve or from `on_patch` is rethrown once the running solves are done;
// the realisations not yet started are not solved.
std::vector<PatchResult> solve_patches(const HomogeniseOptions& options,
                                       const std::vector<std::optional<PatchResult>>& cached,
                                       const std::function<void(int realisation, const PatchResult&)>& on_patch);

// The junction locus the tables imply: S = σ0/τ_i from the BEM's μs,max by (3.1.23), so the
// locus' upper asymptote is the BEM's, with the hand-set rate law (n, L, m).
struct JunctionSummary {
  double alpha = 0, n = 0, sigma0_over_tau_i = 0, location_per_s = 0, strain_rate_index_m = 0,
         reference_load_rate_per_s = 0, interface_shear_strength_Pa = 0, mu_s_max = 0, mu_boundary = 0;
};
JunctionSummary junction(const HomogeniseOptions& options, const CellTable& cells);

// One line for each tabulated quantity whose discretisation error exceeds the options'
// target_relative_error of its value (μs,max, μ_b): what, the error, the grid, and what to change.
std::vector<std::string> resolution_warnings(const HomogeniseOptions& options, const CellTable& cells);

// The law file without provenance and Stribeck section (the caller adds both): pin, lubricant,
// thermal, junction, the pin table (columns of the rig's contract plus standard errors and the
// wedge / rugosity split) and the cell table it came from.
nlohmann::json law_json(const HomogeniseOptions& options, const CellTable& cells, const PinTable& pin);

}  // namespace tribo::homogenise
