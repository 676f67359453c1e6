#include "gap/test_block.h"

#include <stdexcept>

#include "gap/compare.h"
#include "gap/verdict.h"

namespace tribo::gap {

TestBlockGap test_block_gap(const ExperimentBundle& test, const rig::RigParameters& model_rig, const Diagnosis& d,
                            std::uint64_t seed, const std::optional<rig::RigParameters>& diagnosed_rig) {
  const Comparison comparison(test, model_rig);
  const std::vector<Item>& items = comparison.items();
  if (items.empty()) throw std::invalid_argument("test block: the bundle gives no item to compare");
  const std::vector<bool> all(items.size(), true);
  // The calibrated rig moved as the test's rig was moved from the diagnosed one.
  auto on_test_rig = [&](rig::RigParameters r) {
    if (!diagnosed_rig) return r;
    r.mass_kg *= model_rig.mass_kg / diagnosed_rig->mass_kg;
    r.stiffness_N_per_m *= model_rig.stiffness_N_per_m / diagnosed_rig->stiffness_N_per_m;
    r.damping_N_s_per_m *= model_rig.damping_N_s_per_m / diagnosed_rig->damping_N_s_per_m;
    r.normal_load_N *= model_rig.normal_load_N / diagnosed_rig->normal_load_N;
    r.slider_radius_m *= model_rig.slider_radius_m / diagnosed_rig->slider_radius_m;
    return r;
  };
  TestBlockGap out;
  out.items = static_cast<int>(items.size());
  auto gap_of = [&](const rig::RigParameters& rig, const rig::FrictionModel& model) {
    return breakdown(items, comparison.residuals(comparison.predict(on_test_rig(rig), model, seed)), all).gap;
  };
  out.gap_before = gap_of(d.rig, d.calibrated);
  const Candidate* chosen = verdict_candidate(d);
  out.gap_after = chosen ? gap_of(chosen->rig, chosen->model) : out.gap_before;
  for (const std::string& name : d.verdict.beside())
    for (const Candidate& c : d.candidates)
      if (verdict_name(c.effects) == name) out.gap_beside[name] = gap_of(c.rig, c.model);
  out.noise_floor = breakdown(items, comparison.relative_noise(), all).gap;
  return out;
}

}  // namespace tribo::gap
