#include "gap/discriminate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gap/compare.h"
#include "gap/verdict.h"
#include "numerics/format.h"

namespace tribo::gap {
namespace {

std::string speeds_text(const std::vector<double>& v) {
  return numerics::fmt(v.front(), "%.3g") + " … " + numerics::fmt(v.back(), "%.3g") + " m/s";
}

}  // namespace

rig::RigParameters ProposedTest::rig_for(rig::RigParameters rig) const {
  rig.stiffness_N_per_m *= stiffness_factor;
  rig.normal_load_N *= load_factor;
  return rig;
}

bool parts_alike_mechanisms(const ExperimentBundle& b) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const Run& r : b.runs) {
    if (r.trace.has_drive_history()) return true;
    for (double s : r.trace.normal_stress_Pa)
      if (s > 0.0) lo = std::min(lo, s), hi = std::max(hi, s);
  }
  return hi >= kHeavierLoadFactor * lo;
}

bool can_decide(const Verdict& v, const std::string& other, const std::string& test) {
  const bool alike = std::find(v.alike_mechanisms.begin(), v.alike_mechanisms.end(), other) != v.alike_mechanisms.end();
  return !alike || test == "slide_hold_slide" || test == "heavier_load";
}

double Separation::floors() const { return noise_floor > 0.0 ? gap / noise_floor : std::numeric_limits<double>::quiet_NaN(); }

std::vector<ProposedTest> proposed_tests(const std::vector<double>& speeds_m_per_s, double duration_s, double noise_fraction) {
  if (speeds_m_per_s.empty()) throw std::invalid_argument("proposed tests: no driven speed to start from");
  SyntheticOptions present;
  present.speeds_m_per_s = speeds_m_per_s;
  present.duration_s = duration_s;
  present.noise_fraction = noise_fraction;
  std::vector<ProposedTest> out;

  ProposedTest hold{"slide_hold_slide", "", present};
  hold.runs.hold_times_s = {1.0, 3.0, 10.0};
  hold.description = "a slide-hold-slide at " + numerics::fmt(speeds_m_per_s[speeds_m_per_s.size() / 2], "%.3g") +
                     " m/s: holds of 1, 3 and 10 s, " + numerics::fmt(duration_s, "%.3g") + " s of sliding after each";
  out.push_back(hold);

  ProposedTest wider{"wider_speeds", "", present};
  wider.runs.speeds_m_per_s = {speeds_m_per_s.front() / 3.0, speeds_m_per_s.back() * 3.0};
  wider.description = "runs at " + numerics::fmt(wider.runs.speeds_m_per_s.front(), "%.3g") + " and " +
                      numerics::fmt(wider.runs.speeds_m_per_s.back(), "%.3g") + " m/s, a factor 3 beyond the present " + speeds_text(speeds_m_per_s);
  out.push_back(wider);

  ProposedTest stiffer{"stiffer_spring", "the present speeds with a spring twice as stiff", present};
  stiffer.stiffness_factor = 2.0;
  out.push_back(stiffer);

  ProposedTest heavier{"heavier_load", "the present speeds at twice the normal load", present};
  heavier.load_factor = kHeavierLoadFactor;
  out.push_back(heavier);
  return out;
}

TestRecord::TestRecord(const ProposedTest& t, const rig::RigParameters& rig_a, const rig::FrictionModel& a, std::uint64_t seed)
    : test_(t), seed_(seed), comparison_(synthesize_bundle(t.rig_for(rig_a), a, t.runs, seed), t.rig_for(rig_a)) {
  const std::vector<Item>& items = comparison_.items();
  if (items.empty()) throw std::invalid_argument("proposed test " + t.name + ": its record gives no item to compare");
  predicted_a_ = comparison_.predict(t.rig_for(rig_a), a, seed);
  // The floor: what the record's noise leaves, or what the record's own model leaves on it when
  // that is more — the analysis' reproducibility. A constant-speed run's model predicts its own
  // record to a fifth of the noise floor or better; a slide-hold-slide on a stick-slipping rig does
  // not (its steady levels are window means of a stick-slip whose phase the restart after each
  // hold sets: a Coulomb model's own record is missed by about one floor).
  const std::vector<bool> all(items.size(), true);
  floor_ = std::max(breakdown(items, comparison_.relative_noise(), all).gap, breakdown(items, comparison_.residuals(predicted_a_), all).gap);
}

Separation TestRecord::against(const rig::RigParameters& rig_b, const rig::FrictionModel& b) const {
  const std::vector<Item>& items = comparison_.items();
  const std::vector<double>& pa = predicted_a_;
  const std::vector<double> pb = comparison_.predict(test_.rig_for(rig_b), b, seed_);
  // The two predictions against each other in the record's units: the record's noise is in
  // neither. A feature one model shows and the other lacks counts 1, as a missing feature does in
  // any gap.
  std::vector<double> d(items.size(), 0.0);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (std::isnan(pa[i]) != std::isnan(pb[i])) d[i] = 1.0;
    else if (!std::isnan(pa[i])) d[i] = (pb[i] - pa[i]) / comparison_.scale(items[i].observable);
  }
  Separation s;
  s.test = test_.name;
  s.description = test_.description;
  s.items = static_cast<int>(items.size());
  s.gap = breakdown(items, d, std::vector<bool>(items.size(), true)).gap;
  s.noise_floor = floor_;
  return s;
}

}  // namespace tribo::gap
