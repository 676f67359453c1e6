// A ball's EHL film as the rig reads it (rig/ball_film.h), on films built here in closed form: a
// family whose central film is h_c = A (ηU)^0.67 s^(−1/q) and traction F = B (ηU)^0.2 s^0.9 at every
// share s — a Hamrock–Dowson-like film, self-similar in speed. The reading is then exact between
// the shares (ln s, ln F linear in ln h_c) and between the speed nodes (the film-scaled
// interpolation), so it must give back the closed form to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "rig/ball_film.h"

namespace tribo::rig {
namespace {

constexpr double kA = 2e-7;    // m / (Pa m)^0.67: h_c at ηU = 1 Pa m and s = 1
constexpr double kB = 0.3;     // N: F at ηU = 1 Pa m and s = 1
constexpr double kQ = 0.1;     // h_c ∝ s^(−q): a stiff film, W_f ∝ h̄^(−10) at fixed ηU
constexpr double kLoad = 10.0; // N

double film_m(double eta_u, double s) { return kA * std::pow(eta_u, kBallFilmSpeedExponent) * std::pow(s, -kQ); }
double traction_N(double eta_u, double s) { return kB * std::pow(eta_u, 0.2) * std::pow(s, 0.9); }
// The closed form's share at separation h and ηU (uncapped).
double share_at(double h, double eta_u) { return std::pow(h / (kA * std::pow(eta_u, kBallFilmSpeedExponent)), -1.0 / kQ); }

struct Films {
  std::vector<double> share, eta_u;
  std::vector<std::vector<double>> central, traction;
};

// Shares 1e-4 … 1 (three a decade) at ηU = 0, 0.01, 0.1 and 1 Pa m: a decade between speed nodes.
Films closed_form_films() {
  Films f;
  for (int j = -12; j <= 0; ++j) f.share.push_back(j == 0 ? 1.0 : std::pow(10.0, j / 3.0));
  f.eta_u = {0.0, 0.01, 0.1, 1.0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double e : f.eta_u) {
    std::vector<double> h, t;
    for (double s : f.share) {
      h.push_back(e > 0.0 ? film_m(e, s) : nan);
      t.push_back(e > 0.0 ? traction_N(e, s) : nan);
    }
    f.central.push_back(h);
    f.traction.push_back(t);
  }
  return f;
}

BallFilm closed_form_ball() {
  const Films f = closed_form_films();
  return BallFilm(f.share, f.eta_u, f.central, f.traction, kLoad);
}

TEST(BallFilm, BetweenSpeedNodesTheFilmScaledReadingIsExactForASelfSimilarFilm) {
  // ηU = 0.0316 Pa m, halfway between two nodes a decade apart, at films carrying 0.3 % … 100 % of
  // W: share and traction to 1e-12 (rounding of exp/log). At fixed h̄ the load rises as (ηU)^6.7
  // here: a value linear in ln ηU between the nodes would overstate it by orders of magnitude.
  const BallFilm ball = closed_form_ball();
  for (double eta_u : {0.0316, 0.05, 0.7}) {
    for (double s : {0.003, 0.05, 0.5, 1.0}) {
      const double h = film_m(eta_u, s);
      const BallFilm::Film at = ball.at(h, eta_u);
      EXPECT_NEAR(at.load_N / (s * kLoad), 1.0, 1e-12) << eta_u << ' ' << s;
      EXPECT_NEAR(at.shear_N / traction_N(eta_u, s), 1.0, 1e-12) << eta_u << ' ' << s;
      // ∂W_f/∂h̄ of W s(h̄) with s ∝ h̄^(−1/q): −W_f/(q h̄).
      EXPECT_NEAR(at.load_slope_N_per_m / (-at.load_N / (kQ * h)), 1.0, 1e-12) << eta_u << ' ' << s;
    }
  }
}

// A film that is not self-similar: its speed exponent drifts with the share and its load exponent
// with the speed, as a real EHL film's do between the isoviscous and piezoviscous regimes.
double drifting_film_m(double eta_u, double s) {
  const double n = 0.6 + 0.03 * std::log10(s), q = 0.1 + 0.02 * std::log10(eta_u);
  return kA * std::pow(eta_u, n) * std::pow(s, -q);
}
double drifting_traction_N(double eta_u, double s) { return kB * std::pow(eta_u, 0.2) * std::pow(s, 0.9 + 0.05 * std::log10(eta_u)); }

BallFilm drifting_ball() {
  Films f = closed_form_films();
  for (std::size_t k = 1; k < f.eta_u.size(); ++k)
    for (std::size_t j = 0; j < f.share.size(); ++j) {
      f.central[k][j] = drifting_film_m(f.eta_u[k], f.share[j]);
      f.traction[k][j] = drifting_traction_N(f.eta_u[k], f.share[j]);
    }
  return BallFilm(f.share, f.eta_u, f.central, f.traction, kLoad);
}

TEST(BallFilm, AtEachNodeTheReadingIsThatNodesFilmsAndItIsContinuousAcrossTheNodes) {
  // At a node the film is that node's inversion alone (the interval's weight 0 or 1), and a hair
  // either side of it the same to 1e-6 relative (the interpolant is continuous, with a kink).
  const Films f = closed_form_films();
  std::vector<std::vector<double>> central(f.central), traction(f.traction);
  for (std::size_t k = 1; k < f.eta_u.size(); ++k)
    for (std::size_t j = 0; j < f.share.size(); ++j)
      central[k][j] = drifting_film_m(f.eta_u[k], f.share[j]), traction[k][j] = drifting_traction_N(f.eta_u[k], f.share[j]);
  const BallFilm ball = drifting_ball();
  for (std::size_t k = 1; k < f.eta_u.size(); ++k) {
    const BallFilmCurve node(f.share, central[k], traction[k]);
    for (double s : {0.001, 0.03, 0.6}) {
      const double h = drifting_film_m(f.eta_u[k], s), e = f.eta_u[k];
      EXPECT_NEAR(ball.at(h, e).load_N / (node.at(h).share * kLoad), 1.0, 1e-12) << k << ' ' << s;
      for (double side : {1.0 - 1e-9, 1.0 + 1e-9}) {
        if (e * side > f.eta_u.back()) continue;
        EXPECT_NEAR(ball.at(h, e * side).load_N / ball.at(h, e).load_N, 1.0, 1e-6) << k << ' ' << s << ' ' << side;
        EXPECT_NEAR(ball.at(h, e * side).shear_N / ball.at(h, e).shear_N, 1.0, 1e-6) << k << ' ' << s << ' ' << side;
      }
    }
  }
}

TEST(BallFilm, TheLoadsSlopeIsItsDerivativeInTheSeparation) {
  // ∂W_f/∂h̄ at fixed ηU against a centred difference (step 1e-6 h̄: truncation ~1e-12, rounding
  // ~1e-10 relative): at a node, a third and two thirds of the way between nodes, below the first
  // node, and where one node's film is at its cap and the other's not — 1e-6.
  const BallFilm ball = drifting_ball();
  for (double eta_u : {0.1, 0.0215, 0.464, 0.002}) {
    for (double s : {0.002, 0.05, 0.7, 1.3}) {
      const double h = drifting_film_m(eta_u, s), dh = 1e-6 * h;
      const double slope = (ball.at(h + dh, eta_u).load_N - ball.at(h - dh, eta_u).load_N) / (2.0 * dh);
      EXPECT_NEAR(ball.at(h, eta_u).load_slope_N_per_m / slope, 1.0, 1e-6) << eta_u << ' ' << s;
    }
  }
  // Between the nodes 0.1 and 1 at 0.3 Pa m, 3 % below the whole-load film: the slower node is read
  // 10 % below its own whole-load film (capped at 2 W), the faster 5 % above (not capped) — the
  // slope is the uncapped node's part of it.
  const double eta_u = 0.3, h = 0.97 * drifting_film_m(eta_u, 1.0), dh = 1e-6 * h;
  const double slope = (ball.at(h + dh, eta_u).load_N - ball.at(h - dh, eta_u).load_N) / (2.0 * dh);
  EXPECT_LT(slope, 0.0);
  EXPECT_NEAR(ball.at(h, eta_u).load_slope_N_per_m / slope, 1.0, 1e-6);
}

TEST(BallFilm, BelowTheFirstNodeTheFirstNodesFilmIsScaledDownAndAtRestThereIsNone) {
  const BallFilm ball = closed_form_ball();
  const double eta_u = 1e-3, h = film_m(eta_u, 0.2);  // a decade below the first node
  EXPECT_NEAR(ball.at(h, eta_u).load_N / (0.2 * kLoad), 1.0, 1e-12);
  // At ηU = 1e-300 Pa m (a slider just stuck) the scaled film's share underflows: no film, not NaN.
  const BallFilm::Film crawl = ball.at(h, 1e-300);
  EXPECT_EQ(crawl.load_N, 0.0);
  EXPECT_EQ(crawl.shear_N, 0.0);
  EXPECT_EQ(crawl.load_slope_N_per_m, 0.0);
  const BallFilm::Film rest = ball.at(h, 0.0);
  EXPECT_EQ(rest.load_N, 0.0);
  EXPECT_EQ(rest.shear_N, 0.0);
}

TEST(BallFilm, AFilmThinnerThanTheWholeLoadsPushesHarderUpToTheCapAndBeyondTheTableIsRefused) {
  const BallFilm ball = closed_form_ball();
  const double eta_u = 0.3, whole = film_m(eta_u, 1.0);
  // 1 % thinner: s = 0.99^(−10) = 1.106; 20 % thinner would be 9.3 W — capped at 2 W, flat there.
  EXPECT_NEAR(ball.at(0.99 * whole, eta_u).load_N / kLoad, share_at(0.99 * whole, eta_u), 1e-12);
  const BallFilm::Film capped = ball.at(0.8 * whole, eta_u);
  EXPECT_EQ(capped.load_N, kBallFilmMaxShare * kLoad);
  EXPECT_EQ(capped.load_slope_N_per_m, 0.0);
  // Capped at both nodes the blend is the cap itself, at every speed between (not 2 W less a rounding).
  for (double e = 0.1; e < 1.0; e *= 1.0123) EXPECT_EQ(ball.at(0.5 * film_m(e, 1.0), e).load_N, kBallFilmMaxShare * kLoad) << e;
  // Thicker than the smallest share's film: the power law continued, the film fades.
  const double thick = 2.0 * film_m(eta_u, 1e-4);
  EXPECT_NEAR(ball.at(thick, eta_u).load_N / kLoad, share_at(thick, eta_u), 1e-12 * share_at(thick, eta_u));
  EXPECT_THROW(ball.at(whole, 1.01), std::out_of_range);
  EXPECT_THROW(ball.at(whole, -1e-9), std::out_of_range);
  EXPECT_THROW(ball.at(0.0, eta_u), std::invalid_argument);
  EXPECT_THROW(ball.at(std::numeric_limits<double>::quiet_NaN(), eta_u), std::invalid_argument);
}

TEST(BallFilm, UnsolvedSharesAreSkippedAndANodeWithFewerThanTwoIsRefused) {
  Films f = closed_form_films();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // The largest shares left out at the slowest node: the film there continues the last interval's
  // power law, exact for this family.
  for (std::size_t j = 8; j < f.share.size(); ++j) f.central[1][j] = f.traction[1][j] = nan;
  const BallFilm ball(f.share, f.eta_u, f.central, f.traction, kLoad);
  const double h = film_m(0.01, 1.0);
  EXPECT_NEAR(ball.at(h, 0.01).load_N / kLoad, 1.0, 1e-12);
  for (std::size_t j = 1; j < f.share.size(); ++j) f.central[1][j] = nan;
  EXPECT_THROW(BallFilm(f.share, f.eta_u, f.central, f.traction, kLoad), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::rig
