// A measured line profile (a stylus trace, one line of a map) made ready for a line contact's solver:
// levelled, then low-pass filtered to the wavelengths the solver's nodes resolve; and a map (below).
//
// Levelling removes the least-squares straight line (a stylus scan's tilt and offset: the
// instrument's own "levelled" Rq is taken about it). The filter is the Gaussian profile filter of
// ISO 16610-21 (formerly ISO 11562): the weighting function
//   s(x) = exp(−π (x / (α λc))²) / (α λc),   α = √(ln 2 / π) ≈ 0.4697,
// passes a sinusoid of wavelength λ with the amplitude ratio exp(−π (α λc / λ)²) — one half at the
// cut-off λc, 0.84 at 2 λc, 1/16 at λc / 2. The weights are cut at |x| = λc, where they have
// fallen to 6.5e-7 of the centre's, and renormalised; the filtered profile is given only where the
// whole window lies on the profile (ISO's end-effect problem is left out, not patched over).
#pragma once

#include <Eigen/Core>

namespace tribo::contact {

// z minus its least-squares line over equally spaced samples. At least 2 samples.
Eigen::ArrayXd level_profile(const Eigen::ArrayXd& z);

struct FilteredProfile {
  Eigen::ArrayXd height_m;  // the mean line (the long wavelengths) at the valid samples
  Eigen::Index first = 0;   // index into the input of height_m(0): the window's half width in samples
};

// The Gaussian-filtered mean line of `z` (samples `spacing_m` apart) for cut-off `cutoff_m`; bad
// arguments (spacing or cut-off not > 0, a profile shorter than two windows) raise
// std::invalid_argument with the reason.
FilteredProfile gaussian_profile_filter(const Eigen::ArrayXd& z, double spacing_m, double cutoff_m);

// The filter's amplitude transmission of a sinusoid of wavelength λ (ISO 16610-21's closed form).
double gaussian_filter_transmission(double wavelength_m, double cutoff_m);

// A height map (rows along x, columns along y) made ready for a point contact's solver in the same
// way: its least-squares plane removed, and the areal Gaussian filter of ISO 16610-61, whose weighting
// function is the profile filter's in x times the same in y — so it is applied as the profile filter
// along every column and then along every row, and passes cos(2πx/λx) cos(2πy/λy) with the product of
// the two profile transmissions — given only where the whole window lies on the map.
Eigen::ArrayXXd level_map(const Eigen::ArrayXXd& z);  // at least 2 × 2 samples

struct FilteredMap {
  Eigen::ArrayXXd height_m;                // the mean surface at the valid samples
  Eigen::Index first_x = 0, first_y = 0;   // the input's indices of height_m(0, 0)
};
FilteredMap gaussian_areal_filter(const Eigen::ArrayXXd& z, double dx_m, double dy_m, double cutoff_m);

}  // namespace tribo::contact
