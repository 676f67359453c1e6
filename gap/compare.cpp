#include "gap/compare.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <exception>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "gap/trace_features.h"
#include "numerics/format.h"
#include "numerics/median.h"
#include "numerics/parallel.h"
#include "rig/drive.h"
#include "rig/instrument.h"
#include "rig/observables.h"

namespace tribo::gap {
namespace {

using trace::analyse_constant_speed;
using trace::analyse_drive_history;
using trace::block_noise;
using trace::drive_segments;
using trace::DriveSegments;
using trace::Features;
using trace::high_pass_noise;
using trace::interp;
using trace::interp_to_end;
using trace::kMinSegmentSamples;
using trace::kSlipDropPoints;
using trace::kStepBins;
using trace::Signal;
using trace::steady_mu;
using trace::three_sample_mean;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Bins after a step are split in contiguous blocks of this many (issue 15): a held-out bin must not
// sit between two trained neighbours, or any curve through the trained ones passes it.
constexpr int kBinsPerBlock = 3;
constexpr int kSamplesPerPeriod = 50;  // output density of simulated constant-speed runs
constexpr double kSimulatedCycles = 4.0;  // cycles a simulated constant-speed window holds at least (RunPlan::simulated_extra_s)
// ... and at most about a quarter of this many events later (a stick-slip cycle is a breakaway and
// a re-attachment): a constant-speed simulation ends at this event, its window the second half of
// what it simulated (predict_plan). A deterministic rig's limit cycle says in 50 cycles what it says
// in 750 — the paper record at 42 µm/s and k = 2254 N/m (375 s, a 0.5-s simulated cycle) was two
// thirds of every prediction of that bundle.
constexpr long kWindowEvents = 200;
// A constant-speed run that slides without an event ends once two consecutive windows of this many
// natural periods agree in mean friction to 1e-4 W (rig::SimulationOptions::settle_window_periods):
// steady sliding gives no event to count, and the paper record's 375-s run at 42 µm/s, sliding
// steadily under a candidate, took 0.6 s (1.2 M samples) against 6 ms stick-slipping.
constexpr double kSettleWindowPeriods = 250.0;
constexpr long kStaticPointEvents = 40;  // a static point's run stops after this many events (20 stick-slip cycles or more)
constexpr double kStaticPointCycles_s = 10.0;  // and simulates at most this long after loading the contact
constexpr const char* kFrictionLevel = "friction level";

bool is_friction_level(const std::string& observable) {
  return observable == "mu_peak" || observable == "mu_trough" || observable == "mean_mu" || observable == "mu_s_vs_load_rate" ||
         observable == "steady_mu";
}

std::string phase_of(const std::string& observable, int index, const std::string& regime) {
  // A quasi-harmonic run never sticks (thesis §5.2): the extrema of its friction are the swing
  // about μk during continuous slip, not breakaway and re-attachment, so every feature of its
  // trace belongs to stable slip. regimes.csv's items (the regime, the oscillation's amplitude and
  // frequency) describe the whole cycle in every regime.
  const bool regime_point = observable == "regime_mismatch" || observable == "amplitude_m" || observable == "frequency_rad_per_s";
  if (regime == "quasi_harmonic" && !regime_point) return "stable slip";
  if (observable == "mu_peak" || observable == "mu_s_vs_load_rate") return "slip onset";
  if (observable == "slip_drop") return index <= 2 ? "slip transient" : "late slip";
  if (observable == "mu_trough") return "slip end";
  if (observable == "rise_time_s") return "stick";
  if (observable == "steady_mu" || observable == "steady_scatter") return "stable slip";
  if (observable == "peak_after_hold") return "slip onset after hold";
  if (observable == "mu_after_step") return index < kStepBins / 2 ? "slip transient after step" : "stable slip after step";
  if (observable == "mean_mu" && regime == "steady_sliding") return "stable slip";
  return "cycle";
}

struct Simulated {
  std::vector<rig::Sample> samples;
  std::vector<rig::Event> events;
  std::vector<double> friction_N;
  rig::SimulationSummary summary;
};

// The friction channel read as the plan's record was (RunPlan::spring_force_channel).
Simulated run_simulation(const rig::RigParameters& rig, const rig::Drive& drive, const rig::FrictionLaw& law,
                         const rig::FrictionModel& model, std::uint64_t seed, const rig::SimulationOptions& options,
                         const RunPlan& plan) {
  Simulated s;
  rig::SimulationResult r = rig::simulate(rig, drive, law, options);
  s.summary = r.summary;
  s.samples = std::move(r.samples);
  s.events = std::move(r.events);
  rig::InstrumentModel instrument = rig::instrument_from(model, seed);
  instrument.inertia_corrected = !plan.spring_force_channel;
  if (!s.samples.empty()) s.friction_N = rig::measure_friction_N(rig, instrument, s.samples);
  return s;
}

// The response to the first velocity step up (see StepResponse).
StepResponse read_step_response(const Signal& s, const RunPlan& plan, double W) {
  StepResponse out;
  const double t_first = s.t.front();
  for (std::size_t k = 1; k < plan.step_times_s.size(); ++k) {
    if (!(plan.step_speeds_m_per_s[k] > plan.step_speeds_m_per_s[k - 1] && plan.step_speeds_m_per_s[k - 1] > 0.0)) continue;
    const double a = t_first + plan.step_times_s[k - 1], t_step = t_first + plan.step_times_s[k];
    const double t_end = k + 1 < plan.step_times_s.size() ? t_first + plan.step_times_s[k + 1] : s.t.back();
    const double before = steady_mu(s, a, t_step);
    const double after = steady_mu(s, t_step, t_end) - before;
    const double x_step = interp(s.t, s.x_drive, t_step);
    const double t_search = t_step + 0.25 * (t_end - t_step);
    auto rise = [&](std::size_t i) { return three_sample_mean(s.mu, i) - before; };
    double best = 0.0, x_best = 0.0;
    std::size_t i_best = 0;
    for (std::size_t i = 1; i + 1 < s.t.size(); ++i) {
      if (s.t[i] <= t_step || s.t[i] > t_search) continue;
      if (rise(i) > best) best = rise(i), x_best = s.x_drive[i] - x_step, i_best = i;
    }
    if (!(best > 0.0 && x_best > 0.0)) continue;
    out.peak_rise = best;
    out.peak_travel_m = x_best;
    out.steady_change = after;
    out.speed_ratio = plan.step_speeds_m_per_s[k] / plan.step_speeds_m_per_s[k - 1];
    out.loading_stiffness_N_per_m = W * best / x_best;
    for (std::size_t i = i_best + 1; i + 1 < s.t.size() && s.t[i] <= t_end; ++i)
      if (rise(i) - after <= (best - after) / std::exp(1.0)) {
        out.decay_distance_m = s.x_drive[i] - x_step - x_best;
        break;
      }
    return out;
  }
  return out;
}

// A velocity step as the rig sees it: the first segment starts in steady sliding; at every step
// the contact re-locks and the slider is carried by the surface from where it is until the
// spring force reaches the static limit (it breaks away, re-arming slip-history effects). This
// stands for the finite machine stiffness of a velocity-step apparatus, where the load point
// speeds up and the stress rises elastically before the interface slips faster.
Simulated simulate_steps(const rig::RigParameters& rig, const RunPlan& plan, const rig::FrictionLaw& law, const rig::FrictionModel& model,
                         std::uint64_t seed, rig::SimulationOptions options) {
  Simulated all;
  all.summary.completed = true;
  double t_offset = 0.0, x_drive_offset = 0.0, x_end = 0.0;
  const std::vector<double> outputs = options.output_times_s;  // of the whole history
  for (std::size_t k = 0; k < plan.step_times_s.size(); ++k) {
    const double t_end = k + 1 < plan.step_times_s.size() ? plan.step_times_s[k + 1] : plan.duration_s;
    options.duration_s = t_end - plan.step_times_s[k];
    options.output_times_s.clear();
    for (double t : outputs)
      if (t >= plan.step_times_s[k] && t <= t_end) options.output_times_s.push_back(t - plan.step_times_s[k]);
    options.start_in_steady_sliding = k == 0;
    options.initial_displacement_m = x_end;
    const Simulated seg = run_simulation(rig, rig::Drive::constant(plan.step_speeds_m_per_s[k]), law, model, seed + k, options, plan);
    if (!seg.summary.completed || seg.samples.empty()) {
      all.summary = seg.summary;
      all.summary.completed = false;
      return all;
    }
    for (std::size_t i = 0; i < seg.samples.size(); ++i) {
      rig::Sample s = seg.samples[i];
      s.t_s += t_offset;
      s.drive_displacement_m += x_drive_offset;
      all.samples.push_back(s);
      all.friction_N.push_back(seg.friction_N[i]);
    }
    t_offset += options.duration_s;
    x_drive_offset = all.samples.back().drive_displacement_m;
    x_end = seg.samples.back().x_m;
  }
  return all;
}

// A slide-hold-slide history: the same re-lock at every step, but as one run under the measured
// drive (rig::SimulationOptions::relock_at_drive_steps), so the friction law's state carries
// across the steps — the contact's age grows through a hold, which is what the test measures.
Simulated simulate_history(const rig::RigParameters& rig, const RunPlan& plan, const rig::FrictionLaw& law, const rig::FrictionModel& model,
                         std::uint64_t seed, rig::SimulationOptions options) {
  options.duration_s = plan.duration_s;
  options.start_in_steady_sliding = true;
  options.relock_at_drive_steps = true;
  return run_simulation(rig, rig::Drive::steps(plan.step_times_s, plan.step_speeds_m_per_s), law, model, seed, options, plan);
}

// How much longer than the measured record a constant-speed run is simulated (RunPlan): enough
// for kSimulatedCycles of the measured cycle (its period, else rise plus fall time) in the
// analysed window; 0 for a record without one, or with that many already.
double simulated_extra_s(const Features& measured, double slip_step_s, double duration_s) {
  const auto value = [&](const char* key) { return measured.count(key) ? measured.at(key) : kNaN; };
  double cycle_s = value("period_s");
  if (!std::isfinite(cycle_s)) cycle_s = value("rise_time_s") + slip_step_s * (kSlipDropPoints + 1);
  if (!(cycle_s > 0.0)) return 0.0;
  return std::max(0.0, kSimulatedCycles * cycle_s - (1.0 - rig::kStartupFraction) * duration_s);
}

double median_spacing(const std::vector<double>& t) {
  std::vector<double> d;
  for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
  return numerics::median(std::move(d));
}

// How a constant-speed record was sampled: uniformly, or (a logger that samples on change, an
// event-driven simulator's output) densely while the slider slips and sparsely while it sticks.
// The spacing's 10th and 90th percentiles tell them apart: the sparse spacing at least
// kAdaptiveSpacingRatio times the dense one is a policy, not jitter (a uniform record is left as
// it is, read at its median spacing).
constexpr double kAdaptiveSpacingRatio = 4.0;
void read_sampling_policy(const std::vector<double>& t, RunPlan& plan) {
  std::vector<double> d;
  for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
  if (d.size() < 10) return;
  std::sort(d.begin(), d.end());
  const double dense = d[d.size() / 10], sparse = d[d.size() * 9 / 10];
  if (!(sparse > kAdaptiveSpacingRatio * dense)) return;
  plan.slip_spacing_s = dense;
  plan.stick_spacing_s = sparse;
  // Read both sides smoothed over the sparse spacing: where the breakaway falls between two stick
  // samples changes from cycle to cycle with the stick's own scatter, and a reading finer than
  // the spacing would compare those phases rather than the friction.
  plan.sample_spacing_s = sparse;
}

// A simulated run read as the record was sampled (RunPlan::slip_spacing_s): a sample every
// stick spacing while the slider sticks, from the re-attachment on, and every slip spacing while
// it slips, the first one slip spacing after the breakaway. A sparse record never holds the
// breakaway or the re-attachment themselves — its peak is the last stick sample before the
// breakaway, its trough the first one a stick spacing after the slip — and the simulation, read
// densely, would: at 7 mm/s on a 20-ms stick spacing that is 0.015 in μ at every peak and trough.
// Where the breakaway falls between two stick samples changes from cycle to cycle in a record
// (its stick times scatter); a deterministic simulation's would not, and would hold one phase at
// every cycle. So the last stick reading of cycle n lies a fraction frac(n φ) of the stick
// spacing before the breakaway (φ the golden ratio: phases spread evenly over the cycles).
Signal sampled_as_recorded(const Signal& s, const std::vector<bool>& slipping, const RunPlan& plan) {
  constexpr double kGolden = 0.6180339887498949;
  Signal out;
  std::size_t i = 0;
  long cycle = 0;
  double forced = kNaN;  // the next instant when it is fixed already (the first slip sample)
  for (double t = s.t.front(); t <= s.t.back();) {
    while (i + 1 < s.t.size() && s.t[i + 1] <= t) ++i;
    // Linear between samples i and i + 1 (s.t[i] ≤ t < s.t[i + 1]), the last value at the end:
    // interp_to_end() without its search, which this walk has done already.
    const bool inside = i + 1 < s.t.size();
    const double w = inside ? (t - s.t[i]) / (s.t[i + 1] - s.t[i]) : 0.0;
    auto at = [&](const std::vector<double>& y) { return inside ? y[i] + w * (y[i + 1] - y[i]) : y.back(); };
    out.t.push_back(t);
    out.mu.push_back(at(s.mu));
    if (!s.x.empty()) out.x.push_back(at(s.x));
    double next = slipping[i] ? t + plan.slip_spacing_s : t + plan.stick_spacing_s;
    if (std::isfinite(forced)) {
      next = forced, forced = kNaN;
    } else if (!slipping[i]) {
      for (std::size_t j = i + 1; j < s.t.size() && s.t[j] < next; ++j)
        if (slipping[j]) {
          ++cycle;
          const double reading = s.t[j] - plan.stick_spacing_s * (cycle * kGolden - std::floor(cycle * kGolden));
          next = s.t[j] + plan.slip_spacing_s;
          if (reading > t) forced = next, next = reading;
          break;
        }
    }
    t = next;
  }
  return out;
}

// The instants a drive history's simulation outputs: the measured ones, and each `lag_s` earlier
// (within the run) where an instrument with that lag reads the state; increasing, no repeats.
std::vector<double> recorder_instants(const std::vector<double>& measured_s, double lag_s) {
  std::vector<double> out = measured_s;
  if (lag_s > 0.0)
    for (double t : measured_s)
      if (t - lag_s > 0.0) out.push_back(t - lag_s);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// The simulation of one plan, analysed as the measured side was (features by key); the trace
// as measured when `trace` is given. Empty for a parameter set the rig rejects (e.g. overdamped):
// its items have no prediction, residual 1.
Features predict_plan(const RunPlan& plan, const rig::RigParameters& rig, const rig::FrictionModel& model, const rig::FrictionLaw& law,
                      std::uint64_t seed, double tolerance, std::optional<SimulatedRun>* trace) {
  Features f;
  const double W = rig.normal_load_N, k = rig.stiffness_N_per_m;
  rig::SimulationOptions options;
  options.relative_tolerance = options.displacement_tolerance_fraction = tolerance;
  try {
    switch (plan.kind) {
      case RunPlan::Kind::constant_speed:
      case RunPlan::Kind::drive_history: {
        const bool history = plan.kind == RunPlan::Kind::drive_history;
        options.duration_s = plan.duration_s + plan.simulated_extra_s;
        Comparison::limit_events(options, rig);
        // A constant-speed run ends at its kWindowEvents-th event or, sliding without an event,
        // where it settles; a trace for the report spans the record, its features read off the
        // same prefix (its run reports where it settled).
        if (!history) {
          if (!trace) options.stop_after_events = kWindowEvents;
          options.settle_window_periods = kSettleWindowPeriods;
          options.stop_when_settled = !trace;
        }
        options.samples_per_period = kSamplesPerPeriod;
        // A drive history is read at the measured instants: the simulation outputs there (and τ
        // earlier, where a lagging instrument reads the acceleration), not on a grid of its natural
        // period — 4 samples per period of a 1e6 N/m machine were 13 times the record's 5850.
        if (history) options.output_times_s = recorder_instants(plan.sample_times_s, rig::instrument_from(model, seed).lag_s);
        options.start_in_steady_sliding = history;
        Simulated sim;
        if (history) {
          sim = plan.carry_law_state ? simulate_history(rig, plan, law, model, seed, options)
                                     : simulate_steps(rig, plan, law, model, seed, options);
        } else {
          sim = run_simulation(rig, rig::Drive::constant(plan.v_m_per_s), law, model, seed, options, plan);
        }
        if (!sim.summary.completed || sim.samples.size() < 3) break;
        // Where the features' simulation ends: at the record's end (and its extra cycles), at the
        // kWindowEvents-th event, or where it settled into steady sliding — a run stopped there
        // has every sample up to it, a trace's run is cut there.
        double t_read = !history && static_cast<long>(sim.events.size()) >= kWindowEvents
                            ? sim.events[static_cast<std::size_t>(kWindowEvents - 1)].t_s
                            : std::numeric_limits<double>::infinity();
        if (std::isfinite(sim.summary.settled_at_s)) t_read = std::min(t_read, sim.summary.settled_at_s);  // never for a history
        Signal s;
        std::vector<bool> slipping;
        for (auto* v : {&s.t, &s.mu, &s.x, &s.x_drive}) v->reserve(sim.samples.size());
        slipping.reserve(sim.samples.size());
        for (std::size_t i = 0; i < sim.samples.size(); ++i) {
          if (!s.t.empty() && !(sim.samples[i].t_s > s.t.back())) continue;
          s.t.push_back(sim.samples[i].t_s);
          s.mu.push_back(sim.friction_N[i] / W);
          s.x.push_back(sim.samples[i].x_m);
          s.x_drive.push_back(sim.samples[i].drive_displacement_m);
          slipping.push_back(sim.samples[i].phase != rig::Phase::stick);
        }
        if (history) {
          // Sampled where the measurement was: a bin near the step holds one or two measured
          // samples, and the simulated bin must average the same instants, not the whole bin.
          Signal at;
          for (double t : plan.sample_times_s) {  // the run ends at the last measured instant
            at.t.push_back(t);
            at.mu.push_back(interp_to_end(s.t, s.mu, t));
            at.x_drive.push_back(interp_to_end(s.t, s.x_drive, t));
          }
          f = analyse_drive_history(at, plan, nullptr);
        } else {
          Signal read = trace ? s : std::move(s);
          std::vector<bool> read_slipping = trace ? slipping : std::move(slipping);
          if (std::isfinite(t_read)) {
            const std::size_t n = static_cast<std::size_t>(std::upper_bound(read.t.begin(), read.t.end(), t_read) - read.t.begin());
            for (auto* v : {&read.t, &read.mu, &read.x, &read.x_drive}) v->resize(n);
            read_slipping.resize(n);
          }
          if (plan.slip_spacing_s > 0.0) {
            read = sampled_as_recorded(read, read_slipping, plan);
            if (trace) s = sampled_as_recorded(s, slipping, plan);
          }
          double step = plan.slip_step_s;
          const double from = rig::analysis_start_s(0.0, std::min(t_read, plan.duration_s));
          std::string x_regime;
          if (plan.regime_from_x)
            x_regime = rig::classify_regime(rig, rig::recorded_regime_evidence(rig, read.t, read.x, plan.v_m_per_s, from));
          f = analyse_constant_speed(read, plan.sample_spacing_s, step, nullptr, from, plan.regime_from_x ? &x_regime : nullptr);
        }
        if (trace) {  // over the record's span (a slow run is simulated past it, RunPlan::simulated_extra_s)
          SimulatedRun run{plan.label, {}, {}, {}};
          for (std::size_t i = 0; i < s.t.size() && s.t[i] <= plan.duration_s; ++i) {
            run.t_s.push_back(s.t[i]);
            run.friction_N.push_back(s.mu[i] * W);
            run.mu.push_back(s.mu[i]);
          }
          *trace = std::move(run);
        }
        break;
      }
      case RunPlan::Kind::static_point: {
        // A static point is read per stick event of stick-slip at the load rate φ̇ = k v / W
        // (DESIGN §7, static_friction.csv), so it is simulated as one: the mean breakaway reading
        // after the start-up, like the traces' windows. The first breakaway from rest is not
        // like for like when the law has memory: a squeeze film built in the slip before it is
        // still there at an in-cycle breakaway, never at the first one.
        const double v = plan.v_m_per_s * W / k;
        options.duration_s = plan.duration_s;
        // A few cycles of breakaways are all it reads: a law that chatters at a velocity match, or
        // many short cycles, end the run at the event limit instead of the budget of a trace.
        options.max_events = std::min<long>(Comparison::event_budget(rig, plan.duration_s), kStaticPointEvents);
        // Only breakaways matter: keep no samples and output as sparsely as allowed.
        options.samples_per_period = 4;  // the rig's minimum
        options.stick_samples_per_run = 10;
        // Read off the same friction channel as the traces.
        const rig::InstrumentModel instrument = rig::instrument_from(model, seed);
        std::vector<std::pair<double, double>> breakaways;  // (t_s, reading)
        rig::SimulationObserver observer;
        observer.on_event = [&](const rig::Event& e) {
          if (e.kind == rig::EventKind::breakaway) breakaways.emplace_back(e.t_s, rig::breakaway_reading(instrument, e.mu, e.load_rate_per_s));
        };
        const rig::SimulationSummary run = rig::simulate(rig, rig::Drive::constant(v), law, options, observer);
        if (const auto mu = static_point_reading(breakaways, run, options.max_events, rig::analysis_start_s(0.0, plan.duration_s)))
          f["mu_s"] = *mu;
        break;
      }
      case RunPlan::Kind::regime_point: {
        const double mu_scale = std::max(model.baseline.mu_s, 0.05);
        options.duration_s = std::clamp(6.0 * mu_scale * W / (k * plan.v_m_per_s) + 1.0, 1.0, 60.0);
        Comparison::limit_events(options, rig);
        const rig::SimulationResult r = rig::simulate(rig, rig::Drive::constant(plan.v_m_per_s), law, options);
        if (!r.summary.completed) break;
        const rig::RunObservables o = rig::summarise(rig, r.samples, r.events, rig::analysis_start_s(0.0, r.summary.end_time_s));
        f["regime_mismatch"] = o.regime == plan.regime ? 0.0 : 1.0;
        f["amplitude_m"] = 0.5 * o.peak_to_peak_m;
        if (std::isfinite(o.period_s) && o.period_s > 0.0) f["frequency_rad_per_s"] = 2.0 * M_PI / o.period_s;
        break;
      }
    }
  } catch (const std::invalid_argument&) {
    return {};  // rejected by the rig: no prediction
  }
  return f;
}

// What a provisional split unit is tied to: a driven speed (a constant-speed run, a static point
// at the speed k v / W gives, a regime point), or nothing but itself (a drive segment's level, a
// peak after a hold, a block of bins after a step).
struct UnitKey {
  double v_m_per_s = kNaN;
  std::string stratum;  // of a unit of its own: the observable it holds
  static UnitKey at_speed(double v) { return {v, {}}; }
  static UnitKey own(const std::string& observable) { return {kNaN, observable}; }
};

// Held-out data must be data the fit has not seen (issue 15): the split units are blocks, and
// even blocks train, odd ones are held out (pipeline.h make_fit_problem). Units at one driven speed (within
// kSameSpeed: a run and the static point read off it) form one block, so a held-out speed is a
// speed nothing was trained at; blocks at speeds come first, in order of speed. The others
// alternate within their observable, in the order the data give them, the first training: a
// drive history interleaves its observables (slide, hold, slide, ...), and numbered in turn a
// slide-hold-slide test put every slide in training and every hold's peak in the held-out half,
// where no fit could learn from a hold (an independent rate-and-state case: `unexplained`).
// Returns each provisional unit's block; the block numbers may skip.
std::vector<int> split_blocks(const std::vector<UnitKey>& keys) {
  constexpr double kSameSpeed = 0.02;
  std::vector<std::size_t> by_speed;
  for (std::size_t u = 0; u < keys.size(); ++u)
    if (std::isfinite(keys[u].v_m_per_s)) by_speed.push_back(u);
  std::stable_sort(by_speed.begin(), by_speed.end(), [&](std::size_t a, std::size_t b) { return keys[a].v_m_per_s < keys[b].v_m_per_s; });
  std::vector<int> block(keys.size(), -1);
  int next = 0;
  double block_v = 0.0;
  for (std::size_t k = 0; k < by_speed.size(); ++k) {
    const double v = keys[by_speed[k]].v_m_per_s;
    if (k == 0 || !(std::abs(v - block_v) <= kSameSpeed * std::max(std::abs(block_v), std::abs(v)))) block_v = v, ++next;
    block[by_speed[k]] = next - 1;
  }
  const int base = next + next % 2;  // even
  std::map<std::string, int> seen;   // units of each stratum so far
  int trained = 0, held = 0;
  for (std::size_t u = 0; u < keys.size(); ++u)
    if (block[u] < 0) block[u] = seen[keys[u].stratum]++ % 2 == 0 ? base + 2 * trained++ : base + 2 * held++ + 1;
  return block;
}

}  // namespace

Comparison::Comparison(const ExperimentBundle& bundle, const rig::RigParameters& rig) {
  // Provisional units, one per measurement the data give (a run, a static point, a regime point,
  // a drive segment's level, a block of bins after a step), merged into split blocks at the end.
  std::vector<UnitKey> unit_keys;
  auto new_unit = [&](const UnitKey& key) {
    unit_keys.push_back(key);
    return static_cast<int>(unit_keys.size()) - 1;
  };
  const double W = bundle.normal_load_N.value_or(rig.normal_load_N);
  double scatter_floor = 0.0;  // largest sample noise of the drive-history records (steady_scatter's scale)
  std::vector<std::size_t> order(bundle.runs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return bundle.runs[a].v_m_per_s < bundle.runs[b].v_m_per_s; });
  auto add = [&](const std::string& observable, int index, const std::string& where, const std::string& regime, double v,
                 int unit, double value, const std::string& key, const Features& noise) {
    Item it;
    it.observable = observable;
    it.where = where;
    it.phase = phase_of(observable, index, regime);
    it.regime = regime;
    it.v_m_per_s = v;
    it.unit = unit;
    it.measured = value;
    if (const auto n = noise.find(key); n != noise.end() && std::isfinite(n->second)) it.noise = n->second;
    it.plan = static_cast<int>(plans_.size()) - 1;
    it.key = key;
    items_.push_back(it);
  };

  for (std::size_t r : order) {
    const Run& run = bundle.runs[r];
    const Trace& tr = run.trace;
    Signal s;
    s.t = tr.t_s;
    if (!tr.mu.empty()) {
      s.mu = tr.mu;
    } else if (!tr.friction_N.empty()) {
      for (double F : tr.friction_N) s.mu.push_back(F / W);
    } else {
      for (double x : tr.x_m) s.mu.push_back(rig.stiffness_N_per_m * x / W);
    }
    s.x = tr.x_m;
    RunPlan plan;
    plan.label = "run " + run.run_id;
    plan.spring_force_channel = bundle.spring_force_channel;
    plan.v_m_per_s = run.v_m_per_s;
    plan.duration_s = tr.t_s.back() - tr.t_s.front();
    plan.sample_spacing_s = median_spacing(tr.t_s);
    if (bundle.kind == "pin_on_disc") read_sampling_policy(tr.t_s, plan);
    if (!(plan.sample_spacing_s > 0.0)) throw std::invalid_argument("run " + run.run_id + ": trace time t_s does not increase");
    const bool history_kind = bundle.kind == "velocity_step" || bundle.kind == "slide_hold_slide";
    if (history_kind && !tr.has_drive_history())
      throw std::invalid_argument("run " + run.run_id + ": a " + bundle.kind + " test needs the drive record (column v_drive_m_per_s)");
    if (!history_kind && tr.has_drive_history() && drive_segments(tr.t_s, tr.v_drive_m_per_s).speed_m_per_s.size() > 1)
      throw std::invalid_argument("run " + run.run_id +
                                  ": the drive changes speed; say which test this is with [rig] kind = \"velocity_step\" or \"slide_hold_slide\"");
    if (history_kind) {
      plan.kind = RunPlan::Kind::drive_history;
      plan.carry_law_state = bundle.kind == "slide_hold_slide";
      const DriveSegments segments = drive_segments(tr.t_s, tr.v_drive_m_per_s);
      plan.step_times_s = segments.start_s;
      plan.step_speeds_m_per_s = segments.speed_m_per_s;
      const auto holds = std::count(segments.speed_m_per_s.begin(), segments.speed_m_per_s.end(), 0.0);
      if (bundle.kind == "slide_hold_slide" && holds == 0)
        throw std::invalid_argument("run " + run.run_id + ": a slide_hold_slide test needs a hold (the drive at rest for at least " +
                                    std::to_string(kMinSegmentSamples) + " samples)");
      if (!(segments.speed_m_per_s.front() > 0.0))
        throw std::invalid_argument("run " + run.run_id + ": the drive record must start sliding (positive speed)");
      for (double t : tr.t_s) plan.sample_times_s.push_back(t - tr.t_s.front());
      if (!tr.x_drive_m.empty()) {
        s.x_drive = tr.x_drive_m;
      } else {
        s.x_drive.assign(tr.t_s.size(), 0.0);
        for (std::size_t i = 1; i < tr.t_s.size(); ++i)
          s.x_drive[i] = s.x_drive[i - 1] + 0.5 * (tr.v_drive_m_per_s[i] + tr.v_drive_m_per_s[i - 1]) * (tr.t_s[i] - tr.t_s[i - 1]);
      }
      Features noise;
      const Features f = analyse_drive_history(s, plan, &plan.step_bin_edges_m, &noise);
      const double record_noise = high_pass_noise(s.mu);
      if (!std::isfinite(step_response_.peak_rise)) step_response_ = read_step_response(s, plan, W);
      plans_.push_back(plan);
      for (std::size_t k = 0; k < plan.step_times_s.size(); ++k) {
        const std::string key = "steady_mu_" + std::to_string(k);
        if (f.count(key) && std::isfinite(f.at(key))) {
          const std::string where = plan.label + ", v = " + numerics::fmt(plan.step_speeds_m_per_s[k], "%.3g") + " m/s";
          const int unit = new_unit(UnitKey::own("steady_mu"));
          add("steady_mu", 0, where, "steady_sliding", plan.step_speeds_m_per_s[k], unit, f.at(key), key, noise);
          const std::string scatter_key = "steady_scatter_" + std::to_string(k);
          if (f.count(scatter_key) && std::isfinite(f.at(scatter_key)))
            add("steady_scatter", 0, where, "steady_sliding", plan.step_speeds_m_per_s[k], unit, f.at(scatter_key), scatter_key, noise);
          scatter_floor = std::max(scatter_floor, record_noise);
        }
        const std::string peak_key = "peak_after_hold_" + std::to_string(k);
        if (f.count(peak_key) && std::isfinite(f.at(peak_key))) {
          const double t_hold = plan.step_times_s[k + 1] - plan.step_times_s[k];
          add("peak_after_hold", 0, plan.label + ", after a " + numerics::fmt(t_hold, "%.3g") + " s hold", "stick_slip",
              plan.step_speeds_m_per_s[k + 1], new_unit(UnitKey::own("peak_after_hold")), f.at(peak_key), peak_key, noise);
          items_.back().hold_s = t_hold;
        }
        if (k == 0) continue;
        const auto& edges = plan.step_bin_edges_m[k - 1];
        std::vector<int> block_unit(kStepBins / kBinsPerBlock + 1, -1);
        for (int j = 0; j < kStepBins; ++j) {
          const std::string bin_key = "after_step_" + std::to_string(k) + "_" + std::to_string(j);
          if (!f.count(bin_key)) continue;
          int& unit = block_unit[static_cast<std::size_t>(j / kBinsPerBlock)];
          if (unit < 0) unit = new_unit(UnitKey::own("mu_after_step"));
          add("mu_after_step", j,
              numerics::fmt(edges[static_cast<std::size_t>(j)] * 1e6, "%.3g") + "-" + numerics::fmt(edges[static_cast<std::size_t>(j) + 1] * 1e6, "%.3g") +
                  " um after step " + std::to_string(k),
              "steady_sliding", plan.step_speeds_m_per_s[k], unit, f.at(bin_key), bin_key, noise);
        }
      }
    } else {
      plan.kind = RunPlan::Kind::constant_speed;
      if (!(run.v_m_per_s > 0.0)) throw std::invalid_argument("run " + run.run_id + ": constant-speed trace needs v_m_per_s > 0");
      std::string regime;
      double step = 0.0;
      // With the slider's displacement recorded, its regime is read as the rig reads a simulated
      // run's (rig::classify_regime), quasi-harmonic oscillation included, and it decides whether
      // the friction extrema are read at all. μ alone cannot give that evidence: friction does not
      // say whether the slider moves with the disc, so a μ oscillation with sticks and one in
      // continuous slip look alike, and the friction extrema can only say stick-slip (it
      // oscillates) or steady sliding (it does not).
      std::string x_regime;
      plan.regime_from_x = !s.x.empty();
      if (plan.regime_from_x)
        x_regime = rig::classify_regime(
            rig, rig::recorded_regime_evidence(rig, s.t, s.x, run.v_m_per_s, rig::analysis_start_s(s.t.front(), s.t.back())));
      const std::string* oscillation_from = plan.regime_from_x ? &x_regime : nullptr;
      const Features f = analyse_constant_speed(s, plan.sample_spacing_s, step, &regime, kNaN, oscillation_from);
      if (plan.regime_from_x) regime = x_regime;
      plan.slip_step_s = step;
      plan.simulated_extra_s = simulated_extra_s(f, step, plan.duration_s);
      const Features noise = block_noise(s, plan.sample_spacing_s, step, oscillation_from);
      plans_.push_back(plan);
      const std::string where = "v = " + numerics::fmt(run.v_m_per_s, "%.3g") + " m/s";
      const int unit = new_unit(UnitKey::at_speed(run.v_m_per_s));
      for (const auto& [key, value] : f) {
        if (!std::isfinite(value)) continue;
        if (key.rfind("slip_drop_", 0) == 0) {
          const int j = std::stoi(key.substr(10));
          add("slip_drop", j, where + ", slip onset + " + std::to_string(j) + " x " + numerics::fmt(step, "%.3g") + " s", regime, run.v_m_per_s, unit, value, key, noise);
        } else {
          add(key, 0, where, regime, run.v_m_per_s, unit, value, key, noise);
        }
      }
    }
  }

  std::vector<StaticPoint> points = bundle.static_points;
  std::stable_sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.phi_dot_per_s < b.phi_dot_per_s; });
  // A row is one breakaway: rows repeated at one load rate scatter by the breakaway's own
  // cycle-to-cycle spread and the reading's noise, which is each row's standard error — pooled
  // over the rates that repeat (0 when none does).
  const double static_noise = [&] {
    double ss = 0.0;
    int dof = 0;
    for (std::size_t a = 0; a < points.size();) {
      std::size_t b = a;
      while (b < points.size() && points[b].phi_dot_per_s == points[a].phi_dot_per_s) ++b;
      double m = 0.0;
      for (std::size_t i = a; i < b; ++i) m += points[i].mu_s / static_cast<double>(b - a);
      for (std::size_t i = a; i < b; ++i) ss += (points[i].mu_s - m) * (points[i].mu_s - m);
      dof += static_cast<int>(b - a) - 1;
      a = b;
    }
    return dof > 0 ? std::sqrt(ss / dof) : 0.0;
  }();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const StaticPoint& p = points[k];
    const double v = p.phi_dot_per_s * W / rig.stiffness_N_per_m;
    if (k > 0 && points[k - 1].phi_dot_per_s == p.phi_dot_per_s) {
      // A repeat at the same load rate: another row of the same simulation (points are sorted).
      add("mu_s_vs_load_rate", 0, plans_.back().label, "static", v, items_.back().unit, p.mu_s, "mu_s", {{"mu_s", static_noise}});
      continue;
    }
    RunPlan plan;
    plan.kind = RunPlan::Kind::static_point;
    plan.label = "phi_dot = " + numerics::fmt(p.phi_dot_per_s, "%.3g") + " 1/s";
    plan.v_m_per_s = p.phi_dot_per_s;  // a load rate; the speed follows from the simulated rig's k and W
    // Time for the spring to load the contact to μs, then for several stick-slip cycles (each
    // reloads by 2(μs − μk) < 2 μs), half of it after the start-up — but no more than
    // kStaticPointCycles_s of them: a stick that long outlasts any memory the catalogue's laws
    // keep (squeeze-out ≤ 2.5 s at the thinnest fitted film), so the first breakaway is in-cycle
    // too, and a slow load rate would otherwise leave a model that creeps or rings after it to
    // be integrated for hours (the thesis example's 1e-4 1/s point: 26 000 s more).
    const double load_s = (2.0 * p.mu_s + 0.2) / p.phi_dot_per_s;
    plan.duration_s = load_s + std::min(2.0 * load_s, kStaticPointCycles_s);
    plans_.push_back(plan);
    add("mu_s_vs_load_rate", 0, plan.label, "static", v, new_unit(UnitKey::at_speed(v)), p.mu_s, "mu_s", {{"mu_s", static_noise}});
  }

  std::vector<RegimePoint> regimes = bundle.regimes;
  std::stable_sort(regimes.begin(), regimes.end(), [](const auto& a, const auto& b) { return a.v_m_per_s < b.v_m_per_s; });
  for (const RegimePoint& p : regimes) {
    RunPlan plan;
    plan.kind = RunPlan::Kind::regime_point;
    plan.label = "v = " + numerics::fmt(p.v_m_per_s, "%.3g") + " m/s";
    plan.regime = p.regime;
    plan.v_m_per_s = p.v_m_per_s;
    plans_.push_back(plan);
    const int unit = new_unit(UnitKey::at_speed(p.v_m_per_s));
    add("regime_mismatch", 0, plan.label + " (" + p.regime + ")", p.regime, p.v_m_per_s, unit, 0.0, "regime_mismatch", {});
    if (std::isfinite(p.amplitude_m) && p.amplitude_m > 0.0)
      add("amplitude_m", 0, plan.label, p.regime, p.v_m_per_s, unit, p.amplitude_m, "amplitude_m", {});
    if (std::isfinite(p.frequency_rad_per_s) && p.frequency_rad_per_s > 0.0)
      add("frequency_rad_per_s", 0, plan.label, p.regime, p.v_m_per_s, unit, p.frequency_rad_per_s, "frequency_rad_per_s", {});
  }

  if (items_.empty()) throw std::invalid_argument("bundle " + bundle.name + ": no usable measurement (no trace long enough to analyse)");
  const std::vector<int> block = split_blocks(unit_keys);
  units_ = static_cast<int>(std::set<int>(block.begin(), block.end()).size());
  for (Item& it : items_) it.unit = block[static_cast<std::size_t>(it.unit)];

  std::vector<double> speeds;
  for (const Item& it : items_) speeds.push_back(it.v_m_per_s);
  std::sort(speeds.begin(), speeds.end());
  speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
  const double median = speeds[speeds.size() / 2];
  for (Item& it : items_) it.speed_class = speeds.size() < 2 ? "all v" : (it.v_m_per_s < median ? "low v" : "high v");

  // Friction levels share one scale, the RMS of all measured levels: a level that happens to lie
  // near zero (the trough 2 μk − μs of Coulomb stick-slip) must not turn sensor noise into a large
  // relative error. Every other observable is scaled by the RMS of its own measured values.
  std::map<std::string, std::pair<double, int>> sq;
  for (const Item& it : items_) {
    auto& acc = sq[is_friction_level(it.observable) ? std::string(kFrictionLevel) : it.observable];
    acc.first += it.measured * it.measured, ++acc.second;
  }
  for (const Item& it : items_) {
    if (std::any_of(scales_.begin(), scales_.end(), [&](const auto& s) { return s.first == it.observable; })) continue;
    const auto& acc = sq.at(is_friction_level(it.observable) ? std::string(kFrictionLevel) : it.observable);
    double rms = std::sqrt(acc.first / acc.second);
    // A record that slides as steadily as its noise allows has no scatter to scale by: its
    // sensor noise is the yardstick then (a model's oscillation is judged against it).
    if (it.observable == "steady_scatter") rms = std::max(rms, scatter_floor);
    scales_.emplace_back(it.observable, rms > 0.0 ? rms : 1.0);
  }
  if (const double noise = median_relative_noise(); noise > 0.0)
    tolerance_ = std::clamp(kToleranceBelowNoise * noise, kFinestTolerance, kCoarsestTolerance);
}

std::vector<double> Comparison::relative_noise() const {
  std::vector<double> out;
  for (const Item& it : items_) out.push_back(it.noise / scale(it.observable));
  return out;
}

double Comparison::median_relative_noise() const {
  std::vector<double> relative = relative_noise();
  std::erase_if(relative, [](double r) { return !(r > 0.0); });
  return relative.empty() ? 0.0 : numerics::median(std::move(relative));
}

void Comparison::set_integration_tolerance(double relative_tolerance) {
  if (!(relative_tolerance >= kFinestTolerance && relative_tolerance <= kCoarsestTolerance))
    throw std::invalid_argument("integration tolerance must lie in [1e-10, 1e-6]");
  tolerance_ = relative_tolerance;
}

double Comparison::event_rate_per_s(const rig::RigParameters& rig) {
  return kEventsPerPeriod * rig.natural_frequency_rad_per_s() / (2.0 * M_PI);
}

long Comparison::event_budget(const rig::RigParameters& rig, double duration_s) {
  const double events = event_rate_per_s(rig) * duration_s;
  if (!std::isfinite(events)) return kFewestEvents;
  return std::max(kFewestEvents, static_cast<long>(std::ceil(events)));
}

void Comparison::limit_events(rig::SimulationOptions& options, const rig::RigParameters& rig) {
  options.max_events = event_budget(rig, options.duration_s);
  const double rate_per_s = event_rate_per_s(rig);
  options.max_event_rate_per_s = std::isfinite(rate_per_s) ? rate_per_s : 0.0;
  options.events_before_rate_limit = kFewestEvents;
}

double Comparison::scale(const std::string& observable) const {
  for (const auto& [name, s] : scales_)
    if (name == observable) return s;
  throw std::invalid_argument("no observable " + observable);
}

std::vector<double> Comparison::residuals(const std::vector<double>& simulated) const {
  std::vector<double> r(items_.size());
  std::map<std::string, double> scale_of(scales_.begin(), scales_.end());
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const Item& it = items_[i];
    r[i] = std::isfinite(simulated[i]) ? (simulated[i] - it.measured) / scale_of.at(it.observable) : 1.0;
    // A steady window's scatter is a ceiling: a model that oscillates more than the record
    // fluctuates misses; one that slides more steadily than the record's slow wander (which no
    // friction law in the catalogue makes) does not.
    if (it.observable == "steady_scatter") r[i] = std::max(r[i], 0.0);
  }
  return r;
}

std::vector<double> Comparison::predict(const rig::RigParameters& rig, const rig::FrictionModel& model, std::uint64_t seed,
                                        std::vector<SimulatedRun>* traces, const std::vector<bool>* items_needed) const {
  std::vector<double> out(items_.size(), kNaN);
  std::vector<bool> plan_needed(plans_.size(), items_needed == nullptr);
  if (items_needed)
    for (std::size_t i = 0; i < items_.size(); ++i)
      if ((*items_needed)[i]) plan_needed[static_cast<std::size_t>(items_[i].plan)] = true;
  const std::shared_ptr<const rig::FrictionLaw> law = rig::make_friction_law(model);
  // The plans are independent simulations: in parallel (the candidate fits run side by side, and
  // inside them this loop is serial).
  std::vector<Features> features(plans_.size());
  std::vector<std::optional<SimulatedRun>> plan_traces(plans_.size());
  numerics::parallel_for(plans_.size(), [&](std::size_t p) {
    if (plan_needed[p]) features[p] = predict_plan(plans_[p], rig, model, *law, seed, tolerance_, traces ? &plan_traces[p] : nullptr);
  });
  for (std::size_t p = 0; p < plans_.size(); ++p)
    if (traces && plan_traces[p]) traces->push_back(std::move(*plan_traces[p]));
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const Features& f = features[static_cast<std::size_t>(items_[i].plan)];
    if (const auto it = f.find(items_[i].key); it != f.end()) out[i] = it->second;
  }
  return out;
}

std::optional<double> static_point_reading(const std::vector<std::pair<double, double>>& breakaways, const rig::SimulationSummary& run,
                                           long max_events, double window_start_s) {
  if (!run.completed && run.events <= max_events) return std::nullopt;  // the simulator stops past the limit
  auto read = std::find_if(breakaways.begin(), breakaways.end(), [&](const auto& b) { return b.first >= window_start_s; });
  if (read == breakaways.end()) read = breakaways.begin() + static_cast<long>(breakaways.size() / 2);
  if (read == breakaways.end()) return std::nullopt;
  double sum = 0.0;
  for (auto it = read; it != breakaways.end(); ++it) sum += it->second;
  return sum / static_cast<double>(breakaways.end() - read);
}

}  // namespace tribo::gap
