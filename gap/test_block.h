// The reported shrink on a separate test block (issue 15). The diagnosis fits on its train blocks
// and chooses the verdict on its held-out blocks, so the held-out shrink it reports is the one
// that won a contest on those very blocks: a winner's number, optimistic by however much luck
// the choice absorbed. A test block is data neither the fits nor the choice saw — other runs of
// the same machine and specimen (in the selftest: the same truth at driven speeds between the
// diagnosed ones, with fresh noise). On it the calibrated baseline and the verdict's candidate,
// as fitted, predict every item, and the shrink is 1 − gap_after / gap_before over all its items.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/diagnosis.h"
#include "rig/parameters.h"

namespace tribo::gap {

struct TestBlockGap {
  int items = 0;
  double gap_before = 0.0;   // the calibrated baseline's gap over all the test bundle's items
  double gap_after = 0.0;    // the verdict candidate's (= gap_before for "none" and "unexplained")
  double noise_floor = 0.0;  // the gap of the test items' own standard errors (Item::noise)
  // The gap of each candidate named beside the verdict (Verdict::beside), by name: on a test the
  // diagnosis proposed (discriminate.h), the one nearest the record is the one the test decides for.
  std::map<std::string, double> gap_beside;
  // What the test decides among the verdict and those named beside it. One is ruled out when it
  // misses the record by kDecidingFloors noise floors (discriminate.h) more than the nearest does,
  // unless its mechanism is alike at constant speed to the nearest's and the test cannot part such
  // mechanisms (no hold, no velocity step, no normal load kHeavierLoadFactor from the diagnosed
  // one's). `standing`: the rest, nearest first; `decided_for` the one left when one is; the verdict
  // after the test is the verdict while it stands, else the nearest. All empty when nothing was
  // named beside the verdict (or there is no verdict's candidate); `decision_floors` the margin of
  // the nearest ruled out over the nearest, in floors (NaN when none is ruled out).
  std::vector<std::string> standing, ruled_out;
  std::string decided_for, verdict_after;
  double decision_floors = 0.0;
  double shrink() const { return gap_before > 0.0 ? 1.0 - gap_after / gap_before : 0.0; }
};

// `model_rig` as for diagnose(): the model's rig with the test bundle's [rig] keys applied (the
// comparison takes the normal load and what the bundle leaves out from it); the predictions use
// the rig the diagnosis calibrated. A test run on a changed rig (a stiffer spring, another load)
// gives `diagnosed_rig`, the model's rig with the diagnosed bundle's keys applied: each calibrated
// rig constant is then scaled by the test's stated value over the diagnosed one's. Throws
// std::invalid_argument when the test bundle gives no item to compare.
TestBlockGap test_block_gap(const ExperimentBundle& test, const rig::RigParameters& model_rig, const Diagnosis& d,
                            std::uint64_t seed, const std::optional<rig::RigParameters>& diagnosed_rig = std::nullopt);

}  // namespace tribo::gap
