// Homogenisation against closed forms: the flat pin's squeeze film with flow factors (thesis
// (3.2.2), Appendix III), no wedge load between parallel faces, Petroff's full-film shear, the
// fully plastic junction (thesis (3.1.9), (3.1.23)), and the Stribeck curve's ηU scaling and its
// minimum at the transition to full film.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>

#include <nlohmann/json.hpp>

#include "contact/surface.h"
#include "homogenise/law.h"
#include "homogenise/patch.h"
#include "homogenise/pin.h"
#include "homogenise/solid_contact.h"
#include "lubrication/micro_ehl.h"
#include "rig/homogenised_law.h"
#include "rig/law_table.h"
#include "rig/steady_sliding.h"

namespace tribo::homogenise {
namespace {

constexpr double kSigma = 4e-7;

// A cell table with uniform, known factors: φx = φy = phi, smooth film h̄_T = h, φf = 1, no contact.
CellTable uniform_cells(double phi) {
  CellTable t;
  t.sigma_m = kSigma;
  for (double r : {1.0, 2.0, 4.0, 8.0, 16.0}) {
    t.separation_m.push_back(r * kSigma);
    t.solid_pressure_Pa.push_back({0, 0});
    t.area_fraction.push_back({0, 0});
    t.solid_pressure_coarse_Pa.push_back({0, 0});
    t.area_fraction_coarse.push_back({0, 0});
    t.phi_x.push_back({phi, 0});
    t.phi_y.push_back({phi, 0});
    t.phi_s.push_back({0, 0});
    t.film_over_sigma.push_back({r, 0});
    t.phi_f.push_back({1, 0});
    t.couette_shear_factor.push_back({1, 0});
    t.phi_fp.push_back({1, 0});
    t.contact_fraction.push_back({0, 0});
    t.lift_per_eta_u_per_m.push_back({0, 0});
  }
  return t;
}

TEST(PinScale, FlatPinSqueezeIsAppendixIIIDividedByThePressureFlowFactor) {
  // thesis (3.2.2): N_f = −(3/2) π η R⁴ ḣ / h³; with φ the conductance is φ h³/12η, so K = 3πR⁴/(2φh³).
  // The disc's cut rim is second order (lubrication tests); 65 nodes across leave < 0.5 %.
  HomogeniseOptions o;
  const double phi = 0.8;
  const PinTable pin = pin_scale(o, uniform_cells(phi));
  for (std::size_t m = 0; m < pin.separation_m.size(); ++m) {
    const double h = pin.separation_m[m], r = o.pin.radius_m;
    const double closed = 1.5 * M_PI * std::pow(r, 4) / (phi * h * h * h);
    EXPECT_NEAR(pin.squeeze_per_eta_m[m] / closed, 1.0, 5e-3) << "h = " << h;
  }
}

TEST(PinScale, ParallelFacesCarryNoWedgeLoadAndShearAsPetroff) {
  // Uniform coefficients: the Couette divergence vanishes, so the steady film carries nothing
  // (to the Newton tolerance); the shear on the pin is Petroff's ηU A/h exactly.
  HomogeniseOptions o;
  const PinTable pin = pin_scale(o, uniform_cells(0.9));
  for (std::size_t m = 0; m < pin.separation_m.size(); ++m) {
    const double h = pin.separation_m[m];
    const double scale = pin.nominal_area_m2 * o.pin.radius_m / (h * h);  // a wedge load of order ηU A R/h²
    EXPECT_LT(std::abs(pin.wedge_lift_per_eta_u_m[m]), 1e-9 * scale);
    EXPECT_NEAR(pin.shear_per_eta_u_m[m], pin.nominal_area_m2 / h, 1e-12 * pin.nominal_area_m2 / h);
  }
}

TEST(PinScale, ACrownedPinLiftsWhereTheFlatOneDoesNot) {
  // A spherical crown makes a converging-diverging film: with cavitation it carries a load that
  // grows as the film thins (≈ 1/h̄ for a sphere near the flat, Hamrock's point-contact scaling).
  HomogeniseOptions o;
  o.pin.shape = PinShape::spherical;
  o.pin.crown_radius_m = 0.5;
  const PinTable pin = pin_scale(o, uniform_cells(1.0));
  for (std::size_t m = 0; m + 1 < pin.separation_m.size(); ++m) {
    EXPECT_GT(pin.wedge_lift_per_eta_u_m[m], pin.wedge_lift_per_eta_u_m[m + 1]);
    EXPECT_GT(pin.wedge_lift_per_eta_u_m[m + 1], 0.0);
  }
}

TEST(PinScale, ASlightlyTiltedFaceLiftsAsItsSlopeSqueezesTheFilm) {
  // A face tilted by θ (leading edge raised) under uniform flow factors φ: the Couette divergence
  // (U/2) ∂h/∂x = −Uθ/2 is uniform, the squeeze problem's ḣ = −Uθ/2 — so to first order in
  // ε = θR/h̄ (the h³ variation's first-order pressure is odd in x and carries nothing) the wedge
  // carries (θ/2) K per ηU, and in closed form the disc's paraboloid, ∇²p = −6ηUθ/(φh̄³):
  //   N_w/(ηU) = 3π θ R⁴ / (4 φ h̄³).
  // ε ≤ 0.01 here (ε² = 1e-4); the cut rim as in the squeeze test above (< 0.5 % on 65 nodes), and
  // the two solves share the grid, so against each other only ε² and the solver's tolerance remain.
  HomogeniseOptions o;
  const double phi = 0.8, r = o.pin.radius_m;
  o.pin.tilt_rad = 0.01 * kSigma / r;
  const CellTable cells = uniform_cells(phi);
  const PinTable pin = pin_scale(o, cells);
  ASSERT_EQ(pin.reynolds_unconverged, 0) << pin.messages;
  for (std::size_t m = 0; m < pin.separation_m.size(); ++m) {
    // The rows put the trailing edge on the cell separations.
    EXPECT_DOUBLE_EQ(pin.separation_m[m], cells.separation_m[m] + o.pin.tilt_rad * r);
    const double h = pin.separation_m[m];
    // (On the last row the leading half lies above the table, where the film is smooth: φ = 1.)
    const double closed = 3.0 * M_PI * o.pin.tilt_rad * std::pow(r, 4) / (4.0 * phi * h * h * h);
    if (m + 1 < pin.separation_m.size()) {
      EXPECT_NEAR(pin.wedge_lift_per_eta_u_m[m] / closed, 1.0, 5e-3) << "h = " << h;
    }
    EXPECT_NEAR(pin.wedge_lift_per_eta_u_m[m] / (0.5 * o.pin.tilt_rad * pin.squeeze_per_eta_m[m]), 1.0, 1e-3) << "h = " << h;
  }
  // A crown tilted less than its own slope at the rim (θR_c < R): its lowest point lies inside the
  // face, θ²R_c/2 below the centre, and that point sits on the cell separations.
  o.pin.shape = PinShape::spherical, o.pin.crown_radius_m = 5.0, o.pin.tilt_rad = 1e-4;
  const PinTable crowned = pin_scale(o, cells);
  for (std::size_t m = 0; m < crowned.separation_m.size(); ++m)
    EXPECT_DOUBLE_EQ(crowned.separation_m[m], cells.separation_m[m] + 0.5 * 1e-4 * 1e-4 * 5.0);
}

TEST(PinScale, TheFaceDropIsTheLowestPointOfTheTiltedFace) {
  // d = −min f over the disc, f = r²/(2R_c) − θx: sampled on a fine polar net against face_drop_m,
  // for a flat face, a crown whose lowest point lies inside (θR_c < R) and one tilted past its rim.
  for (const auto& [shape, crown, tilt] : {std::tuple{PinShape::flat, 0.0, 2e-4}, std::tuple{PinShape::spherical, 5.0, 5e-4},
                                           std::tuple{PinShape::spherical, 5.0, 2e-3}}) {
    Pin pin;
    pin.shape = shape, pin.crown_radius_m = crown, pin.tilt_rad = tilt;
    double lowest = 0.0;
    for (int a = 0; a <= 720; ++a)
      for (int k = 0; k <= 2000; ++k) {
        const double rr = pin.radius_m * k / 2000.0, x = rr * std::cos(M_PI * a / 360.0);
        lowest = std::min(lowest, (shape == PinShape::spherical ? rr * rr / (2.0 * crown) : 0.0) - tilt * x);
      }
    EXPECT_NEAR(face_drop_m(pin), -lowest, 1e-6 * face_drop_m(pin)) << "tilt " << tilt;
  }
}

// A small Gaussian patch on a nearly rigid body (E* huge), loaded so that about 10 % of it is at the
// cap: W/A_nom = 0.1 σ0.
HomogeniseOptions rigid_plastic_patch() {
  HomogeniseOptions o;
  o.surface.grid = 64;
  o.surface.size_m = 2e-4;
  o.surface.kind = contact::SpectrumKind::gaussian_acf;
  o.surface.rms_height_m = kSigma;
  o.surface.correlation_length_m = 2e-5;
  o.e_star_Pa = 1e16;
  o.separation_ratios = {1.0, 2.0, 3.0, 5.0, 8.0};
  o.pin.normal_load_N = 0.1 * o.hardness_Pa * M_PI * o.pin.radius_m * o.pin.radius_m;
  return o;
}

TEST(Junction, FullyPlasticContactGivesTaborsStaticAndKineticFriction) {
  // Every loaded cell yields: A = W/p_cap, so the slip area at p_cap = √(σ0² − α τ_i²) gives
  // μs,max = 1/√(S² − α) (thesis 3.1.23) and the kinetic μ_b = τ_i/σ0. The last, partly loaded
  // cell adds at most one cell's area: 1/(loaded cells) ≈ 0.3 %.
  const HomogeniseOptions o = rigid_plastic_patch();
  const PatchResult p = solve_patch(o, 0);
  ASSERT_EQ(p.unconverged, 0) << p.messages;
  const double s = o.hardness_Pa / o.interface_shear_strength_Pa;
  EXPECT_NEAR(p.mu_s_max / (1.0 / std::sqrt(s * s - o.alpha)), 1.0, 5e-3);
  EXPECT_NEAR(p.mu_boundary / (1.0 / s), 1.0, 5e-3);
  // No solid load above the first contact; load falls as the separation grows.
  for (std::size_t m = 0; m < p.separation_m.size(); ++m) {
    if (p.separation_m[m] >= p.first_contact_separation_m) {
      EXPECT_EQ(p.solid_pressure_Pa[m], 0.0);
    }
    if (m > 0) {
      EXPECT_LE(p.solid_pressure_Pa[m], p.solid_pressure_Pa[m - 1]);
    }
  }
  // Flow factors reach the smooth film at 8σ: 1 − 1.5 (σ/h)² ≈ 0.977 (Patir–Cheng small-roughness rate).
  EXPECT_NEAR(p.phi_x.back(), 1.0 - 1.5 / 64.0, 0.02);
}

TEST(SolvePatches, APatchThatCannotBeKeptFailsTheSolveWithItsReasonAndStartsNoMore) {
  // A caller that cannot keep a patch (a full disk) must fail the solve with its own error once the
  // threads are done — not terminate the program from inside the OpenMP critical section that
  // serialises the callback — and the realisations not yet started are not solved (on one thread:
  // the first patch's failure leaves the other two unsolved, so the callback runs once).
  HomogeniseOptions o = rigid_plastic_patch();
  o.realisations = 3;
  o.threads = 1;
  int kept = 0;
  try {
    solve_patches(o, {}, [&](int, const PatchResult&) {
      ++kept;
      throw std::runtime_error("no space left on device");
    });
    FAIL() << "a patch that cannot be kept must fail the solve";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "no space left on device");
  }
  EXPECT_EQ(kept, 1);
}

// A patch with hand-set columns: N_s and A_r falling to 0 at 4σ, smooth-film flow factors, lift
// 1e6/r per m — NaN at 2σ (a lift cell that converged nowhere) — and the junction on its three
// grids, finest first.
struct JunctionLevels {
  double finest, coarse, coarser;
};
PatchResult toy_patch(JunctionLevels mu_s_max, JunctionLevels mu_boundary) {
  PatchResult p;
  for (double r : {1.0, 2.0, 3.0, 4.0, 8.0}) {
    p.separation_m.push_back(r * kSigma);
    p.solid_pressure_Pa.push_back(r < 4.0 ? 1e8 * std::pow(1.0 - r / 4.0, 2) : 0.0);
    p.area_fraction.push_back(r < 4.0 ? 0.1 * std::pow(1.0 - r / 4.0, 2) : 0.0);
    p.solid_pressure_coarse_Pa.push_back(1.1 * p.solid_pressure_Pa.back());
    p.area_fraction_coarse.push_back(1.2 * p.area_fraction.back());
    for (auto* c : {&p.phi_x, &p.phi_y, &p.phi_f, &p.couette_shear_factor, &p.phi_fp}) c->push_back(1.0);
    for (auto* c : {&p.phi_s, &p.contact_fraction}) c->push_back(0.0);
    p.film_over_sigma.push_back(r);
    p.lift_per_eta_u_per_m.push_back(r == 2.0 ? std::nan("") : 1e6 / r);
  }
  p.mu_s_max = mu_s_max.finest, p.mu_s_max_coarse = mu_s_max.coarse, p.mu_s_max_coarser = mu_s_max.coarser;
  p.mu_boundary = mu_boundary.finest, p.mu_boundary_coarse = mu_boundary.coarse, p.mu_boundary_coarser = mu_boundary.coarser;
  p.contact_grid = 2048;
  p.junction_grid = 4096;
  return p;
}

TEST(LawFile, SeparationsWithoutAConvergedSolveAreLeftOutOfTheTableAndListed) {
  // A lift cell that converged in no realisation leaves NaN at its separation; the pin scale and the
  // rig's monotone interpolant need finite nodes, so the table omits that separation (every column
  // alike), names it, and the law still reads back.
  HomogeniseOptions o;
  o.surface.rms_height_m = kSigma;
  const PatchResult p = toy_patch({0.55, 0.55, 0.55}, {0.19, 0.19, 0.19});
  const CellTable cells = aggregate(o, {p});
  ASSERT_EQ(cells.separation_m.size(), 4u);
  ASSERT_EQ(cells.dropped_separation_m, std::vector<double>{2.0 * kSigma});
  const nlohmann::json law = law_json(o, cells, pin_scale(o, cells));
  const auto& table = law.at("table");
  ASSERT_EQ(table.at("separation_m").size(), 4u);
  EXPECT_EQ(table.at("separation_m")[1].get<double>(), 3.0 * kSigma);
  EXPECT_EQ(table.at("dropped_separations_m")[0].get<double>(), 2.0 * kSigma);
  EXPECT_NO_THROW(rig::law_table_from_json(law, "law.json"));
  // A tilted face: the rows and the separation left out, both on the table's axis (the film at the
  // face centre, θR above the cells' separation), and the tilt in the law's pin.
  o.pin.tilt_rad = 1e-4;
  const nlohmann::json tilted = law_json(o, cells, pin_scale(o, cells));
  EXPECT_EQ(tilted.at("table").at("separation_m")[1].get<double>(), 3.0 * kSigma + 1e-4 * o.pin.radius_m);
  EXPECT_EQ(tilted.at("table").at("dropped_separations_m")[0].get<double>(), 2.0 * kSigma + 1e-4 * o.pin.radius_m);
  EXPECT_EQ(tilted.at("pin").at("tilt_rad").get<double>(), 1e-4);
}

// The junction reports the first-order extrapolation 2 μ(Δ) − μ(2Δ) from its two finest grids and,
// as its discretisation error, the realisations' mean change of that extrapolation from the two
// coarsest (solid_contact.h, cell_table.h), over the realisations solved on all three; the law
// carries both beside the standard error and the finest grid's own value, and a warning names
// each quantity above the target.
TEST(LawFile, JunctionIsExtrapolatedAndItsErrorIsTheMeanChangeOfTheExtrapolation) {
  HomogeniseOptions o;
  o.surface.rms_height_m = kSigma;
  o.target_relative_error = 0.01;
  // μs,max: the first realisation is exactly first order in Δ (0.65, 0.63, 0.62: both extrapolations
  // 0.61, no change), the second is not (0.69, 0.63, 0.62: 0.57 then 0.61). μ_b: the two
  // extrapolations move 0.001 in opposite directions, so their mean does not move at all.
  const PatchResult unsolved = toy_patch({std::nan(""), 0.9, 0.9}, {0.3, std::nan(""), 0.3});  // left out
  const CellTable cells =
      aggregate(o, {toy_patch({0.62, 0.63, 0.65}, {0.2000, 0.2000, 0.1990}), toy_patch({0.62, 0.63, 0.69}, {0.2000, 0.2000, 0.2010}), unsolved});
  EXPECT_NEAR(cells.mu_s_max.mean, 0.61, 1e-12);
  EXPECT_NEAR(cells.mu_s_max_on_junction_grid.mean, 0.62, 1e-12);
  EXPECT_NEAR(cells.mu_s_max_discretisation_error, 0.02, 1e-12);     // (0 + 0.04) / 2
  EXPECT_NEAR(cells.mu_boundary.mean, 0.2, 1e-12);
  EXPECT_NEAR(cells.mu_boundary_discretisation_error, 0.001, 1e-12);  // not 0: the changes do not cancel
  const nlohmann::json law = law_json(o, cells, pin_scale(o, cells));
  const nlohmann::json& junction = law.at("junction");
  EXPECT_EQ(junction.at("mu_s_max").get<double>(), cells.mu_s_max.mean);
  EXPECT_EQ(junction.at("mu_s_max_discretisation_error").get<double>(), cells.mu_s_max_discretisation_error);
  EXPECT_EQ(junction.at("mu_s_max_on_junction_grid").get<double>(), cells.mu_s_max_on_junction_grid.mean);
  EXPECT_EQ(junction.at("contact_grid").get<int>(), 2048);
  EXPECT_EQ(junction.at("junction_grid").get<int>(), 4096);
  const std::vector<std::string> warnings = law.at("warnings").get<std::vector<std::string>>();
  ASSERT_EQ(warnings.size(), 1u);  // μs,max at 3.3 % warns, μ_b at 0.5 % does not
  EXPECT_EQ(warnings[0].rfind("mu_s_max = 0.61 carries a discretisation error of 0.02 (3.3 %, target 1 %) from the 4096² junction grid", 0), 0u)
      << warnings[0];
  o.target_relative_error = 0.04;
  EXPECT_TRUE(resolution_warnings(o, cells).empty());
  // An extrapolation under the fully plastic value τ_i/√(σ0² − α τ_i²) ((3.1.5), 0.5689 with the
  // defaults), which no grid can go below, is kept at it: 2 × 0.575 − 0.59 = 0.56 is not reported.
  const double tau = o.interface_shear_strength_Pa;
  const CellTable under = aggregate(o, {toy_patch({0.575, 0.59, 0.60}, {0.2, 0.2, 0.2})});
  EXPECT_NEAR(under.mu_s_max.mean, tau / std::sqrt(o.hardness_Pa * o.hardness_Pa - o.alpha * tau * tau), 1e-12);
}

// A coarsest junction solve that failed (NaN) does not drop the realisation: the extrapolation
// from the two finest stands, and its own correction (the distance to the middle grid's value) is
// its error — on the safe side of the change it replaces.
TEST(LawFile, WhereTheCoarsestJunctionSolveFailedTheCorrectionIsTheError) {
  HomogeniseOptions o;
  o.surface.rms_height_m = kSigma;
  const CellTable cells = aggregate(o, {toy_patch({0.62, 0.63, std::nan("")}, {0.2000, 0.2010, std::nan("")})});
  EXPECT_NEAR(cells.mu_s_max.mean, 0.61, 1e-12);
  EXPECT_NEAR(cells.mu_s_max_discretisation_error, 0.02, 1e-12);  // |0.61 − 0.63|
  EXPECT_NEAR(cells.mu_boundary.mean, 0.1990, 1e-12);
  EXPECT_NEAR(cells.mu_boundary_discretisation_error, 0.0020, 1e-12);
}

// The coarse grid's pressures only start the fine solves: the answer is the cold start's to the
// BEM's tolerance (1e-8 of the deflection; the loads to 1e-6), in fewer iterations.
TEST(SolidContact, CoarseGridStartKeepsTheAnswerInFewerIterations) {
  HomogeniseOptions o;
  o.surface.grid = 64;
  o.surface.size_m = 5e-4;
  o.surface.rms_height_m = kSigma;
  o.surface.cutoff_wavelength_m = 1.6e-5;
  o.separation_ratios = {0.5, 1.0, 2.0, 3.0, 6.0};
  const Eigen::ArrayXXd z = contact::gaussian_surface(o.surface);
  SolidPressures coarse;
  solid_contact(o, contact::fourier_refine(z, 2), nullptr, &coarse);
  const SolidContact cold = solid_contact(o, contact::fourier_refine(z, 4));
  const SolidContact warm = solid_contact(o, contact::fourier_refine(z, 4), &coarse);
  ASSERT_EQ(cold.unconverged + warm.unconverged, 0) << cold.messages << warm.messages;
  for (std::size_t m = 0; m < o.separation_ratios.size(); ++m) {
    EXPECT_NEAR(warm.solid_pressure_Pa[m], cold.solid_pressure_Pa[m], 1e-6 * cold.solid_pressure_Pa[m] + 1e-9);
    EXPECT_NEAR(warm.area_fraction[m], cold.area_fraction[m], 2.0 / (256.0 * 256.0));  // a cell or two at the edge
  }
  EXPECT_NEAR(warm.mu_s_max, cold.mu_s_max, 1e-3 * cold.mu_s_max);
  EXPECT_NEAR(warm.mu_boundary, cold.mu_boundary, 1e-3 * cold.mu_boundary);
  EXPECT_LT(warm.bem_iterations, cold.bem_iterations);
  std::printf("BEM iterations at 256²: cold %d, from 128² %d\n", cold.bem_iterations, warm.bem_iterations);
}

// One paraboloidal asperity (R = 100 µm) pressed δ = 10 nm into the counter-face (a = 1 µm, 20
// cells; p_H = 0.72 GPa, elastic) through the solid solve with micro-EHL films: the spot's shear at
// every ηU node is the film of its Hertz contact (lubrication/micro_ehl.h) to 2 % of τ_i — the BEM's
// counted area (half a cell of 20, 2.5 %, tripled in R_eq; h_c ∝ R^0.46) is all that differs — and
// τ_i exactly at rest and where there is no contact.
TEST(SolidContact, ASingleAsperitysFilmIsThatOfItsHertzContact) {
  HomogeniseOptions o;
  const int n = 256;
  const double radius = 1e-4, approach = 1e-8, side = 12.8e-6, sigma = 1e-8;
  o.surface.grid = n;
  o.surface.size_m = side;
  o.surface.rms_height_m = sigma;
  o.separation_ratios = {1.0, 2.0, 3.0};  // approaches 10 nm, 0, −10 nm
  o.micro_ehl = MicroEhl{};
  Eigen::ArrayXXd z(n, n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i - n / 2) * side / n, y = (j - n / 2) * side / n;
      z(i, j) = (x * x + y * y) / (2.0 * radius) - (approach + sigma);
    }
  const SolidContact s = solid_contact(o, z);
  ASSERT_EQ(s.unconverged, 0) << s.messages;
  const double a = std::sqrt(radius * approach), load = 4.0 / 3.0 * o.e_star_Pa * std::sqrt(radius) * std::pow(approach, 1.5);
  contact::ContactSpot hertz;
  hertz.area_m2 = M_PI * a * a;
  hertz.load_N = load;
  hertz.mean_pressure_Pa = load / hertz.area_m2;
  hertz.equivalent_radius_m = radius;
  const lubrication::MicroEhlOptions films = micro_ehl_options(o);
  const std::vector<double> eta_u = micro_ehl_eta_u_Pa_m(o);
  ASSERT_EQ(s.spot_shear_Pa.size(), 3u);
  double lowest = o.interface_shear_strength_Pa;
  for (std::size_t k = 0; k < eta_u.size(); ++k) {
    const double expected = lubrication::spot_film(hertz, eta_u[k], films).shear_Pa;
    EXPECT_NEAR(s.spot_shear_Pa[0][k], expected, 0.02 * o.interface_shear_strength_Pa) << "eta U = " << eta_u[k];
    EXPECT_EQ(s.spot_shear_Pa[2][k], o.interface_shear_strength_Pa);  // no contact
    lowest = std::min(lowest, s.spot_shear_Pa[0][k]);
  }
  EXPECT_EQ(s.spot_shear_Pa[0][0], o.interface_shear_strength_Pa);
  EXPECT_EQ(s.spot_film_share[0][0], 0.0);  // no film at rest
  EXPECT_NEAR(s.spot_film_share[0].back(), 1.0 - lubrication::spot_film(hertz, eta_u.back(), films).boundary_share, 0.02);
  EXPECT_LT(lowest, 0.7 * o.interface_shear_strength_Pa);  // the axis reaches films that carry the spot
}

// A mixed-lubrication table: N_s falls to 0 at 3σ, lift and squeeze from a rugosity-like law.
rig::LawTable stribeck_table(double eta) {
  rig::LawTable t;
  t.pin.nominal_area_m2 = 7e-5;
  t.lubricant.viscosity_Pa_s = eta;
  t.lubricant.temperature_viscosity_per_K = 0.0;  // isothermal: η does not depend on U
  t.thermal = {46, 52, 1.2e-5, 1.0};
  t.junction.locus.sigma0_over_tau_i = 5.3;
  t.junction.interface_shear_strength_Pa = 2e8;
  for (int k = 0; k <= 40; ++k) {
    const double r = 0.5 + 0.25 * k, h = r * kSigma;
    t.separation_m.push_back(h);
    t.solid_load_N.push_back(r < 3.0 ? 400.0 * std::pow(1.0 - r / 3.0, 3) : 0.0);
    t.real_area_m2.push_back(r < 3.0 ? 1e-7 * std::pow(1.0 - r / 3.0, 2) : 0.0);
    t.lift_per_eta_u_m.push_back(1e5 * std::exp(-r));
    t.squeeze_per_eta_m.push_back(1.5 * M_PI * std::pow(4.76e-3, 4) / std::pow(h, 3));
    t.shear_per_eta_u_m.push_back(t.pin.nominal_area_m2 / h);
  }
  return t;
}

TEST(Stribeck, IsothermalFrictionDependsOnEtaTimesSpeedAlone) {
  // All fluid terms are ∝ ηU (rigid-film Reynolds is homogeneous in ηU), so doubling η and halving U
  // leaves the steady state unchanged (to the bisection tolerance).
  const rig::HomogenisedBase thin(stribeck_table(0.01), 100.0), thick(stribeck_table(0.02), 100.0);
  for (double u : {1e-3, 1e-1, 3.0, 30.0}) {
    const rig::SteadySliding a = rig::steady_sliding(thin, u), b = rig::steady_sliding(thick, u / 2);
    EXPECT_NEAR(a.mu, b.mu, 1e-9 * a.mu) << "U = " << u;
    EXPECT_NEAR(a.separation_m, b.separation_m, 1e-9 * a.separation_m);
  }
}

TEST(Stribeck, MinimumSitsWhereTheFilmTakesOverTheLoad) {
  // Boundary → mixed: μ falls as the film unloads the asperities; full film: μ = ηU S/W rises with
  // U. So the smallest μ over a log sweep lies where the solids' share has just vanished.
  const rig::HomogenisedBase base(stribeck_table(0.02), 100.0);
  double best_mu = 1e9, best_u = 0, share_at_best = 0;
  for (int k = 0; k <= 80; ++k) {
    const double u = 1e-3 * std::pow(10.0, k / 16.0);
    const rig::SteadySliding s = rig::steady_sliding(base, u);
    ASSERT_TRUE(s.converged) << s.message;
    if (s.mu < best_mu) {
      best_mu = s.mu;
      best_u = u;
      share_at_best = s.solid_load_N / 100.0;
    }
  }
  EXPECT_GT(best_u, 1e-3);
  EXPECT_LT(best_u, 1e2);
  EXPECT_LT(share_at_best, 0.05);  // full film at the minimum …
  // … but only just: at a third of that speed the solids still carry part of the load.
  EXPECT_GT(rig::steady_sliding(base, best_u / 3).solid_load_N, 0.0);
}

}  // namespace
}  // namespace tribo::homogenise
