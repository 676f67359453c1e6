// The second, independent generator of the gap selftest (issue 15): "measured" bundles from a
// rig simulator written apart from rig/ — its own integrator (integrator.h), each catalogue
// mechanism in an alternative published form (laws.h), a measuring chain with gain, lag,
// anti-alias filtering at a recorder rate, drift, coloured noise and quantisation
// (measuring_chain.h), and rig constants a few per cent away from the nominal ones the bundle
// tells the diagnosis. The bundle is in the format gap/bundle.h reads (only its types are used
// here: this target links no rig/ code), so the diagnosis sees it as it sees real data.
#pragma once

#include <cstdint>
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
  ExperimentBundle bundle;
};

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

}  // namespace tribo::gap::independent
