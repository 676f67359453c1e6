// Greenwood & Williamson (Proc. R. Soc. A 295 (1966) 300) statistical contact of a rough surface
// with a flat: identical spherical summits of radius β, areal density η, heights z with density
// φ(z) of standard deviation σ_s; each summit is a Hertz contact. At separation d (from the mean
// summit plane), with F_k(h) = ∫_h^∞ (s − h)^k φ*(s) ds on the standardised density φ*:
//   summits in contact   N / A0 = η F_0(d/σ_s)
//   real area            A / A0 = π η β σ_s F_1(d/σ_s)
//   nominal pressure     W / A0 = (4/3) η E* √β σ_s^{3/2} F_{3/2}(d/σ_s)
// Summit heights:
//   Gaussian      φ*(s) = exp(−s²/2)/√(2π)
//   exponential   φ*(s) = e^{−s} (s ≥ 0 measured from the lowest summit), F_k(h) = Γ(k+1) e^{−h}
//                 for h ≥ 0, hence A / W = √(π β / σ_s) / E* exactly at every load.
// Summit parameters from the spectral moments of an isotropic surface (McCool, Wear 107 (1986) 37):
//   η = m4 / (6π√3 m2),  β = (3/8) √(π / m4),  σ_s = √(m0 − 3.717e-4 / (η² β²)),
// where m0 = Rq², m2 = ⟨(∂h/∂x)²⟩ = h'_rms²/2, m4 = ⟨(∂²h/∂x²)²⟩ = (3/8) ⟨(∇²h)²⟩.
#pragma once

#include "contact/surface.h"

namespace tribo::contact {

enum class SummitDistribution { gaussian, exponential };

struct GreenwoodWilliamson {
  double summit_density_per_m2 = 0.0;  // η
  double summit_radius_m = 0.0;        // β
  double summit_std_m = 0.0;           // σ_s
  double e_star_Pa = 0.0;
  SummitDistribution distribution = SummitDistribution::gaussian;
};

struct GwState {
  double separation_m = 0.0;    // d
  double pressure_Pa = 0.0;     // nominal W / A0
  double area_fraction = 0.0;   // A / A0
  double summits_per_m2 = 0.0;  // N / A0
};

// Throws std::invalid_argument naming the non-positive parameter.
void validate(const GreenwoodWilliamson& gw);

// F_k(h) of the standardised summit density (k = 0, 1, 3/2 are the ones used).
double gw_integral(SummitDistribution distribution, double k, double h);

GwState gw_at_separation(const GreenwoodWilliamson& gw, double separation_m);
// The separation that carries a nominal pressure W/A0 > 0 (bisection on the monotone F_{3/2}).
GwState gw_at_pressure(const GreenwoodWilliamson& gw, double nominal_pressure_Pa);

// McCool's summit parameters from a surface's statistics (see header).
GreenwoodWilliamson gw_from_statistics(const SurfaceStatistics& stats, double e_star_Pa,
                                       SummitDistribution distribution = SummitDistribution::gaussian);

}  // namespace tribo::contact
