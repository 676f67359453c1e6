// The small synthetic bundle the diagnosis tests share (diagnosis_test.cpp, diagnosis_slow_test.cpp):
// three speeds, 1.5 s a run — enough stick-slip cycles for the features, a few seconds a diagnosis.
#pragma once

#include "gap/synthesize.h"

namespace tribo::gap {

inline SyntheticOptions small() {
  SyntheticOptions o;
  o.speeds_m_per_s = {8e-3, 1.4e-2, 2.4e-2};
  o.duration_s = 1.5;
  return o;
}

}  // namespace tribo::gap
