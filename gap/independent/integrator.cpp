#include "gap/independent/integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace tribo::gap::independent {
namespace {

constexpr int kBisections = 40;

struct State {
  double x = 0.0, xdot = 0.0, theta = 1.0, h = 0.0;
  double t_rest = 0.0;   // time since the slider last stuck
  bool stuck = true;
  double direction = 1.0;  // sign of the friction when U = 0 exactly while slipping
};

using Vec = std::array<double, 4>;  // x, ẋ, θ, h

class Machine {
 public:
  Machine(const RigConstants& rig, const IndependentLaw& law, double v) : rig_(rig), law_(law), v_(v) {}

  double solid_fraction(double speed, double h) const {
    double chi = 1.0;
    if (law_.lift) chi *= law_.lift->solid_fraction(speed);
    if (law_.squeeze) chi *= 1.0 - law_.squeeze->fluid_fraction(h);
    return chi;
  }
  double fluid_force(double speed) const {
    double f = 0.0;
    if (law_.eyring) f += law_.eyring->force_N(speed);
    if (law_.vogel) f += law_.vogel->force_N(speed);
    return f;
  }
  double load_rate_per_s() const { return rig_.stiffness_N_per_m * std::abs(v_) / rig_.normal_load_N; }
  // Static threshold (N) of a stuck slider.
  double static_mu(const State& s) const {
    if (law_.rate_state && !law_.rate_state->reset_at_breakaway) return law_.rate_state->mu(0.0, s.theta);
    if (law_.stick_ageing) return law_.stick_ageing->mu_s(s.t_rest);
    if (law_.rate_hardening) return law_.rate_hardening->mu_s(load_rate_per_s());
    return law_.mu_s;
  }
  double threshold_N(const State& s) const { return solid_fraction(0.0, s.h) * std::max(static_mu(s), 0.0) * rig_.normal_load_N; }
  double holding_force_N(const State& s) const { return rig_.stiffness_N_per_m * s.x + rig_.damping_N_s_per_m * v_; }

  // Friction on the slider while slipping. Its sign is the slip direction, a mode that changes
  // only at a located event (U = 0): a sign(U) inside the RK4 stages would let a step land just
  // short of U = 0 again and again (chattering) instead of crossing it.
  double slip_friction_N(double xdot, double theta, double h, double direction) const {
    const double speed = std::abs(v_ - xdot);
    const double sign = direction;
    const double mu = law_.rate_state ? law_.rate_state->mu(speed, theta) : law_.mu_k;
    return sign * (solid_fraction(speed, h) * std::max(mu, 0.0) * rig_.normal_load_N + fluid_force(speed));
  }
  Vec rates(const Vec& y, double direction) const {
    const double U = v_ - y[1], speed = std::abs(U);
    Vec d{};
    d[0] = y[1];
    d[1] = (slip_friction_N(y[1], y[2], y[3], direction) - rig_.damping_N_s_per_m * y[1] - rig_.stiffness_N_per_m * y[0]) / rig_.mass_kg;
    d[2] = law_.rate_state ? law_.rate_state->theta_rate_per_s(speed, y[2]) : 0.0;
    d[3] = law_.squeeze ? law_.squeeze->thickness_rate_m_per_s(speed, y[3], rig_.normal_load_N) : 0.0;
    return d;
  }
  // One RK4 step of length τ while slipping.
  State slip_step(const State& s, double tau) const {
    const Vec y{s.x, s.xdot, s.theta, s.h};
    auto add = [](const Vec& a, const Vec& b, double f) {
      Vec c;
      for (int i = 0; i < 4; ++i) c[i] = a[i] + f * b[i];
      return c;
    };
    const Vec k1 = rates(y, s.direction), k2 = rates(add(y, k1, 0.5 * tau), s.direction), k3 = rates(add(y, k2, 0.5 * tau), s.direction),
              k4 = rates(add(y, k3, tau), s.direction);
    State out = s;
    out.x = y[0] + tau / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    out.xdot = y[1] + tau / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    out.theta = std::max(y[2] + tau / 6.0 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]), 1e-300);
    out.h = std::max(y[3] + tau / 6.0 * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3]), 0.0);
    out.t_rest += tau;
    return out;
  }
  // Exact motion while stuck: carried by the disc; θ ages (θ̇ = 1 − 0) or holds (slip law);
  // the film squeezes out by its closed form.
  State stick_step(const State& s, double tau) const {
    State out = s;
    out.x = s.x + v_ * tau;
    out.xdot = v_;
    if (law_.rate_state) out.theta = s.theta + tau * law_.rate_state->theta_rate_per_s(0.0, s.theta);
    if (law_.squeeze && s.h > 0.0) out.h = law_.squeeze->thickness_at_rest_m(s.h, tau, rig_.normal_load_N);
    out.t_rest += tau;
    return out;
  }
  double slack_N(const State& s) const { return std::abs(holding_force_N(s)) - threshold_N(s); }

  // Stick → slip at time t.
  State break_away(State at, double t, RawRecord& rec) const {
    at.stuck = false;
    at.direction = holding_force_N(at) >= 0.0 ? 1.0 : -1.0;
    if (law_.rate_state && law_.rate_state->reset_at_breakaway) at.theta = law_.rate_state->state_at_rest(static_mu(at));
    rec.breakaway_t_s.push_back(t);
    return at;
  }
  // U = 0 while slipping, at time t: the slider sticks if the force that holds it is within the
  // threshold (of a contact with no time at rest yet), else slips on, the other way if need be.
  State reattach(State at, double t, RawRecord& rec) const {
    at.xdot = v_;
    rec.reattach_t_s.push_back(t);
    if (slack_N(State{at.x, at.xdot, at.theta, at.h, 0.0, true, at.direction}) <= 0.0) {
      at.stuck = true;
      at.t_rest = 0.0;
    } else {
      at.direction = holding_force_N(at) >= 0.0 ? 1.0 : -1.0;
    }
    return at;
  }
  // The drive speed jumps to v at time t (integrator.h): a stuck slider is carried along by the
  // rigid contact, then tested for breakaway; a slipping one keeps ẋ, and U = 0 is a re-attachment.
  // U is zero but for rounding when a slider at rest in steady sliding (ẋ = 0 up to the last bits
  // of the force balance) meets a stopped drive: |U| ≤ 1e-9 |Δv| counts as zero.
  State jump(State s, double v, double t, RawRecord& rec) {
    const double dv = v - v_;
    v_ = v;
    if (s.stuck) {
      s.xdot = v;
      return slack_N(s) > 0.0 ? break_away(s, t, rec) : s;
    }
    return std::abs(v - s.xdot) <= 1e-9 * std::abs(dv) ? reattach(s, t, rec) : s;
  }

  // Advances by τ, locating at most a few events inside; appends event times.
  State advance(State s, double t, double tau, RawRecord& rec, int depth = 0) const {
    if (tau <= 0.0) return s;
    if (depth > 8) throw std::runtime_error("independent integrator: more than 8 events in one step");
    if (s.stuck) {
      const State end = stick_step(s, tau);
      if (slack_N(end) <= 0.0) return end;
      double lo = 0.0, hi = tau;  // slack(lo) ≤ 0 < slack(hi)
      for (int i = 0; i < kBisections; ++i) {
        const double mid = 0.5 * (lo + hi);
        (slack_N(stick_step(s, mid)) <= 0.0 ? lo : hi) = mid;
      }
      return advance(break_away(stick_step(s, hi), t + hi, rec), t + hi, tau - hi, rec, depth + 1);
    }
    if (s.xdot != v_) s.direction = v_ - s.xdot > 0.0 ? 1.0 : -1.0;
    const State end = slip_step(s, tau);
    const double u0 = s.direction * (v_ - s.xdot), u1 = s.direction * (v_ - end.xdot);  // along the slip
    if (u1 > 0.0 || u0 < 0.0) return end;
    // U reaches zero inside the step: locate it.
    double lo = 0.0, hi = tau;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (lo + hi);
      (s.direction * (v_ - slip_step(s, mid).xdot) > 0.0 ? lo : hi) = mid;
    }
    if (hi < 1e-9 * tau && u0 == 0.0) return end;  // just broke away at U = 0; the slip has not begun
    return advance(reattach(slip_step(s, hi), t + hi, rec), t + hi, tau - hi, rec, depth + 1);
  }

  double friction_now(const State& s) const {
    return s.stuck ? holding_force_N(s) : slip_friction_N(s.xdot, s.theta, s.h, s.direction);
  }

 private:
  RigConstants rig_;
  IndependentLaw law_;
  double v_;
};

}  // namespace

void DriveHistory::validate() const {
  if (start_s.empty() || start_s.size() != speed_m_per_s.size() || start_s.front() != 0.0)
    throw std::invalid_argument("drive history: start_s and speed_m_per_s must be of one length >= 1, start_s[0] = 0");
  for (std::size_t j = 0; j < start_s.size(); ++j) {
    if (!std::isfinite(start_s[j]) || !std::isfinite(speed_m_per_s[j])) throw std::invalid_argument("drive history: not finite");
    if (j && !(start_s[j] > start_s[j - 1])) throw std::invalid_argument("drive history: start_s must increase strictly");
  }
}

std::size_t DriveHistory::segment_at(double t) const {
  const auto after = std::upper_bound(start_s.begin(), start_s.end(), t);
  return after == start_s.begin() ? 0 : static_cast<std::size_t>(after - start_s.begin()) - 1;
}

double DriveHistory::displacement_at(double t) const {
  const std::size_t k = segment_at(t);
  double x = 0.0;
  for (std::size_t j = 0; j < k; ++j) x += speed_m_per_s[j] * (start_s[j + 1] - start_s[j]);
  return x + speed_m_per_s[k] * (t - start_s[k]);
}

RawRecord integrate(const RigConstants& rig, const IndependentLaw& law, const DriveHistory& drive, const IntegratorOptions& o) {
  if (!(o.step_s > 0.0) || !(o.duration_s > o.step_s)) throw std::invalid_argument("independent integrator: step_s and duration_s must be positive, duration > step");
  if (o.record_every < 1) throw std::invalid_argument("independent integrator: record_every must be >= 1");
  drive.validate();
  const double v = drive.speed_m_per_s.front();
  Machine m(rig, law, v);
  RawRecord rec;
  rec.step_s = o.step_s * o.record_every;
  State s;
  s.x = o.initial_displacement_m;
  s.stuck = o.start_stuck;
  s.xdot = o.start_stuck ? v : o.initial_speed_m_per_s;
  s.direction = (v - s.xdot) >= 0.0 ? 1.0 : -1.0;
  if (!o.start_stuck && v == s.xdot) s.direction = m.holding_force_N(s) >= 0.0 ? 1.0 : -1.0;
  // The film starts dry; the rate-and-state contact starts at the steady state of the first drive speed.
  if (law.rate_state) s.theta = law.rate_state->decay_distance_m / std::max(std::abs(v), 1e-12);
  const std::size_t n = static_cast<std::size_t>(std::llround(o.duration_s / o.step_s));
  const std::size_t n_out = n / static_cast<std::size_t>(o.record_every) + 1;
  rec.t_s.reserve(n_out), rec.x_m.reserve(n_out), rec.xdot_m_per_s.reserve(n_out), rec.friction_N.reserve(n_out);
  auto record = [&](double t) {
    rec.t_s.push_back(t);
    rec.x_m.push_back(s.x);
    rec.xdot_m_per_s.push_back(s.xdot);
    rec.friction_N.push_back(m.friction_now(s));
  };
  record(0.0);
  std::size_t segment = 0;  // of the drive, at the start of the step
  for (std::size_t i = 0; i < n; ++i) {
    const double t0 = static_cast<double>(i) * o.step_s, t1 = static_cast<double>(i + 1) * o.step_s;
    try {
      // Up to each drive jump inside (t0, t1], the jump, then the rest of the step: the state
      // recorded at a jump's time is the one after it.
      double t = t0;
      for (; segment + 1 < drive.start_s.size() && drive.start_s[segment + 1] <= t1; ++segment) {
        const double t_jump = drive.start_s[segment + 1];
        s = m.advance(s, t, t_jump - t, rec);
        s = m.jump(s, drive.speed_m_per_s[segment + 1], t_jump, rec);
        t = t_jump;
      }
      s = m.advance(s, t, t1 - t, rec);
    } catch (const std::runtime_error& e) {
      rec.completed = false;
      rec.message = e.what();
      return rec;
    }
    if (!std::isfinite(s.x) || !std::isfinite(s.xdot)) {
      rec.completed = false;
      rec.message = "independent integrator: state not finite at t = " + std::to_string(t0);
      return rec;
    }
    if ((i + 1) % static_cast<std::size_t>(o.record_every) == 0) record(t1);
  }
  return rec;
}

RawRecord integrate(const RigConstants& rig, const IndependentLaw& law, double v, const IntegratorOptions& o) {
  return integrate(rig, law, DriveHistory::constant(v), o);
}

CoulombStickSlip coulomb_stick_slip(const RigConstants& rig, double mu_s, double mu_k, double v) {
  const double delta = (mu_s - mu_k) * rig.normal_load_N / rig.stiffness_N_per_m;
  const double wn = std::sqrt(rig.stiffness_N_per_m / rig.mass_kg);
  return {2.0 * delta, 2.0 * std::hypot(delta, v / wn), 2.0 * delta / v, (M_PI + 2.0 * std::atan(v / (wn * delta))) / wn};
}

}  // namespace tribo::gap::independent
