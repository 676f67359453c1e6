// The driven surface: speed v(t) of the disc at the friction track, piecewise linear in time.
//
// A constant speed, velocity steps and slide-hold-slide are piecewise-constant histories; a
// table of (t, v) is interpolated linearly. Beyond the last knot the last speed holds. The drive
// displacement X(t) = ∫₀ᵗ v dt' is exact (trapezoids of a piecewise-linear v).
#pragma once

#include <cstddef>
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

  double speed_m_per_s(double t_s) const { return speed_m_per_s(t_s, segment_at(t_s)); }
  double acceleration_m_per_s2(double t_s) const { return acceleration_m_per_s2(t_s, segment_at(t_s)); }
  double displacement_m(double t_s) const { return displacement_m(t_s, segment_at(t_s)); }
  // The segment t lies in: [breakpoint i, breakpoint i + 1), so a breakpoint starts the new one.
  std::size_t segment_at(double t_s) const;
  // The same quantities by segment i's formula, which holds on its closed interval: at the next
  // breakpoint these are the limits from the left. The simulator integrates one segment at a
  // time, and its event functions at the segment's end must see the drive that led there.
  double speed_m_per_s(double t_s, std::size_t i) const { return v_start_[i] + slope_[i] * (t_s - t_[i]); }
  double acceleration_m_per_s2(double, std::size_t i) const { return slope_[i]; }
  double displacement_m(double t_s, std::size_t i) const;
  double initial_speed_m_per_s() const { return v_start_.front(); }
  // Times where v or dv/dt jumps: the integrator restarts there.
  const std::vector<double>& breakpoints_s() const { return t_; }
  // First breakpoint strictly after t, or +inf.
  double next_breakpoint_s(double t_s) const;

 private:
  Drive(std::vector<double> t, std::vector<double> v_start, std::vector<double> slope);

  std::vector<double> t_;        // segment start times, t_[0] = 0
  std::vector<double> v_start_;  // speed at each segment start
  std::vector<double> slope_;    // dv/dt within each segment
  std::vector<double> x_start_;  // displacement at each segment start
};

}  // namespace tribo::rig
