// What the single-candidate tests on the independent generator share (slip_law_test.cpp,
// squeeze_film_test.cpp): the diagnosis of one case of the full independent set against its
// miscalibrated Coulomb model, with only the catalogue effect that stands for the case's mechanism
// as candidate (20 bootstrap resamples: the tests read the fit, not the confidence).
#pragma once

#include <string>

#include "gap/diagnosis.h"
#include "gap/independent/generator.h"
#include "rig/friction_model.h"

namespace tribo::gap {

inline Diagnosis diagnose_with_one_candidate(const independent::IndependentCase& c, const std::string& effect) {
  DiagnosisOptions o;
  o.bootstrap_samples = 20;
  o.candidates = {effect};
  return diagnose(c.bundle, apply_bundle_rig(c.bundle, rig::RigParameters{}), rig::coulomb(c.model_mu_s, c.model_mu_k), o);
}

}  // namespace tribo::gap
