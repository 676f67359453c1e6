// Closed forms of the thesis' junction model (chapter III.1) — static friction from plastic
// junction growth under combined normal and tangential load.
//
//   Tabor, fully plastic junction, thesis (3.1.9):   σ0 A = √(W² + α F²)
//   Anelastic growth law, thesis (3.1.13):            b Aⁿ dA/dt + σ0 A = √(W² + α F²)
//   Slip when the junctions shear, thesis (3.1.14):   μs = F_s / W = τ_i A_s / W
//   Static-friction locus, thesis (3.1.24), S = σ0/τ_i, L = σ0^{1+n} / (Wⁿ b):
//       φ̇ = L · μs^{-n} · S^{-(1+n)} · [ √(1 + α μs²) − S μs ]
//   Upper asymptote fixes S, thesis (3.1.23):         S = √(1/μs,max² + α)
//   Strain-rate hardening, thesis (5.1.2):            σ0 = κ φ̇^m, i.e. L = L_ref (φ̇/φ̇_ref)^{m(1+n)}
//
// φ̇ is the load-rate variable τ̇/σ ≈ Ḟ/W in 1/s (3.1.20)–(3.1.21).
#pragma once

namespace tribo::contact {

// Parameters of the locus (3.1.24). `location_per_s` is L = σ0^{1+n}/(Wⁿ b) at the reference load
// rate; with strain_rate_index_m > 0 the flow stress, hence L, follows σ0 = κ φ̇^m (5.1.2).
struct JunctionLocus {
  double alpha = 25.0;                   // Tabor's combined-stress coefficient (3.1.5), 10..25
  double n = 1.25;                       // area exponent of anelastic damping (3.1.12), 1..1.5
  double sigma0_over_tau_i = 5.30;       // S, from the upper asymptote (3.1.23); 5.3 for μs,max = 0.55, α = 25
  double location_per_s = 1.0;           // L at φ̇_ref
  double strain_rate_index_m = 0.0;      // m in σ0 = κ φ̇^m; 0 for mild steel, ≈ 0.1 brass (5.1.2)
  double reference_load_rate_per_s = 1.0;  // φ̇_ref at which location_per_s is given
};

// Throws std::invalid_argument naming the parameter when the locus is not physical
// (α ≤ 0, n < 0, S² ≤ α, L ≤ 0, m < 0 or m (1+n) ≥ 1, φ̇_ref ≤ 0).
void validate(const JunctionLocus& locus);

// thesis (3.1.23): S = σ0/τ_i that makes μs → μs,max as φ̇ → 0.
double sigma0_over_tau_i_from_upper_asymptote(double mu_s_max, double alpha);

// The upper asymptote μs,max = 1/√(S² − α) implied by a locus (inverse of (3.1.23)).
double upper_asymptote(const JunctionLocus& locus);

// thesis (3.1.24) read forwards: the load rate φ̇ (1/s) at which slip occurs with friction μs,
// for 0 < μs ≤ μs,max. With strain-rate hardening the relation is solved for φ̇ in closed form.
double load_rate_at_static_friction_per_s(const JunctionLocus& locus, double mu_s);

// thesis (3.1.24) inverted: μs at load rate φ̇ ≥ 0; μs,max at φ̇ = 0, decreasing monotonically.
// Solved to machine precision by a bracketed Newton iteration in ln μs (the locus is monotone).
double static_friction_from_load_rate(const JunctionLocus& locus, double phi_dot_per_s);

// L that puts the point (φ̇, μs) on the locus — how a measured static friction value fixes the
// location parameter (thesis §5.1 fits L to the data with S from the asymptote).
double location_through_point_per_s(const JunctionLocus& shape, double phi_dot_per_s, double mu_s);

// thesis (3.1.9): real area of a fully plastic junction, A = √(W² + α F²) / σ0.
double tabor_area_m2(double normal_load_N, double tangential_load_N, double alpha, double sigma0_Pa);

}  // namespace tribo::contact
