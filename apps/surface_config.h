// The [surface] table of a generated rough surface and the [domain] it covers, read by one reader
// for `tribo contact` (kind = "gaussian"), `tribo homogenise` and `tribo reynolds flow-factors`, so
// that the same table means the same surface in every command. Keys and defaults:
//   [surface] kind                         "gaussian" (contact also takes "sphere" and "file")
//             spectrum                     "gaussian_acf" | "self_affine"; default "gaussian_acf"
//             rms_height_m | rms_slope     exactly one, no default (homogenise needs rms_height_m)
//             seed                         1
//             gaussian_acf: correlation_length_m (required), correlation_length_across_m
//                           (default 0: isotropic)
//             self_affine:  hurst (0.8), rolloff_wavelength_m (0: the domain size),
//                           cutoff_wavelength_m (0: the grid spacing), peklenik_gamma (1: isotropic;
//                           > 1 a lay along x, the sliding direction)
//   [domain]  size_m                       1e-3 m
//             grid                         128 points a side (8 .. 16384)
#pragma once

#include "apps/config.h"
#include "contact/surface.h"

namespace tribo::cli {

// The spectrum keys alone (spectrum, seed and the spectrum's lengths) into `p`: also for a table
// that is not [surface] (the lower surface of `tribo reynolds`' rough_pair geometry).
void read_spectrum(ConfigTable& t, contact::GaussianSurfaceParams& p);

// [surface] (already known to be of kind "gaussian") and [domain] (nullptr when absent), checked
// with contact::validate. Neither table is finished: the caller may read more keys from them.
contact::GaussianSurfaceParams read_gaussian_surface(ConfigTable& surface, ConfigTable* domain);

}  // namespace tribo::cli
