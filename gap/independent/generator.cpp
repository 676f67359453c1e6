#include "gap/independent/generator.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace tribo::gap::independent {
namespace {

double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
double log_uniform(std::mt19937_64& rng, double a, double b) { return std::exp(uniform(rng, std::log(a), std::log(b))); }

// Stick time of undamped Coulomb stick-slip, 2Δ/v (integrator.h's reference), to place the
// stick-time and rate laws so that they matter at the synthetic speeds.
double coulomb_stick_time(const RigConstants& rig, double mu_s, double mu_k, double v) {
  return coulomb_stick_slip(rig, mu_s, mu_k, v).stick_time_s;
}

}  // namespace

const std::vector<std::string>& independent_effects() {
  static const std::vector<std::string> e{"rate_dependent_static", "strain_rate_hardening", "slip_transient", "viscous_friction",
                                          "squeeze_film", "hydrodynamic_lift", "thermal_thinning", "instrument"};
  return e;
}

ExperimentBundle record_bundle(const IndependentLaw& truth, const RigConstants& actual, const RigConstants& told, const ChannelChain& friction,
                               const ChannelChain& displacement, const ChannelChain& velocity, const GeneratorOptions& o, std::uint64_t seed) {
  ExperimentBundle b;
  b.name = "independent";
  b.kind = "pin_on_disc";
  b.mass_kg = told.mass_kg;
  b.stiffness_N_per_m = told.stiffness_N_per_m;
  b.damping_N_s_per_m = told.damping_N_s_per_m;
  b.normal_load_N = told.normal_load_N;
  b.slider_radius_m = told.slider_radius_m;
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 17);
  for (std::size_t k = 0; k < o.speeds_m_per_s.size(); ++k) {
    const double v = o.speeds_m_per_s[k];
    IntegratorOptions io;
    io.step_s = o.step_s;
    io.duration_s = o.duration_s;
    const RawRecord raw = integrate(actual, truth, v, io);
    if (!raw.completed) throw std::runtime_error("independent generator: run at " + std::to_string(v) + " m/s did not complete: " + raw.message);
    Run run;
    run.run_id = std::to_string(k);
    run.v_m_per_s = v;
    run.file = "traces/run_" + run.run_id + ".csv";
    run.trace.friction_N = record_channel(raw.friction_N, raw.step_s, friction, o.recorder, rng, &run.trace.t_s);
    run.trace.x_m = record_channel(raw.x_m, raw.step_s, displacement, o.recorder, rng, nullptr);
    run.trace.xdot_m_per_s = record_channel(raw.xdot_m_per_s, raw.step_s, velocity, o.recorder, rng, nullptr);
    // The operator's static friction: the recorded maximum around each breakaway (the filter
    // delays and rounds it), averaged over the breakaways after the start-up transient.
    double mu_sum = 0.0;
    int n = 0;
    const auto& t = run.trace.t_s;
    for (double tb : raw.breakaway_t_s) {
      if (tb < 0.3 * o.duration_s) continue;
      double peak = -1e300;
      for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= tb - 5e-3 && t[i] <= tb + 1e-2) peak = std::max(peak, run.trace.friction_N[i]);
      if (peak > -1e300) mu_sum += peak / told.normal_load_N, ++n;
    }
    if (n) b.static_points.push_back({told.stiffness_N_per_m * v / told.normal_load_N, mu_sum / n});
    b.runs.push_back(std::move(run));
  }
  return b;
}

IndependentCase make_independent_case(const std::string& effect, std::uint64_t seed, const GeneratorOptions& o) {
  if (effect != "none" && std::find(independent_effects().begin(), independent_effects().end(), effect) == independent_effects().end())
    throw std::invalid_argument("independent generator: unknown effect '" + effect + "'");
  std::mt19937_64 rng(seed * 2654435761ULL + 0x1F2E3D4CULL);
  IndependentCase c;
  c.true_effect = effect;
  const double mu_s = uniform(rng, 0.28, 0.36), mu_k = uniform(rng, 0.16, 0.21);
  c.truth.mu_s = mu_s, c.truth.mu_k = mu_k;
  c.model_mu_s = 1.15 * mu_s, c.model_mu_k = 0.9 * mu_k;

  // The rig as it is: a few per cent off what the bundle tells.
  c.told = RigConstants{};
  c.actual = c.told;
  auto spread = [&](double f) { return 1.0 + uniform(rng, -f, f); };
  c.actual.stiffness_N_per_m *= spread(o.constant_spread);
  c.actual.mass_kg *= spread(o.constant_spread);
  c.actual.normal_load_N *= spread(o.constant_spread);
  c.actual.damping_N_s_per_m *= spread(o.damping_spread);
  const double W = c.actual.normal_load_N;

  // A benign chain on every channel: ±2 % gain, ≤ 0.5 ms delay, a 0.2 ms sensor, offset and drift
  // of a few tenths of a per cent of μk W, AR(1) noise, a 12-bit converter over ±2 W.
  c.friction_chain.gain = spread(0.02);
  c.friction_chain.delay_s = uniform(rng, 0.0, 5e-4);
  c.friction_chain.sensor_time_constant_s = 2e-4;
  c.friction_chain.offset = uniform(rng, -0.003, 0.003) * mu_k * W;
  c.friction_chain.drift_per_s = uniform(rng, -0.002, 0.002) * mu_k * W / o.duration_s;
  c.friction_chain.noise_rms = o.noise_fraction * mu_k * W;
  c.friction_chain.noise_correlation = uniform(rng, 0.5, 0.9);
  c.friction_chain.quantum = 4.0 * c.told.normal_load_N / 4096.0;
  c.displacement_chain.gain = spread(0.01);
  c.displacement_chain.noise_rms = 2e-6;
  c.displacement_chain.noise_correlation = 0.5;
  c.displacement_chain.quantum = 0.02 / 4096.0;  // ±10 mm over 12 bits
  c.velocity_chain.gain = spread(0.02);
  c.velocity_chain.noise_rms = 1e-3;
  c.velocity_chain.noise_correlation = 0.5;
  c.velocity_chain.quantum = 0.4 / 4096.0;  // ±0.2 m/s

  const double v_mid = o.speeds_m_per_s[o.speeds_m_per_s.size() / 2];
  if (effect == "none") {
    c.form = "Coulomb";
  } else if (effect == "rate_dependent_static") {
    StickTimeAgeing a;
    a.mu_inf = uniform(rng, 0.45, 0.6);
    a.exponent = uniform(rng, 0.5, 1.0);
    a.mu_0 = mu_k + uniform(rng, 0.02, 0.05);
    const double target = mu_s + uniform(rng, 0.0, 0.05);
    const double t_mid = coulomb_stick_time(c.actual, target, mu_k, v_mid);
    const double L = std::log((a.mu_inf - a.mu_0) / (a.mu_inf - target));
    a.time_s = t_mid / std::pow(L, 1.0 / a.exponent);
    c.truth.stick_ageing = a;
    c.form = "stick-time ageing, Kato et al. 1972";
  } else if (effect == "strain_rate_hardening") {
    RateHardening h;
    h.mu_s_ref = mu_s + uniform(rng, 0.03, 0.08);
    h.coefficient = uniform(rng, 0.08, 0.2);
    h.reference_rate_per_s = c.actual.stiffness_N_per_m * o.speeds_m_per_s.front() / W;
    c.truth.rate_hardening = h;
    c.form = "Johnson-Cook logarithmic rate hardening";
  } else if (effect == "slip_transient") {
    // Odd seeds the slip law (Ruina 1983), even seeds the ageing law (Dieterich 1979). b small
    // enough that the steady-state weakening (a − b) ln V stays a minor part: the transient
    // μs → μss, set by the reset, carries the mechanism.
    RateState rs;
    rs.evolution = seed % 2 ? RateState::Evolution::slip : RateState::Evolution::ageing;
    rs.b = uniform(rng, 0.01, 0.02);
    rs.a = 0.1 * rs.b;
    rs.reference_speed_m_per_s = 1e-2;
    rs.decay_distance_m = log_uniform(rng, 3e-4, 1.5e-3);
    // The ageing law takes ln θ down linearly at first, over ≈ ln(θ0 V/D_c) · D_c: shorten D_c so
    // that friction has fallen by 1/e of the drop after about the drawn distance.
    if (rs.evolution == RateState::Evolution::ageing) rs.decay_distance_m /= std::max(1.0, (mu_s - mu_k) / rs.b);
    // Steady sliding at the middle speed at μk: μ0 + a ln(1 + v/V0) + b ln(V0/v) = μk.
    rs.mu_0 = mu_k - rs.a * std::log1p(v_mid / rs.reference_speed_m_per_s) - rs.b * std::log(rs.reference_speed_m_per_s / v_mid);
    c.truth.rate_state = rs;
    c.form = rs.evolution == RateState::Evolution::slip ? "Dieterich-Ruina rate and state, slip law" : "Dieterich-Ruina rate and state, ageing law";
  } else if (effect == "viscous_friction") {
    c.truth.eyring = EyringFilm{uniform(rng, 20.0, 45.0), log_uniform(rng, 0.02, 0.08)};
    c.form = "Eyring shear-thinning film";
  } else if (effect == "squeeze_film") {
    SqueezeFilmOde s;
    s.max_fraction = uniform(rng, 0.4, 0.7);
    s.build_up_distance_m = log_uniform(rng, 5e-4, 3e-3);
    // Film thickness from the time to squeeze it to half (h⁻³ law): τ½ = 7π η R⁴ / (2 φ_max W h_e²).
    const double t_half = log_uniform(rng, 0.01, 0.04);
    s.full_thickness_m = std::sqrt(7.0 * M_PI * s.viscosity_Pa_s * std::pow(s.radius_m, 4) / (2.0 * s.max_fraction * W * t_half));
    c.truth.squeeze = s;
    c.form = "film-thickness ODE, Reynolds parallel-disc squeeze";
  } else if (effect == "hydrodynamic_lift") {
    c.truth.lift = StribeckLift{uniform(rng, 0.4, 0.6), log_uniform(rng, 0.01, 0.03), uniform(rng, 1.0, 2.0)};
    c.form = "exponential Stribeck lift";
  } else if (effect == "thermal_thinning") {
    VogelThinning th;
    th.coefficient_N_s_per_m = uniform(rng, 250.0, 500.0);
    th.heating_K_s_per_m = VogelThinning::heating_for_maximum_at(log_uniform(rng, 0.015, 0.04), th.bulk_temperature_K, th.vogel_B_K, th.vogel_T_inf_K);
    c.truth.vogel = th;
    c.form = "Vogel viscosity, flash temperature linear in speed";
  } else if (effect == "instrument") {
    const double g = uniform(rng, 1.15, 1.3);
    c.friction_chain.gain *= std::uniform_int_distribution<int>(0, 1)(rng) ? g : 1.0 / g;
    c.friction_chain.sensor_time_constant_s = uniform(rng, 1e-3, 3e-3);
    c.form = "load-cell gain error and first-order lag";
  }
  c.bundle = record_bundle(c.truth, c.actual, c.told, c.friction_chain, c.displacement_chain, c.velocity_chain, o, seed);
  return c;
}

}  // namespace tribo::gap::independent
