// The rig generator: "measured" bundles simulated by the rig's own code (rig/simulator.h) from a
// friction model and measured through its instrument model plus sensor noise. The selftest's
// first generator draws its cases through it (selftest.h); the diagnosis simulates the tests it
// proposes through it (discriminate.h).
#pragma once

#include <cstdint>
#include <vector>

#include "gap/bundle.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

struct SyntheticOptions {
  // Driven speeds of the stick-slip traces on the thesis rig (φ̇ = k v / W ≈ 0.7 … 5 1/s).
  std::vector<double> speeds_m_per_s{6e-3, 1e-2, 1.7e-2, 2.8e-2, 4.5e-2};
  double duration_s = 2.0;
  int samples_per_period = 50;    // trace density while slipping (rig/simulator.h)
  // rms noise of the friction sensor as a fraction of μk W (thesis strain-gauge channel ≈ 1 %).
  double noise_fraction = 0.01;
  // The test block (gap/test_block.h): runs of the same truth at speeds between the diagnosed
  // ones (their geometric means), with noise drawn afresh — data neither the fits nor the
  // verdict saw, on which the reported shrink is measured.
  std::vector<double> test_speeds_m_per_s{7.7e-3, 1.3e-2, 2.2e-2, 3.55e-2};
  // Effect strength: the first generator's drawn effect parameters scaled away from no effect by
  // a factor drawn from [lower, upper] per case (1, 1: the development draws).
  double strength_lower = 1.0, strength_upper = 1.0;
  // Slide-hold-slide instead of constant speeds (empty: constant speeds): one run at the middle
  // of speeds_m_per_s that slides for duration_s, then holds (v = 0) for each of these times in
  // turn, sliding duration_s after each; the bundle's kind is "slide_hold_slide".
  std::vector<double> hold_times_s;
};

// "Measured" bundle: the truth simulated at every speed (or through the slide-hold-slide
// history), measured through its instrument plus noise; for constant speeds static_friction.csv
// with one point per run, the mean of its measured breakaways.
ExperimentBundle synthesize_bundle(const rig::RigParameters& rig, const rig::FrictionModel& truth, const SyntheticOptions& options,
                                   std::uint64_t seed);

}  // namespace tribo::gap
