// The thermoelastic crown of a face heated by friction: how far the middle of a slider's face
// stands proud of its rim when the frictional heat flows into it.
//
// In steady state the surface of a half-space taking a heat flux q(x, y) (W/m²) bends with
//   ∇²ₛ u_z = −δ q,   δ = (1 + ν) α / k   (the thermal distortivity, m/W)
// (Barber, J. Appl. Mech. 34 (1967); Barber, Elasticity, ch. "Thermoelasticity"), u_z towards the
// heat, ∇²ₛ the Laplacian along the surface: the point source Q gives u_z = −δ Q ln r / (2π) + C.
// Over a disc of radius a heated uniformly the logarithmic potential is ln a − 1/2 at the centre
// and ln a on the rim, so the centre stands out by
//   Δ = δ Q / (4π) = (1 + ν) α Q / (4π k),
// whatever the radius. No elastic modulus enters: a free thermal strain field is only bent by it.
#pragma once

namespace tribo::contact {

struct ThermoelasticSolid {
  double expansion_per_K = 11.5e-6;       // α; alloy steel 11–13e-6 /K (handbook range)
  double poisson_ratio = 0.3;             // ν; steel
  double conductivity_W_per_m_K = 46.0;   // k; alloy steel (≈ 1 % C), as lubrication::JaegerContact
};

// Throws std::invalid_argument naming the field (α < 0, ν outside [0, 0.5), k ≤ 0, non-finite).
void validate(const ThermoelasticSolid& solid);

// Δ (m) for the heat Q (W, ≥ 0) flowing into the face uniformly over a disc.
double thermoelastic_crown_m(const ThermoelasticSolid& solid, double heat_W);

}  // namespace tribo::contact
