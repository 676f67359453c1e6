// Each friction effect alone against a closed form or a limit (rig/effects/*.h state the
// equations), and the composition rules of rig/effect.h.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "contact/junction_locus.h"
#include "rig/composite_law.h"
#include "rig/effects/slip_transient.h"
#include "rig/effects/squeeze_film.h"
#include "rig/friction_model.h"
#include "rig/instrument.h"
#include "rig/observables.h"
#include "rig/simulator.h"

namespace tribo::rig {
namespace {

SimulationResult run(const RigParameters& rig, const FrictionModel& model, double v, double duration,
                     bool steady_start = false) {
  SimulationOptions opt;
  opt.duration_s = duration;
  opt.start_in_steady_sliding = steady_start;
  opt.samples_per_period = 400;
  const auto law = make_friction_law(model);
  SimulationResult r = simulate(rig, Drive::constant(v), *law, opt);
  EXPECT_TRUE(r.summary.completed) << r.summary.message;
  return r;
}

// Samples of the first slip phase (from the first breakaway to the next velocity match).
std::vector<Sample> first_slip(const SimulationResult& r) {
  std::vector<Sample> out;
  for (const Sample& s : r.samples) {
    if (s.phase == Phase::slip) out.push_back(s);
    else if (!out.empty()) break;
  }
  return out;
}

TEST(SlipTransient, DecaysWithSlipDistanceNotTimeAtBothRigFrequencies) {
  // Thesis §5.2a: the same normalised decay against displacement at ω = 102 and 152 rad/s.
  FrictionModel m = coulomb(0.3, 0.15);
  m.set("slip_transient", "amplitude", 0.5);
  m.set("slip_transient", "decay_distance_m", 3e-4);
  RigParameters heavy, light;
  light.mass_kg = heavy.stiffness_N_per_m / (152.0 * 152.0);  // lead weights removed
  const double W = heavy.normal_load_N, v = 1e-3;
  const auto slip_heavy = first_slip(run(heavy, m, v, 3.0));
  const auto slip_light = first_slip(run(light, m, v, 3.0));
  ASSERT_GT(slip_heavy.size(), 50u);
  ASSERT_GT(slip_light.size(), 50u);
  // Closed form F(s) = W [μk + (μs − μk) e^{−s/D_c}] on both rigs, to the integrator's accuracy.
  for (const auto* slip : {&slip_heavy, &slip_light}) {
    for (const Sample& s : *slip) {
      const double expected = W * (0.15 + 0.5 * 0.15 * std::exp(-s.slip_distance_m / 3e-4));
      ASSERT_NEAR(s.friction_N, expected, 1e-6 * W) << "s = " << s.slip_distance_m;
    }
  }
  // Against time the two differ: the lighter rig accelerates faster and reaches the half-decay
  // distance D_c ln 2 sooner — by about the frequency ratio 152/102 for a free-vibration start.
  auto half_decay_time = [](const std::vector<Sample>& slip) {
    for (const Sample& s : slip) {
      if (s.slip_distance_m >= 3e-4 * std::numbers::ln2) return s.t_s - slip.front().t_s;
    }
    return slip.back().t_s - slip.front().t_s;
  };
  EXPECT_GT(half_decay_time(slip_heavy) / half_decay_time(slip_light), 1.2);
}

TEST(SlipTransient, RateWeakeningRelaxesOverDcToRuinasSlipLawSteadyState) {
  // rig/effects/slip_transient.h: with β > 0 the increment relaxes over D_c of slip towards
  // Δμ_ss(U) = −β ln(U/U_ref) (Ruina 1983, slip law). Steady sliding at v with a viscous film
  // c = 40 N s/m so that c + r exceeds the weakening slope W β / v (≈ 19 N s/m) and sliding is
  // stable: after 3 s (1500 D_c of slip) friction is W (μk + Δμ_ss(v)) + c v.
  const RigParameters rig;
  const double beta = 0.01, u_ref = 0.01, v = 0.05, dc = 1e-4;
  FrictionModel m = coulomb(0.3, 0.15);
  m.set("slip_transient", "decay_distance_m", dc);
  m.set("slip_transient", "rate_weakening", beta);
  m.set("slip_transient", "reference_speed_m_per_s", u_ref);
  m.set("viscous_friction", "coefficient_N_s_per_m", 40.0);
  const auto r = run(rig, m, v, 3.0, /*steady_start=*/true);
  const Sample& last = r.samples.back();
  const double expected = (0.15 - beta * std::log(v / u_ref)) * rig.normal_load_N + 40.0 * v;
  EXPECT_NEAR(last.friction_N, expected, 1e-6 * expected);
  // At one speed the state relaxes exponentially in slip distance: from R = 0 after s = D_c,
  // R = Δμ_ss (1 − e^{−1}); the rate vanishes at rest (|U| ln|U| → 0), and β = 0 has no R at all.
  const effects::SlipTransient e(1.0, dc, beta, u_ref);
  const double target = e.steady_increment(v);
  EXPECT_NEAR(target, -beta * std::log(5.0), 1e-15);
  std::vector<double> state{0.0, 0.0}, rates(2);
  FrictionContext fc;
  fc.relative_speed_m_per_s = v;
  const int steps = 100000;
  const double dt = dc / v / steps;
  for (int k = 0; k < steps; ++k) {  // midpoint rule, error O(dt²)
    fc.state = state;
    e.state_rates(EffectContext{&fc, 0.3, 0.15, state}, rates);
    std::vector<double> mid{state[0], state[1] + 0.5 * dt * rates[1]};
    e.state_rates(EffectContext{&fc, 0.3, 0.15, mid}, rates);
    state[1] += dt * rates[1];
  }
  EXPECT_NEAR(state[1], target * (1.0 - std::exp(-1.0)), 1e-9);
  fc.relative_speed_m_per_s = 0.0;
  e.state_rates(EffectContext{&fc, 0.3, 0.15, state}, rates);
  EXPECT_EQ(rates[1], 0.0);
  EXPECT_EQ(e.state_size(), 2u);
  EXPECT_EQ(effects::SlipTransient(1.0, dc).state_size(), 1u);
}

TEST(SlipTransient, AgeingShareFollowsDieterichsAgeingLawAtOneSpeed) {
  // rig/effects/slip_transient.h: with the ageing share f the increment follows Dieterich's ageing
  // law with b = β/f. At one speed V its state relaxes as θ − D_c/V ∝ e^{−s/D_c} (Ruina 1983), so
  // X(s) = Δμ_ss + b ln(1 + (e^{(X0 − Δμ_ss)/b} − 1) e^{−s/D_c}). Started 5 b above the stable level
  // it falls linearly at first, by b per D_c, where the slip law's exponential falls by 5 b (1 − 1/e).
  const double beta = 0.009, f = 0.9, b = beta / f, u_ref = 0.01, v = 0.04, dc = 3e-4;
  const effects::SlipTransient e(1.0, dc, beta, u_ref, f);
  ASSERT_TRUE(e.ageing());
  EXPECT_EQ(e.state_size(), 1u);
  const double x_ss = e.steady_increment(v), x0 = x_ss + 5.0 * b;
  auto closed_form = [&](double s) { return x_ss + b * std::log1p(std::expm1(5.0) * std::exp(-s / dc)); };
  FrictionContext fc;
  fc.relative_speed_m_per_s = v;
  std::vector<double> state{x0}, rates(1);
  auto rate = [&](double x) {
    const std::vector<double> at{x};
    e.state_rates(EffectContext{&fc, 0.3, 0.15, at}, rates);
    return rates[0];
  };
  const int steps = 30000;
  const double dt = 3.0 * dc / v / steps;
  double x = x0, x_at_dc = 0.0;
  for (int k = 1; k <= steps; ++k) {  // classical RK4, error O(dt⁴)
    const double k1 = rate(x), k2 = rate(x + 0.5 * dt * k1), k3 = rate(x + 0.5 * dt * k2), k4 = rate(x + dt * k3);
    x += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (k == steps / 3) x_at_dc = x;
  }
  EXPECT_NEAR(x_at_dc, closed_form(dc), 1e-12);
  EXPECT_NEAR(x, closed_form(3.0 * dc), 1e-12);
  EXPECT_NEAR(x0 - x_at_dc, b, 0.02 * b);  // linear: b ln(e^5) − b ln(1 + (e^5 − 1)/e) = 0.99 b
  // The kinetic increment is the state, floored at −μk.
  state[0] = x_at_dc;
  EXPECT_EQ(e.kinetic_increment(EffectContext{&fc, 0.3, 0.15, state}), x_at_dc);
  // As the slip slows the stable level rises above X and the state heals with time: at |U| = V/100
  // from the stable level of V, dX/dt = (|U|/D_c) b (e^{β ln(100)/b} − 1) > 0; the slip law's
  // relaxation at f → 0 is the same rate to first order in the deviation over b.
  fc.relative_speed_m_per_s = v / 100.0;
  EXPECT_NEAR(rate(x_ss), (v / 100.0 / dc) * b * std::expm1(beta * std::log(100.0) / b), 1e-12);
  const effects::SlipTransient slip_law(1.0, dc, beta, u_ref), nearly(1.0, dc, beta, u_ref, 1e-7);
  EXPECT_FALSE(slip_law.ageing());
  fc.relative_speed_m_per_s = v;
  std::vector<double> two{0.0, x_ss + 0.001}, r2(2), one{x_ss + 0.001}, r1(1);
  slip_law.state_rates(EffectContext{&fc, 0.3, 0.15, two}, r2);
  nearly.state_rates(EffectContext{&fc, 0.3, 0.15, one}, r1);
  EXPECT_NEAR(r1[0], r2[1], 1e-6 * std::abs(r2[1]));
  // At rest nothing moves: the next slip onset sets the state.
  fc.relative_speed_m_per_s = 0.0;
  EXPECT_EQ(rate(x_ss), 0.0);
}

TEST(RateDependentStatic, BreakawayLiesOnTheJunctionLocus) {
  const RigParameters rig;
  FrictionModel m = coulomb(0.55, 0.1);
  m.add("rate_dependent_static");
  contact::JunctionLocus locus;
  locus.alpha = 25.0;
  locus.n = 1.25;
  locus.sigma0_over_tau_i = contact::sigma0_over_tau_i_from_upper_asymptote(0.55, 25.0);
  locus.location_per_s = m.get("rate_dependent_static", "location_per_s");
  for (double v : {1e-5, 1e-4, 7.112e-4, 3e-3}) {
    const double phi_dot = rig.stiffness_N_per_m * v / rig.normal_load_N;  // (3.1.20) with r v̇ = 0
    const double mu_expected = contact::static_friction_from_load_rate(locus, phi_dot);
    const auto r = run(rig, m, v, 1.2 * mu_expected * rig.normal_load_N / (rig.stiffness_N_per_m * v));
    ASSERT_FALSE(r.events.empty());
    ASSERT_EQ(r.events.front().kind, EventKind::breakaway);
    EXPECT_NEAR(r.events.front().load_rate_per_s, phi_dot, 1e-12 * phi_dot);
    // Event location to CVODE's root tolerance: 1e-8 in μ.
    EXPECT_NEAR(r.events.front().mu, mu_expected, 1e-8) << "v = " << v;
  }
  // The default location parameter was computed through the thesis point μs = 0.26 at 2.8e-2 in/s
  // (Fig 5.2.1), so that point cannot test it. The thesis' other breakaway, μs = 0.45 in Fig 5.2.2,
  // was taken "slower than Fig 5.2.1" (section 5.2a; its caption's speed is illegible) within the
  // load rates §5.1 spans, 1e-4 … 1e1 1/s: the locus must put μs = 0.45 at a load rate inside that
  // span and at a drive speed below 7.11e-4 m/s (a locus falling the wrong way, or too steeply or
  // too flatly by a decade in its location, fails one of the three).
  const double rig_rate_per_m = rig.stiffness_N_per_m / rig.normal_load_N;  // φ̇ per unit drive speed
  const double phi_dot = contact::load_rate_at_static_friction_per_s(locus, 0.45);  // (3.1.24) read forwards
  EXPECT_GT(phi_dot, 1e-4);
  EXPECT_LT(phi_dot, 1e1);
  EXPECT_LT(phi_dot / rig_rate_per_m, 7.112e-4);
}

TEST(StrainRateHardening, FlattensTheLocusAroundItsReferenceRate) {
  FrictionModel plain = coulomb(0.55, 0.1), hard = plain;
  plain.add("rate_dependent_static");
  hard.add("rate_dependent_static");
  hard.set("strain_rate_hardening", "m", 0.1);
  const auto lp = std::dynamic_pointer_cast<const CompositeLaw>(make_friction_law(plain));
  const auto lh = std::dynamic_pointer_cast<const CompositeLaw>(make_friction_law(hard));
  FrictionContext c;
  c.tangential_load_rate_per_s = hard.get("strain_rate_hardening", "reference_load_rate_per_s");
  EXPECT_NEAR(lh->static_coefficient(c), lp->static_coefficient(c), 1e-12);  // same at φ̇_ref
  // (5.1.2): φ̇^{1 − m(1+n)} replaces φ̇, so a decade of load rate spans less μs.
  c.tangential_load_rate_per_s *= 10.0;
  const double hi_p = lp->static_coefficient(c), hi_h = lh->static_coefficient(c);
  c.tangential_load_rate_per_s /= 100.0;
  const double lo_p = lp->static_coefficient(c), lo_h = lh->static_coefficient(c);
  EXPECT_LT(lo_h - hi_h, lo_p - hi_p);
  EXPECT_GT(hi_h, hi_p);
}

TEST(ViscousFriction, SteadySlidingCarriesMuKWPlusCU) {
  const RigParameters rig;
  FrictionModel m = coulomb(0.3, 0.15);
  m.set("viscous_friction", "coefficient_N_s_per_m", 40.0);
  const double v = 0.05;
  const auto r = run(rig, m, v, 3.0, /*steady_start=*/true);
  const Sample& last = r.samples.back();
  // Positive slope c damps the start-up kick (e^{−(r+c)t/2M} ≈ 1e-27 after 3 s); U = v − ẋ.
  EXPECT_NEAR(last.friction_N, 0.15 * rig.normal_load_N + 40.0 * v, 1e-9 * last.friction_N);
  EXPECT_NEAR(last.x_m * rig.stiffness_N_per_m, last.friction_N, 1e-6 * last.friction_N);
}

TEST(SqueezeFilm, SlipRunsThroughVelocityMatchesWhereTheBaselineSticksAtOnce) {
  const RigParameters rig;
  const FrictionModel base = coulomb(0.5, 0.12);
  FrictionModel film = base;
  film.add("squeeze_film");
  const double v = 1e-4, duration = 2.0 * 0.5 * rig.normal_load_N / (rig.stiffness_N_per_m * v);
  const auto rb = run(rig, base, v, duration);
  const auto rf = run(rig, film, v, duration);
  auto reversals_before_reattach = [](const SimulationResult& r) {
    int n = 0;
    for (const Event& e : r.events) {
      if (e.kind == EventKind::reattach) break;
      if (e.kind == EventKind::reversal) ++n;
    }
    return n;
  };
  EXPECT_EQ(reversals_before_reattach(rb), 0);
  EXPECT_GE(reversals_before_reattach(rf), 1);  // more than one slip half-cycle

  // Thesis §5.2a: where the slip passes zero relative speed the film still carries part of the load
  // (squeezing it out takes τ_sq), so μ there is the solid's share of μk, below μk = 0.12 and above 0;
  // summarise reads it off the reversals (mu_at_reversal_mean). The baseline has no reversal: NaN.
  const RunObservables ob = summarise(rig, rb.samples, rb.events, 0.0), of = summarise(rig, rf.samples, rf.events, 0.0);
  EXPECT_TRUE(std::isnan(ob.mu_at_reversal_mean));
  double sum = 0.0;
  int n = 0;
  for (const Event& e : rf.events)
    if (e.kind == EventKind::reversal) {
      EXPECT_GT(e.mu, 0.0);
      EXPECT_LT(e.mu, 0.12);
      sum += e.mu, ++n;
    }
  ASSERT_EQ(of.reversals, n);
  EXPECT_NEAR(of.mu_at_reversal_mean, sum / n, 1e-15);
}

// Appendix III's squeeze-out time between parallel discs, τ_sq = 3πηR⁴/(4W) (1/(h/2)² − 1/h²)
// = 9πηR⁴/(4Wh²), sets whether the film makes the rig's equations stiff: a film squeezed out
// within a radian of the rig's oscillation (τ_sq ω_n < 1) is integrated with BDF, where Adams'
// steps would be held to ≈ τ_sq by their stability through every stick. The catalogue's default
// film (h = 1 µm on the thesis rig: τ_sq ω_n = 2.58) is not; at h = 2.5 µm (0.41) it is.
TEST(SqueezeFilm, AFilmSqueezedOutWithinARadianOfTheRigsOscillationIsStiff) {
  const RigParameters rig;
  const double wn = rig.natural_frequency_rad_per_s(), W = rig.normal_load_N;
  for (const auto& [h, stiff] : {std::pair{1e-6, false}, std::pair{2.5e-6, true}}) {
    const effects::SqueezeFilm film(0.8, 2e-3, h, 2e-3, 0.021);
    const double tau = 9.0 * std::numbers::pi * 0.021 * std::pow(2e-3, 4) / (4.0 * W * h * h);
    EXPECT_NEAR(film.squeeze_time_s(W), tau, 1e-12 * tau);
    EXPECT_EQ(tau * wn < 1.0, stiff) << "h = " << h << " m, tau wn = " << tau * wn;
    EXPECT_EQ(film.stiff(W, wn), stiff) << "h = " << h << " m, tau wn = " << tau * wn;
  }
}

// The stiff film's run (BDF) converges with the tolerance: a film of τ_sq ω_n = 0.1 (h = 5 µm),
// at the gap predictions' tolerance 1e-6 and at the default 1e-10, gives the same events, their
// times within 1e-4 of a natural period: a hundred times the local tolerance, for the global error
// a step-by-step local control leaves over a few cycles (2.3e-5 of it measured, 2026-12-05).
TEST(SqueezeFilm, AStiffFilmsRunConvergesWithTheTolerance) {
  const RigParameters rig;
  FrictionModel film = coulomb(0.5, 0.12);
  film.set("squeeze_film", "film_thickness_m", 5e-6);
  film.set("squeeze_film", "build_up_distance_m", 2e-4);
  const auto law = make_friction_law(film);
  ASSERT_TRUE(law->stiff(rig.normal_load_N, rig.natural_frequency_rad_per_s()));
  const double v = 1e-2, period = 2.0 * std::numbers::pi / rig.natural_frequency_rad_per_s();
  auto events = [&](double tolerance) {
    SimulationOptions opt;
    opt.duration_s = 1.5;  // the first breakaway at μs W / (k v) = 0.45 s
    opt.relative_tolerance = opt.displacement_tolerance_fraction = tolerance;
    SimulationResult r = simulate(rig, Drive::constant(v), *law, opt);
    EXPECT_TRUE(r.summary.completed) << r.summary.message;
    return r.events;
  };
  const auto coarse = events(1e-6), fine = events(1e-10);
  ASSERT_GE(fine.size(), 4u);
  ASSERT_EQ(coarse.size(), fine.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_EQ(coarse[i].kind, fine[i].kind) << "event " << i;
    worst = std::max(worst, std::abs(coarse[i].t_s - fine[i].t_s));
  }
  EXPECT_LT(worst, 1e-4 * period) << fine.size() << " events, worst " << worst << " s";
}

// Growth rate of a small oscillation about steady sliding at v, from the ẋ envelope.
double growth_rate(const FrictionModel& m, double v) {
  const RigParameters rig;
  // Windows 1 s apart and early enough that a growing oscillation is still small (kick 1e-3 v).
  const auto r = run(rig, m, v, 2.0, /*steady_start=*/true);
  double early = 0.0, late = 0.0;
  for (const Sample& s : r.samples) {
    if (s.t_s >= 0.5 && s.t_s < 1.0) early = std::max(early, std::abs(s.xdot_m_per_s));
    if (s.t_s >= 1.5) late = std::max(late, std::abs(s.xdot_m_per_s));
  }
  return std::log(late / early) / 1.0;
}

TEST(ThermalThinning, SteadySlidingIsUnstableExactlyWhereMinusWdMuDUExceedsR) {
  // F_th = c0 U e^{−U/U_T}: −dF/dU = c0 e^{−u}(u − 1), u = U/U_T, exceeds r between two roots.
  const RigParameters rig;
  const double c0 = 300.0, ut = 0.0254, r = rig.damping_N_s_per_m;
  FrictionModel m = coulomb(0.12, 0.12);
  m.set("thermal_thinning", "traction_coefficient_N_s_per_m", c0);
  m.set("thermal_thinning", "thermal_speed_m_per_s", ut);
  auto excess = [&](double u) { return c0 * std::exp(-u) * (u - 1.0) - r; };
  auto bisect = [&](double a, double b) {
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (a + b);
      ((excess(a) < 0) == (excess(mid) < 0) ? a : b) = mid;
    }
    return 0.5 * (a + b);
  };
  const double u1 = bisect(1.0, 2.0), u2 = bisect(2.0, 20.0);
  for (double u : {0.95 * u1, 1.05 * u1, 0.95 * u2, 1.05 * u2}) {
    const bool unstable = u > u1 && u < u2;
    const double sigma = growth_rate(m, u * ut);
    const double linear = -(r - (c0 * std::exp(-u) * (u - 1.0))) / (2.0 * rig.mass_kg);
    EXPECT_EQ(sigma > 0.0, unstable) << "u = " << u << ", linear rate " << linear;
    // The envelope peaks sit up to a period (0.06 s) off their nominal 1 s spacing: ±6 % of the
    // rate, plus the sampling of the peaks; allow 10 % + 0.05 1/s.
    EXPECT_NEAR(sigma, linear, 0.1 * std::abs(linear) + 0.05) << "u = " << u;
  }
}

TEST(Instrument, IdealChannelsReadTheTrueFrictionOfAnUndampedRig) {
  RigParameters rig;
  rig.damping_N_s_per_m = 0.0;  // (4.2.3) neglects r ẋ only
  const auto r = run(rig, coulomb(0.3, 0.2), 1e-3, 3.0);
  const auto measured = measure_friction_N(rig, InstrumentModel{}, r.samples);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    ASSERT_NEAR(measured[i], r.samples[i].friction_N, 1e-9 * rig.normal_load_N) << "sample " << i;
  }
}

// A rig without an accelerometer (paper on paper, Colas et al. 2019) records the spring force
// k x alone: it differs from the true friction by the slider's inertia, M ẍ. In an undamped
// Coulomb slip the friction stays at μk W while k x swings about it by (μs − μk) W either way, so
// the spring force's range over a cycle is 2 (μs − μk) W against the friction's μs − μk.
TEST(Instrument, TheSpringForceChannelReadsKxAndMissesTheInertia) {
  RigParameters rig;
  rig.damping_N_s_per_m = 0.0;
  const auto r = run(rig, coulomb(0.3, 0.2), 1e-3, 3.0);
  const auto spring = measure_friction_N(rig, InstrumentModel{.inertia_corrected = false}, r.samples);
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    ASSERT_NEAR(spring[i], rig.stiffness_N_per_m * r.samples[i].x_m, 1e-12 * rig.normal_load_N) << "sample " << i;
    ASSERT_NEAR(spring[i] + rig.mass_kg * r.samples[i].xddot_m_per_s2, r.samples[i].friction_N, 1e-9 * rig.normal_load_N) << "sample " << i;
    if (r.samples[i].t_s > 1.0) lo = std::min(lo, spring[i]), hi = std::max(hi, spring[i]);
  }
  // Over the last two seconds' cycles, to the integrator's event location (1e-3 of the drop).
  EXPECT_NEAR(hi - lo, 2.0 * (0.3 - 0.2) * rig.normal_load_N, 1e-3 * 0.1 * rig.normal_load_N);
}

TEST(Instrument, GainScalesAndNoiseHasTheRequestedRms) {
  RigParameters rig;
  rig.damping_N_s_per_m = 0.0;
  const auto r = run(rig, coulomb(0.3, 0.2), 1e-3, 3.0);
  const auto ideal = measure_friction_N(rig, InstrumentModel{}, r.samples);
  const auto scaled = measure_friction_N(rig, InstrumentModel{.gain = 1.1, .seed = 1}, r.samples);
  const auto noisy = measure_friction_N(rig, InstrumentModel{.noise_N = 0.5, .seed = 7}, r.samples);
  double ss = 0.0;
  for (std::size_t i = 0; i < ideal.size(); ++i) {
    ASSERT_NEAR(scaled[i], 1.1 * ideal[i], 1e-12 * std::abs(ideal[i]) + 1e-12);
    ss += (noisy[i] - ideal[i]) * (noisy[i] - ideal[i]);
  }
  const double rms = std::sqrt(ss / ideal.size());
  // N ≈ 5000 samples: the rms estimate has a relative standard error 1/√(2N) ≈ 1 %; allow 5 %.
  ASSERT_GT(ideal.size(), 2000u);
  EXPECT_NEAR(rms, 0.5, 0.025);
}

// A first-order sensor τ ẏ + y = u fed a ramp u = a t from rest reads y = a (t − τ (1 − e^{−t/τ}))
// (its closed form); the exact discretisation holds it to round-off on any sample spacing, here
// an uneven one coarser than τ in places.
TEST(Instrument, SensorLagFollowsARampAsItsClosedForm) {
  RigParameters rig;  // x(t) = a t with ẍ = 0: the channel's input is g k a t
  const double a = 2e-4, tau = 3e-3;
  std::vector<Sample> samples;
  for (double t = 0.0; t < 0.05; t += (samples.size() % 3 == 0 ? 0.4e-3 : 4.1e-3)) {
    Sample s;
    s.t_s = t, s.x_m = a * t;
    samples.push_back(s);
  }
  const auto read = measure_friction_N(rig, InstrumentModel{.gain = 1.2, .time_constant_s = tau}, samples);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double t = samples[i].t_s;
    const double expected = 1.2 * rig.stiffness_N_per_m * a * (t - tau * (1.0 - std::exp(-t / tau)));
    ASSERT_NEAR(read[i], expected, 1e-12 * rig.stiffness_N_per_m * a * 0.05) << "t = " << t;
  }
  // The breakaway reading is that steady response: g (μ − τ μ̇).
  EXPECT_DOUBLE_EQ(breakaway_reading(InstrumentModel{.gain = 1.2, .time_constant_s = tau}, 0.3, 2.0), 1.2 * (0.3 - tau * 2.0));
}

// A sinusoid through the sensor comes out scaled by 1/√(1 + (ωτ)²) and late by atan(ωτ)/ω (its
// frequency response); sampled 200 times a period, the linear interpolation between samples is
// exact to O((ωh)²) ≈ 1e-3 of the amplitude, the tolerance.
TEST(Instrument, SensorLagAttenuatesAndDelaysASinusoidAsItsFrequencyResponse) {
  const RigParameters rig;
  const double w = 2.0 * std::numbers::pi * 20.0, tau = 4e-3, h = 2.0 * std::numbers::pi / w / 200.0;
  std::vector<Sample> samples;
  for (int i = 0; i < 4000; ++i) {
    Sample s;
    s.t_s = i * h, s.x_m = std::sin(w * s.t_s);  // ẍ left 0: the channel reads k x
    samples.push_back(s);
  }
  const auto read = measure_friction_N(rig, InstrumentModel{.time_constant_s = tau}, samples);
  const double amp = rig.stiffness_N_per_m / std::sqrt(1.0 + w * tau * w * tau), phase = std::atan(w * tau);
  for (std::size_t i = 2000; i < samples.size(); ++i) {  // after 10 periods, 125 τ: the start has decayed
    const double t = samples[i].t_s;
    const double expected = amp * std::sin(w * t - phase);
    ASSERT_NEAR(read[i], expected, 1e-3 * rig.stiffness_N_per_m) << "t = " << t;
  }
}

TEST(Composition, EffectsAtZeroStrengthLeaveTheBaselineTraceUnchanged) {
  const RigParameters rig;
  const FrictionModel base = coulomb(0.3, 0.2);
  FrictionModel zero = base;
  zero.set("slip_transient", "amplitude", 0.0);
  zero.set("rate_and_state", "a", 0.0);
  zero.set("rate_and_state", "b", 0.0);
  zero.set("viscous_friction", "coefficient_N_s_per_m", 0.0);
  zero.set("squeeze_film", "film_fraction", 0.0);
  zero.set("hydrodynamic_lift", "max_fraction", 0.0);
  zero.set("thermal_thinning", "traction_coefficient_N_s_per_m", 0.0);
  const auto rb = run(rig, base, 1e-3, 4.0);
  const auto rz = run(rig, zero, 1e-3, 4.0);
  ASSERT_EQ(rb.events.size(), rz.events.size());
  for (std::size_t i = 0; i < rb.events.size(); ++i) {
    // Zero-strength states still enter CVODE's error norm, so step sizes may differ slightly:
    // event times agree to the integrator's tolerance.
    EXPECT_NEAR(rb.events[i].t_s, rz.events[i].t_s, 1e-8 * rb.events[i].t_s);
    EXPECT_NEAR(rb.events[i].x_m, rz.events[i].x_m, 1e-9);
  }
}

TEST(Composition, ListingOrderDoesNotMatter) {
  const RigParameters rig;
  FrictionModel a = coulomb(0.4, 0.15), b = a;
  for (const char* e : {"slip_transient", "rate_and_state", "viscous_friction", "squeeze_film", "rate_dependent_static"}) a.add(e);
  for (const char* e : {"rate_dependent_static", "squeeze_film", "viscous_friction", "rate_and_state", "slip_transient"}) b.add(e);
  EXPECT_EQ(make_friction_law(a)->name(), make_friction_law(b)->name());
  const auto ra = run(rig, a, 1e-3, 2.0), rb = run(rig, b, 1e-3, 2.0);
  ASSERT_EQ(ra.samples.size(), rb.samples.size());
  for (std::size_t i = 0; i < ra.samples.size(); ++i) ASSERT_EQ(ra.samples[i].x_m, rb.samples[i].x_m);
}

TEST(Catalogue, EveryEffectHasDocumentedBoundedParametersAndRejectsOutOfRange) {
  for (const EffectInfo& e : effect_catalogue()) {
    EXPECT_FALSE(e.thesis_reference.empty()) << e.name;
    for (const ParameterSpec& p : e.parameters) {
      EXPECT_LE(p.lower, p.default_value) << e.name << "." << p.name;
      EXPECT_GE(p.upper, p.default_value) << e.name << "." << p.name;
      EXPECT_FALSE(p.unit.empty()) << e.name << "." << p.name;
    }
  }
  FrictionModel m = coulomb(0.3, 0.2);
  m.set("squeeze_film", "film_fraction", 1.5);
  EXPECT_THROW(make_friction_law(m), std::invalid_argument);
  EXPECT_THROW(effect_info("wear"), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::rig
