// A ball on the disc (`[pin] shape = "ball"`): its elastohydrodynamic film solved for the rig at
// shares of the load over the ηU axis — the pin scale of a ball-on-disc tribometer.
//
// Load sharing (Johnson, Greenwood & Poon 1972; Gelinck & Schipper 2000, as lubrication/
// mixed_point.h): of the ball's load W the film carries W_f = s W and the asperities the rest;
// each is solved as if alone on bodies whose modulus is scaled by its share, so the film is the
// smooth EHL point contact (lubrication/ehl_point.h) at load s W and reduced modulus s E' — its
// Hertz radius the whole load's, a = (3 W R / (4 E*))^{1/3}. The asperities carry the patches' own
// nominal pressure p_s(h̄) over that circle (pin.h with the circle as the face), so the solid
// columns are the BEM's, not Greenwood–Williamson's.
//
// The ball is held still on the sliding disc (a pin-on-disc rig): entrainment u_m = U/2, sliding
// Δu = U. At each ηU node (U = ηU/η0) the film is solved at shares s_j (log-spaced from
// kBallFilmMinShare to 1): central film h_c(s_j) between the mean planes and its Eyring traction
// F(s_j) (lubrication/ehl_traction.h, at the film's own pressures, τ0 of [micro_ehl]). law.json
// keeps the films; the rig reads the film's load at a separation and ηU from them
// (rig/ball_film.h: the inversion of h_c(s) and the film-scaled interpolation between nodes).
// A share whose solve did not converge is left out, and listed.
//
// The film depends on η0 u_m alone only with Barus' law; with Roelands' the table's film at ηU is
// the reference oil's at U = ηU/η0, and a warmer oil in the rig (η(ΔT) U) reads it at a slower
// speed — the same reading as the asperity tops' films (micro_ehl.h). Left out: the asperity
// pressure's shape over the circle (uniform), the roughness in the film's flow, the rugosity lift
// and the Petroff shear of the flat circle (the EHL film is the ball's fluid: both would count it
// twice), the film's own heating (the rig's flash temperature enters through η(ΔT)).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "homogenise/options.h"

namespace tribo::homogenise {

struct BallFilmTable {
  double hertz_radius_m = 0;
  std::vector<double> share;                        // s_j, increasing, the last 1
  std::vector<double> eta_u_Pa_m;                   // the table's ηU axis (the first 0)
  std::vector<std::vector<double>> central_film_m;  // [ηU][s]: h_c (NaN unsolved or at ηU = 0)
  std::vector<std::vector<double>> traction_N;      // [ηU][s]: F (NaN alike)
  double thinnest_film_m = 0;         // the films not solved below (ball_film)
  int not_needed = 0;                 // solves skipped so: thinner still, NaN in the rows above
  int unconverged = 0;
  std::vector<std::string> messages;  // one per film solve left out
};

inline constexpr double kBallFilmMinShare = 1e-4;
inline constexpr int kBallFilmSharesPerDecade = 3;

// One speed node's films as ball_film solves them: its row of the table (NaN unsolved), the reason
// each share's solve was left out ("" where it converged or was not needed) and the shares not
// needed. eta_u_Pa_m and thinnest_film_m say which solve it belongs to.
struct BallFilmNode {
  double eta_u_Pa_m = 0, thinnest_film_m = 0;
  std::vector<double> central_film_m, traction_N;
  std::vector<std::string> left_out;
  int not_needed = 0;
};

// Where finished speed nodes are kept, so that a killed run resumes (`tribo homogenise` keeps them
// in DIR/ball-film/): `load(k)` returns node k if a run with the same inputs finished it; a loaded
// node is taken only if it belongs to this solve (the same ηU, thinnest film and number of shares),
// otherwise it is solved again. `finished(k, node, taken)` is called once for every node, one
// call at a time: first for each node taken from `load` (taken = true), then for each node solved,
// as it finishes (taken = false; the one to keep). Either may be empty. The first exception from
// `finished` or from a node's solve is rethrown when the running solves are done; the nodes not yet
// started are not solved, and after a `finished` that threw no node is passed on.
struct BallFilmStore {
  std::function<std::optional<BallFilmNode>(std::size_t k)> load;
  std::function<void(std::size_t k, const BallFilmNode& node, bool taken)> finished;
};

// The node as JSON (the films as law.json's ball_film rows: an unsolved film is null) and back;
// the reader throws nlohmann::json::exception on a torn or foreign file.
nlohmann::json to_json(const BallFilmNode& node);
BallFilmNode ball_film_node_from_json(const nlohmann::json& j);

// Solves the films (in parallel over the speeds, options.threads). At each speed the shares are
// solved in increasing order until two films have converged and the last is thinner than
// `thinnest_film_m`: the larger shares' films are thinner still. add_ball_film (pin.h) passes half the
// separation at which the asperities alone carry W — the rig's balance never lies below it, and the
// solves there are the thinnest, slowest and likeliest to fail (on a 65² grid at slow speeds,
// nanometre films under high load). 0 solves every share. Throws std::invalid_argument unless
// options describe a ball; std::runtime_error when at some ηU fewer than two shares converged.
BallFilmTable ball_film(const HomogeniseOptions& options, double thinnest_film_m, const BallFilmStore& store = {});

}  // namespace tribo::homogenise
