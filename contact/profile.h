// A measured line profile (a stylus trace, one line of a map) made ready for a line contact's solver:
// levelled, then low-pass filtered to the wavelengths the solver's nodes resolve.
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

}  // namespace tribo::contact
