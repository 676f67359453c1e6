#include "rig/composite_law.h"

namespace tribo::rig {

CompositeLaw::CompositeLaw(BaselineLaw baseline, std::optional<contact::JunctionLocus> locus,
                           std::vector<std::unique_ptr<FrictionEffect>> effects)
    : baseline_(std::move(baseline)), locus_(std::move(locus)), effects_(std::move(effects)) {
  if (locus_) contact::validate(*locus_);
  for (const auto& e : effects_) {
    offsets_.push_back(state_size_);
    state_size_ += e->state_size();
  }
}

std::string CompositeLaw::name() const {
  std::string n = baseline_.kinetic ? "kinetic_curve" : "coulomb";
  if (locus_) n += locus_->strain_rate_index_m > 0.0 ? "+junction_locus(m>0)" : "+junction_locus";
  for (const auto& e : effects_) n += "+" + e->name();
  return n;
}

void CompositeLaw::initial_state(std::span<double> state) const {
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->initial_state(slice(state, i));
}

void CompositeLaw::state_tolerances(std::span<double> atol) const {
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->state_tolerances(slice(atol, i));
}

double CompositeLaw::static_coefficient(const FrictionContext& c) const {
  return locus_ ? contact::static_friction_from_load_rate(*locus_, c.tangential_load_rate_per_s) : baseline_.mu_s;
}

double CompositeLaw::baseline_kinetic_coefficient(double u) const {
  return baseline_.kinetic ? baseline_.kinetic->mu(u) : baseline_.mu_k;
}

EffectContext CompositeLaw::effect_context(const FrictionContext& c, std::size_t i) const {
  EffectContext e;
  e.rig = &c;
  e.mu_s = static_coefficient(c);
  e.mu_k_baseline = baseline_kinetic_coefficient(c.relative_speed_m_per_s);
  e.state = slice(c.state, i);
  return e;
}

double CompositeLaw::solid_fraction(const FrictionContext& c) const {
  double chi = 1.0;
  for (std::size_t i = 0; i < effects_.size(); ++i) chi *= effects_[i]->solid_fraction(effect_context(c, i));
  return chi;
}

double CompositeLaw::static_limit_N(const FrictionContext& c) const {
  FrictionContext at_rest = c;
  at_rest.relative_speed_m_per_s = 0.0;
  return solid_fraction(at_rest) * static_coefficient(c) * c.normal_load_N;
}

double CompositeLaw::kinetic_force_N(const FrictionContext& c) const {
  double mu = baseline_kinetic_coefficient(c.relative_speed_m_per_s), fluid = 0.0, chi = 1.0;
  for (std::size_t i = 0; i < effects_.size(); ++i) {
    const EffectContext e = effect_context(c, i);
    chi *= effects_[i]->solid_fraction(e);
    mu += effects_[i]->kinetic_increment(e);
    fluid += effects_[i]->fluid_force_N(e);
  }
  return chi * mu * c.normal_load_N + fluid;
}

void CompositeLaw::state_rates(const FrictionContext& c, std::span<double> rates) const {
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->state_rates(effect_context(c, i), slice(rates, i));
}

void CompositeLaw::on_slip_onset(const FrictionContext& c, std::span<double> state) const {
  for (std::size_t i = 0; i < effects_.size(); ++i) effects_[i]->on_slip_onset(effect_context(c, i), slice(state, i));
}

}  // namespace tribo::rig
