// The calibration stage's second start (diagnosis.h step 1): friction levels read off the
// measured items, so that the baseline fit need not find μs and μk from the model's guesses alone.
#pragma once

#include <vector>

#include "gap/compare.h"

namespace tribo::gap {

struct FrictionLevels {
  double mu_s = 0.0, mu_k = 0.0;
};

// μs: the mean friction maximum of stick-slip (mu_peak), else of the static points
// (mu_s_vs_load_rate); μk: midway between the mean maximum and minimum, as in Coulomb stick-slip,
// else the steady-sliding level (steady_mu), else the mean friction (mean_mu). A level the data do
// not give falls back to the other one, then to `fallback`. Clamped to μs in [0.011, 1.49] and
// μk in [0.05 μs, μs], inside the baseline fit's bounds.
FrictionLevels friction_levels_from_data(const std::vector<Item>& items, const FrictionLevels& fallback);

}  // namespace tribo::gap
