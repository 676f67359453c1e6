// The unit of work of every gap fit (issue 35): one prediction of a bundle — every run of the
// foreign Coulomb control (tests/gap/data/foreign-coulomb-control, five long stick-slip runs and
// their static points) simulated at the integration tolerance its noise sets and read into
// items. A candidate's 5 × 5 grid with its baseline re-fits is a few hundred of these, so their
// cost is the diagnosis' cost. Arg: the catalogue effect added to the calibrated Coulomb model
// (0 none, then the catalogue's order); reported per prediction, on the calling thread alone
// (OMP_NUM_THREADS=1 keeps the predictions' parallel runs serial).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/compare.h"
#include "gap/diagnosis.h"
#include "gap/fit.h"
#include "rig/friction_model.h"

namespace {

const std::vector<std::string> kEffects{"none",          "slip_transient", "viscous_friction",     "thermal_thinning",
                                        "hydrodynamic_lift", "squeeze_film", "rate_dependent_static", "rate_and_state"};

const std::filesystem::path kBundle = std::filesystem::path(TRIBO_SOURCE_DIR) / "tests/gap/data/foreign-coulomb-control";

// The foreign control's predictions by the calibrated Coulomb baseline (docs/gap.md) with `add`'s
// effects and parameters set on it, timed.
void predict_foreign_control(benchmark::State& state, const std::function<void(tribo::rig::FrictionModel&)>& add) {
  using namespace tribo;
  const gap::ExperimentBundle bundle = gap::read_bundle(kBundle);
  const rig::RigParameters rig = gap::apply_bundle_rig(bundle, rig::RigParameters{});
  const gap::Comparison comparison(bundle, rig);
  rig::FrictionModel model = rig::coulomb(0.362, 0.190);
  add(model);
  for (auto _ : state) benchmark::DoNotOptimize(comparison.predict(rig, model, 1));
}

void BM_PredictForeignControl(benchmark::State& state) {
  const std::string& effect = kEffects.at(static_cast<std::size_t>(state.range(0)));
  state.SetLabel(effect);
  predict_foreign_control(state, [&](tribo::rig::FrictionModel& model) {
    if (effect != "none") model.add(effect);
  });
}
BENCHMARK(BM_PredictForeignControl)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

// The two candidates whose fits were the slowest of validation case 14818 (independent thermal
// thinning, 2026-12-05), with the parameters they settled on there, added to the same control:
// arg 0, a slip transient with rate weakening (a 0.0137, D_c 4.3 µm, β 0.0084), whose state R
// tracks the stable level a slip of D_c behind; arg 1, a squeeze film (φ_max 0.361, D_b 0.228 mm,
// h 6.9 µm), whose share decays while stuck.
void BM_PredictForeignControlSlowCandidate(benchmark::State& state) {
  const bool transient = state.range(0) == 0;
  state.SetLabel(transient ? "slip_transient, rate weakening" : "squeeze_film");
  predict_foreign_control(state, [&](tribo::rig::FrictionModel& model) {
    if (transient) {
      model.set("slip_transient", "amplitude", 0.0137);
      model.set("slip_transient", "decay_distance_m", 4.3e-6);
      model.set("slip_transient", "rate_weakening", 0.0084);
    } else {
      model.set("squeeze_film", "film_fraction", 0.361);
      model.set("squeeze_film", "build_up_distance_m", 2.28e-4);
      model.set("squeeze_film", "film_thickness_m", 6.9e-6);
    }
  });
}
BENCHMARK(BM_PredictForeignControlSlowCandidate)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

// A measured record's prediction: the paper-on-paper stick-slip at k = 2254 N/m
// (../shared/data/real, beside the checkout; skipped without it), three runs of 375, 14 and 3.8 s,
// at the calibrated Coulomb baseline of docs/gap-paper (μs 0.504, μk 0.348, ζ 0.043), one effect
// added (an index into kEffects) — the bundle, or one run of it (run ≥ 0, no static points).
void predict_paper_k2254(benchmark::State& state, long run, std::size_t effect) {
  using namespace tribo;
  const std::filesystem::path dir = std::filesystem::path(TRIBO_SOURCE_DIR) / "../shared/data/real/stickslip-paper-k2254";
  if (!std::filesystem::exists(dir)) {
    state.SkipWithError("../shared/data/real/stickslip-paper-k2254 not found");
    return;
  }
  gap::ExperimentBundle bundle = gap::read_bundle(dir);
  if (run >= 0) {
    bundle.runs = {bundle.runs.at(static_cast<std::size_t>(run))};
    bundle.static_points.clear();
  }
  rig::RigParameters rig = gap::apply_bundle_rig(bundle, rig::RigParameters{});
  gap::set_damping_ratio(rig, 0.04281);
  const gap::Comparison comparison(bundle, rig);
  rig::FrictionModel model = rig::coulomb(0.5039, 0.3481);
  if (effect > 0) model.add(kEffects.at(effect));
  for (auto _ : state) benchmark::DoNotOptimize(comparison.predict(rig, model, 1));
}

// Arg: the run's index, −1 for the whole bundle; the Coulomb baseline alone.
void BM_PredictPaperK2254(benchmark::State& state) {
  state.SetLabel(state.range(0) < 0 ? "all runs" : "run " + std::to_string(state.range(0)));
  predict_paper_k2254(state, state.range(0), 0);
}
BENCHMARK(BM_PredictPaperK2254)->DenseRange(-1, 2)->Unit(benchmark::kMillisecond);

// The whole bundle with each catalogue effect at its default parameters (arg as
// BM_PredictForeignControl's): what one evaluation of a candidate's fit costs there.
void BM_PredictPaperK2254Effect(benchmark::State& state) {
  const auto effect = static_cast<std::size_t>(state.range(0));
  state.SetLabel(kEffects.at(effect));
  predict_paper_k2254(state, -1, effect);
}
BENCHMARK(BM_PredictPaperK2254Effect)->DenseRange(0, 6)->Unit(benchmark::kMillisecond);

// The measured velocity step (basalt gouge, BRAVA; ../shared/data/real, skipped without it): one
// 118-s run driven at 3 then 10 µm/s. `model`'s predictions of it on a rig of the given stiffness
// and damping ratio, timed.
void predict_velocity_step(benchmark::State& state, double stiffness_N_per_m, double damping_ratio,
                           const tribo::rig::FrictionModel& model) {
  using namespace tribo;
  const std::filesystem::path dir = std::filesystem::path(TRIBO_SOURCE_DIR) / "../shared/data/real/velstep-basalt-brava";
  if (!std::filesystem::exists(dir)) {
    state.SkipWithError("../shared/data/real/velstep-basalt-brava not found");
    return;
  }
  const gap::ExperimentBundle bundle = gap::read_bundle(dir);
  rig::RigParameters rig = gap::apply_bundle_rig(bundle, rig::RigParameters{});
  rig.stiffness_N_per_m = stiffness_N_per_m;
  gap::set_damping_ratio(rig, damping_ratio);
  const gap::Comparison comparison(bundle, rig);
  for (auto _ : state) benchmark::DoNotOptimize(comparison.predict(rig, model, 1));
}

// At the calibrated Coulomb baseline of the 2026-12-05 report (μs 0.6164, μk 0.6060, ζ 0.110,
// k 1.021e6 N/m), one effect added (an index into kEffects).
void BM_PredictVelocityStep(benchmark::State& state) {
  const auto effect = static_cast<std::size_t>(state.range(0));
  tribo::rig::FrictionModel model = tribo::rig::coulomb(0.6164, 0.6060);
  if (effect > 0) model.add(kEffects.at(effect));
  state.SetLabel(kEffects.at(effect));
  predict_velocity_step(state, 1.021e6, 0.1101, model);
}
BENCHMARK(BM_PredictVelocityStep)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

// Where a fit's search wanders into chatter: μs = μk with hydrodynamic lift that drops steeply near
// U = 0 (max_fraction 0.095, U½ 40 µm/s), k 1.037e6 N/m, ζ 0.256 (520.8 N s/m) — a grid start of the lift
// candidate. Every slip re-attaches at once from 0.8 s on; the event rate limit
// (Comparison::limit_events) ends the run there, where the whole run's budget let it chatter
// through 384 000 events (1.2 s) first.
void BM_PredictVelocityStepChatter(benchmark::State& state) {
  tribo::rig::FrictionModel model = tribo::rig::coulomb(0.6141, 0.6141);
  model.set("hydrodynamic_lift", "max_fraction", 0.095);
  model.set("hydrodynamic_lift", "half_speed_m_per_s", 3.981e-5);
  predict_velocity_step(state, 1.037e6, 0.2559, model);
}
BENCHMARK(BM_PredictVelocityStepChatter)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
