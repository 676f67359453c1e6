// The thesis' chapter-V observations (shared/data/thesis/observations.csv) beside what a simulated
// thesis rig gives: one row per observation with the thesis value, tribo's value, the tolerance the
// verdict uses and the verdict. Quantities come from the rig runs at the thesis' figure speeds and,
// for a homogenised law, from its steady sliding (the Stribeck curve and the film's settling).
#pragma once

#include <string>
#include <vector>

#include "rig/friction_law.h"
#include "rig/homogenised_law.h"
#include "rig/parameters.h"
#include "rig/sweep.h"

namespace tribo::cli {

constexpr double kInch_m = 0.0254;

// Driven speeds of the thesis' figures: stick-slip at 2.8e-2 in/s (Fig 5.2.1), multi-cycle slip slower
// than that (Fig 5.2.2: its caption's 0.11 in/s contradicts its text; tribo runs it at 1e-4 in/s) and
// the quasi-harmonic oscillation at 5.3 in/s (Fig 5.2.8).
struct ThesisFigureRuns {
  rig::SweepPoint stick_slip;    // 2.8e-2 in/s
  rig::SweepPoint multi_cycle;   // 1e-4 in/s
  rig::SweepPoint quasi_harmonic;  // 5.3 in/s
};
constexpr double kStickSlipSpeed_m_per_s = 2.8e-2 * kInch_m;
constexpr double kMultiCycleSpeed_m_per_s = 1e-4 * kInch_m;
constexpr double kQuasiHarmonicSpeed_m_per_s = 5.3 * kInch_m;

struct ComparisonRow {
  std::string observation;   // what is compared
  std::string source;        // where the thesis states it
  std::string thesis;        // the thesis' value ("0.26", "stick_slip", "slip distance")
  std::string tribo;         // tribo's value, "" when this law cannot give it
  std::string tolerance;     // what "agrees" means for this row
  std::string verdict;       // agrees | off by ±x % | miss | not evaluated
  std::string note;          // how tribo's value was obtained
};

// `law` is the rig's law; `homogenised` (may be null) its homogenised base, which adds the rows that
// need steady sliding: the speed of the friction maximum and the transient's decay variable. The
// stable slip's μ at zero relative velocity is read off the multi-cycle run's reversals (any law).
std::vector<ComparisonRow> compare_with_thesis(const rig::RigParameters& rig, const rig::FrictionLaw& law,
                                               const rig::HomogenisedBase* homogenised, const ThesisFigureRuns& runs);

// μs of the law at load rate φ̇ with the contact at rest (the law's initial state): static limit / W.
double static_coefficient_at_rest(const rig::FrictionLaw& law, double normal_load_N, double load_rate_per_s);

// How many rows say "agrees".
int agreeing(const std::vector<ComparisonRow>& rows);

// Verdict of a value against a thesis number: "agrees" when |tribo/thesis − 1| ≤ relative_tolerance,
// else "off by +x %" (or "−x %"); "not evaluated" for a non-finite value.
std::string numeric_verdict(double tribo, double thesis, double relative_tolerance);

}  // namespace tribo::cli
