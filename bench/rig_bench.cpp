// Rig integration speed: simulated seconds per wall second (reported as the counter
// `sim_s_per_wall_s`) for the thesis rig in stick-slip (Coulomb μs = 0.3, μk = 0.2) at three
// drive speeds and with μs on the junction locus at two, the number of stick-slip events per run,
// the locus inverted alone, and the demo's speed sweep on 1 and 2 threads.
#include <benchmark/benchmark.h>

#include "contact/junction_locus.h"
#include "rig/friction_model.h"
#include "rig/kinetic_laws.h"
#include "rig/simulator.h"
#include "rig/sweep.h"

#include <cmath>

namespace {

// Ten simulated seconds of the thesis rig driven at state.range(0) × 1e-4 m/s with `law`.
void stick_slip(benchmark::State& state, const tribo::rig::FrictionLaw& law) {
  const tribo::rig::RigParameters rig;
  const double v = static_cast<double>(state.range(0)) * 1e-4;  // m/s
  tribo::rig::SimulationOptions opt;
  opt.duration_s = 10.0;
  long events = 0;
  for (auto _ : state) {
    tribo::rig::SimulationObserver observer;
    observer.on_event = [&](const tribo::rig::Event&) { ++events; };
    const auto summary = tribo::rig::simulate(rig, tribo::rig::Drive::constant(v), law, opt, observer);
    benchmark::DoNotOptimize(summary.integrator_steps);
  }
  state.counters["sim_s_per_wall_s"] =
      benchmark::Counter(opt.duration_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["events_per_run"] = static_cast<double>(events) / static_cast<double>(state.iterations());
}

void BM_ThesisRigStickSlip(benchmark::State& state) { stick_slip(state, *tribo::rig::make_coulomb(0.3, 0.2)); }
BENCHMARK(BM_ThesisRigStickSlip)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

// The same rig with μs on the junction locus (3.1.24) with strain-rate hardening (5.1.2) and a
// slip transient beside it — the model of the gap selftest's second-effect cases, where every
// breakaway event function asks for μs at the current load rate, i.e. for the locus inverted.
void BM_LocusRigStickSlip(benchmark::State& state) {
  tribo::rig::FrictionModel model = tribo::rig::coulomb(0.26, 0.2);
  model.add("strain_rate_hardening");
  model.add("slip_transient");
  stick_slip(state, *tribo::rig::make_friction_law(model));
}
BENCHMARK(BM_LocusRigStickSlip)->Arg(10)->Arg(100)->Unit(benchmark::kMillisecond);

// The locus inverted alone: μs at a load rate, over four decades of φ̇ (thesis steel locus,
// μs,max = 0.55, n = 1.25, α = 25, m = 0.1).
void BM_StaticFrictionFromLoadRate(benchmark::State& state) {
  tribo::contact::JunctionLocus locus;
  locus.sigma0_over_tau_i = tribo::contact::sigma0_over_tau_i_from_upper_asymptote(0.55, locus.alpha);
  locus.strain_rate_index_m = 0.1;
  double phi_dot = 1e-2, sum = 0.0;
  for (auto _ : state) {
    sum += tribo::contact::static_friction_from_load_rate(locus, phi_dot);
    phi_dot = phi_dot > 1e2 ? 1e-2 : phi_dot * 1.01;
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_StaticFrictionFromLoadRate)->Unit(benchmark::kNanosecond);

// The demo's sweep (24 log-spaced speeds, 3e-5 … 12 in/s, Coulomb μs = 0.3, μk = 0.2) on 1 and
// 2 threads: points per wall second, and the 2-thread speed-up is the ratio of the two.
void BM_SpeedSweep(benchmark::State& state) {
  const tribo::rig::RigParameters rig;
  auto law = tribo::rig::make_coulomb(0.3, 0.2);
  std::vector<double> speeds;
  for (int i = 0; i < 24; ++i) speeds.push_back(7.62e-7 * std::pow(0.3048 / 7.62e-7, i / 23.0));
  tribo::rig::SweepOptions opt;
  opt.threads = static_cast<int>(state.range(0));
  opt.duration_for = [&](double v) { return tribo::rig::stick_slip_duration_s(rig, v, 0.1, 5.0, 2.0); };
  for (auto _ : state) {
    const auto points = tribo::rig::sweep_drive_speeds(rig, *law, speeds, opt);
    benchmark::DoNotOptimize(points.data());
  }
  state.counters["points_per_s"] =
      benchmark::Counter(static_cast<double>(speeds.size() * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SpeedSweep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
