#include "gap/independent/generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <stdexcept>

namespace tribo::gap::independent {
namespace {

double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
double log_uniform(std::mt19937_64& rng, double a, double b) { return std::exp(uniform(rng, std::log(a), std::log(b))); }

// The rig as it is: k, M and W within ± constant_spread of what the bundle tells, the damping
// (known worst) within ± damping_spread.
RigConstants as_it_is(const RigConstants& told, double constant_spread, double damping_spread, std::mt19937_64& rng) {
  auto spread = [&](double f) { return 1.0 + uniform(rng, -f, f); };
  RigConstants actual = told;
  actual.stiffness_N_per_m *= spread(constant_spread);
  actual.mass_kg *= spread(constant_spread);
  actual.normal_load_N *= spread(constant_spread);
  actual.damping_N_s_per_m *= spread(damping_spread);
  return actual;
}

// What the bundle says of how well it knows k, M and r: the spreads as_it_is() draws within, as an
// operator states a calibration's tolerance. (W's error is a scale of μ for these laws; not stated.)
std::map<std::string, double> stated_uncertainty(double constant_spread, double damping_spread) {
  return {{"mass_kg", constant_spread}, {"stiffness_N_per_m", constant_spread}, {"damping_N_s_per_m", damping_spread}};
}

// Stick time of undamped Coulomb stick-slip, 2Δ/v (integrator.h's reference), to place the
// stick-time and rate laws so that they matter at the synthetic speeds.
double coulomb_stick_time(const RigConstants& rig, double mu_s, double mu_k, double v) {
  return coulomb_stick_slip(rig, mu_s, mu_k, v).stick_time_s;
}

// The explicit RK4 step for a drive-history run. The fastest rate of the slipping machine is the
// slider's speed following the friction: the direct effect acts as a damper aW/(V0 + U)
// (laws.h: ∂μ/∂U = a/(V0 + U)), so that rate is (aW/(V0 + U) + r)/M at the lowest slip speed U
// the run meets; RK4 is stable below 2.79/rate on the negative axis (1.5 kept). The oscillation
// is resolved at ω_n Δt ≤ 0.2. (Halving or quartering the step moves the record by ≤ 2e-6 μ.)
double stable_step_s(const RigConstants& rig, const IndependentLaw& law, double lowest_slip_speed_m_per_s) {
  double damping = rig.damping_N_s_per_m;
  if (law.rate_state) damping += law.rate_state->a * rig.normal_load_N / (law.rate_state->reference_speed_m_per_s + lowest_slip_speed_m_per_s);
  return std::min(1.5 * rig.mass_kg / damping, 0.2 * std::sqrt(rig.mass_kg / rig.stiffness_N_per_m));
}

// The slide-hold-slide and velocity-step cases (generator.h).
IndependentCase make_drive_history_case(const std::string& kind, const std::string& effect, std::uint64_t seed, const DriveHistoryOptions& o) {
  if (effect != "rate_and_state" && effect != "none")
    throw std::invalid_argument("independent generator: no " + kind + " case for effect '" + effect + "' (rate_and_state or none)");
  const bool shs = kind == "slide_hold_slide";
  // Every draw is made whatever the effect: one seed, one machine, drive and chain for both.
  std::mt19937_64 rng(seed * 0x2545F4914F6CDD1DULL + (shs ? 0x5A1DULL : 0x7E57ULL));
  IndependentCase c;
  c.true_effect = effect;
  // The material, in the ranges of rock and gouge (Marone 1998): steady friction at V, a, b − a
  // (velocity weakening), D_c; the velocity step at a ≈ 0.01, b ≈ 0.012.
  const double mu_ss = uniform(rng, 0.55, 0.7);
  const double a = shs ? uniform(rng, 0.005, 0.015) : uniform(rng, 0.008, 0.012);
  const double b = a + (shs ? uniform(rng, 0.002, 0.01) : uniform(rng, 0.0015, 0.0025));
  const double V = log_uniform(rng, 1e-6, 1e-5);
  const double dc = log_uniform(rng, 1e-6, std::min(2e-5, 2.0 * V));  // D_c/V ≤ 2 s: a record of minutes, not hours
  const double mu_s_coulomb = mu_ss + uniform(rng, 0.01, 0.03);       // the control's static friction
  // The machine as told. Stiff: at least five times the critical stiffness W(b − a)/D_c of
  // steady sliding (Ruina 1983; Rice & Ruina 1983), so that the record is stable sliding with
  // transients. Well damped: ζ in [0.3, 0.7]. The mass is a loading train's: it only sets how
  // fast the slider's speed follows the friction, at (aW/V0)/M ≫ every rate of the test (the
  // direct effect overdamps the machine), and keeps the explicit step (stable_step_s) ≥ 1e-5 s.
  c.told.normal_load_N = uniform(rng, 50.0, 100.0);
  c.told.mass_kg = log_uniform(rng, 10.0, 50.0);
  c.told.stiffness_N_per_m = std::max(log_uniform(rng, 1e5, 1e6), 5.0 * c.told.normal_load_N * (b - a) / dc);
  c.told.damping_N_s_per_m = 2.0 * uniform(rng, 0.3, 0.7) * std::sqrt(c.told.stiffness_N_per_m * c.told.mass_kg);
  c.actual = as_it_is(c.told, o.constant_spread, o.damping_spread, rng);
  auto spread = [&](double f) { return 1.0 + uniform(rng, -f, f); };
  const double W = c.actual.normal_load_N, k = c.actual.stiffness_N_per_m;

  // A laboratory chain: ±2 % gain, ≤ 5 ms delay, offset and drift (over the record, once its
  // length is known) of a few tenths of a per cent of μW, AR(1) noise at noise_fraction of μW, a
  // 16-bit converter over ±2 W; the displacement (the spring's stretch, μW/k) to 0.1 % of itself,
  // 16 bits over ±2 W/k.
  c.friction_chain.gain = spread(0.02);
  c.friction_chain.delay_s = uniform(rng, 0.0, 5e-3);
  c.friction_chain.sensor_time_constant_s = 2e-4;
  c.friction_chain.offset = uniform(rng, -0.003, 0.003) * mu_ss * W;
  const double drift_fraction = uniform(rng, -0.002, 0.002);
  c.friction_chain.noise_rms = o.noise_fraction * mu_ss * W;
  c.friction_chain.noise_correlation = uniform(rng, 0.5, 0.9);
  c.friction_chain.quantum = 4.0 * c.told.normal_load_N / 65536.0;
  c.displacement_chain.gain = spread(0.01);
  c.displacement_chain.noise_rms = 1e-3 * mu_ss * W / k;
  c.displacement_chain.noise_correlation = 0.5;
  c.displacement_chain.quantum = 4.0 * c.told.normal_load_N / c.told.stiffness_N_per_m / 65536.0;

  // The drive: slides of slide_decay_lengths · D_c at each speed (the ageing law's state returns
  // to steady sliding as exp(−slip/D_c): 25 D_c leaves e⁻²⁵ of a hold's θ) and at least
  // min_slide_s long, holds at v = 0.
  const double slide_m = o.slide_decay_lengths * dc;
  double t_end = 0.0;
  auto segment = [&](double duration_s, double v) {
    c.drive.start_s.push_back(t_end);
    c.drive.speed_m_per_s.push_back(v);
    t_end += duration_s;
  };
  auto slide = [&](double v) { segment(std::max(slide_m / v, o.min_slide_s), v); };
  slide(V);
  if (shs) {
    for (double hold : o.hold_times_s) segment(hold, 0.0), slide(V);
  } else {
    slide(o.step_factor * V);
    slide(V);
  }
  c.friction_chain.drift_per_s = drift_fraction * mu_ss * W / t_end;

  c.truth.mu_s = mu_s_coulomb, c.truth.mu_k = mu_ss;
  // The diagnosis' model: the control's Coulomb law, μs 3 % high and μk 2 % low.
  c.model_mu_s = 1.03 * mu_s_coulomb, c.model_mu_k = 0.98 * mu_ss;
  if (effect == "rate_and_state") {
    RateState rs;
    rs.evolution = RateState::Evolution::ageing;
    rs.reset_at_breakaway = false;
    rs.a = a, rs.b = b, rs.decay_distance_m = dc;
    rs.reference_speed_m_per_s = shs ? V : 0.01 * V;
    // Steady sliding at V at μss: μ0 + a ln(1 + V/V0) + b ln(V0/V) = μss.
    rs.mu_0 = mu_ss - a * std::log1p(V / rs.reference_speed_m_per_s) - b * std::log(rs.reference_speed_m_per_s / V);
    c.truth.rate_state = rs;
    c.form = "Dieterich-Ruina rate and state, ageing law, healing while stuck";
  } else {
    c.form = "Coulomb";
  }

  // From steady sliding at V: the slider at rest (ẋ = 0) where the spring holds μss W. The
  // lowest slip speed: 0 at a hold's stick; in a velocity step the slider only moves to take up
  // the spring's share of a friction change, U stays near the drive's speed (half of V kept).
  const int n = static_cast<int>(std::ceil(o.output_step_s / stable_step_s(c.actual, c.truth, shs ? 0.0 : 0.5 * V)));
  IntegratorOptions io;
  io.step_s = o.output_step_s / n;
  io.record_every = n;
  io.duration_s = t_end;
  io.start_stuck = false;
  io.initial_displacement_m = mu_ss * W / k;
  const RawRecord raw = integrate(c.actual, c.truth, c.drive, io);
  if (!raw.completed) throw std::runtime_error("independent generator: " + kind + " run did not complete: " + raw.message);

  ExperimentBundle& bundle = c.bundle;
  bundle.name = "independent_" + kind;
  bundle.kind = kind;
  bundle.mass_kg = c.told.mass_kg;
  bundle.stiffness_N_per_m = c.told.stiffness_N_per_m;
  bundle.damping_N_s_per_m = c.told.damping_N_s_per_m;
  bundle.normal_load_N = c.told.normal_load_N;
  bundle.slider_radius_m = c.told.slider_radius_m;
  bundle.relative_uncertainty = stated_uncertainty(o.constant_spread, o.damping_spread);
  std::mt19937_64 noise_rng(seed * 0x9E3779B97F4A7C15ULL + 29);
  Run run;
  run.run_id = "0";
  run.v_m_per_s = V;
  run.file = "traces/run_0.csv";
  Trace& tr = run.trace;
  tr.friction_N = record_channel(raw.friction_N, raw.step_s, c.friction_chain, o.recorder, noise_rng, &tr.t_s);
  tr.x_m = record_channel(raw.x_m, raw.step_s, c.displacement_chain, o.recorder, noise_rng, nullptr);
  for (double t : tr.t_s) tr.x_drive_m.push_back(c.drive.displacement_at(t)), tr.v_drive_m_per_s.push_back(c.drive.speed_at(t));
  bundle.runs.push_back(std::move(run));
  return c;
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
  b.relative_uncertainty = stated_uncertainty(o.constant_spread, o.damping_spread);
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ULL + 17);
  for (std::size_t k = 0; k < o.speeds_m_per_s.size(); ++k) {
    const double v = o.speeds_m_per_s[k];
    IntegratorOptions io;
    io.step_s = o.step_s;
    io.duration_s = o.duration_s;
    const RawRecord raw = integrate(actual, truth, v, io);
    if (!raw.completed) {
      char speed[32];
      std::snprintf(speed, sizeof speed, "%g", v);
      throw std::runtime_error(std::string("independent generator: run at ") + speed + " m/s did not complete: " + raw.message);
    }
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
  c.actual = as_it_is(c.told, o.constant_spread, o.damping_spread, rng);
  auto spread = [&](double f) { return 1.0 + uniform(rng, -f, f); };
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

IndependentCase make_slide_hold_slide_case(const std::string& effect, std::uint64_t seed, const DriveHistoryOptions& o) {
  return make_drive_history_case("slide_hold_slide", effect, seed, o);
}

IndependentCase make_velocity_step_case(const std::string& effect, std::uint64_t seed, const DriveHistoryOptions& o) {
  return make_drive_history_case("velocity_step", effect, seed, o);
}

std::map<std::string, double> truth_parameters(const IndependentCase& c) {
  const IndependentLaw& t = c.truth;
  std::map<std::string, double> p{{"coulomb.mu_s", t.mu_s},
                                  {"coulomb.mu_k", t.mu_k},
                                  {"rig.mass_kg", c.actual.mass_kg},
                                  {"rig.stiffness_N_per_m", c.actual.stiffness_N_per_m},
                                  {"rig.damping_N_s_per_m", c.actual.damping_N_s_per_m},
                                  {"rig.normal_load_N", c.actual.normal_load_N},
                                  {"friction_channel.gain", c.friction_chain.gain},
                                  {"friction_channel.delay_s", c.friction_chain.delay_s},
                                  {"friction_channel.sensor_time_constant_s", c.friction_chain.sensor_time_constant_s}};
  if (t.stick_ageing)
    p.insert({{"stick_ageing.mu_0", t.stick_ageing->mu_0},
              {"stick_ageing.mu_inf", t.stick_ageing->mu_inf},
              {"stick_ageing.time_s", t.stick_ageing->time_s},
              {"stick_ageing.exponent", t.stick_ageing->exponent}});
  if (t.rate_hardening)
    p.insert({{"rate_hardening.mu_s_ref", t.rate_hardening->mu_s_ref},
              {"rate_hardening.coefficient", t.rate_hardening->coefficient},
              {"rate_hardening.reference_rate_per_s", t.rate_hardening->reference_rate_per_s}});
  if (t.rate_state)
    p.insert({{"rate_state.mu_0", t.rate_state->mu_0},
              {"rate_state.a", t.rate_state->a},
              {"rate_state.b", t.rate_state->b},
              {"rate_state.reference_speed_m_per_s", t.rate_state->reference_speed_m_per_s},
              {"rate_state.decay_distance_m", t.rate_state->decay_distance_m},
              {"rate_state.slip_law", t.rate_state->evolution == RateState::Evolution::slip ? 1.0 : 0.0}});
  if (t.lift)
    p.insert({{"lift.max_fraction", t.lift->max_fraction},
              {"lift.stribeck_speed_m_per_s", t.lift->stribeck_speed_m_per_s},
              {"lift.exponent", t.lift->exponent}});
  if (t.squeeze)
    p.insert({{"squeeze.max_fraction", t.squeeze->max_fraction},
              {"squeeze.full_thickness_m", t.squeeze->full_thickness_m},
              {"squeeze.build_up_distance_m", t.squeeze->build_up_distance_m}});
  if (t.eyring)
    p.insert({{"eyring.coefficient_N_s_per_m", t.eyring->coefficient_N_s_per_m}, {"eyring.eyring_speed_m_per_s", t.eyring->eyring_speed_m_per_s}});
  if (t.vogel)
    p.insert({{"vogel.coefficient_N_s_per_m", t.vogel->coefficient_N_s_per_m}, {"vogel.heating_K_s_per_m", t.vogel->heating_K_s_per_m}});
  return p;
}

}  // namespace tribo::gap::independent
