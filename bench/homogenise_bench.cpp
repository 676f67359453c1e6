// Cost of `tribo homogenise` by stage (homogenise/patch.h, pin.h) on the thesis steel preset
// (examples/thesis-steel.toml): one realisation — BEM load–separation and junction solves on the
// preset's contact grid (2048², and 1024² for the discretisation error), the flow- and
// shear-factor cells, the cavitating lift cells on 64² and the preset's 128² — and the
// pin-face average Reynolds solves of pin_scale; and the contact spots' films of one table node (the
// labelling and the film at every ηU node, lubrication/micro_ehl.h). One thread per realisation, as
// the CLI runs them (it solves realisations in parallel, one per thread).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "apps/homogenise_config.h"
#include "contact/contact_spots.h"
#include "contact/surface.h"
#include "lubrication/micro_ehl.h"
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

// The films of one table node on the preset's 2048² contact grid. The field: the realisation's lowest
// 0.16 % of nodes (the real area's share at the pin's pressure) at the hardness — the spots' count
// and sizes set the cost, not their pressures.
void BM_SpotFilms(benchmark::State& state) {
  const auto o = preset(128);
  const Eigen::ArrayXXd z = tribo::contact::fourier_refine(tribo::contact::gaussian_surface(o.surface), 16);
  std::vector<double> sorted(z.data(), z.data() + z.size());
  const auto k = static_cast<std::ptrdiff_t>(0.0016 * static_cast<double>(sorted.size()));
  std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
  const Eigen::ArrayXXd p = (z <= sorted[static_cast<std::size_t>(k)]).cast<double>() * o.hardness_Pa;
  const auto grid = tribo::contact::Grid::patch(z.rows(), z.cols(), o.surface.size_m, o.surface.size_m);
  const tribo::lubrication::MicroEhlOptions films = tribo::homogenise::micro_ehl_options(o);
  const std::vector<double> eta_u = tribo::homogenise::micro_ehl_eta_u_Pa_m(o);
  std::size_t spots = 0;
  for (auto _ : state) {
    const auto s = tribo::contact::contact_spots(p, grid, o.e_star_Pa);
    for (double e : eta_u) benchmark::DoNotOptimize(tribo::lubrication::mean_spot_films(s, e, films));
    spots = s.size();
  }
  state.counters["spots"] = static_cast<double>(spots);
  state.counters["eta_u_nodes"] = static_cast<double>(eta_u.size());
}
BENCHMARK(BM_SpotFilms)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
