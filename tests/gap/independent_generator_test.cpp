// The selftest's independent generator (gap/independent/) against references: its integrator
// against closed forms of the rig, the alternative friction forms against their published
// steady states and closed forms, the measuring chain's filter, noise and converter.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "gap/independent/generator.h"

namespace tribo::gap::independent {
namespace {

// Free vibration, no friction: M ẍ + r ẋ + k x = 0 from x0 at rest has
// x(t) = x0 e^{−σt} (cos ω_d t + (σ/ω_d) sin ω_d t), σ = r/2M, ω_d = √(k/M − σ²) (any vibrations text).
// RK4 at ω_n Δt ≈ 1e-3 has a global error ~ (ω_n Δt)⁴ ω_n t x0 ≈ 1e-13 m over 1 s: tolerance 1e-10 of x0.
TEST(IndependentIntegrator, FreeVibrationMatchesClosedForm) {
  RigConstants rig;  // thesis rig, r/2M = 0.868 1/s
  IndependentLaw law;
  law.mu_s = law.mu_k = 0.0;
  IntegratorOptions o;
  o.duration_s = 1.0;
  o.initial_displacement_m = 1e-3;
  o.start_stuck = false;
  const RawRecord r = integrate(rig, law, 0.0, o);
  ASSERT_TRUE(r.completed) << r.message;
  const double sigma = rig.damping_N_s_per_m / (2.0 * rig.mass_kg);
  const double wd = std::sqrt(rig.stiffness_N_per_m / rig.mass_kg - sigma * sigma);
  double worst = 0.0;
  for (std::size_t i = 0; i < r.t_s.size(); i += 97) {
    const double t = r.t_s[i];
    const double x = 1e-3 * std::exp(-sigma * t) * (std::cos(wd * t) + sigma / wd * std::sin(wd * t));
    worst = std::max(worst, std::abs(r.x_m[i] - x));
  }
  EXPECT_LT(worst, 1e-13);
}

// Undamped Coulomb stick-slip (μs > μk) has a closed form (integrator.h, Den Hartog): stick spans
// 2Δ in x, Δ = (μs − μk) W/k, and lasts 2Δ/v; slip lasts (π + 2 atan(v/(ω_n Δ)))/ω_n; x spans
// 2√(Δ² + (v/ω_n)²). Events are located by bisection to 1e-12 Δt and slip is RK4: times to 1e-7 s,
// lengths to 1e-6 of themselves (x is read at the Δt grid: an extremum within ẍΔt²/8 ≈ 1e-11 m).
TEST(IndependentIntegrator, UndampedCoulombStickSlipMatchesClosedForm) {
  RigConstants rig;
  rig.damping_N_s_per_m = 0.0;
  IndependentLaw law;
  law.mu_s = 0.3, law.mu_k = 0.2;
  const double v = 0.01;
  IntegratorOptions o;
  o.duration_s = 1.5;
  const RawRecord r = integrate(rig, law, v, o);
  ASSERT_TRUE(r.completed) << r.message;
  const CoulombStickSlip ref = coulomb_stick_slip(rig, law.mu_s, law.mu_k, v);
  ASSERT_GE(r.breakaway_t_s.size(), 3u);
  ASSERT_GE(r.reattach_t_s.size(), 2u);
  for (std::size_t i = 1; i + 1 < r.breakaway_t_s.size() && i < r.reattach_t_s.size(); ++i) {
    EXPECT_NEAR(r.reattach_t_s[i] - r.breakaway_t_s[i], ref.slip_time_s, 1e-7) << "cycle " << i;
    EXPECT_NEAR(r.breakaway_t_s[i + 1] - r.reattach_t_s[i], ref.stick_time_s, 1e-7) << "cycle " << i;
  }
  // The span of x after the first breakaway (the first stick starts from x = 0).
  double lo = 1e9, hi = -1e9;
  for (std::size_t i = 0; i < r.t_s.size(); ++i)
    if (r.t_s[i] > r.reattach_t_s[0]) lo = std::min(lo, r.x_m[i]), hi = std::max(hi, r.x_m[i]);
  EXPECT_NEAR(hi - lo, ref.peak_to_peak_m, 1e-6 * ref.peak_to_peak_m);
  // Stick spans 2Δ: from the re-attachment to the next breakaway the slider rides the disc.
  const std::size_t a = static_cast<std::size_t>(std::ceil(r.reattach_t_s[1] / o.step_s)), b = static_cast<std::size_t>(r.breakaway_t_s[2] / o.step_s);
  EXPECT_NEAR(r.x_m[b] - r.x_m[a], ref.stick_span_m, v * o.step_s + 1e-6 * ref.stick_span_m);
}

// Dieterich–Ruina steady state (Ruina 1983; Marone 1998, Annu. Rev. Earth Planet. Sci. 26, eq. 3):
// at constant V both evolution laws settle at θss = D_c/V and μss = μ0 + (a − b) ln(V/V0).
// The state ODE is integrated here by RK4 far past D_c/V; tolerance 1e-9 in μ.
TEST(IndependentLaws, RateStateSteadyStateIsMu0PlusAMinusBLogV) {
  for (const auto evolution : {RateState::Evolution::ageing, RateState::Evolution::slip}) {
    RateState rs;
    rs.mu_0 = 0.6, rs.a = 0.010, rs.b = 0.015, rs.reference_speed_m_per_s = 1e-6, rs.decay_distance_m = 1e-5;
    rs.evolution = evolution;
    for (double V : {1e-7, 3e-6, 1e-4}) {
      double theta = 10.0 * rs.decay_distance_m / V;  // far from steady state
      const double dt = 0.02 * rs.decay_distance_m / V;
      for (int i = 0; i < 5000; ++i) {  // 100 D_c of slip
        const double k1 = rs.theta_rate_per_s(V, theta), k2 = rs.theta_rate_per_s(V, theta + 0.5 * dt * k1);
        const double k3 = rs.theta_rate_per_s(V, theta + 0.5 * dt * k2), k4 = rs.theta_rate_per_s(V, theta + dt * k3);
        theta += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
      EXPECT_NEAR(rs.mu_canonical(V, theta), rs.mu_0 + (rs.a - rs.b) * std::log(V / rs.reference_speed_m_per_s), 1e-9) << V;
    }
  }
}

// Ageing law at constant V is linear in θ: θ(t) = D_c/V + (θ0 − D_c/V) e^{−Vt/D_c} (Dieterich 1979).
TEST(IndependentLaws, AgeingLawRelaxesExponentiallyAtConstantSpeed) {
  RateState rs;
  rs.evolution = RateState::Evolution::ageing;
  rs.decay_distance_m = 5e-4;
  const double V = 0.02, theta0 = 3.0, dt = 1e-5;
  double theta = theta0;
  for (int i = 0; i < 20000; ++i) {
    const double k1 = rs.theta_rate_per_s(V, theta), k2 = rs.theta_rate_per_s(V, theta + 0.5 * dt * k1);
    const double k3 = rs.theta_rate_per_s(V, theta + 0.5 * dt * k2), k4 = rs.theta_rate_per_s(V, theta + dt * k3);
    theta += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double ss = rs.decay_distance_m / V, t = 20000 * dt;
  EXPECT_NEAR(theta, ss + (theta0 - ss) * std::exp(-V * t / rs.decay_distance_m), 1e-9 * theta0);
}

// The film-thickness ODE at rest is ḣ = −c h⁴ with the closed form h⁻³ = h0⁻³ + 3ct (laws.h, from
// Reynolds' parallel-disc squeeze, thesis Appendix III). RK4 of the ODE against it: 1e-8 relative.
TEST(IndependentLaws, SqueezeOdeAtRestMatchesClosedForm) {
  SqueezeFilmOde s;
  s.full_thickness_m = 2e-6;
  const double W = 93.857, h0 = 2e-6, T = 0.05, dt = 1e-6;
  double h = h0;
  for (int i = 0; i < static_cast<int>(T / dt); ++i) {
    auto f = [&](double y) { return s.thickness_rate_m_per_s(0.0, y, W); };
    const double k1 = f(h), k2 = f(h + 0.5 * dt * k1), k3 = f(h + 0.5 * dt * k2), k4 = f(h + dt * k3);
    h += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_NEAR(h, s.thickness_at_rest_m(h0, T, W), 1e-8 * h0);
  EXPECT_LT(h, 0.7 * h0);  // the film does squeeze out on this time scale
}

// Vogel thinning: θ_T chosen for a maximum at U_max puts dF/dU = 0 there (laws.h).
TEST(IndependentLaws, VogelThinningForceIsMaximalWhereAsked) {
  VogelThinning th;
  const double u_max = 0.025;
  th.heating_K_s_per_m = VogelThinning::heating_for_maximum_at(u_max, th.bulk_temperature_K, th.vogel_B_K, th.vogel_T_inf_K);
  const double du = 1e-6;
  EXPECT_NEAR((th.force_N(u_max + du) - th.force_N(u_max - du)) / (2 * du), 0.0, 1e-6 * th.coefficient_N_s_per_m);
  EXPECT_LT(th.force_N(0.5 * u_max), th.force_N(u_max));
  EXPECT_LT(th.force_N(2.0 * u_max), th.force_N(u_max));
}

// Bilinear Butterworth (Oppenheim & Schafer, §7.1): |H(f_c)| = 1/√2 exactly (pre-warped cut-off);
// a sine filtered at the fine rate has the closed-form gain once the start-up transient has gone
// (tolerance 2e-3: the amplitude is read off samples, 100 per period at 1 kHz).
TEST(MeasuringChain, ButterworthGainMatchesDesignAtKnownFrequencies) {
  const double dt = 1e-5, fc = 200.0;
  const ButterworthLowPass lp(4, fc, dt);
  EXPECT_NEAR(lp.gain_at(fc), 1.0 / std::sqrt(2.0), 1e-12);
  for (double f : {50.0, 200.0, 400.0}) {
    std::vector<double> u(200000);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = std::sin(2.0 * M_PI * f * static_cast<double>(i) * dt);
    const std::vector<double> y = lp.apply(u);
    double amp = 0.0;
    for (std::size_t i = u.size() / 2; i < u.size(); ++i) amp = std::max(amp, std::abs(y[i]));
    EXPECT_NEAR(amp, lp.gain_at(f), 2e-3) << f << " Hz";
  }
  EXPECT_NEAR(lp.gain_at(400.0), 1.0 / std::sqrt(1.0 + std::pow(2.0, 8.0)), 2e-3);  // fourth order: −24 dB/octave
}

// The converter: every recorded value is a whole number of steps q and within q/2 of the value
// before it (a noiseless chain, so the difference is the rounding alone); samples are uniform.
TEST(MeasuringChain, QuantisationStepAndUniformSampling) {
  const double dt = 1e-5;
  std::vector<double> fine(100001);
  for (std::size_t i = 0; i < fine.size(); ++i) fine[i] = 20.0 + 5.0 * std::sin(2.0 * M_PI * 3.0 * static_cast<double>(i) * dt);
  ChannelChain clean, quantised;
  quantised.quantum = 4.0 * 93.857 / 4096.0;
  Recorder rec;
  std::mt19937_64 rng(1);
  std::vector<double> t;
  const std::vector<double> a = record_channel(fine, dt, clean, rec, rng, &t);
  const std::vector<double> b = record_channel(fine, dt, quantised, rec, rng, nullptr);
  ASSERT_EQ(a.size(), 1001u);
  for (std::size_t j = 0; j < a.size(); ++j) {
    EXPECT_NEAR(b[j] / quantised.quantum, std::round(b[j] / quantised.quantum), 1e-9);
    EXPECT_LE(std::abs(b[j] - a[j]), 0.5 * quantised.quantum + 1e-12);
    EXPECT_NEAR(t[j], 1e-3 * static_cast<double>(j), 1e-12);
  }
}

// AR(1) noise n_j = ρ n_{j−1} + σ√(1−ρ²) ξ_j: stationary rms σ and lag-one correlation ρ. With
// 2e5 samples at ρ = 0.8 the effective sample size is ≈ 2e4: tolerances 3 % on σ, 0.02 on ρ.
TEST(MeasuringChain, Ar1NoiseHasItsRmsAndCorrelation) {
  std::mt19937_64 rng(7);
  const std::vector<double> n = ar1_noise(200000, 0.5, 0.8, rng);
  double s2 = 0.0, c1 = 0.0;
  for (std::size_t j = 0; j < n.size(); ++j) {
    s2 += n[j] * n[j];
    if (j) c1 += n[j] * n[j - 1];
  }
  const double rms = std::sqrt(s2 / n.size());
  EXPECT_NEAR(rms, 0.5, 0.03 * 0.5);
  EXPECT_NEAR(c1 / s2, 0.8, 0.02);
}

// A generated case: the bundle tells the nominal rig (not the perturbed one), holds five uniform
// 1 kHz traces with friction, x and ẋ, and one static point per stick-slip run; a control is
// Coulomb stick-slip whose recorded maxima sit near its μs (filter and chain: within 3 %).
TEST(IndependentGenerator, ControlBundleTellsNominalRigAndRecordsStickSlip) {
  const IndependentCase c = make_independent_case("none", 351);
  const RigConstants nominal;
  EXPECT_EQ(*c.bundle.stiffness_N_per_m, nominal.stiffness_N_per_m);
  EXPECT_EQ(*c.bundle.normal_load_N, nominal.normal_load_N);
  EXPECT_LE(std::abs(c.actual.stiffness_N_per_m / nominal.stiffness_N_per_m - 1.0), 0.03 + 1e-12);
  EXPECT_LE(std::abs(c.actual.normal_load_N / nominal.normal_load_N - 1.0), 0.03 + 1e-12);
  ASSERT_EQ(c.bundle.runs.size(), 5u);
  for (const tribo::gap::Run& r : c.bundle.runs) {
    ASSERT_EQ(r.trace.t_s.size(), 2001u);
    EXPECT_EQ(r.trace.friction_N.size(), r.trace.t_s.size());
    EXPECT_EQ(r.trace.x_m.size(), r.trace.t_s.size());
    EXPECT_NEAR(r.trace.t_s[1] - r.trace.t_s[0], 1e-3, 1e-12);
  }
  ASSERT_EQ(c.bundle.static_points.size(), 5u);
  const double told_over_actual = c.actual.normal_load_N / nominal.normal_load_N;
  for (const tribo::gap::StaticPoint& p : c.bundle.static_points) EXPECT_NEAR(p.mu_s, c.truth.mu_s * told_over_actual, 0.03 * c.truth.mu_s);
}

TEST(IndependentGenerator, EveryFormProducesACompleteBundle) {
  GeneratorOptions o;
  o.duration_s = 0.5;  // short: this checks that every form runs, not what it shows
  for (const std::string& e : independent_effects()) {
    const IndependentCase c = make_independent_case(e, 2, o);
    EXPECT_EQ(c.bundle.runs.size(), 5u) << e;
    EXPECT_FALSE(c.form.empty()) << e;
  }
  EXPECT_THROW(make_independent_case("no_such_effect", 1), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::gap::independent
