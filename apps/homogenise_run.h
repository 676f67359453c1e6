// The homogenisation pipeline as `tribo homogenise` and `tribo demo` run it: realisations (cached in
// DIR/patches so a killed run resumes) → cell table → pin table → DIR/law.json with provenance and
// the Stribeck curve at the pin's load, DIR/stribeck.csv, DIR/area.csv and their PNGs.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "apps/homogenise_config.h"

namespace tribo::cli {

// `run` was read from `config` (its bytes' hash keys the patch cache and goes into provenance).
// Returns the law file's JSON as written to out/law.json.
nlohmann::json homogenise_into(const HomogeniseRun& run, const std::filesystem::path& config,
                               const std::filesystem::path& out, bool plots);

}  // namespace tribo::cli
