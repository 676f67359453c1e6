// Which further test would tell apart two models the present data cannot (verdict.h
// indistinguishable: earning candidates neither of which has decisive held-out evidence over the
// other). Each proposed test is simulated with the first model as the truth (synthesize.h: the
// rig's simulator, its instrument, sensor noise), analysed by the same comparison as any bundle
// (compare.h), and predicted with both models as fitted; the separation is the gap between the
// two predictions over the test's items, in units of that test's own floor: the gap its items'
// standard errors leave (as for the held-out data), or the gap the first model leaves on its own
// record when that is more (the analysis' reproducibility, which a slide-hold-slide on a
// stick-slipping rig lacks). A separation of a few floors is a test that decides; one below a
// floor is a test the two models pass alike.
//
// The tests an experimentalist can run on the same pin-on-disc rig without new specimens:
//   slide_hold_slide   slide at the middle driven speed, hold 1, 3, 10 s, slide after each — static
//                      friction that grows with time at rest (a squeeze film, contact ageing) heals
//                      in a hold; one that reads the load rate at slip (thesis (3.1.24)) does not
//   wider_speeds       the driven speeds of the present runs extended by a factor 3 each way —
//                      forms that agree inside the measured range part outside it
//   stiffer_spring     the present speeds with the spring twice as stiff: the load rate at slip
//                      doubles at each speed, the natural period shortens by √2
//   heavier_load       the present speeds at twice the normal load: films that carry a fixed
//                      force or follow W with a time constant separate from solid friction ∝ W
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gap/compare.h"
#include "gap/diagnosis_types.h"
#include "gap/synthesize.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

struct ProposedTest {
  std::string name;         // slide_hold_slide, wider_speeds, stiffer_spring, heavier_load
  std::string description;  // what to run, in the lab's words
  SyntheticOptions runs;    // speeds, durations, holds
  double stiffness_factor = 1.0, load_factor = 1.0;  // on the rig of each model
  rig::RigParameters rig_for(rig::RigParameters rig) const;  // a rig with the factors applied
};

// The four tests around the present constant-speed runs (their driven speeds, each `duration_s`
// long), at a friction-sensor noise of `noise_fraction` of μk W.
std::vector<ProposedTest> proposed_tests(const std::vector<double>& speeds_m_per_s, double duration_s, double noise_fraction);

// The load factor of the heavier_load test: two records this far apart in normal load part the
// mechanisms a squeeze film and the junction locus share at one load (rig::EffectInfo::
// alike_at_constant_speed).
inline constexpr double kHeavierLoadFactor = 2.0;

// Whether a bundle holds what parts alike mechanisms (rig::EffectInfo::alike_at_constant_speed): a
// run with a drive history (a hold, a velocity step) or traces whose normal_stress_Pa spans a factor
// kHeavierLoadFactor. A pin-on-disc bundle of constant-speed runs at its one normal_load_N does not.
bool parts_alike_mechanisms(const ExperimentBundle& b);

// Whether proposed test `test` can decide between the verdict `v` and `other`, a candidate named
// beside it (Verdict::beside): any test for one the held-out data do not tell apart; for an alike
// mechanism only slide_hold_slide and heavier_load — the other two part the two fitted forms, not
// the mechanisms (a stiffer spring shortens the stick time as a faster drive does).
bool can_decide(const Verdict& v, const std::string& other, const std::string& test);

// A separation that decides: two floors, as a signal is visible at two (selftest.h kVisibleSignalFloors).
inline constexpr double kDecidingFloors = 2.0;

struct Separation {
  std::string test, description;
  int items = 0;
  double gap = 0.0;          // between the two models' predictions, gap units of the test's items
  double noise_floor = 0.0;  // the test's own floor (above; 0: its items carry no noise and its model meets its record)
  double floors() const;     // gap / noise_floor (NaN without a floor)
};

// Test t recorded once from model a (on its fitted rig, scaled by the test's factors), analysed,
// and a's prediction of it with the floor they give; `against` then separates any model b from a
// on that record. Throws std::invalid_argument when the test's record gives no item to compare.
class TestRecord {
 public:
  TestRecord(const ProposedTest& t, const rig::RigParameters& rig_a, const rig::FrictionModel& a, std::uint64_t seed);
  // The separation of model b (on its own fitted rig, scaled as a's) from a.
  Separation against(const rig::RigParameters& rig_b, const rig::FrictionModel& b) const;

 private:
  ProposedTest test_;
  std::uint64_t seed_;
  Comparison comparison_;
  std::vector<double> predicted_a_;
  double floor_ = 0.0;
};

}  // namespace tribo::gap
