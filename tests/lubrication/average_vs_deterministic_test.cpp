// Homogenised against deterministic (issue 14): square pads B = 16, 32, 64 correlation lengths wide
// with a rough stationary wall, solved node by node on their rough gap, against the average Reynolds
// equation with the Patir–Cheng factors lubrication::flow_factors measures on OTHER realisations
// (independent seeds, periodic cells). A pad is one sample of the roughness: its answer scatters
// about the homogenised one by the fluctuation of its effective conductance over (B/ℓ)² independent
// patches, ∝ ℓ/B in 2-D, and its ambient rim adds a boundary layer. So the pads' mean must approach
// the homogenised value as B grows, and (squeeze load) their scatter must fall at an observed order
// ≈ 1 — the representative-volume convergence that justifies using the tables at the pin's scale.
//
// The gap is rigid (no contact deformation): the separations are chosen so that contact spots are
// rare, where the BEM would not move the film.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/surface.h"
#include "lubrication/flow_factors.h"
#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"
#include "tests/lubrication/observed_order.h"
#include "tests/lubrication/fixture.h"

namespace tribo::lubrication {
namespace {

constexpr double kSigma = 0.2e-6;             // composite rms height (m)
constexpr double kCorrelation = 20e-6;        // ℓ of the Gaussian ACF (m)
constexpr int kPointsPerCorrelation = 4;      // the same spacing in the cells and the pads
constexpr double kFloorFraction = 1e-3;       // film floor at contact, × σ (as flow_factors)
constexpr double kFloor = 1.5 * kFloorFraction * kSigma;  // a node at or below this touches
using fixture::kEta;
constexpr int kSeeds = 6;                     // pads per size, seeds 101…; the cells use 1…12
const std::vector<int> kPadCorrelations = {16, 32, 64};

contact::GaussianSurfaceParams surface(int correlations, std::uint64_t seed) {
  contact::GaussianSurfaceParams p;
  p.kind = contact::SpectrumKind::gaussian_acf;
  p.rms_height_m = kSigma;
  p.correlation_length_m = kCorrelation;
  p.size_m = correlations * kCorrelation;
  p.grid = correlations * kPointsPerCorrelation;
  p.seed = seed;
  return p;
}

// The pad: the n × n heights as nodes at spacing L/n, ambient pressure on all four edges.
ReynoldsProblem rough_pad(int correlations, std::uint64_t seed, double h_over_sigma) {
  const contact::GaussianSurfaceParams p = surface(correlations, seed);
  const Eigen::ArrayXXd z = contact::gaussian_surface(p);
  ReynoldsProblem pr;
  const double dx = p.size_m / static_cast<double>(p.grid);
  pr.grid = contact::Grid{p.grid, p.grid, dx, dx};
  pr.gap_m = rough_pair_gap_m(z, Eigen::ArrayXXd::Zero(p.grid, p.grid), h_over_sigma * kSigma, kFloorFraction * kSigma);
  pr.viscosity_Pa_s = kEta;
  return pr;
}

// The Patir–Cheng row at h/σ from 12 periodic cells 32 ℓ wide (seeds 1…12).
FlowFactorRow measured_factors(double h_over_sigma) {
  HomogenisationOptions o;
  o.surface = surface(32, 1);
  o.gap_ratios = {h_over_sigma};
  o.realisations = 12;
  o.viscosity_Pa_s = kEta;
  o.contact_gap_fraction = kFloorFraction;
  return flow_factors(o).front();
}

struct Sample {
  double mean = 0, scatter = 0;  // over the seeds: mean and standard deviation
};
Sample sample(const std::vector<double>& v) {
  const Estimate e = estimate(v);  // standard error s/√n → the standard deviation s
  return {e.mean, e.standard_error * std::sqrt(static_cast<double>(v.size()))};
}

// Runs `per_pad(correlations, seed)` over the pad sizes and seeds; prints and returns the samples.
template <class F>
std::vector<Sample> over_pads(const char* what, double homogenised, F&& per_pad) {
  std::vector<Sample> samples;
  for (int correlations : kPadCorrelations) {
    std::vector<double> values;
    for (int s = 0; s < kSeeds; ++s) values.push_back(per_pad(correlations, static_cast<std::uint64_t>(101 + s)));
    samples.push_back(sample(values));
    std::printf("pad %2d l: %s %.4f +- %.4f (homogenised %.4f)\n", correlations, what, samples.back().mean,
                samples.back().scatter, homogenised);
  }
  return samples;
}

// The pads' mean approaches the homogenised value: within `tolerance` on the widest pads, and
// closer there than on the narrowest.
void expect_mean_converges(const std::vector<Sample>& samples, double homogenised, double tolerance) {
  const double first = std::abs(samples.front().mean / homogenised - 1.0);
  const double last = std::abs(samples.back().mean / homogenised - 1.0);
  EXPECT_LT(last, tolerance);
  EXPECT_LT(last, first);
}

// The pads' scatter falls as (ℓ/B)^order; order 1 for an effective property of a 2-D random medium.
double scatter_order(const std::vector<Sample>& samples) {
  std::vector<double> spacing, scatter;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    spacing.push_back(1.0 / kPadCorrelations[k]);  // ℓ/B
    scatter.push_back(samples[k].scatter);
  }
  const double order = observed_order(spacing, scatter);
  std::printf("scatter falls as (l/B)^%.2f\n", order);
  return order;
}

TEST(AverageVersusDeterministic, SqueezeLoadOfRoughPadsConvergesToTheFlowFactorPrediction) {
  // Squeeze at ḣ = −1 µm/s: the average equation ∇·(φ h̄³/12η ∇p̄) = ḣ with uniform φx = φy = φ
  // carries W_smooth/φ — solved here literally with the factor fields. At h̄ = 4σ the thinnest film
  // of the widest pad is ≈ 0.2σ: closer to contact a RIGID rough gap squeezes much of its load out
  // of a few near-contact nodes (Δp ~ 12η ḣ Δx²/h³ there), which the BEM's deformation would relieve.
  constexpr double kHOverSigma = 5.0;
  const FlowFactorRow row = measured_factors(kHOverSigma);
  const double phi = 0.5 * (row.phi_x.mean + row.phi_y.mean);
  const auto samples = over_pads("W_det/W_smooth", 1.0 / phi, [&](int correlations, std::uint64_t seed) {
    ReynoldsProblem det = rough_pad(correlations, seed, kHOverSigma);
    // Where the surfaces touch (film at the floor) the solids carry the approach: no fluid is
    // squeezed there, as the cells treat contact spots as islands.
    det.gap_rate_m_per_s = (det.gap_m > kFloor).select(-1e-6, det.grid.field(0.0));
    ReynoldsProblem avg = det;
    avg.gap_m = det.grid.field(kHOverSigma * kSigma);
    const ReynoldsSolution a = solve_reynolds(det), b = solve_reynolds(avg);
    EXPECT_TRUE(a.summary.converged && b.summary.converged);
    return a.load_N / b.load_N;
  });
  // The rough film carries 1/φ ≈ 1.06 × the smooth film's load; the 64 ℓ pads give 1.0475 ± 0.0034
  // (standard error), 1.1 % low. Tolerance 2.5 %: that standard error and φ's from 12 cells (≈ 0.5 %)
  // three times over. The scatter's order: 1 ± 0.6 (a standard deviation from 6 seeds is uncertain
  // by ≈ 30 %, which over a factor 4 in B moves the fitted order by ≈ 0.3 either way, twice).
  expect_mean_converges(samples, 1.0 / phi, 0.025);
  const double order = scatter_order(samples);
  EXPECT_GT(order, 0.4);
  EXPECT_LT(order, 1.6);
}

TEST(AverageVersusDeterministic, SlidingShearOfRoughPadsConvergesToTheCouetteShearFactor) {
  // A smooth wall sliding at U over the rough pad, ambient rim, full film: the mean shear stress on
  // the stationary rough wall, τ = ηU/h_T − (h_T/2) ∂p/∂x over the non-contact nodes (contact nodes
  // count zero), against the homogenised (ηU/h̄)(φf − φfs). ∂p/∂x at a node from its mean x-face
  // flow q̄ by q̄ = −h_T³ p'/(12η) + U h_T/2, as the cells measure it (flow_factors.h), so
  // τ = −2ηU/h_T + 6η q̄/h_T².
  constexpr double kHOverSigma = 3.0;
  const FlowFactorRow row = measured_factors(kHOverSigma);
  const double u = 0.1, h = kHOverSigma * kSigma;
  const auto samples = over_pads("shear factor", row.couette_shear_factor.mean, [&](int correlations, std::uint64_t seed) {
    ReynoldsProblem det = rough_pad(correlations, seed, kHOverSigma);
    det.sliding_speed_m_per_s = u;
    const ReynoldsSolution sol = solve_reynolds(det);
    EXPECT_TRUE(sol.summary.converged);
    const Eigen::ArrayXXd q = x_face_flow_m2_per_s(det, sol);  // (nx − 1) × ny
    const Eigen::Index nx = det.grid.nx, ny = det.grid.ny;
    double sum = 0.0;
    for (Eigen::Index j = 0; j < ny; ++j)
      for (Eigen::Index i = 1; i + 1 < nx; ++i) {
        const double ht = det.gap_m(i, j);
        if (ht <= kFloor) continue;
        const double qn = 0.5 * (q(i - 1, j) + q(i, j));
        sum += -2.0 * kEta * u / ht + 6.0 * kEta * qn / (ht * ht);
      }
    return sum / static_cast<double>((nx - 2) * ny) * h / (kEta * u);
  });
  // φf − φfs ≈ 0.87 at h̄ = 3σ; the ambient rim biases small pads upwards (+8 % at 16 ℓ, +2 % at 32 ℓ,
  // +0.4 % at 64 ℓ). The local shear ~ 1/h_T² of the thinnest films has a heavy tail, so the scatter
  // does not fall cleanly (not asserted); the 64 ℓ mean's standard error is ≈ 1.3 %, hence 2.5 %.
  expect_mean_converges(samples, row.couette_shear_factor.mean, 0.025);
}

}  // namespace
}  // namespace tribo::lubrication
