// Event-driven integration of the rig, thesis (4.2.1):  M ẍ + r ẋ + k x = F.
//
// Two phases, switched only at named, directional events located by CVODE root finding:
//   stick (ẋ = v):  F = F_need = M v̇ + r v + k x; it ends at
//       `breakaway_forward`   F_static − F_need crosses 0 downwards  → slip with d = +1 (U > 0)
//       `breakaway_backward`  F_static + F_need crosses 0 downwards  → slip with d = −1 (U < 0)
//   slip (direction d):  F = d F_k(|U|, state); it ends at
//       `velocity_match`      d U crosses 0 downwards. Then the contact re-attaches if
//                             |F_need| ≤ F_reattach; otherwise it keeps slipping with d → −d.
// Drive breakpoints (velocity steps) restart the integrator; a stuck slider follows the new speed.
// Nothing in the right-hand side evaluates sign(U): the direction is part of the phase.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rig/drive.h"
#include "rig/friction_law.h"
#include "rig/parameters.h"

namespace tribo::rig {

struct SimulationOptions {
  double duration_s = 5.0;
  // CVODE local error test: |e_i| ≤ relative_tolerance |y_i| + atol_i, with atol for x equal to
  // displacement_tolerance_fraction × W/k (the Coulomb displacement scale) and for ẋ that times ω_n.
  double relative_tolerance = 1e-10;
  double displacement_tolerance_fraction = 1e-10;
  // Output spacing while slipping: (2π/ω_n) / samples_per_period.
  int samples_per_period = 200;
  // Output spacing while stuck: max(slip spacing, duration_s / stick_samples_per_run).
  int stick_samples_per_run = 4000;
  // When not empty: samples at these instants (s from the start, increasing, within the run) and
  // at the events, instead of the grid of the two options above — what a recorder sampling at
  // known instants needs, where a stiff machine's natural period would ask for many times more.
  std::vector<double> output_times_s;
  // A run with more events than this stops and says so (e.g. chattering at a velocity match).
  long max_events = 2'000'000;
  // A run whose integrator takes more steps than this between two output instants (or events)
  // stops and says so (CV_TOO_MUCH_WORK): a crawl or a stall, not a solution.
  long max_steps_per_output = 200'000;
  // When > 0: the run also stops, in the same way, once its events by time t outnumber
  // events_before_rate_limit + max_event_rate_per_s × t. A budget in proportion to the duration,
  // judged as it is spent: a run that chatters (a Zeno sequence of velocity matches, thousands
  // of events a period) stops where it starts to, not after the whole run's budget.
  double max_event_rate_per_s = 0.0;
  long events_before_rate_limit = 1000;
  // When > 0: the run ends, completed, at the first phase boundary after this many events — a
  // caller that reads a periodic response needs a number of cycles, not the whole duration.
  long stop_after_events = 0;
  // When > 0: steady sliding is detected — the slider slips, with no event and no drive step,
  // through two consecutive windows of this many natural periods whose time-mean friction differs
  // by at most settle_tolerance_fraction × W. The summary says when (settled_at_s); with
  // stop_when_settled the run ends there, completed. A caller reading a stationary response needs
  // a window of it, not the duration: a slider that slides steadily at 42 µm/s for 375 s gives no
  // event for stop_after_events to count. Every event restarts the windows, so stick-slip,
  // however slow its stick, never counts as settled; a sustained oscillation without sticking
  // settles once its cycles average out over a window.
  double settle_window_periods = 0.0;
  double settle_tolerance_fraction = 1e-4;
  bool stop_when_settled = false;
  double initial_displacement_m = 0.0;  // slider displacement at t = 0
  // By default the slider starts stuck (ẋ = v). With start_slipping it starts at
  // initial_velocity_m_per_s, which must differ from v(0); the slip direction follows from U.
  bool start_slipping = false;
  double initial_velocity_m_per_s = 0.0;
  // Start at rest on the moving surface in the steady-sliding equilibrium, k x = F_k(U = v(0))
  // (overrides the two options above), kicked by ẋ = 1e-3 v: how a slider released onto a running
  // disc starts. Whether
  // it then sticks, oscillates or slides steadily is the rig's own answer.
  bool start_in_steady_sliding = false;
  // At every drive breakpoint reached while slipping, the contact re-locks (event `relock`): the
  // slider takes the drive's new speed and sticks until the spring reaches the static limit. This
  // is how a velocity-step machine's stiff load point looks to the rig — the stress rises
  // elastically after the step before the interface slips at the new rate — with the friction
  // law's state carried through (healing, film, temperature), not restarted.
  bool relock_at_drive_steps = false;
};

// relock: a drive step re-locked a slipping contact (SimulationOptions::relock_at_drive_steps).
enum class EventKind { breakaway, reattach, reversal, relock };
const char* to_string(EventKind kind);

struct Event {
  double t_s = 0.0;
  EventKind kind = EventKind::breakaway;
  int slip_direction = 0;        // direction of the slip that starts (breakaway, reversal) or 0 (reattach)
  double x_m = 0.0;
  double xdot_m_per_s = 0.0;
  double friction_N = 0.0;       // friction on the slider at the event, before the switch
  double mu = 0.0;               // friction_N / W; at a breakaway this is μs
  double load_rate_per_s = 0.0;  // φ̇ = |dF/dt|/W just before breakaway (thesis 3.1.20)
  double phase_duration_s = 0.0; // length of the phase that just ended
  double slip_distance_m = 0.0;  // ∫|U|dt of the slip that just ended (0 at breakaway)
};

struct Sample {
  double t_s = 0.0;
  double x_m = 0.0;
  double xdot_m_per_s = 0.0;
  double xddot_m_per_s2 = 0.0;
  double friction_N = 0.0;       // true friction force on the slider
  double drive_speed_m_per_s = 0.0;
  double drive_displacement_m = 0.0;
  double slip_distance_m = 0.0;
  Phase phase = Phase::stick;
  int slip_direction = 0;
};

struct SimulationSummary {
  bool completed = false;        // reached duration_s, stop_after_events, or stop_when_settled
  double settled_at_s = std::numeric_limits<double>::quiet_NaN();  // steady sliding detected (settle_window_periods)
  std::string message;
  double end_time_s = 0.0;
  long integrator_steps = 0;
  long events = 0;
};

struct SimulationResult {
  SimulationSummary summary;
  std::vector<Sample> samples;
  std::vector<Event> events;
};

// Observers receive samples and events as they happen (to stream long runs to disk).
struct SimulationObserver {
  std::function<void(const Sample&)> on_sample;
  std::function<void(const Event&)> on_event;
};

// Integrates from a stuck start at t = 0. Throws std::invalid_argument for invalid parameters;
// integrator failures are reported in the summary (completed = false, message says why).
SimulationSummary simulate(const RigParameters& rig, const Drive& drive, const FrictionLaw& law,
                           const SimulationOptions& options, const SimulationObserver& observer);

// Convenience: collects every sample and event.
SimulationResult simulate(const RigParameters& rig, const Drive& drive, const FrictionLaw& law,
                          const SimulationOptions& options);

}  // namespace tribo::rig
