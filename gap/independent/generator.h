// The second, independent generator of the gap selftest (issue 15): "measured" bundles from a
// rig simulator written apart from rig/ — its own integrator (integrator.h), each catalogue
// mechanism in an alternative published form (laws.h), a measuring chain with gain, lag,
// anti-alias filtering at a recorder rate, drift, coloured noise and quantisation
// (measuring_chain.h), and rig constants a few per cent away from the nominal ones the bundle
// tells the diagnosis. The bundle is in the format gap/bundle.h reads (only its types are used
// here: this target links no rig/ code), so the diagnosis sees it as it sees real data.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/independent/integrator.h"
#include "gap/independent/laws.h"
#include "gap/independent/measuring_chain.h"

namespace tribo::gap::independent {

struct GeneratorOptions {
  // Driven speeds of the stick-slip runs (as the first generator: thesis rig, φ̇ ≈ 0.7 … 5 1/s).
  std::vector<double> speeds_m_per_s{6e-3, 1e-2, 1.7e-2, 2.8e-2, 4.5e-2};
  double duration_s = 2.0;
  double step_s = 1e-5;                 // integrator step
  Recorder recorder;                    // 1 kHz, 4th-order Butterworth at 200 Hz
  double noise_fraction = 0.01;         // rms of the friction channel's AR(1) noise / (μk W)
  double constant_spread = 0.03;        // k, M, W off their told values by up to ± this fraction
  double damping_spread = 0.10;         // r (known worst) by up to ± this fraction
};

struct IndependentCase {
  std::string true_effect;              // catalogue name of the mechanism present, "none" for a control
  std::string form;                     // the form it is written in here (one line)
  IndependentLaw truth;
  RigConstants actual, told;            // the rig as it is, and as the bundle's [rig] says
  ChannelChain friction_chain, displacement_chain, velocity_chain;
  double model_mu_s = 0.0, model_mu_k = 0.0;  // the miscalibrated Coulomb model for the diagnosis
  DriveHistory drive;                   // the drive as run (drive-history cases; else empty)
  ExperimentBundle bundle;
};

// What a case holds, by name, in this generator's own forms (not the catalogue's): the baseline
// μs and μk, the rig as it is, the friction channel's gain, delay and sensor lag, and the
// parameters of the withheld mechanism ("squeeze.full_thickness_m", ...). For truth.json: a user
// who reads a diagnosis of the case can compare what it fitted with what was there.
std::map<std::string, double> truth_parameters(const IndependentCase& c);

// Catalogue effects this generator has an alternative form for.
const std::vector<std::string>& independent_effects();

// One case: random physical parameters from `seed` (a stream of its own, not the first
// generator's), strong enough to matter at the synthetic speeds. Throws std::invalid_argument
// for an unknown effect and std::runtime_error when a run does not complete.
IndependentCase make_independent_case(const std::string& true_effect, std::uint64_t seed, const GeneratorOptions& options = {});

// The bundle from a truth, the rig as it is, the chains and what the bundle is to say of the rig.
// Static friction: one point per run, the mean of the recorded friction maxima at its breakaways
// after 30 % of the run, at the load rate the operator computes from the told k and W (k v / W).
ExperimentBundle record_bundle(const IndependentLaw& truth, const RigConstants& actual, const RigConstants& told,
                               const ChannelChain& friction, const ChannelChain& displacement, const ChannelChain& velocity,
                               const GeneratorOptions& options, std::uint64_t seed);

// Drive-history tests as rock- and polymer-friction laboratories run them, on a stiff,
// well-damped machine: a slide-hold-slide (Dieterich 1972, 1979; Marone 1998, Annu. Rev. Earth
// Planet. Sci. 26:643) — slide at V, hold with the drive stopped for t_h, slide again at V, for
// holds of increasing length — and a velocity step V → f V → V (Dieterich 1979; Ruina 1983).
struct DriveHistoryOptions {
  std::vector<double> hold_times_s{1.0, 3.0, 10.0, 30.0, 100.0};  // slide-hold-slide, in this order
  double step_factor = 10.0;          // velocity step: V → f V → V
  double slide_decay_lengths = 25.0;  // slip at each speed before the drive changes, in D_c,
  double min_slide_s = 2.0;           // and at least this long (the steady level is read off its end)
  double output_step_s = 1e-3;        // the integrator's record, which the chain filters and decimates
  Recorder recorder{50.0, 4, 0.4};    // 50 Hz, 4th-order Butterworth at 10 Hz
  double noise_fraction = 0.003;      // rms of the friction channel's AR(1) noise / (μ W)
  double constant_spread = 0.03;      // k, M, W off their told values by up to ± this fraction
  double damping_spread = 0.10;       // r by up to ± this fraction
};

// One drive-history case, true_effect "rate_and_state" or "none" (else std::invalid_argument;
// std::runtime_error when the run does not complete). Parameters are drawn from `seed` (a stream
// of their own); the same seed gives both effects the same machine, drive and chain.
//   rate_and_state   Dieterich–Ruina, ageing law, no reset at breakaway: the static threshold is
//                    μ(0, θ) and θ ages by the hold time, so the peak on re-sliding after a hold
//                    rises ≈ b ln(1 + t_h V/D_c) above the steady level (Marone 1998); V0 = V
//                    for the slide-hold-slide, V0 = V/100 for the velocity step, whose steady
//                    level then moves by (a − b) ln(V2/V1) + a ln((1 + V0/V2)/(1 + V0/V1)), the
//                    second term (the regularisation, laws.h) ≈ −0.009 a.
//   none             Coulomb μs > μk: no healing — the same peak μs after any hold (and, once it
//                    has stuck, stick-slip while sliding, as a Coulomb slider has on an
//                    underdamped machine) and no rate dependence.
// The bundle: one run (kind "slide_hold_slide" or "velocity_step", v_m_per_s = V) with friction_N
// and x_m through the chains, and the drive's commanded record x_drive_m, v_drive_m_per_s (a
// servo logs its set point: exact at the sample times); [rig] tells k, M, r, W a few per cent off.
IndependentCase make_slide_hold_slide_case(const std::string& true_effect, std::uint64_t seed, const DriveHistoryOptions& options = {});
IndependentCase make_velocity_step_case(const std::string& true_effect, std::uint64_t seed, const DriveHistoryOptions& options = {});

}  // namespace tribo::gap::independent
