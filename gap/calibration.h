// Starts read off the measured items: the calibration stage's second start (diagnosis.h step 1),
// friction levels, so that the baseline fit need not find μs and μk from the model's guesses
// alone; and a slide-hold-slide test's healing, where rate_and_state's fit starts.
#pragma once

#include <limits>
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

// Healing read off the re-slide peaks of a slide-hold-slide test: the ageing law's
// Δμ_peak(t_h) = b ln(1 + t_h V / D_c) (Marone 1998, Annu. Rev. Earth Planet. Sci. 26:643, eq. 9
// with the state aged by the hold) fitted to the peak_after_hold items in `use`, V each item's
// re-slide speed: b by linear least squares for each D_c of a log grid over [1e-8, 1e-2] m (the
// catalogue's fit range), the D_c of least squared error kept. NaN for both with fewer than two
// peaks, or when the peaks do not grow with the hold (no positive covariance with ln t_h).
struct Healing {
  double b = std::numeric_limits<double>::quiet_NaN();
  double decay_distance_m = std::numeric_limits<double>::quiet_NaN();
};
Healing healing_from_data(const std::vector<Item>& items, const std::vector<bool>& use);

}  // namespace tribo::gap
