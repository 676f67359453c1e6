// Junction growth in the BEM: normal contact under a tangential load F with Tabor's combined
// yield criterion as the local pressure cap.
//
//   thesis (3.1.5):  σ0² = p² + α τ²   on every yielding cell; here τ is the interfacial shear
//                    stress, taken uniform over the real contact, τ = F / A.
//   ⇒ local cap      p_cap(F) = √(σ0² − α (F/A)²),   A = A(W, p_cap) from the elastic-plastic solve,
// a fixed point in A, solved as the root of the increasing function
//   ψ(c) = c² + α (F / A(c))² − σ0²,   c = p_cap ∈ (W / A_nominal, σ0].
// For a fully plastic contact every loaded cell sits at the cap, so A = W / p_cap and the root is
// Tabor's junction σ0 A = √(W² + α F²) (3.1.9). Where part of the contact is elastic (p < p_cap) the
// cap binds only on the plastic cells and the BEM area grows less than (3.1.9) predicts.
// Slip (gross sliding) sets in when τ = F/A reaches the interfacial strength τ_i (3.1.14).
#pragma once

#include <limits>
#include <string>

#include "contact/normal_contact.h"

namespace tribo::contact {

struct TangentialContactOptions {
  double hardness_Pa = 0.0;  // σ0, > 0
  double alpha = 25.0;       // α of (3.1.5), thesis 10..25
  // τ_i: the junction slips when F/A ≥ τ_i; ∞ never slips.
  double interface_shear_strength_Pa = std::numeric_limits<double>::infinity();
  // Stop the outer iteration when the bracket on c is narrower than cap_tolerance · σ0, or when
  // |ψ(c)| ≤ cap_tolerance · σ0² (A(c) is piecewise constant on a grid, so ψ can jump past 0).
  double cap_tolerance = 1e-9;
  int max_outer_iterations = 80;
  NormalContactOptions normal;  // tolerance and iteration limit of each inner solve (cap is set here)
};

struct TangentialContactResult {
  NormalContactResult contact;      // at the consistent cap
  double tangential_load_N = 0.0;
  double shear_stress_Pa = 0.0;     // τ = F / A
  double pressure_cap_Pa = 0.0;     // √(σ0² − α τ²)
  bool slipped = false;             // τ ≥ τ_i: the junction cannot hold F
  bool converged = false;           // outer and last inner solve converged
  int outer_iterations = 0;         // elastic-plastic solves
  int inner_iterations = 0;         // CG iterations summed over them
  std::string message;
};

// Throws std::invalid_argument for bad input (non-positive hardness or α < 0, negative or
// non-finite loads, or W² + α F² above (σ0 A_nominal)², which no area within the domain carries).
TangentialContactResult solve_tangential_load(ElasticHalfSpace& halfspace, const Eigen::ArrayXXd& gap0_m,
                                              double normal_load_N, double tangential_load_N,
                                              const TangentialContactOptions& options);

}  // namespace tribo::contact
