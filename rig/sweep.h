// A sweep over constant driven speeds, run in parallel (OpenMP, one simulation per thread; the
// friction law is immutable and shared). Results are in the order of `speeds` whatever the
// thread count, so a sweep is reproducible.
#pragma once

#include <functional>
#include <vector>

#include "rig/friction_law.h"
#include "rig/observables.h"
#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::rig {

struct SweepPoint {
  double drive_speed_m_per_s = 0.0;
  SimulationResult result;
  RunObservables observables;
};

struct SweepOptions {
  SimulationOptions simulation;       // duration_s is replaced by duration_for(v) when set
  std::function<double(double)> duration_for;
  int threads = 0;                    // 0: OpenMP's default
  std::function<void(const SweepPoint&)> on_point_done;  // called under a lock, in completion order
};

// Simulated seconds long enough for `cycles` stick-slip cycles of amplitude Δμ W/k at speed v
// (stick time 2Δμ W/(k v) plus a period), and at least `minimum_s`.
double stick_slip_duration_s(const RigParameters& rig, double v, double delta_mu, double cycles, double minimum_s);

std::vector<SweepPoint> sweep_drive_speeds(const RigParameters& rig, const FrictionLaw& law,
                                           const std::vector<double>& speeds, const SweepOptions& options);

}  // namespace tribo::rig
