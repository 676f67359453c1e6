// The flash temperature of a surface that passes under a heat source (Blok 1937; Jaeger 1942), at
// high Péclet number: each point of the surface crosses the heated zone in a time short beside the
// time heat takes to spread along the surface, so heat enters the solid normal to its surface only,
// as into a half-space whose surface flux is switched on as the point enters the zone. A constant
// flux q warms the surface of a half-space by 2q√(t/π)/e after a time t (Carslaw & Jaeger,
// "Conduction of Heat in Solids", 2nd ed. 1959, §2.9), e = √(kρc) the solid's thermal effusivity.
// A point at x moving at u has been heated by the flux of each element dx' upstream of it for
// (x − x')/u, so by superposition (Duhamel)
//
//   T(x) − T_bulk = 1/(e √(π u)) ∫_{x0}^{x} q(x') / √(x − x') dx',
//
// x0 the zone's leading edge. It holds where the Péclet number Pe = u l/(2κ) is large (l the
// half-length of the heated zone, κ = k/(ρc) the diffusivity): Archard ("The temperature of
// rubbing surfaces", Wear 2 (1959) 438) takes Pe > 5 as the fast-source regime. The bulk of the
// solid stays at its temperature (the heat of one pass only; a body that warms over a run is not
// modelled).
//
// Discretisation on nodes x_0 < x_1 < … < x_{n−1} (any spacing): q is constant over each node's
// cell, from the midpoint with the node before to the midpoint with the node after (the first cell
// starts at x_0, the last ends at x_{n−1}), and the kernel 1/√(x − x') is integrated exactly over
// each cell: ∫_a^b dx'/√(x − x') = 2(√(x − a) − √(x − b)). The rise at node i is
//   T_i = Σ_{j<i} W_ij q_j + W_ii q_i,
// W_ii taking the part of node i's own cell upstream of x_i. A uniform flux is integrated exactly;
// a smooth one converges at order 3/2 in the spacing (the flux's change over a node's own cell,
// ∝ Δ, meets the kernel's singularity there, whose integral is ∝ √Δ; observed in the tests).
// Because a node's rise depends only on the flux at and upstream of it, a flux that depends on the
// temperature (the film's shear heat, ehl_traction.h) is found node by node from the leading edge.
#pragma once

#include <cstddef>
#include <vector>

namespace tribo::lubrication {

// The solid a moving surface belongs to.
struct HeatedSolid {
  double thermal_conductivity_W_per_m_K = 0.0;  // k (hardened bearing steel ≈ 46)
  double density_kg_per_m3 = 0.0;               // ρ (steel ≈ 7800)
  double specific_heat_J_per_kg_K = 0.0;        // c (steel ≈ 460)
};

// Throws std::invalid_argument naming the field that is not finite and positive.
void validate(const HeatedSolid& solid);
double thermal_effusivity(const HeatedSolid& solid);   // e = √(kρc), W s^½/(m² K)
double thermal_diffusivity_m2_per_s(const HeatedSolid& solid);  // κ = k/(ρc)

// Pe = u l/(2κ) of a surface moving at u past a heated zone of half-length l.
double peclet_number(const HeatedSolid& solid, double speed_m_per_s, double half_length_m);

// The weights W_ij of the discretisation above for one surface moving at `speed_m_per_s` (> 0,
// towards increasing x) over the nodes `x_m`, kept as a packed lower triangle (n(n+1)/2 values).
class MovingSurface {
 public:
  // Throws std::invalid_argument for fewer than two nodes, nodes that do not increase strictly or
  // are not finite, a speed that is not finite and positive, or a bad solid.
  MovingSurface(const std::vector<double>& x_m, double speed_m_per_s, const HeatedSolid& solid);

  // Σ_{j<i} W_ij q_j (K): the rise at node i from the flux upstream of it; q has one value per node (W/m²).
  double upstream_rise_K(std::size_t i, const double* flux_W_per_m2) const;
  // W_ii (K m²/W): the rise at node i per unit flux over its own cell upstream of it.
  double own_weight(std::size_t i) const { return w_[i * (i + 1) / 2 + i]; }

 private:
  std::vector<double> w_;  // row i holds W_i0 … W_ii
};

// The surface's temperature rise (K) at every node under a given flux (W/m², one value per node).
// Throws as MovingSurface, and for a flux of another size.
std::vector<double> moving_surface_temperature_rise_K(const std::vector<double>& x_m, const std::vector<double>& flux_W_per_m2,
                                                      double speed_m_per_s, const HeatedSolid& solid);

}  // namespace tribo::lubrication
