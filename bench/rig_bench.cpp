// Rig integration speed: simulated seconds per wall second (reported as the counter
// `sim_s_per_wall_s`) for the thesis rig in stick-slip (Coulomb μs = 0.3, μk = 0.2) at three
// drive speeds, and the number of stick-slip events per run.
#include <benchmark/benchmark.h>

#include "rig/kinetic_laws.h"
#include "rig/simulator.h"
#include "rig/sweep.h"

#include <cmath>

namespace {

void BM_ThesisRigStickSlip(benchmark::State& state) {
  const tribo::rig::RigParameters rig;
  const double v = static_cast<double>(state.range(0)) * 1e-4;  // m/s
  auto law = tribo::rig::make_coulomb(0.3, 0.2);
  tribo::rig::SimulationOptions opt;
  opt.duration_s = 10.0;
  long events = 0;
  for (auto _ : state) {
    tribo::rig::SimulationObserver observer;
    observer.on_event = [&](const tribo::rig::Event&) { ++events; };
    const auto summary = tribo::rig::simulate(rig, tribo::rig::Drive::constant(v), *law, opt, observer);
    benchmark::DoNotOptimize(summary.integrator_steps);
  }
  state.counters["sim_s_per_wall_s"] =
      benchmark::Counter(opt.duration_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["events_per_run"] = static_cast<double>(events) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ThesisRigStickSlip)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

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
