// The unit of work of every gap fit (issue 35): one prediction of a bundle — every run of the
// foreign Coulomb control (tests/gap/data/foreign-coulomb-control, five long stick-slip runs and
// their static points) simulated at the integration tolerance its noise sets and read into
// items. A candidate's 5 × 5 grid with its baseline re-fits is a few hundred of these, so their
// cost is the diagnosis' cost. Arg: the catalogue effect added to the calibrated Coulomb model
// (0 none, then the catalogue's order); reported per prediction, on the calling thread alone
// (OMP_NUM_THREADS=1 keeps the predictions' parallel runs serial).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "gap/bundle.h"
#include "gap/compare.h"
#include "gap/diagnosis.h"
#include "rig/friction_model.h"

namespace {

const std::filesystem::path kBundle = std::filesystem::path(TRIBO_SOURCE_DIR) / "tests/gap/data/foreign-coulomb-control";

void BM_PredictForeignControl(benchmark::State& state) {
  using namespace tribo;
  const gap::ExperimentBundle bundle = gap::read_bundle(kBundle);
  const rig::RigParameters rig = gap::apply_bundle_rig(bundle, rig::RigParameters{});
  const gap::Comparison comparison(bundle, rig);
  rig::FrictionModel model = rig::coulomb(0.362, 0.190);  // the calibrated baseline (docs/gap.md)
  const std::vector<std::string> effects{"none", "slip_transient", "viscous_friction", "thermal_thinning", "hydrodynamic_lift",
                                         "squeeze_film", "rate_dependent_static"};
  const std::string& effect = effects.at(static_cast<std::size_t>(state.range(0)));
  if (effect != "none") model.add(effect);
  state.SetLabel(effect);
  for (auto _ : state) benchmark::DoNotOptimize(comparison.predict(rig, model, 1));
}
BENCHMARK(BM_PredictForeignControl)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
