// Rate-dependent junction growth under a tangential ramp, integrated in time (thesis §3.1).
//
//   thesis (3.1.13):  b Aⁿ dA/dt + σ0 A = √(W² + α F²),    F = F0 + Ḟ t,   A(0) = √(W² + α F0²)/σ0
//   slip, (3.1.14):   F = τ_i A  (event, crossing upwards), μs = F_s / W
//   load rate:        the ramp's φ̇ = Ḟ/W, and (3.1.21) φ̇_s = τ_i Ȧ_s / W at the slip instant.
// In units a = σ0 A / W, f = F / W, s = L t with L = σ0^{1+n}/(Wⁿ b) (the locus' location
// parameter of contact/junction_locus.h) the ODE reads aⁿ da/ds = √(1 + α f²) − a and the slip
// condition f = a/S, S = σ0/τ_i. At the slip instant (μs, φ̇_s) lies exactly on the closed-form
// locus (3.1.24); the ramp rate itself satisfies locus μs(Ḟ/W) ≤ μs ≤ μs,max, because slip needs
// Ḟ ≥ τ_i Ȧ_s and the area lags its equilibrium √(W² + α F²)/σ0.
// Integrated with SUNDIALS CVODE (BDF, dense 1×1 Newton) with root finding on F − τ_i A.
#pragma once

#include <string>
#include <vector>

namespace tribo::contact {

struct JunctionRampParams {
  double normal_load_N = 0.0;                // W
  double hardness_Pa = 0.0;                  // σ0
  double interface_shear_strength_Pa = 0.0;  // τ_i, with σ0/τ_i > √α for a finite μs,max (3.1.23)
  double alpha = 25.0;                       // α (3.1.5)
  double n = 1.25;                           // area exponent of the damping (3.1.12)
  double damping_b = 0.0;                    // b in (3.1.13), N·s / m^{2(1+n)}
  double load_rate_N_per_s = 0.0;            // Ḟ > 0
  double initial_tangential_load_N = 0.0;    // F0 ≥ 0
  double relative_tolerance = 1e-10;         // CVODE rtol on a (atol = rtol · a(0))
  int trajectory_samples = 0;                // > 0: record A(t), F(t) at this many equal times to slip
};

struct JunctionRampResult {
  bool slipped = false;
  double slip_time_s = 0.0;
  double static_friction = 0.0;             // μs = F_s / W
  double tangential_load_at_slip_N = 0.0;   // F_s
  double area_at_slip_m2 = 0.0;             // A_s
  double area_rate_at_slip_m2_per_s = 0.0;  // Ȧ_s from (3.1.13)
  double load_rate_per_s = 0.0;             // ramp φ̇ = Ḟ/W
  double phi_dot_at_slip_per_s = 0.0;       // (3.1.21): τ_i Ȧ_s / W
  long steps = 0;
  std::string message;
  std::vector<double> time_s, area_m2, tangential_load_N;  // trajectory, when requested
};

// Throws std::invalid_argument naming the bad parameter.
JunctionRampResult integrate_junction_ramp(const JunctionRampParams& params);

// b of (3.1.13) from the locus location parameter L = σ0^{1+n} / (Wⁿ b), i.e. b = σ0^{1+n}/(Wⁿ L).
double damping_from_location(double normal_load_N, double hardness_Pa, double n, double location_per_s);

}  // namespace tribo::contact
