// A measured constant-speed run's regime (gap/compare.cpp): with the slider's displacement
// recorded it is the rig's own classification (rig::classify_regime), so a persistent oscillation
// without sticks is quasi-harmonic and its items belong to stable slip; from μ alone the friction
// extrema can only say the same record oscillates, i.e. stick-slip.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gap/compare.h"

namespace tribo::gap {
namespace {

// x = x0 + A sin(ωt) at V = 10 mm/s with Aω = V/2: the sliding speed V − ẋ stays in [V/2, 3V/2],
// no stick. A = 100 µm swings μ = kx/W by 2kA/W ≈ 0.022, 11 % of μ ≈ 0.2 — above the 5 % at which
// the μ analysis looks for extrema, so μ alone sees an oscillation.
Run oscillating_run(const std::string& id, bool with_displacement) {
  const rig::RigParameters rig;
  const double v = 1e-2, w = 50.0, a = 0.5 * v / w, x0 = 0.2 * rig.normal_load_N / rig.stiffness_N_per_m;
  Run r;
  r.run_id = id;
  r.v_m_per_s = v;
  for (double t = 0.0; t <= 4.0; t += 1e-3) {
    const double x = x0 + a * std::sin(w * t);
    r.trace.t_s.push_back(t);
    if (with_displacement) {
      r.trace.x_m.push_back(x);  // μ = kx/W
    } else {
      r.trace.mu.push_back(rig.stiffness_N_per_m * x / rig.normal_load_N);
    }
  }
  return r;
}

TEST(MeasuredRegime, DisplacementTellsQuasiHarmonicFromStickSlip) {
  ExperimentBundle with_x, mu_only;
  with_x.runs.push_back(oscillating_run("x", true));
  mu_only.runs.push_back(oscillating_run("mu", false));
  const Comparison cx(with_x, rig::RigParameters{}), cmu(mu_only, rig::RigParameters{});
  // The same μ record gives the same friction features either way: extrema, so a mu_peak item.
  auto has = [](const Comparison& c, const std::string& observable) {
    for (const Item& it : c.items())
      if (it.observable == observable) return true;
    return false;
  };
  ASSERT_TRUE(has(cx, "mu_peak") && has(cx, "mean_mu"));
  ASSERT_TRUE(has(cmu, "mu_peak") && has(cmu, "mean_mu"));
  // With x: quasi-harmonic, and every item of the run in stable slip (no breakaway, no stick).
  for (const Item& it : cx.items()) {
    EXPECT_EQ(it.regime, "quasi_harmonic") << it.observable;
    EXPECT_EQ(it.phase, "stable slip") << it.observable;
  }
  // From μ alone: the extrema are read as stick-slip, the peak as slip onset.
  for (const Item& it : cmu.items()) {
    EXPECT_EQ(it.regime, "stick_slip") << it.observable;
    if (it.observable == "mu_peak") {
      EXPECT_EQ(it.phase, "slip onset");
    }
  }
}

}  // namespace
}  // namespace tribo::gap
