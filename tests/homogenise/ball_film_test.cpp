// A ball on the disc (homogenise/ball_film.h): its face is Hertz's circle, its film the EHL point
// contact at the share of the load it carries, and the rig's steady sliding runs from boundary
// friction (Bowden & Tabor's τ_i/H where the asperities yield) to the ball's full EHL film.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "homogenise/ball_film.h"
#include "homogenise/law.h"
#include "homogenise/pin.h"
#include "homogenise/solid_contact.h"
#include "contact/surface.h"
#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "rig/ball_film.h"
#include "rig/homogenised_law.h"
#include "rig/law_table.h"
#include "rig/steady_sliding.h"

namespace tribo::homogenise {
namespace {

constexpr double kBallSigma = 2e-8;
constexpr double kBallHardness = 6e9;
constexpr int kFilmGrid = 33;  // coarse: every reference below is solved on the same grid

// The ball of examples/ehl-ball-on-disc.toml (a 3/4-in steel ball on a steel disc, mineral oil,
// 10 N), its film unheated (γ = 0) and its speeds 0.01–3 m/s.
HomogeniseOptions ball_options() {
  HomogeniseOptions o;
  o.surface.rms_height_m = kBallSigma;
  o.e_star_Pa = 1.154e11;
  o.hardness_Pa = kBallHardness;
  o.interface_shear_strength_Pa = 6e8;
  o.lubricant.viscosity_Pa_s = 0.04;
  o.lubricant.pressure_viscosity_per_Pa = 2e-8;
  o.lubricant.temperature_viscosity_per_K = 0.0;
  o.pin.shape = PinShape::ball;
  o.pin.radius_m = 9.525e-3;
  o.pin.normal_load_N = 10.0;
  o.pin.film_grid = kFilmGrid;
  MicroEhl films;
  films.min_speed_m_per_s = 0.01;
  films.max_speed_m_per_s = 3.0;
  o.micro_ehl = films;
  return o;
}

// Asperities that yield: p_s(h̄) = 2 GPa (1 − h̄/4σ)² up to 4σ, A_r/A = p_s/H; a smooth film
// (φ = 1) between them. The spots' shear is τ_i at every ηU (no asperity-top films).
CellTable yielding_cells(const HomogeniseOptions& o) {
  CellTable t;
  t.sigma_m = kBallSigma;
  const std::size_t speeds = micro_ehl_eta_u_Pa_m(o).size();
  for (double r : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0, 23.0, 26.0, 30.0, 35.0, 40.0}) {
    const double p = r < 4.0 ? 2e9 * std::pow(1.0 - r / 4.0, 2) : 0.0;
    t.separation_m.push_back(r * kBallSigma);
    for (auto* c : {&t.solid_pressure_Pa, &t.solid_pressure_coarse_Pa}) c->push_back({p, 0});
    for (auto* c : {&t.area_fraction, &t.area_fraction_coarse}) c->push_back({p / kBallHardness, 0});
    for (auto* c : {&t.phi_x, &t.phi_y, &t.phi_f, &t.couette_shear_factor, &t.phi_fp}) c->push_back({1, 0});
    for (auto* c : {&t.phi_s, &t.contact_fraction, &t.lift_per_eta_u_per_m}) c->push_back({0, 0});
    t.film_over_sigma.push_back({r, 0});
    t.spot_shear_Pa.emplace_back(speeds, Estimate{o.interface_shear_strength_Pa, 0});
    t.spot_shear_coarse_Pa.push_back(t.spot_shear_Pa.back());
    t.spot_film_share.emplace_back(speeds, Estimate{0, 0});
  }
  t.mu_s_max = {0.5, 0};
  t.mu_boundary = {0.1, 0};
  t.realisations = 1;
  return t;
}

// The ball's pin table with its films, as homogenise makes it.
PinTable ball_pin(const HomogeniseOptions& o, const CellTable& cells) {
  PinTable pin = pin_scale(o, cells);
  add_ball_film(o, pin);
  return pin;
}

lubrication::PiezoviscousLubricant ball_oil(const HomogeniseOptions& o) {
  lubrication::PiezoviscousLubricant l;
  l.viscosity_Pa_s = o.lubricant.viscosity_Pa_s;
  l.pressure_viscosity_per_Pa = o.lubricant.pressure_viscosity_per_Pa;
  l.law = o.micro_ehl->pressure_viscosity_law;
  return l;
}

// The film of the ball at share s of its load while the disc slides at U under the held ball:
// u_m = U/2, Δu = U, load s W on the modulus s E' (load sharing, ball_film.h) — and its traction.
struct Film {
  double central_m, traction_N;
};
Film film_at_share(const HomogeniseOptions& o, double share, double u) {
  lubrication::EhlPointOptions grid;
  grid.nodes_x = grid.nodes_y = kFilmGrid;
  const double w = share * o.pin.normal_load_N;
  const lubrication::EhlPointResult f =
      lubrication::solve_ehl_point({w, o.pin.radius_m, share * 2.0 * o.e_star_Pa, 0.5 * u}, ball_oil(o), grid);
  EXPECT_TRUE(f.converged) << f.message;
  return {f.central_film_m,
          lubrication::ehl_point_traction(f, ball_oil(o), u, o.micro_ehl->eyring_stress_Pa, w, {}, o.micro_ehl->limiting_shear).force_N};
}

TEST(BallFilm, TheFaceIsHertzsCircleAndTheAsperitiesCarryThePatchPressureOverIt) {
  // Johnson (1985) (4.22): a³ = 3 W R / (4 E*) — 85.226 µm for 10 N on a 9.525 mm ball, E* 115.4 GPa.
  const HomogeniseOptions o = ball_options();
  EXPECT_NEAR(nominal_contact_radius_m(o), 8.5226e-5, 1e-9);
  const CellTable cells = yielding_cells(o);
  const PinTable pin = ball_pin(o, cells);
  const double area = M_PI * std::pow(nominal_contact_radius_m(o), 2);
  EXPECT_NEAR(pin.nominal_area_m2 / area, 1.0, 1e-12);
  for (std::size_t m = 0; m < pin.separation_m.size(); ++m) {
    // The film over the circle is uniform: N_s = π a² p_s(h̄) exactly (the face's weights sum to π a²).
    EXPECT_NEAR(pin.solid_load_N[m], area * cells.solid_pressure_Pa[m].mean, 1e-12 * area * 2e9) << m;
    // The ball's fluid is its EHL film alone: no rigid lift or Petroff shear beside it.
    EXPECT_EQ(pin.wedge_lift_per_eta_u_m[m] + pin.rugosity_lift_per_eta_u_m[m] + pin.shear_per_eta_u_m[m], 0.0);
  }
  // Solves that did not converge (thin films at large shares on this coarse grid) are each listed.
  ASSERT_TRUE(pin.ball.has_value());
  EXPECT_EQ(pin.ball->messages.size(), static_cast<std::size_t>(pin.ball->unconverged));
}

TEST(BallFilm, TheJunctionSeesTheMeanHertzPressure) {
  // The junction's capped solves run at the nominal pressure: a ball's W/(πa²), 0.44 GPa here —
  // exactly a flat pin's whose face is the ball's Hertz circle (the same solves to the bit).
  HomogeniseOptions ball = ball_options();
  ball.surface.grid = 32;
  ball.surface.size_m = 4e-6;
  ball.surface.rms_height_m = 5e-8;
  ball.surface.cutoff_wavelength_m = 5e-7;
  HomogeniseOptions flat = ball;
  flat.pin.shape = PinShape::flat;
  flat.pin.radius_m = nominal_contact_radius_m(ball);
  const Eigen::ArrayXXd z = contact::gaussian_surface(ball.surface);
  const SolidContact on_ball = junction_contact(ball, z), on_face = junction_contact(flat, z);
  ASSERT_EQ(on_ball.unconverged, 0);
  EXPECT_EQ(on_ball.mu_boundary, on_face.mu_boundary);
  EXPECT_EQ(on_ball.mu_s_max, on_face.mu_s_max);
  // Bowden & Tabor bound it: μ_b ≥ τ_i/H (every contact at most at the hardness).
  EXPECT_GE(on_ball.mu_boundary, ball.interface_shear_strength_Pa / kBallHardness * (1.0 - 1e-6));
}

TEST(BallFilm, AFilmBetweenTheSolvedSharesCarriesTheShareWhoseFilmItIs) {
  // At 1 m/s: the film solved at s = 0.05 (between the shares 0.046 and 0.1) has a thickness at
  // which the table's inversion must give back s = 0.05 and its traction. ln s and ln F are
  // interpolated linearly in ln h_c over a third of a decade of s, where h_c ∝ s^{−q} with q
  // changing slowly: 2 % each.
  const HomogeniseOptions o = ball_options();
  const double u = 1.0;
  std::vector<double> shares, films, tractions;
  for (int j = -12; j <= 0; ++j) {
    shares.push_back(std::pow(10.0, j / 3.0));
    const Film f = film_at_share(o, shares.back(), u);
    films.push_back(f.central_m);
    tractions.push_back(f.traction_N);
  }
  const Film between = film_at_share(o, 0.05, u);
  const rig::BallFilmCurve curve(shares, films, tractions);
  const rig::BallFilmAt at = curve.at(between.central_m);
  EXPECT_NEAR(at.share / 0.05, 1.0, 0.02);
  EXPECT_NEAR(at.traction_N / between.traction_N, 1.0, 0.02);
  // A film squeezed thinner than the whole load's pushes harder than W (the ball rises onto it),
  // up to the cap; at the whole load's own film it carries W.
  const rig::BallFilmAt whole = curve.at(films.back());
  EXPECT_NEAR(whole.share, 1.0, 1e-12);
  EXPECT_NEAR(whole.traction_N / tractions.back(), 1.0, 1e-12);
  EXPECT_GT(curve.at(0.9 * films.back()).share, 1.0);
  EXPECT_EQ(curve.at(0.1 * films.back()).share, rig::kBallFilmMaxShare);
  // Thicker than the smallest share's: the film fades as the last interval's power law.
  const rig::BallFilmAt thick = curve.at(2.0 * films.front());
  EXPECT_LT(thick.share, shares.front());
  EXPECT_GT(thick.share, 0.0);
}

TEST(BallFilm, FilmsThinnerThanTheRestSeparationNeedNotBeSolved) {
  // add_ball_film stops each speed's shares at the first film thinner than half the asperities' rest
  // separation (42 nm here). Wherever the rig's balance can lie — at or above that — the film's
  // load and traction are those of every share solved: the same two films bracket h̄, solved again
  // (1e-9: a film solved twice agrees to its last digits, FFTW's plans aside).
  const HomogeniseOptions o = ball_options();
  const PinTable pin = ball_pin(o, yielding_cells(o));
  ASSERT_TRUE(pin.ball.has_value());
  const BallFilmTable& some = *pin.ball;
  const BallFilmTable all = ball_film(o, 0.0);
  EXPECT_GT(some.not_needed, 0);
  EXPECT_EQ(all.not_needed, 0);
  EXPECT_NEAR(some.thinnest_film_m, 0.5 * 4.0 * kBallSigma * (1.0 - std::sqrt(o.pin.normal_load_N / pin.nominal_area_m2 / 2e9)), 0.05 * some.thinnest_film_m);
  for (std::size_t k = 1; k < all.eta_u_Pa_m.size(); ++k) {
    const rig::BallFilmCurve a(some.share, some.central_film_m[k], some.traction_N[k]), b(all.share, all.central_film_m[k], all.traction_N[k]);
    for (double h = some.thinnest_film_m; h < 20.0 * some.thinnest_film_m; h *= 1.1) {
      EXPECT_NEAR(a.at(h).share / b.at(h).share, 1.0, 1e-9) << k << ' ' << h;
      EXPECT_NEAR(a.at(h).traction_N / b.at(h).traction_N, 1.0, 1e-9) << k << ' ' << h;
    }
  }
}

TEST(BallFilm, NoFilmShearsAboveItsLimitingShearStress) {
  // [micro_ehl] limiting_shear_pressure_coefficient Λ: each solved film shears at no more than Λ p
  // anywhere, so its traction is at most Λ times the load it carries, Λ s W (its pressures
  // integrate to s W to the solver's load balance, 1e-6 here), and the fastest films reach it
  // (to 1e-6: sheared at the limit wherever they carry load); the limit lowers the traction of the
  // film at share 0.05 and 1 m/s.
  HomogeniseOptions o = ball_options();
  o.micro_ehl->limiting_shear.pressure_coefficient = 0.02;
  const BallFilmTable t = ball_film(o, 40e-9);
  int solved = 0;
  double nearest = 0.0;
  for (std::size_t k = 1; k < t.eta_u_Pa_m.size(); ++k)
    for (std::size_t j = 0; j < t.share.size(); ++j) {
      if (std::isnan(t.traction_N[k][j])) continue;
      ++solved;
      const double bound = 0.02 * t.share[j] * o.pin.normal_load_N;
      EXPECT_LE(t.traction_N[k][j], bound * (1.0 + 1e-6)) << k << " " << j;
      nearest = std::max(nearest, t.traction_N[k][j] / bound);
    }
  EXPECT_GT(solved, 10);
  EXPECT_GT(nearest, 1.0 - 1e-6);
  const Film f = film_at_share(o, 0.05, 1.0);
  HomogeniseOptions unlimited = ball_options();
  EXPECT_LT(f.traction_N, film_at_share(unlimited, 0.05, 1.0).traction_N);
}

TEST(BallFilm, AKilledRunResumesFromTheSpeedNodesItKept) {
  // A first run keeps every node it solves (as JSON, the way `tribo homogenise` writes
  // DIR/ball-film/); a second run that finds only every other node — a run killed half-way — solves
  // exactly the missing ones and tabulates the same films (kept nodes to the bit, the solved again
  // to 1e-9 as above), the unconverged and skipped counts alike. A node kept from another solve
  // (another thinnest film) is not taken.
  const HomogeniseOptions o = ball_options();
  const double thinnest_film_m = 40e-9;
  std::map<std::size_t, std::string> kept;
  const BallFilmStore keep_all{{}, [&](std::size_t k, const BallFilmNode& node, bool taken) {
                                 EXPECT_FALSE(taken);
                                 kept[k] = to_json(node).dump();
                               }};
  const BallFilmTable first = ball_film(o, thinnest_film_m, keep_all);
  const std::size_t speeds = first.eta_u_Pa_m.size();
  ASSERT_GE(speeds, 5u);
  ASSERT_EQ(kept.size(), speeds - 1);  // ηU = 0 has no film

  std::vector<std::size_t> solved_again, taken_back;
  const BallFilmStore half{[&](std::size_t k) -> std::optional<BallFilmNode> {
                             if (k % 2 == 0) return std::nullopt;
                             BallFilmNode node = ball_film_node_from_json(nlohmann::json::parse(kept.at(k)));
                             if (k == 1) node.thinnest_film_m *= 2.0;  // from a solve with another rest separation
                             return node;
                           },
                           [&](std::size_t k, const BallFilmNode&, bool taken) { (taken ? taken_back : solved_again).push_back(k); }};
  const BallFilmTable resumed = ball_film(o, thinnest_film_m, half);
  std::sort(solved_again.begin(), solved_again.end());
  std::vector<std::size_t> expected{1};
  for (std::size_t k = 2; k < speeds; k += 2) expected.push_back(k);
  EXPECT_EQ(solved_again, expected);
  std::vector<std::size_t> kept_odd;
  for (std::size_t k = 3; k < speeds; k += 2) kept_odd.push_back(k);
  EXPECT_EQ(taken_back, kept_odd);
  EXPECT_EQ(resumed.not_needed, first.not_needed);
  EXPECT_EQ(resumed.unconverged, first.unconverged);
  EXPECT_EQ(resumed.messages, first.messages);
  for (std::size_t k = 1; k < speeds; ++k)
    for (std::size_t j = 0; j < first.share.size(); ++j) {
      const double a = first.central_film_m[k][j], b = resumed.central_film_m[k][j];
      const double fa = first.traction_N[k][j], fb = resumed.traction_N[k][j];
      ASSERT_EQ(std::isnan(a), std::isnan(b)) << k << ' ' << j;
      if (std::isnan(a)) continue;
      const double tolerance = (k % 2 == 1 && k != 1) ? 0.0 : 1e-9;
      EXPECT_NEAR(b / a, 1.0, tolerance) << k << ' ' << j;
      EXPECT_NEAR(fb / fa, 1.0, tolerance) << k << ' ' << j;
    }
}

TEST(BallFilm, ANodeThatCannotBeKeptFailsTheSolveWithItsReason) {
  // A store that cannot write (a full disk) must fail the solve with its own error, from outside
  // the threads that solve the nodes — not terminate the program from inside one.
  const HomogeniseOptions o = ball_options();
  int calls = 0;
  const BallFilmStore full_disk{{}, [&](std::size_t, const BallFilmNode&, bool) {
                                  ++calls;
                                  throw std::runtime_error("no space left on device");
                                }};
  try {
    ball_film(o, 40e-9, full_disk);
    FAIL() << "a store that throws must fail the solve";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no space left on device");
  }
  EXPECT_EQ(calls, 1);
}

TEST(BallFilm, BetweenSpeedNodesTheRigReadsTheFilmSolvedAtThatSpeed) {
  // Nodes at 1 and 3.16 m/s (two a decade, the coarsest axis the docs allow), the films solved at
  // the table's 13 shares; at 1.78 m/s, between them, the films solved directly at 10 % and 100 %
  // of W. The rig's reading (rig/ball_film.h: each node's film at h̄ (ηU_k/ηU)^0.67, ln s and ln F
  // linear in ln ηU) must put the film carrying that share at the solved thickness and give its
  // traction. Tolerance: the film's speed exponent here differs from Hamrock–Dowson's 0.67 by
  // ≲ 0.05, which over a quarter of the half-decade's ln-span moves h̄ by ≲ 1.5 %; the traction is
  // read at the share, where it is not quite a power law of U either (at 10 % of W the solved
  // traction at 1.78 m/s lies 1.7 % below its neighbours' geometric mean): 3 %.
  const HomogeniseOptions o = ball_options();
  const double eta = o.lubricant.viscosity_Pa_s, u_lo = 1.0, u_hi = std::sqrt(10.0), u = std::sqrt(u_lo * u_hi);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> shares;
  for (int j = -12; j <= 0; ++j) shares.push_back(j == 0 ? 1.0 : std::pow(10.0, j / 3.0));
  std::vector<std::vector<double>> films{std::vector<double>(shares.size(), nan)}, tractions = films;
  for (double node : {u_lo, u_hi}) {
    films.emplace_back();
    tractions.emplace_back();
    for (double s : shares) {
      const Film f = film_at_share(o, s, node);
      films.back().push_back(f.central_m);
      tractions.back().push_back(f.traction_N);
    }
  }
  const rig::BallFilm ball(shares, {0.0, eta * u_lo, eta * u_hi}, films, tractions, o.pin.normal_load_N);
  for (double s : {0.1, 1.0}) {
    const Film direct = film_at_share(o, s, u);
    // The separation at which the rig's film carries s W: bisection in ln h̄ (W_f falls with h̄).
    double lo = std::log(0.5 * direct.central_m), hi = std::log(2.0 * direct.central_m);
    for (int i = 0; i < 100; ++i) {
      const double mid = 0.5 * (lo + hi);
      (ball.at(std::exp(mid), eta * u).load_N > s * o.pin.normal_load_N ? lo : hi) = mid;
    }
    const double h = std::exp(0.5 * (lo + hi));
    EXPECT_NEAR(h / direct.central_m, 1.0, 0.015) << s;
    EXPECT_NEAR(ball.at(h, eta * u).shear_N / direct.traction_N, 1.0, 0.03) << s;
  }
}

// The whole chain: pin table → law.json → the rig's steady sliding, against direct solves.
class BallOnDisc : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {  // the films once for the suite (≈ 2 s)
    const HomogeniseOptions o = ball_options();
    const nlohmann::json law = law_json(o, yielding_cells(o), ball_pin(o, yielding_cells(o)));
    base_ = new rig::HomogenisedBase(rig::law_table_from_json(law, "ball law.json"), o.pin.normal_load_N);
  }
  static void TearDownTestSuite() {
    delete base_;
    base_ = nullptr;
  }
  const HomogeniseOptions o_ = ball_options();
  static inline rig::HomogenisedBase* base_ = nullptr;
};

TEST_F(BallOnDisc, SlowSlidingIsTheYieldingAsperitiesBoundaryFriction) {
  // At 1 cm/s the full load's film is thinner than the asperities' separation at rest: the film
  // carries a few per cent, and μ is Bowden & Tabor's τ_i/H of yielding contacts (N_s = H A_r),
  // 0.1 — less the share the film takes, plus its own traction.
  const rig::SteadySliding s = rig::steady_sliding(*base_, 0.01);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_LT(s.fluid_share, 0.05);
  EXPECT_NEAR(s.mu, o_.interface_shear_strength_Pa / kBallHardness, 0.005);
  EXPECT_EQ(s.regime, rig::LubricationRegime::boundary);
}

TEST_F(BallOnDisc, FastSlidingRidesOnTheBallsFullEhlFilm) {
  // At 3 m/s the ball's own EHL film at its whole load (solved here directly) is far above the
  // asperities (4σ = 80 nm): the steady separation is that film's central thickness and μ its
  // traction over W. 3 m/s is the axis' last node and the oil unheated (γ = 0), so the rig reads
  // this very film: 1e-6 (the balance's bisection and the Jaeger loop's own tolerance).
  const double u = 3.0;
  const Film full = film_at_share(o_, 1.0, u);
  const rig::SteadySliding s = rig::steady_sliding(*base_, u);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_GT(full.central_m, 8.0 * kBallSigma);
  EXPECT_NEAR(s.separation_m / full.central_m, 1.0, 1e-6);
  EXPECT_NEAR(s.fluid_share, 1.0, 1e-9);
  EXPECT_NEAR(s.mu / (full.traction_N / o_.pin.normal_load_N), 1.0, 1e-6);
  EXPECT_EQ(s.regime, rig::LubricationRegime::full_film);
}

TEST_F(BallOnDisc, TheRigTakesTheBallAtTheLoadItsFilmWasSolvedAt) {
  try {
    rig::HomogenisedBase other(base_->table(), 5.0);
    FAIL() << "a ball's table at another load was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("pin.normal_load_N"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::homogenise
