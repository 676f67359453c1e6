#include "rig/composite_law.h"

#include <algorithm>
#include <stdexcept>

#include "rig/homogenised_law.h"

namespace tribo::rig {

CompositeLaw::CompositeLaw(BaselineLaw baseline, std::optional<contact::JunctionLocus> locus,
                           std::vector<std::unique_ptr<FrictionEffect>> effects)
    : baseline_(std::move(baseline)), locus_(std::move(locus)), effects_(std::move(effects)) {
  if (locus_) contact::validate(*locus_);
  if (baseline_.homogenised && locus_) {
    throw std::invalid_argument("friction: a static-friction locus cannot be combined with the homogenised law (its table has the locus)");
  }
  base_size_ = baseline_.homogenised ? HomogenisedBase::kStateSize : 0;
  state_size_ = base_size_;
  for (const auto& e : effects_) {
    offsets_.push_back(state_size_);
    state_size_ += e->state_size();
  }
}

std::string CompositeLaw::name() const {
  std::string n = baseline_.homogenised ? "homogenised" : baseline_.kinetic ? "kinetic_curve" : "coulomb";
  if (locus_) n += locus_->strain_rate_index_m > 0.0 ? "+junction_locus(m>0)" : "+junction_locus";
  for (const auto& e : effects_) n.append("+").append(e->name());  // not "+" + name(): a false -Wrestrict of GCC 12
  return n;
}

void CompositeLaw::initial_state(std::span<double> state) const {
  if (baseline_.homogenised) baseline_.homogenised->initial_state(state.first(base_size_));
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->initial_state(slice(state, i));
}

void CompositeLaw::state_tolerances(std::span<double> atol, double mu_tolerance) const {
  if (baseline_.homogenised) baseline_.homogenised->state_tolerances(atol.first(base_size_));
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->state_tolerances(slice(atol, i), mu_tolerance);
}

double CompositeLaw::static_coefficient(const FrictionContext& c) const {
  if (baseline_.homogenised) return baseline_.homogenised->static_coefficient(c);
  return locus_ ? contact::static_friction_from_load_rate(*locus_, c.tangential_load_rate_per_s) : baseline_.mu_s;
}

double CompositeLaw::baseline_kinetic_coefficient(double u) const {
  return baseline_.kinetic ? baseline_.kinetic->mu(u) : baseline_.mu_k;
}

template <class Visit>
std::optional<double> CompositeLaw::for_each_effect(const FrictionContext& c, Visit&& visit) const {
  if (effects_.empty()) return std::nullopt;
  EffectContext e;
  e.rig = &c;
  e.mu_s = static_coefficient(c);
  e.mu_k_baseline = baseline_.homogenised ? baseline_.homogenised->solid_kinetic_coefficient(base_state(c), c.relative_speed_m_per_s)
                                          : baseline_kinetic_coefficient(c.relative_speed_m_per_s);
  for (std::size_t i = 0; i < effects_.size(); ++i) {
    e.state = slice(c.state, i);
    visit(i, e);
  }
  return e.mu_s;
}

CompositeLaw::Channels CompositeLaw::channels(const FrictionContext& c, double increment_start) const {
  Channels s;
  s.kinetic = increment_start;
  s.mu_s = for_each_effect(c, [&](std::size_t i, const EffectContext& e) {
    s.solid_fraction *= effects_[i]->solid_fraction(e);
    s.kinetic += effects_[i]->kinetic_increment(e);
    s.fluid_N += effects_[i]->fluid_force_N(e);
    s.static_increment += effects_[i]->static_increment(e);
  });
  return s;
}

double CompositeLaw::static_limit_N(const FrictionContext& c) const {
  FrictionContext at_rest = c;
  at_rest.relative_speed_m_per_s = 0.0;
  const Channels s = channels(at_rest, 0.0);
  if (baseline_.homogenised) return baseline_.homogenised->static_limit_N(c, s.solid_fraction, s.static_increment);
  const double mu_s = s.mu_s ? *s.mu_s : static_coefficient(c);  // at rest or not, μs reads the load rate only
  return s.solid_fraction * (mu_s + s.static_increment) * c.normal_load_N;
}

double CompositeLaw::kinetic_force_N(const FrictionContext& c) const {
  if (baseline_.homogenised) {
    const Channels s = channels(c, 0.0);
    return baseline_.homogenised->kinetic_force_N(c, s.solid_fraction, s.kinetic, s.fluid_N);
  }
  const Channels s = channels(c, baseline_kinetic_coefficient(c.relative_speed_m_per_s));
  return s.solid_fraction * s.kinetic * c.normal_load_N + s.fluid_N;
}

void CompositeLaw::state_rates(const FrictionContext& c, std::span<double> rates) const {
  if (baseline_.homogenised) {
    // Friction power P = F_k |U| heats the film (Jaeger, homogenised_law.h); none while stuck.
    const double fk = c.relative_speed_m_per_s > 0.0 ? kinetic_force_N(c) : 0.0;
    baseline_.homogenised->state_rates(c, fk, rates.first(base_size_));
  }
  for_each_effect(c, [&](std::size_t i, const EffectContext& e) { effects_[i]->state_rates(e, slice(rates, i)); });
}

bool CompositeLaw::stiff(double normal_load_N, double natural_frequency_rad_per_s) const {
  return std::any_of(effects_.begin(), effects_.end(),
                     [&](const auto& e) { return e->stiff(normal_load_N, natural_frequency_rad_per_s); });
}

void CompositeLaw::on_slip_onset(const FrictionContext& c, std::span<double> state) const {
  for_each_effect(c, [&](std::size_t i, const EffectContext& e) { effects_[i]->on_slip_onset(e, slice(state, i)); });
}

}  // namespace tribo::rig
