#include "rig/drive.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tribo::rig {
namespace {

void check_knots(const std::vector<double>& t, const std::vector<double>& v) {
  if (t.empty() || t.size() != v.size()) {
    throw std::invalid_argument("drive: times and speeds must be non-empty and of equal length");
  }
  if (t.front() != 0.0) throw std::invalid_argument("drive: the first time must be 0");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || !std::isfinite(v[i])) {
      throw std::invalid_argument("drive: entry " + std::to_string(i) + " is not finite");
    }
    if (v[i] < 0.0) {
      throw std::invalid_argument("drive: speed at entry " + std::to_string(i) + " is negative (" + std::to_string(v[i]) + " m/s)");
    }
    if (i > 0 && !(t[i] > t[i - 1])) {
      throw std::invalid_argument("drive: times must increase strictly (entry " + std::to_string(i) + ")");
    }
  }
}

}  // namespace

Drive::Drive(std::vector<double> t, std::vector<double> v_start, std::vector<double> slope)
    : t_(std::move(t)), v_start_(std::move(v_start)), slope_(std::move(slope)) {
  x_start_.assign(t_.size(), 0.0);
  for (std::size_t i = 1; i < t_.size(); ++i) {
    const double dt = t_[i] - t_[i - 1];
    x_start_[i] = x_start_[i - 1] + v_start_[i - 1] * dt + 0.5 * slope_[i - 1] * dt * dt;
  }
}

Drive Drive::constant(double speed) { return steps({0.0}, {speed}); }

Drive Drive::steps(const std::vector<double>& t, const std::vector<double>& v) {
  check_knots(t, v);
  return Drive(t, v, std::vector<double>(t.size(), 0.0));
}

Drive Drive::table(const std::vector<double>& t, const std::vector<double>& v) {
  check_knots(t, v);
  std::vector<double> slope(t.size(), 0.0);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) slope[i] = (v[i + 1] - v[i]) / (t[i + 1] - t[i]);
  return Drive(t, v, slope);
}

Drive Drive::slide_hold_slide(double speed, double slide_s, double hold_s) {
  if (!(slide_s > 0.0) || !(hold_s > 0.0)) {
    throw std::invalid_argument("drive: slide and hold durations must be positive");
  }
  return steps({0.0, slide_s, slide_s + hold_s}, {speed, 0.0, speed});
}

std::size_t Drive::segment_at(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
}

double Drive::displacement_m(double t, std::size_t i) const {
  const double dt = t - t_[i];
  return x_start_[i] + v_start_[i] * dt + 0.5 * slope_[i] * dt * dt;
}

double Drive::next_breakpoint_s(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return it == t_.end() ? std::numeric_limits<double>::infinity() : *it;
}

}  // namespace tribo::rig
