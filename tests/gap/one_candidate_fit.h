// What the single-candidate tests on the independent generator share (slip_law_test.cpp,
// squeeze_film_test.cpp): the diagnosis of one case of the full independent set against its
// miscalibrated Coulomb model, with only the catalogue effect that stands for the case's mechanism
// as candidate (20 bootstrap resamples: the tests read the fit, not the confidence).
#pragma once

#include <cstdint>
#include <string>

#include "gap/diagnosis.h"
#include "gap/independent/generator.h"
#include "rig/friction_model.h"

namespace tribo::gap {

// A bundle and the model it is diagnosed against (a selftest case's CaseBundles), seeded as given.
inline Diagnosis diagnose_with_one_candidate(const ExperimentBundle& bundle, const rig::FrictionModel& model, const std::string& effect,
                                             std::uint64_t seed = 1) {
  DiagnosisOptions o;
  o.bootstrap_samples = 20;
  o.candidates = {effect};
  o.seed = seed;
  return diagnose(bundle, apply_bundle_rig(bundle, rig::RigParameters{}), model, o);
}

inline Diagnosis diagnose_with_one_candidate(const independent::IndependentCase& c, const std::string& effect) {
  return diagnose_with_one_candidate(c.bundle, rig::coulomb(c.model_mu_s, c.model_mu_k), effect);
}

}  // namespace tribo::gap
