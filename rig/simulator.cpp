#include "rig/simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics/cvode.h"
#include "numerics/format.h"

namespace tribo::rig {

const char* to_string(EventKind kind) {
  switch (kind) {
    case EventKind::breakaway: return "breakaway";
    case EventKind::reattach: return "reattach";
    case EventKind::reversal: return "reversal";
    case EventKind::relock: return "relock";
  }
  return "?";
}

namespace {

// Layout of the integrated vector: x, ẋ, slip distance s, then the law's own state.
constexpr std::size_t kX = 0, kXdot = 1, kSlip = 2, kLaw = 3;

// The hybrid system: model (rig, drive, law) plus the discrete mode (phase, direction).
struct Machine {
  const RigParameters& rig;
  const Drive& drive;
  const FrictionLaw& law;
  Phase phase = Phase::stick;
  int direction = 0;
  double phase_start_s = 0.0;
  std::string callback_error;
  // The drive's segment being integrated: at its end (a breakpoint, CVODE's stop time) the event
  // functions see the drive that led there, not the next segment's (a hold's zero load rate would
  // hide a breakaway that the last slide's load rate had reached).
  std::size_t segment = 0;

  double drive_speed(double t) const { return drive.speed_m_per_s(t, segment); }
  double drive_acceleration(double t) const { return drive.acceleration_m_per_s2(t, segment); }

  FrictionContext context(double t, const double* y) const {
    FrictionContext c;
    c.t_s = t;
    c.phase = phase;
    c.slip_direction = phase == Phase::slip ? direction : 0;
    c.drive_speed_m_per_s = drive_speed(t);
    // Speed along the slip direction; clipped at 0 for the instant before a velocity match is located.
    c.relative_speed_m_per_s = phase == Phase::slip ? std::max(0.0, direction * (c.drive_speed_m_per_s - y[kXdot])) : 0.0;
    c.normal_load_N = rig.normal_load_N;
    c.tangential_load_rate_per_s = std::abs(force_rate(t)) / rig.normal_load_N;
    c.slip_distance_m = y[kSlip];
    c.time_in_phase_s = t - phase_start_s;
    c.state = std::span<const double>(y + kLaw, law.state_size());
    return c;
  }

  // Force the contact must supply to keep ẋ = v: F_need = M v̇ + r v + k x.
  double needed_force(double t, const double* y) const {
    return rig.mass_kg * drive_acceleration(t) + rig.damping_N_s_per_m * drive_speed(t) +
           rig.stiffness_N_per_m * y[kX];
  }
  // dF_need/dt while stuck (v̇ is piecewise constant).
  double force_rate(double t) const {
    return rig.damping_N_s_per_m * drive_acceleration(t) + rig.stiffness_N_per_m * drive_speed(t);
  }

  // Kinetic friction at the onset of slip in direction d (|U| = 0⁺).
  double kinetic_at_onset(double t, const double* y, int d) const {
    Machine probe = *this;
    probe.phase = Phase::slip;
    probe.direction = d;
    FrictionContext c = probe.context(t, y);
    c.relative_speed_m_per_s = 0.0;
    return law.kinetic_force_N(c);
  }

  // A stuck contact cannot break away below the kinetic friction at zero relative speed: the
  // slider would at once be dragged back to the surface speed.
  double breakaway_limit(double t, const double* y, int d) const { return breakaway_limit(t, y, d, static_limit(t, y)); }
  double breakaway_limit(double t, const double* y, int d, double static_limit_N) const {
    return std::max(static_limit_N, kinetic_at_onset(t, y, d));
  }
  double static_limit(double t, const double* y) const { return law.static_limit_N(context(t, y)); }

  double friction(double t, const double* y) const {
    if (phase == Phase::stick) return needed_force(t, y);
    return direction * law.kinetic_force_N(context(t, y));
  }

  double acceleration(double t, const double* y) const {
    if (phase == Phase::stick) return drive_acceleration(t);
    return (friction(t, y) - rig.damping_N_s_per_m * y[kXdot] - rig.stiffness_N_per_m * y[kX]) / rig.mass_kg;
  }

  void rates(double t, const double* y, double* dy) const {
    const FrictionContext c = context(t, y);
    law.state_rates(c, std::span<double>(dy + kLaw, law.state_size()));
    if (phase == Phase::stick) {
      dy[kX] = drive_speed(t);
      dy[kXdot] = drive_acceleration(t);
      dy[kSlip] = 0.0;
    } else {
      dy[kX] = y[kXdot];
      dy[kXdot] = acceleration(t, y);
      dy[kSlip] = direction * (c.drive_speed_m_per_s - y[kXdot]);
    }
  }

  // Event functions (all located on downward crossings):
  //   stick: g0 = F_lim,+ − F_need (breakaway_forward), g1 = F_lim,− + F_need (breakaway_backward)
  //   slip:  g0 = d U (velocity_match)
  void events(double t, const double* y, double* g) const {
    if (phase == Phase::stick) {
      const double need = needed_force(t, y), limit = static_limit(t, y);  // the same both ways
      g[0] = breakaway_limit(t, y, +1, limit) - need;
      g[1] = breakaway_limit(t, y, -1, limit) + need;
    } else {
      g[0] = direction * (drive_speed(t) - y[kXdot]);
    }
  }
};

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  auto* m = static_cast<Machine*>(data);
  try {
    m->rates(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
  } catch (const std::exception& e) {
    m->callback_error = e.what();
    return -1;
  }
}

int root_callback(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  auto* m = static_cast<Machine*>(data);
  try {
    m->events(t, N_VGetArrayPointer(y), g);
    return 0;
  } catch (const std::exception& e) {
    m->callback_error = e.what();
    return -1;
  }
}

// Steady-sliding detection (SimulationOptions::settle_window_periods): the friction's time mean
// (trapezoidal, so listed output instants serve as well as the slip grid) over consecutive windows
// of slip without an event, each compared with the one before.
class SettleDetector {
 public:
  SettleDetector(double window_s, double tolerance_N) : window_s_(window_s), tolerance_N_(tolerance_N) {}
  void restart() {
    open_ = false;
    previous_mean_ = std::numeric_limits<double>::quiet_NaN();
  }
  // A slip sample; true when the window it closes matches the previous one.
  bool add(double t, double friction_N) {
    if (!open_) {
      open_ = true;
      start_s_ = last_t_ = t;
      last_f_ = friction_N;
      integral_ = 0.0;
      return false;
    }
    integral_ += 0.5 * (friction_N + last_f_) * (t - last_t_);
    last_t_ = t;
    last_f_ = friction_N;
    if (t - start_s_ < window_s_) return false;
    const double mean = integral_ / (t - start_s_);
    const bool settled = std::isfinite(previous_mean_) && std::abs(mean - previous_mean_) <= tolerance_N_;
    previous_mean_ = mean;
    start_s_ = t;
    integral_ = 0.0;
    return settled;
  }

 private:
  double window_s_, tolerance_N_;
  bool open_ = false;
  double start_s_ = 0.0, last_t_ = 0.0, last_f_ = 0.0, integral_ = 0.0;
  double previous_mean_ = std::numeric_limits<double>::quiet_NaN();
};

void validate(const SimulationOptions& o) {
  auto bad = [](const std::string& what) { throw std::invalid_argument("simulation options: " + what); };
  if (!std::isfinite(o.duration_s) || !(o.duration_s > 0.0)) bad("duration_s must be positive");
  if (!(o.relative_tolerance > 0.0) || !(o.relative_tolerance < 1e-2)) bad("relative_tolerance must lie in (0, 1e-2)");
  if (!(o.displacement_tolerance_fraction > 0.0)) bad("displacement_tolerance_fraction must be positive");
  if (o.samples_per_period < 4) bad("samples_per_period must be at least 4");
  if (o.stick_samples_per_run < 1) bad("stick_samples_per_run must be at least 1");
  if (!(o.settle_window_periods >= 0.0) || !std::isfinite(o.settle_window_periods)) bad("settle_window_periods must be finite and >= 0");
  if (!(o.settle_tolerance_fraction > 0.0) || !std::isfinite(o.settle_tolerance_fraction)) bad("settle_tolerance_fraction must be finite and positive");
  if (o.stop_when_settled && !(o.settle_window_periods > 0.0)) bad("stop_when_settled needs settle_window_periods > 0");
  if (!std::isfinite(o.initial_displacement_m)) bad("initial_displacement_m must be finite");
  if (!(o.max_event_rate_per_s >= 0.0) || !std::isfinite(o.max_event_rate_per_s)) bad("max_event_rate_per_s must be finite and >= 0");
  if (o.events_before_rate_limit < 0) bad("events_before_rate_limit must be >= 0");
  if (o.max_steps_per_output < 1) bad("max_steps_per_output must be at least 1");
  for (std::size_t i = 0; i < o.output_times_s.size(); ++i) {
    const double t = o.output_times_s[i];
    if (!std::isfinite(t) || t < 0.0 || (i > 0 && !(t > o.output_times_s[i - 1])))
      bad("output_times_s must be finite, non-negative and increasing (entry " + std::to_string(i) + ")");
  }
}

}  // namespace

SimulationSummary simulate(const RigParameters& rig, const Drive& drive, const FrictionLaw& law,
                           const SimulationOptions& options, const SimulationObserver& observer) {
  validate(rig);
  validate(options);
  const std::size_t n = kLaw + law.state_size();
  const double wn = rig.natural_frequency_rad_per_s();
  const double x_scale = rig.normal_load_N / rig.stiffness_N_per_m;
  const double dt_slip = 2.0 * std::numbers::pi / wn / options.samples_per_period;
  const double dt_stick = std::max(dt_slip, options.duration_s / options.stick_samples_per_run);
  const double t_end = options.duration_s;

  std::vector<double> atol(n);
  atol[kX] = atol[kSlip] = options.displacement_tolerance_fraction * x_scale;
  atol[kXdot] = atol[kX] * wn;
  law.state_tolerances(std::span<double>(atol.data() + kLaw, law.state_size()), options.displacement_tolerance_fraction);

  Machine m{rig, drive, law, Phase::stick, 0, 0.0, {}};
  std::vector<double> y(n, 0.0);
  y[kX] = options.initial_displacement_m;
  y[kXdot] = drive.speed_m_per_s(0.0);
  law.initial_state(std::span<double>(y.data() + kLaw, law.state_size()));
  if (options.start_in_steady_sliding) {
    if (!(drive.speed_m_per_s(0.0) > 0.0)) {
      throw std::invalid_argument("simulation options: steady sliding needs a positive drive speed at t = 0");
    }
    m.phase = Phase::slip;
    m.direction = +1;
    y[kXdot] = 1e-3 * drive.speed_m_per_s(0.0);  // a small kick: an exact equilibrium never leaves
    y[kX] = law.kinetic_force_N(m.context(0.0, y.data())) / rig.stiffness_N_per_m;
  } else if (options.start_slipping) {
    const double u0 = drive.speed_m_per_s(0.0) - options.initial_velocity_m_per_s;
    if (!std::isfinite(u0) || u0 == 0.0) {
      throw std::invalid_argument("simulation options: initial_velocity_m_per_s must differ from the drive speed to start slipping");
    }
    y[kXdot] = options.initial_velocity_m_per_s;
    m.phase = Phase::slip;
    m.direction = u0 > 0.0 ? +1 : -1;
  }

  // Adams–Moulton: the rig is a lightly damped oscillator, non-stiff; Newton with a dense
  // Jacobian keeps the corrector robust across friction jumps. A stiff law (FrictionLaw::stiff)
  // takes BDF, whose steps are not bound by its damping time scale.
  const auto method = law.stiff(rig.normal_load_N, wn) ? numerics::CvodeSettings::Method::bdf : numerics::CvodeSettings::Method::adams;
  const numerics::CvodeSettings settings{method, options.relative_tolerance, atol, options.max_steps_per_output};
  numerics::Cvode cv(rhs_callback, &m, settings, 0.0, y);
  SimulationSummary summary;
  double t = 0.0;

  auto emit_sample = [&]() {
    if (!observer.on_sample) return;
    Sample s;
    s.t_s = t;
    s.x_m = y[kX];
    s.xdot_m_per_s = y[kXdot];
    s.xddot_m_per_s2 = m.acceleration(t, y.data());
    s.friction_N = m.friction(t, y.data());
    s.drive_speed_m_per_s = m.drive_speed(t);
    s.drive_displacement_m = drive.displacement_m(t, m.segment);
    s.slip_distance_m = y[kSlip];
    s.phase = m.phase;
    s.slip_direction = m.phase == Phase::slip ? m.direction : 0;
    observer.on_sample(s);
  };
  auto emit_event = [&](Event e) {
    ++summary.events;
    if (observer.on_event) observer.on_event(e);
  };
  auto law_state = [&]() { return std::span<double>(y.data() + kLaw, law.state_size()); };

  auto breakaway = [&](int d) {
    Event e;
    e.t_s = t;
    e.kind = EventKind::breakaway;
    e.slip_direction = d;
    e.x_m = y[kX];
    e.xdot_m_per_s = m.drive_speed(t);
    e.friction_N = m.needed_force(t, y.data());
    e.mu = std::abs(e.friction_N) / rig.normal_load_N;
    e.load_rate_per_s = std::abs(m.force_rate(t)) / rig.normal_load_N;
    e.phase_duration_s = t - m.phase_start_s;
    emit_event(e);
    m.phase = Phase::slip;
    m.direction = d;
    m.phase_start_s = t;
    y[kXdot] = m.drive_speed(t);
    y[kSlip] = 0.0;
    law.on_slip_onset(m.context(t, y.data()), law_state());
  };

  // Velocity match while slipping in direction d: re-attach when the force needed to hold
  // ẋ = v is within the re-attachment limit (or within the kinetic friction at 0⁺ of the
  // opposite direction, so that neither slip direction is consistent); otherwise slip on in −d.
  auto velocity_match = [&]() {
    y[kXdot] = m.drive_speed(t);
    Event e;
    e.t_s = t;
    e.x_m = y[kX];
    e.xdot_m_per_s = y[kXdot];
    e.friction_N = m.direction * law.kinetic_force_N(m.context(t, y.data()));
    e.mu = std::abs(e.friction_N) / rig.normal_load_N;
    e.slip_distance_m = y[kSlip];
    const double need = m.needed_force(t, y.data());
    const int reverse = -m.direction;
    const double hold = std::max(law.reattach_limit_N(m.context(t, y.data())), m.kinetic_at_onset(t, y.data(), reverse));
    if (std::abs(need) <= hold || need * reverse <= 0.0) {
      e.kind = EventKind::reattach;
      e.phase_duration_s = t - m.phase_start_s;
      emit_event(e);
      m.phase = Phase::stick;
      m.direction = 0;
      m.phase_start_s = t;
      law.on_stick_onset(m.context(t, y.data()), law_state());
    } else {
      e.kind = EventKind::reversal;
      e.slip_direction = reverse;
      e.phase_duration_s = t - m.phase_start_s;
      emit_event(e);
      m.direction = reverse;
    }
  };

  // After a restart the mode may already be inconsistent (a drive step changed v): switch at once.
  auto settle = [&]() {
    for (int guard = 0; guard < 4; ++guard) {
      if (m.phase == Phase::stick) {
        const double need = m.needed_force(t, y.data());
        if (need > m.breakaway_limit(t, y.data(), +1)) {
          breakaway(+1);
        } else if (-need > m.breakaway_limit(t, y.data(), -1)) {
          breakaway(-1);
        } else {
          return;
        }
      } else if (m.direction * (m.drive_speed(t) - y[kXdot]) < 0.0) {
        velocity_match();
      } else {
        return;
      }
    }
  };

  // The next output instant after `now`: on the phase's grid, or the next listed output time.
  std::size_t listed = 0;
  auto next_output_after = [&](double now) {
    if (options.output_times_s.empty()) return now + (m.phase == Phase::stick ? dt_stick : dt_slip);
    while (listed < options.output_times_s.size() && options.output_times_s[listed] <= now) ++listed;
    return listed < options.output_times_s.size() ? options.output_times_s[listed] : t_end;
  };

  SettleDetector settling(options.settle_window_periods * 2.0 * std::numbers::pi / wn,
                          options.settle_tolerance_fraction * rig.normal_load_N);
  bool settled_stop = false;
  // After a regular sample: feed the detector while slipping; true when the run is to end here.
  auto settled_here = [&]() {
    if (!(options.settle_window_periods > 0.0)) return false;
    if (m.phase != Phase::slip) {
      settling.restart();
      return false;
    }
    if (!settling.add(t, m.friction(t, y.data()))) return false;
    if (std::isnan(summary.settled_at_s)) summary.settled_at_s = t;
    return options.stop_when_settled;
  };

  // At a drive breakpoint (CVODE's stop time): the next segment from here on; a slipping contact
  // re-locked if asked; a stuck slider follows the new speed; then any switch the new drive forces.
  auto at_breakpoint = [&]() {
    m.segment = drive.segment_at(t);
    if (options.relock_at_drive_steps && m.phase == Phase::slip && t < t_end) {
      Event e;
      e.t_s = t;
      e.kind = EventKind::relock;
      e.x_m = y[kX];
      e.xdot_m_per_s = y[kXdot];
      e.friction_N = m.direction * law.kinetic_force_N(m.context(t, y.data()));
      e.mu = std::abs(e.friction_N) / rig.normal_load_N;
      e.phase_duration_s = t - m.phase_start_s;
      e.slip_distance_m = y[kSlip];
      emit_event(e);
      m.phase = Phase::stick;
      m.direction = 0;
      m.phase_start_s = t;
      law.on_stick_onset(m.context(t, y.data()), law_state());
    }
    if (m.phase == Phase::stick) y[kXdot] = m.drive_speed(t);
    settle();
  };

  emit_sample();
  double next_sample = 0.0;
  settle();
  while (t < t_end && !settled_stop) {
    if (options.stop_after_events > 0 && summary.events >= options.stop_after_events) break;
    const bool over_budget = summary.events > options.max_events;
    const bool over_rate = options.max_event_rate_per_s > 0.0 &&
                           static_cast<double>(summary.events) >
                               static_cast<double>(options.events_before_rate_limit) + options.max_event_rate_per_s * t;
    if (over_budget || over_rate) {
      const std::string limit = over_budget ? "max_events reached"
                                            : "more than " + std::to_string(options.events_before_rate_limit) + " + " +
                                                  numerics::shortest(options.max_event_rate_per_s) + " per s";
      summary.message = "stopped after " + std::to_string(summary.events) + " events at t = " + numerics::shortest(t) + " s (" + limit +
                        ": chattering between stick and slip?)";
      summary.end_time_s = t;
      return summary;
    }
    m.segment = drive.segment_at(t);
    const double t_stop = std::min(t_end, drive.next_breakpoint_s(t));
    const std::vector<int> directions = m.phase == Phase::stick ? std::vector<int>{-1, -1} : std::vector<int>{-1};
    cv.restart(t, y);
    cv.set_roots(root_callback, directions);
    cv.set_stop_time(t_stop);
    const double dt_phase = m.phase == Phase::stick ? dt_stick : dt_slip;
    if (!options.output_times_s.empty()) {
      next_sample = next_output_after(t);
    } else if (next_sample <= t || next_sample > t + dt_phase) {
      next_sample = t + dt_phase;
    }
    // One CVODE step at a time, the output instants inside each interpolated from its polynomial:
    // the steps are several output spacings long, and CVODE would otherwise check the roots again
    // at every output instant (Cvode::step).
    double t_step = t;
    long steps_since_output = 0;  // CVODE's own step limit counts per call, here one step
    while (true) {
      int flag = cv.step(std::min(next_sample, t_stop), t_step);
      if (flag >= 0 && ++steps_since_output > options.max_steps_per_output) {
        flag = CV_TOO_MUCH_WORK;
        m.callback_error = std::to_string(options.max_steps_per_output) + " steps without reaching the next output instant";
      }
      if (flag < 0) {
        summary.message = "CVODE failed at t = " + numerics::shortest(t_step) + " s with " + numerics::Cvode::describe(flag) +
                          (m.callback_error.empty() ? "" : " (" + m.callback_error + ")") +
                          (cv.last_message().empty() ? "" : ": " + cv.last_message());
        summary.end_time_s = t;
        summary.integrator_steps += cv.steps();
        return summary;
      }
      const bool root = flag == CV_ROOT_RETURN;
      // The regular output instants within the step: before an event (the state at the event is
      // its own sample), and never t_stop (sampled after the drive's breakpoint is handled).
      while (next_sample < t_stop && (root ? next_sample < t_step : next_sample <= t_step)) {
        t = next_sample;
        cv.interpolate(t, y);
        emit_sample();
        steps_since_output = 0;
        next_sample = next_output_after(t);
        if ((settled_stop = settled_here())) break;
      }
      if (settled_stop) break;
      t = t_step;
      std::copy(cv.state().begin(), cv.state().end(), y.begin());
      if (root) {
        emit_sample();  // the state at the event, before the switch: times stay strictly increasing
        settling.restart();
        if (m.phase == Phase::stick) {
          const auto found = cv.roots_found();
          breakaway(found[0] != 0 ? +1 : -1);
        } else {
          velocity_match();
        }
        settle();
        if (t >= t_stop) at_breakpoint();  // an event on the breakpoint itself
        // At a re-attachment the friction jumps (μk W to the spring's pull): the first stick
        // sample comes a slip spacing later, not a stick spacing, whose interpolant would spread
        // the jump (a Coulomb trough read 0.016 high at 4000 stick samples a 375-s run).
        next_sample = options.output_times_s.empty() && m.phase == Phase::stick ? t + dt_slip : next_output_after(t);
        break;
      }
      if (t >= t_stop) {
        at_breakpoint();
        emit_sample();
        settling.restart();
        next_sample = next_output_after(t);
        break;
      }
    }
    summary.integrator_steps += cv.steps();
  }
  summary.completed = true;
  summary.end_time_s = t;
  if (settled_stop) {
    summary.message = "completed: settled into steady sliding at t = " + numerics::shortest(t) + " s (stop_when_settled)";
  } else {
    summary.message = t < t_end ? "completed: stopped after " + std::to_string(summary.events) + " events (stop_after_events)" : "completed";
  }
  return summary;
}

SimulationResult simulate(const RigParameters& rig, const Drive& drive, const FrictionLaw& law,
                          const SimulationOptions& options) {
  SimulationResult result;
  SimulationObserver observer;
  observer.on_sample = [&](const Sample& s) { result.samples.push_back(s); };
  observer.on_event = [&](const Event& e) { result.events.push_back(e); };
  result.summary = simulate(rig, drive, law, options, observer);
  return result;
}

}  // namespace tribo::rig
