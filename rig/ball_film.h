// A ball's elastohydrodynamic film as the rig reads it from law.json ("ball_film", written by
// homogenise/ball_film.h): at each ηU node of the table, the smooth EHL point film solved at shares
// s_j of the ball's load W — its central film h_c(s_j) and its traction F(s_j), NaN where a solve
// was left out.
//
// At one node (BallFilmCurve) the film's load at separation h̄ is W times the share whose central
// film is h̄:
//   h_c(1) ≤ h̄ ≤ h_c(s_min)  ln s linear in ln h_c between the bracketing shares, ln F likewise
//   h̄ > h_c(s_min)          the end interval's power law continued: the film fades
//   h̄ < h_c(1)              the end interval's power law continued as well, up to s = kBallFilmMaxShare:
//                            a film squeezed thinner than the whole load's pushes harder than W, and
//                            the ball rises onto h_c(1) (capped so that the rig's film ODE stays finite)
// so the load falls strictly with h̄ below the cap. A share whose film is not thinner than every
// smaller share's is skipped (h_c must fall with s to be inverted).
//
// Between ηU nodes (BallFilm::at) the film is scaled with the speed: at ηU the film is node k's at
// the separation h̄ (ηU_k/ηU)^0.67 — the central film's speed exponent (Hamrock & Dowson 1977,
// h_c ∝ U^0.67) — and ln s is linear in ln ηU between the two nodes read so; the traction is each
// node's at that share s (ln F linear in ln s between the solved shares), ln F linear in ln ηU.
// Exact for films with h_c ∝ (ηU)^0.67 and F ∝ (ηU)^m at every share; reading the traction at the
// share rather than at the scaled separation keeps the film's departure from 0.67 out of it. At fixed h̄ instead the load rises about as (ηU)^10, and a
// table linear in ln ηU there bent the Stribeck curve between nodes (docs/homogenise.md). Between 0
// and the first positive node the first node's film is scaled alike; at ηU = 0 there is none.
#pragma once

#include <vector>

namespace tribo::rig {

inline constexpr double kBallFilmMaxShare = 2.0;
inline constexpr double kBallFilmSpeedExponent = 0.67;

struct BallFilmAt {
  double share = 0;        // W_f / W
  double traction_N = 0;   // F_f
  double log_slope = 0;    // d ln s / d ln h̄ (< 0; 0 at the cap)
};

// One ηU node's films, inverted.
class BallFilmCurve {
 public:
  // Shares s_j (increasing) with their central films and tractions (NaN entries skipped);
  // std::invalid_argument when fewer than two shares have a film, each thinner than the smaller
  // shares' films.
  BallFilmCurve(const std::vector<double>& share, const std::vector<double>& central_film_m, const std::vector<double>& traction_N);
  // std::invalid_argument unless separation_m > 0.
  BallFilmAt at(double separation_m) const;
  // The traction of the film carrying share s of the load (ln F linear in ln s, the end intervals
  // continued beyond the solved shares).
  double traction_at_share_N(double share) const;

 private:
  std::vector<double> ln_s_, ln_h_, ln_f_;
};

class BallFilm {
 public:
  // The shares, the table's ηU axis (the first 0, strictly increasing), the films [ηU][s] (the row
  // at ηU = 0 is not read) and the ball's load W (N). std::invalid_argument on a shape mismatch or
  // a node with fewer than two usable shares.
  BallFilm(const std::vector<double>& share, std::vector<double> eta_u_Pa_m, const std::vector<std::vector<double>>& central_film_m,
           const std::vector<std::vector<double>>& traction_N, double normal_load_N);

  struct Film {
    double load_N = 0, shear_N = 0;
    double load_slope_N_per_m = 0;  // ∂W_f/∂h̄ at fixed ηU
  };
  // std::out_of_range for ηU outside [0, the last node]; std::invalid_argument unless h̄ > 0.
  Film at(double separation_m, double eta_u_Pa_m) const;

 private:
  std::vector<double> eta_u_;
  std::vector<BallFilmCurve> nodes_;  // nodes_[k − 1] at eta_u_[k]
  double normal_load_N_;
};

}  // namespace tribo::rig
