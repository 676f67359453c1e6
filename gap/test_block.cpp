#include "gap/test_block.h"

#include <stdexcept>

#include "gap/compare.h"
#include "gap/verdict.h"

namespace tribo::gap {

TestBlockGap test_block_gap(const ExperimentBundle& test, const rig::RigParameters& model_rig, const Diagnosis& d,
                            std::uint64_t seed) {
  const Comparison comparison(test, model_rig);
  const std::vector<Item>& items = comparison.items();
  if (items.empty()) throw std::invalid_argument("test block: the bundle gives no item to compare");
  const std::vector<bool> all(items.size(), true);
  TestBlockGap out;
  out.items = static_cast<int>(items.size());
  auto gap_of = [&](const rig::RigParameters& rig, const rig::FrictionModel& model) {
    return breakdown(items, comparison.residuals(comparison.predict(rig, model, seed)), all).gap;
  };
  out.gap_before = gap_of(d.rig, d.calibrated);
  const Candidate* chosen = verdict_candidate(d);
  out.gap_after = chosen ? gap_of(chosen->rig, chosen->model) : out.gap_before;
  out.noise_floor = breakdown(items, comparison.relative_noise(), all).gap;
  return out;
}

}  // namespace tribo::gap
