// The catalogue's squeeze_film (rig/effects/squeeze_film.h: a load share that builds with slip and
// decays over the squeeze-out time) reads the independent generator's film-thickness ODE
// (gap/independent/laws.h: ḣ = |U|(h_e − h)/D_b − c h⁴, share φ_max h/h_e; Reynolds' parallel-disc
// squeeze, so the film thins as t^(-1/3) once it is well squeezed). The squeeze-out time depends on
// the film thickness, which no experiment gives: with it fitted, the film share (0.46 against 0.57)
// and a half time of 0.044 s (truth 0.028 s) are found and the held-out gap falls 0.053 → 0.026;
// held at the catalogue's 1 µm the fit closed less than a fifth of the gap and a rate-dependent
// static friction was named (issue 15; seed 405 of the full independent set).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lubrication/reference/squeeze_film.h"
#include "tests/gap/one_candidate_fit.h"

namespace tribo::gap {
namespace {

TEST(SqueezeFilm, FitFindsTheFilmShareAndASqueezeOutTimeOfTheRightOrder) {
  const independent::IndependentCase c = independent::make_independent_case("squeeze_film", 405);
  ASSERT_TRUE(c.truth.squeeze.has_value());
  const independent::SqueezeFilmOde& s = *c.truth.squeeze;
  const Diagnosis d = diagnose_with_one_candidate(c, "squeeze_film");
  ASSERT_EQ(d.candidates.size(), 1u);
  const Candidate& k = d.candidates.front();
  const double share = k.params.at("squeeze_film.film_fraction"), h = k.params.at("squeeze_film.film_thickness_m");
  // The time to squeeze the film to half its thickness: the catalogue's under the whole load, the
  // truth's under the film's share of it — from its law at rest, h⁻³ = h_e⁻³ + 3 c t (laws.h), so
  // (2³ − 1) h_e⁻³ = 3 c t½.
  const double tau_fit = lubrication::squeeze_out_time_s(k.model.get("squeeze_film", "viscosity_Pa_s"),
                                                         k.model.get("squeeze_film", "patch_radius_m"), k.rig.normal_load_N, h, 0.5 * h);
  const double tau_true = 7.0 / (3.0 * s.squeeze_constant(c.actual.normal_load_N) * std::pow(s.full_thickness_m, 3));
  std::printf("film share %.3f (truth %.3f), half time %.4f s (truth %.4f s), held-out gap %.4f -> %.4f\n", share, s.max_fraction, tau_fit,
              tau_true, k.heldout_gap_before, k.heldout_gap_after);
  // The share within a factor 2 either way: the forms differ (a share proportional to the
  // thickness, which the h⁴ law keeps longer than an exponential), and the records fix the film
  // left after their stick times rather than the share and the half time apart — the fit settles
  // along that valley wherever round-off puts it: 0.441 and 0.0488 s (2026-12-04), 0.347 and
  // 0.0667 s once the rig's event times moved by 1e-9 relative (one-step integration, 2026-12-05),
  // the same share, 0.18, left after 0.044 s; 0.417 on 2026-11-27, within 25 % before.
  EXPECT_GT(share / s.max_fraction, 0.5);
  EXPECT_LT(share / s.max_fraction, 2.0);
  // The half time within a factor of 3 either way: an exponential stands in for the t^(-1/3) tail.
  EXPECT_GT(tau_fit, tau_true / 3.0);
  EXPECT_LT(tau_fit, 3.0 * tau_true);
  EXPECT_LT(k.heldout_gap_after, 0.5 * k.heldout_gap_before);
}

}  // namespace
}  // namespace tribo::gap
