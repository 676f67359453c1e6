// The baseline friction laws: static coefficient μs constant, kinetic coefficient either
// constant (Coulomb) or a function of the relative speed |U|.
//
//   Coulomb:           F_static = μs W,   F_k = μk W
//   Stribeck-type:     μk(U) = μc + (μs0 − μc) exp(−(U/Us)^δ) + cv U        (negative slope allowed)
//   Tabulated:         μk(U) linear between (U_i, μ_i); constant beyond the ends
//
// A negative slope −W dμk/dU larger than the rig's damping r makes steady sliding unstable
// (thesis Appendix II), the origin of quasi-harmonic oscillation.
#pragma once

#include <memory>
#include <vector>

#include "rig/friction_law.h"

namespace tribo::rig {

// μk as a function of |U| (m/s). Implementations are pure functions of speed.
class KineticCurve {
 public:
  virtual ~KineticCurve() = default;
  virtual double mu(double speed_m_per_s) const = 0;
  virtual double slope_per_m_per_s(double speed_m_per_s) const = 0;  // dμk/dU
};

class ConstantCurve final : public KineticCurve {
 public:
  explicit ConstantCurve(double mu_k);
  double mu(double) const override { return mu_k_; }
  double slope_per_m_per_s(double) const override { return 0.0; }

 private:
  double mu_k_;
};

struct StribeckParameters {
  double mu_coulomb = 0.12;            // μc, high-speed level
  double mu_breakaway = 0.2;           // μs0, level as U → 0⁺
  double stribeck_speed_m_per_s = 0.01;  // Us
  double exponent = 1.0;               // δ
  double viscous_per_m_per_s = 0.0;    // cv, coefficient per unit speed
};

class StribeckCurve final : public KineticCurve {
 public:
  explicit StribeckCurve(const StribeckParameters& p);
  double mu(double u) const override;
  double slope_per_m_per_s(double u) const override;

 private:
  StribeckParameters p_;
};

class TabulatedCurve final : public KineticCurve {
 public:
  // speeds strictly increasing, ≥ 0; μ ≥ 0.
  TabulatedCurve(std::vector<double> speeds_m_per_s, std::vector<double> mu);
  double mu(double u) const override;
  double slope_per_m_per_s(double u) const override;

 private:
  std::vector<double> u_, mu_;
};

// μs constant, μk from a curve. With a ConstantCurve this is the Coulomb law of the baseline.
class KineticCurveLaw final : public FrictionLaw {
 public:
  KineticCurveLaw(double mu_s, std::shared_ptr<const KineticCurve> kinetic);
  std::string name() const override { return "kinetic_curve"; }
  double static_limit_N(const FrictionContext& c) const override { return mu_s_ * c.normal_load_N; }
  double kinetic_force_N(const FrictionContext& c) const override {
    return kinetic_->mu(c.relative_speed_m_per_s) * c.normal_load_N;
  }
  double mu_s() const { return mu_s_; }
  const KineticCurve& kinetic() const { return *kinetic_; }

 private:
  double mu_s_;
  std::shared_ptr<const KineticCurve> kinetic_;
};

// The Coulomb law (constant μs ≥ μk).
std::unique_ptr<KineticCurveLaw> make_coulomb(double mu_s, double mu_k);

}  // namespace tribo::rig
