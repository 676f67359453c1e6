// A data acquisition's anti-alias filter (experiment.toml [recorder], gap/bundle.h): every channel
// passes a Butterworth low-pass before it is sampled, so the record shows a breakaway or a
// re-attachment as the filter's smoothed, delayed and ringing step response (a 4th-order filter
// at 200 Hz: ≈ 2 ms of group delay and an 11 % overshoot against a 31-ms slip). A simulation read
// like for like passes the same filter (compare.cpp); without it a Coulomb control's troughs and
// slip drops miss by the filter's response, which calibration cannot absorb.
#pragma once

#include <vector>

#include "gap/bundle.h"

namespace tribo::gap {

// `u`, uniformly sampled at `step_s`, through the filter: the analog Butterworth low-pass realised
// at that step by the bilinear transform with the cut-off pre-warped (liquid-dsp's design, run in
// double precision, DC gain exactly 1), started from the steady state of u's first value.
// Throws std::invalid_argument unless 0 < cutoff · step_s < 1/2 (below the step's Nyquist
// frequency); std::runtime_error if the design fails.
std::vector<double> low_pass(const AntiAliasFilter& filter, const std::vector<double>& u, double step_s);

// |H| of the filter as low_pass() realises it at `step_s`, at `frequency_Hz`.
double gain_at(const AntiAliasFilter& filter, double frequency_Hz, double step_s);

}  // namespace tribo::gap
