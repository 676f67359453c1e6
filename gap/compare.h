// Like-with-like comparison of a bundle with a model (DESIGN §7).
//
// The measured side is analysed once into *items*: one number each, with the observable it
// belongs to, where it lies (speed, cycle phase, slip after a step) and the split unit (the run or
// static point it comes from). The model side is simulated under the same drive (a constant
// driven speed, or the measured drive history for velocity steps), measured through the same
// instrument model and analysed by the same code with the same windows and bins, so every item
// has a simulated counterpart.
//
// Observables:
//   mu_peak            mean μ at the friction maxima of a run (breakaway, static friction)
//   mu_trough          mean μ at the friction minima (end of slip)
//   slip_drop          μ_peak − μ(t_peak + jΔ), j = 1..4: the friction after slip onset, Δ = a
//                      fifth of the measured peak-to-trough time (so no point lands on the
//                      re-attachment jump that ends the slip)
//   rise_time_s        time from a minimum to the next maximum (the stick time of stick-slip)
//   period_s           mean time between maxima
//   peak_to_peak_m     range of the slider displacement x between its 5th and 95th percentiles in time
//   mean_mu            time-averaged μ
//   mu_s_vs_load_rate  μs at the load rate φ̇ of static_friction.csv: the mean breakaway of stick-slip
//                      at v = φ̇ W / k after the start-up (a row is a stick event, DESIGN §7)
//   regime_mismatch    0 when the simulated regime is the measured one, else 1 (regimes.csv)
//   amplitude_m, frequency_rad_per_s  from regimes.csv
//   steady_mu          μ over the last 30 % of each drive segment (velocity steps)
//   steady_scatter     the scatter of μ about its trend line in that window, less the record's
//                      white noise: ≈ 0 for steady sliding, the oscillation for a model that
//                      stick-slips or rings there (scaled by max(RMS of the measured scatters,
//                      the record's noise), so such a model cannot pass for a steady record); a
//                      ceiling: only a simulated scatter above the measured one is a residual
//   mu_after_step      μ − μ_before-step, averaged over bins of load-point displacement after a
//                      step between two slides (bins finer near the step)
//   peak_after_hold    the peak of μ on re-sliding after a hold (slide-hold-slide) above the steady
//                      μ before the hold: static friction grown with the hold time
// The bundle's kind selects the analysis: "pin_on_disc" runs at a constant driven speed each;
// "velocity_step" and "slide_hold_slide" read the drive record (v_drive_m_per_s) into segments —
// a jump above max(1e-3 v_max, 6 σ of the record's high-pass noise) starts one, a segment of fewer
// than 20 samples joins the one before, a speed below the threshold is a hold — and simulate the
// history with the contact re-locked at every step — for slide-hold-slide as one run, the law's
// state (the contact's age) carried through the holds.
// Noise: a constant-speed run's analysis window is also cut into four contiguous blocks, each
// analysed as a run of its own; an item's noise is the blocks' standard deviation / √blocks. A
// step bin's is the record's high-pass noise / √(samples in the bin); a steady level's (and a
// steady scatter's) the scatter of the four sub-windows' values / 2.
// Runs use the part of the trace after the start-up window (rig::analysis_start_s), with μ
// averaged over ±2 measured sample spacings in time; extrema are the maxima and minima of that
// smoothed μ, located between samples, and an extremum cut by the window's start is left out.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::gap {

struct Item {
  std::string observable;
  std::string where;    // human label: "v = 5.0e-03 m/s", "0-12 um after step 1", ...
  std::string phase;    // stick, slip onset, slip transient, slip end, cycle, stable slip, static
  std::string regime;   // measured regime of the run the item comes from
  std::string speed_class;  // "low v" or "high v" (below / above the median driven speed)
  double v_m_per_s = 0.0;   // driven speed the item was measured at
  int unit = 0;         // split block: one driven speed, a drive segment's level or three contiguous
                        // bins after a step; items of one unit go to the same split
  double measured = 0.0;
  // Standard error of `measured` read off the data itself (0 where the data cannot tell): the
  // scatter of the run's blocks analysed as repeats, or the record's high-pass noise averaged
  // over the samples of a bin. It holds whatever a deterministic model cannot follow — sensor
  // noise, cycle-to-cycle scatter, a track whose friction changes along its length.
  double noise = 0.0;
  int plan = 0;         // the simulation that produces it
  std::string key;      // its name in that simulation's analysis
  double hold_s = 0.0;  // peak_after_hold: the hold before the peak (0 for every other observable)
};

// One simulation that reproduces one measurement.
struct RunPlan {
  enum class Kind { constant_speed, drive_history, static_point, regime_point } kind = Kind::constant_speed;
  std::string label;
  std::string regime;                                     // measured regime (regime points)
  double v_m_per_s = 0.0;
  double duration_s = 0.0;
  std::vector<double> step_times_s, step_speeds_m_per_s;  // drive history (velocity steps)
  double sample_spacing_s = 0.0;                          // measured median spacing
  // A constant-speed record sampled densely in slip and sparsely in stick (0: uniform): the
  // simulation is read the same way (compare.cpp, sampled_as_recorded).
  double stick_spacing_s = 0.0, slip_spacing_s = 0.0;
  double slip_step_s = 0.0;                               // Δ of slip_drop (from the measured run)
  // The record has the slider's displacement: whether a constant-speed run oscillates is read off
  // it (rig::classify_regime), for the record and for its simulation alike (trace_features.h
  // analyse_constant_speed); else off μ's span.
  bool regime_from_x = false;
  // A constant-speed run is simulated this much past the measured record, its window starting
  // where the measured one does, so that it holds at least four of the measured cycles: a feature
  // the measured window shows in one or two cycles (a slow run's period) would otherwise be there
  // or not in the simulation as its cycles' phase moves past the window's end — a cliff in the
  // fit's cost, where the item has no prediction (validation seed 14010: the instrument's search
  // lost its way at the slowest run's period). A limit cycle reads the same in a longer window.
  double simulated_extra_s = 0.0;
  std::vector<std::vector<double>> step_bin_edges_m;      // per step: displacement bin edges
  std::vector<double> sample_times_s;                     // drive history: measured times − first
  // Drive history as one run with the law's state carried across steps (slide-hold-slide: the
  // contact ages through a hold); else each segment restarts the law (velocity steps, see
  // compare.cpp: the one-run form changed the velocity-step fits and is not yet understood).
  bool carry_law_state = false;
  bool spring_force_channel = false;  // the bundle's friction_channel: the simulation reads k x alone
};

struct SimulatedRun {
  std::string label;
  std::vector<double> t_s, friction_N, mu;  // as measured by the instrument model, over the record's span
};

// Friction after a velocity step up, read off μ − μ_before (3-sample running mean) against the
// load-point travel X since the step: right after the step the contact re-locks and the load
// point loads it elastically, dF/dX = k, until it slips at the peak; then friction decays to the
// new steady level.
struct StepResponse {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double peak_rise = kNaN;                   // Δμ_peak (first quarter of the record after the step)
  double peak_travel_m = kNaN;               // ΔX_peak, load-point travel to the peak
  double loading_stiffness_N_per_m = kNaN;   // k ≈ W Δμ_peak / ΔX_peak
  // Travel from the peak until the excess over the new steady level has fallen to 1/e of its
  // peak value: the slip distance of the decay (the rig slides with the load point by then).
  double decay_distance_m = kNaN;
  // The new steady level less the old (the steady_mu of each segment's last 30 %) and the step's
  // speed ratio V2/V1: a stable level that falls by β per e-fold of speed (Ruina's slip law,
  // β = b − a) changes by −β ln(V2/V1).
  double steady_change = kNaN;
  double speed_ratio = kNaN;
  // That fall per e-fold of speed, β = −Δμ_ss / ln(V2/V1) (NaN without a step up).
  double stable_fall_per_efold() const { return speed_ratio > 1.0 ? -steady_change / std::log(speed_ratio) : kNaN; }
};

class Comparison {
 public:
  // `rig` supplies what the bundle leaves out (normal load for μ = F/W, ...). Throws
  // std::invalid_argument when the bundle yields no usable item.
  Comparison(const ExperimentBundle& bundle, const rig::RigParameters& rig);

  const std::vector<Item>& items() const { return items_; }
  int units() const { return units_; }

  // Simulated value of every item (NaN where the simulation does not show the feature, e.g. a
  // run that stays in steady sliding has no friction maxima). Thread-safe. With `items_needed`,
  // only the simulations that produce those items run (the others stay NaN).
  std::vector<double> predict(const rig::RigParameters& rig, const rig::FrictionModel& model, std::uint64_t seed,
                              std::vector<SimulatedRun>* traces = nullptr, const std::vector<bool>* items_needed = nullptr) const;

  // Dimensionless residuals (sim − measured)/scale(observable); 1 where the simulation is NaN.
  std::vector<double> residuals(const std::vector<double>& simulated) const;
  double scale(const std::string& observable) const;
  // Each item's standard error in the gap's units, Item::noise / scale(observable) (0 where the
  // data cannot tell): the residuals of the noise alone, whose gap is the noise floor.
  std::vector<double> relative_noise() const;

  // The measured response to the first velocity step up (all NaN without one): starts for the
  // fits of a velocity-step test.
  const StepResponse& step_response() const { return step_response_; }

  // CVODE's relative tolerance (and displacement tolerance fraction) for the predictions, matched
  // to the data: kToleranceBelowNoise times the median relative noise of the items
  // (Item::noise / scale of its observable, in the gap's units), within [kFinestTolerance,
  // kCoarsestTolerance] — the simulation's own error orders of magnitude below what the data
  // resolve, rather than at the rig's default 1e-10 (most of a fit's time is CVODE stepping). The
  // median, not the smallest: a channel recorded without noise (a synthetic displacement) must not
  // set the tolerance for all. Data that cannot tell their noise get kFinestTolerance.
  static constexpr double kToleranceBelowNoise = 1e-3, kFinestTolerance = 1e-10, kCoarsestTolerance = 1e-6;
  double integration_tolerance() const { return tolerance_; }
  void set_integration_tolerance(double relative_tolerance);  // e.g. a reference at kFinestTolerance
  double median_relative_noise() const;                        // 0 when no item carries a noise

  // Events a prediction of `duration_s` may have before it stops as chattering (no prediction):
  // kEventsPerPeriod per natural period of `rig`, at least kFewestEvents. Stick-slip needs two
  // events a cycle, and a cycle is longer than a natural period. What it stops: a Zeno velocity
  // match, where a law that drops steeply within µm/s of U = 0 (hydrodynamic lift with a small U½)
  // is integrated at a tolerance coarser than that speed and every slip re-attaches at once; at
  // the rig's default budget of millions of events one such prediction cost seconds of a fit.
  static constexpr double kEventsPerPeriod = 20.0;
  static constexpr long kFewestEvents = 1000;
  static long event_budget(const rig::RigParameters& rig, double duration_s);
  static double event_rate_per_s(const rig::RigParameters& rig);  // kEventsPerPeriod per natural period
  // A prediction's event limits: event_budget over options.duration_s, and the same rate judged
  // as the run spends it (rig::SimulationOptions::max_event_rate_per_s, after kFewestEvents), so
  // that a run which chatters from some instant on stops there instead of after the whole budget.
  static void limit_events(rig::SimulationOptions& options, const rig::RigParameters& rig);

 private:
  std::vector<Item> items_;
  std::vector<RunPlan> plans_;
  std::vector<std::pair<std::string, double>> scales_;
  int units_ = 0;
  StepResponse step_response_;
  double tolerance_ = kFinestTolerance;
};

// A static point's simulated reading (DESIGN §7): the mean of the breakaway readings (t_s, μ) at
// or after `window_start_s`, or of the later half when none is that late (the run stopped at its
// event limit first), or the last one when the slider slid steadily after it. A run that stopped
// short of its duration for any other reason than `max_events` — the integrator failed — has no
// reading (nullopt): what came before the failure is not a prediction.
std::optional<double> static_point_reading(const std::vector<std::pair<double, double>>& breakaways, const rig::SimulationSummary& run,
                                           long max_events, double window_start_s);

}  // namespace tribo::gap
