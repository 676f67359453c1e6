// The stationary surface of a deterministic mixed-EHL contact (ehl_line.h, ehl_point.h): a profile
// r(x) of transverse ridges — uniform across the entrainment direction, stationary so that the
// problem stays steady (a rough pin or ball on a moving disc) — and, for the point contact, a height
// map r(x, y) on top; and the boundary layers' thickness below which a film passes no pressure flow
// (Hu & Zhu's unified treatment; the headers).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tribo::lubrication {

// Heights of the stationary surface towards the other one (m) at (x0 + i dx, y0 + j dy), m from the
// Hertz centre, i along the entrainment direction; bilinear between the samples, zero outside them.
struct EhlHeightMap {
  double x0_m = 0.0, y0_m = 0.0, dx_m = 0.0, dy_m = 0.0;
  Eigen::ArrayXXd height_m;  // nx × ny, at least 2 × 2
};

struct EhlRoughness {
  // Heights r(x) of the stationary surface towards the other one (m) at increasing x_m (m, from the
  // Hertz centre along the entrainment direction), interpolated linearly onto the nodes; zero
  // outside the profile. May be empty where a map is given.
  std::vector<double> x_m, height_m;
  // The boundary layers' thickness H_c, below which the film passes no pressure flow (an adsorbed
  // fatty-acid monolayer is ≈ 2.5 nm thick, Bowden & Tabor 1950; one on each surface, ≈ 5 nm). > 0.
  double contact_film_m = 5e-9;
  // A node is in contact — sheared as a boundary contact, its load the contact's — where the film
  // above the boundary layers is thinner than this (≥ 0): the film closes onto the layers only
  // asymptotically (its flow falls as the cube of that gap), and one of less than two molecular
  // layers of a hydrocarbon (≈ 0.5 nm each) does not shear as a fluid — confined films turn solid-like
  // at several layers already (Gee, McGuiggan, Israelachvili & Homola, J. Chem. Phys. 93, 1990).
  double contact_margin_m = 1e-9;
  // The pressure at which the touching surface yields (Pa; > 0, +∞: elastic): where the flow
  // balance would need more, the pressure stays at it and the surface flows plastically instead
  // (ehl_point.cpp, ehl_line.cpp: pressures()) — the
  // elastic–perfectly-plastic surface of contact/'s BEM (normal_contact.h), about the softer body's
  // indentation hardness (Tabor 1951). The bulk below deflects elastically under the capped pressure.
  double hardness_Pa = std::numeric_limits<double>::infinity();
  // A point contact's surface across the track as well, added to the ridges (the line contact
  // refuses it): the contact is then no longer symmetric in y, and the whole grid is solved.
  std::optional<EhlHeightMap> map = std::nullopt;
};

// Whether a film h (m) leaves the surfaces in contact (EhlRoughness::contact_margin_m).
inline bool in_contact(const EhlRoughness& roughness, double film_m) {
  return film_m < roughness.contact_film_m + roughness.contact_margin_m;
}

// The pressure-flow coefficient ε = c m³ at the face between nodes a and b, with c = ρ̄/(η̄λ) and m
// the film above the boundary layers, and its derivatives in each node's c and m³. On smooth
// surfaces the mean of the nodes' ε (second order where ε is smooth; the standard EHL
// discretisation, Venner & Lubrecht 2000). With boundary layers the mean of c times the harmonic
// mean of m³ — the film factor as two half cells in series, the finite-volume rule for a coefficient
// that jumps (Patankar, Numerical Heat Transfer and Fluid Flow, 1980, §4.2-6) — so that a face passes
// no flow once either node's film has closed, while the orders-of-magnitude swing of the viscosity
// across a pressurised film is still averaged as on smooth surfaces. The mean of ε let a closed node
// pass half of its open neighbour's flow: at the side edges of a point contact that drained films
// through zero (Newton stalled at every speed below 0.05 m/s on the tests' ball at 20 N), and in a
// line contact it let crawling films sink below the layers by draining them.
struct FaceFlow {
  double value;
  double dc_a, dm3_a, dc_b, dm3_b;
};
inline FaceFlow face_flow(double c_a, double m3_a, double c_b, double m3_b, bool boundary_layers) {
  if (!boundary_layers) return {0.5 * (c_a * m3_a + c_b * m3_b), 0.5 * m3_a, 0.5 * c_a, 0.5 * m3_b, 0.5 * c_b};
  const double sum = m3_a + m3_b, c = 0.5 * (c_a + c_b);
  if (sum <= 0.0) return {0.0, 0.0, 0.0, 0.0, 0.0};
  const double film = 2.0 * m3_a * m3_b / sum;
  return {c * film, 0.5 * film, c * 2.0 * m3_b * m3_b / (sum * sum), 0.5 * film, c * 2.0 * m3_a * m3_a / (sum * sum)};
}

// The transported mass ρ̄H at the face downstream of node k, reconstructed from upwind with a
// limited slope (MUSCL with van Albada's limiter; van Albada, van Leer & Roberts 1982):
//   w_{k+½} = w_k + ½ L(a, b),  a = w_k − w_{k−1}, b = w_{k+1} − w_k,  L = a b (a + b)/(a² + b²),
// and its derivatives in w_{k−1}, w_k, w_{k+1}. Where the mass varies smoothly L → (a + b)/2 and the
// wedge term (w_{k+½} − w_{k−½})/ΔX is second order; where a film closes onto the boundary layers
// (b → 0 after a converging a) L → b → 0 and it is first-order upwind, which does not extrapolate
// a converging inlet through the layers (the reason the unlimited second-order upwind cannot be used
// with roughness). This form of the limiter is differentiable wherever a² + b² > 0 — Newton's
// Jacobian has no jump (its TVD form, L = 0 where a b < 0, left the thick film on 1601 nodes
// cycling at ‖F‖ ≈ 0.015) — and L = 0 on a flat stretch.
struct MassFace {
  double value;
  double d_prev, d_here, d_next;
};
inline MassFace limited_mass_face(double prev, double here, double next) {
  const double a = here - prev, b = next - here;
  const double den = a * a + b * b;
  if (!(den > 0.0)) return {here, 0.0, 1.0, 0.0};
  const double num = a * b * (a + b);
  const double la = ((2.0 * a * b + b * b) * den - 2.0 * a * num) / (den * den);
  const double lb = ((a * a + 2.0 * a * b) * den - 2.0 * b * num) / (den * den);
  return {here + 0.5 * num / den, -0.5 * la, 1.0 + 0.5 * (la - lb), 0.5 * lb};
}

// A waviness a cos(2π x/λ) sampled on [from_m, to_m] (m from the Hertz centre), `points` samples
// evenly spaced (≥ 2), the boundary layers at their default.
EhlRoughness cosine_ridges(double from_m, double to_m, double amplitude_m, double wavelength_m, std::size_t points);

// The profile's height at x (m): linear between its points, 0 outside them (and without points).
double ridge_height_m(const EhlRoughness& roughness, double x_m);
// The surface's height at (x, y) (m): the ridges' plus the map's.
double surface_height_m(const EhlRoughness& roughness, double x_m, double y_m);

// Throws std::invalid_argument, the message starting with `who`, for fewer than two points (unless a
// map stands alone), unequal lengths, a non-finite point, positions that do not increase, a map with
// fewer than 2 × 2 samples, a spacing that is not positive or a height that is not finite, a contact
// film that is not positive, a negative margin or a hardness that is not positive.
void validate(const EhlRoughness& roughness, const std::string& who);

}  // namespace tribo::lubrication
