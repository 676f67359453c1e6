// The driven surface: speed v(t) of the disc at the friction track, piecewise linear in time.
//
// A constant speed, velocity steps and slide-hold-slide are piecewise-constant histories; a
// table of (t, v) is interpolated linearly. Beyond the last knot the last speed holds. The drive
// displacement X(t) = ∫₀ᵗ v dt' is exact (trapezoids of a piecewise-linear v).
#pragma once

#include <vector>

namespace tribo::rig {

class Drive {
 public:
  // v(t) = speed for all t.
  static Drive constant(double speed_m_per_s);
  // v jumps to speeds[i] at times[i]; times[0] must be 0, strictly increasing.
  static Drive steps(const std::vector<double>& times_s, const std::vector<double>& speeds_m_per_s);
  // v interpolated linearly between (times[i], speeds[i]); times[0] must be 0, strictly increasing.
  static Drive table(const std::vector<double>& times_s, const std::vector<double>& speeds_m_per_s);
  // Slide at v for t_slide, hold (v = 0) for t_hold, slide again at v.
  static Drive slide_hold_slide(double speed_m_per_s, double slide_s, double hold_s);

  double speed_m_per_s(double t_s) const;
  double acceleration_m_per_s2(double t_s) const;
  double displacement_m(double t_s) const;
  double initial_speed_m_per_s() const { return v_start_.front(); }
  // Times where v or dv/dt jumps: the integrator restarts there.
  const std::vector<double>& breakpoints_s() const { return t_; }
  // First breakpoint strictly after t, or +inf.
  double next_breakpoint_s(double t_s) const;

 private:
  Drive(std::vector<double> t, std::vector<double> v_start, std::vector<double> slope);
  std::size_t segment(double t_s) const;

  std::vector<double> t_;        // segment start times, t_[0] = 0
  std::vector<double> v_start_;  // speed at each segment start
  std::vector<double> slope_;    // dv/dt within each segment
  std::vector<double> x_start_;  // displacement at each segment start
};

}  // namespace tribo::rig
