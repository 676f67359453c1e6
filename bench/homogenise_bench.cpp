// Cost of `tribo homogenise` by stage (homogenise/patch.h, pin.h) on the thesis steel preset
// (examples/thesis-steel.toml): one realisation — BEM load–separation and junction solves on the
// preset's contact grid (2048², and 1024² for the discretisation error), the flow- and
// shear-factor cells, the cavitating lift cells on 64² and the preset's 128² — and the
// pin-face average Reynolds solves of pin_scale. One thread per realisation, as the CLI runs them
// (it solves realisations in parallel, one per thread).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "apps/homogenise_config.h"
#include "homogenise/cell_table.h"
#include "homogenise/patch.h"
#include "homogenise/pin.h"

namespace {

tribo::homogenise::HomogeniseOptions preset(Eigen::Index grid) {
  auto o = tribo::cli::load_homogenise_run(std::filesystem::path(TRIBO_SOURCE_DIR) / "examples" / "thesis-steel.toml").options;
  o.surface.grid = grid;
  o.threads = 1;
  return o;
}

void BM_SolvePatch(benchmark::State& state) {
  const auto o = preset(state.range(0));
  tribo::homogenise::PatchResult r;
  for (auto _ : state) r = tribo::homogenise::solve_patch(o, 0);
  state.counters["bem_s"] = r.bem_s;
  state.counters["flow_cells_s"] = r.flow_cells_s;
  state.counters["lift_cells_s"] = r.lift_cells_s;
  state.counters["bem_iterations"] = r.bem_iterations;
  state.counters["contact_grid"] = r.contact_grid;
}
BENCHMARK(BM_SolvePatch)->Arg(64)->Arg(128)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_PinScale(benchmark::State& state) {
  const auto o = preset(64);
  const auto cells = tribo::homogenise::aggregate(o, {tribo::homogenise::solve_patch(o, 0)});
  for (auto _ : state) benchmark::DoNotOptimize(tribo::homogenise::pin_scale(o, cells));
}
BENCHMARK(BM_PinScale)->Iterations(2)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
