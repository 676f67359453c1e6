// The homogenisation pipeline as `tribo homogenise` and `tribo demo` run it: realisations (cached in
// DIR/patches so a killed run resumes) → cell table → pin table → DIR/law.json with provenance and
// the Stribeck curve at the pin's load, DIR/stribeck.csv, DIR/area.csv and their PNGs.
#pragma once

#include <filesystem>
#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/homogenise_config.h"
#include "rig/steady_sliding.h"

namespace tribo::cli {

// The Stribeck curve of a law at the pin's load: `solve` (rig::steady_sliding on the law) at each
// speed in turn. A point that did not converge is left out of `points` and listed in
// `unconverged` ({"what", "U_m_per_s", "reason"}), never tabulated or judged; the curve stops at the
// first speed where the film would leave the table (listed too).
struct StribeckCurve {
  std::vector<rig::SteadySliding> points;
  nlohmann::json unconverged = nlohmann::json::array();
};
StribeckCurve stribeck_curve(const std::vector<double>& speeds_m_per_s, const std::function<rig::SteadySliding(double)>& solve);

// `run` was read from `config` (its bytes' hash keys the patch cache and goes into provenance).
// Returns the law file's JSON as written to out/law.json.
nlohmann::json homogenise_into(const HomogeniseRun& run, const std::filesystem::path& config,
                               const std::filesystem::path& out, bool plots);

}  // namespace tribo::cli
