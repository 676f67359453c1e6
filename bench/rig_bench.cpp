// Rig integration speed: simulated seconds per wall second (reported as the counter
// `sim_s_per_wall_s`) for the thesis rig in stick-slip (Coulomb μs = 0.3, μk = 0.2) at three
// drive speeds, and the number of stick-slip events per run.
#include <benchmark/benchmark.h>

#include "rig/kinetic_laws.h"
#include "rig/simulator.h"

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

}  // namespace

BENCHMARK_MAIN();
