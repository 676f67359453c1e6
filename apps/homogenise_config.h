// Reading a `tribo homogenise` config: [surface] and [domain] as `tribo contact` reads a Gaussian
// surface (σ is the composite rms height of the pair) or a measured one (kind = "file", square:
// one realisation, σ its Rq), [material], [junction], [lubricant],
// [pin], [speeds] and [homogenise] (docs/homogenise.md lists every key and its default).
#pragma once

#include <filesystem>
#include <vector>

#include <toml++/toml.h>

#include "homogenise/options.h"

namespace tribo::cli {

struct HomogeniseRun {
  homogenise::HomogeniseOptions options;
  std::vector<double> speeds_m_per_s;  // the Stribeck curve's speeds, log-spaced
  std::vector<std::filesystem::path> input_files;  // files the config names (a measured topography)
};

// Throws InputError naming the file, the key and the reason.
HomogeniseRun load_homogenise_run(const std::filesystem::path& path);
// The same on a parsed document; `path` names it in errors.
HomogeniseRun load_homogenise_run(const toml::table& doc, const std::filesystem::path& path);

}  // namespace tribo::cli
