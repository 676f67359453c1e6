// The structured-grid multigrid backend (PFMG-preconditioned CG, lubrication/struct_multigrid.h)
// on its own: the 5-point Laplacian's eigenvectors as closed-form solutions, the multigrid
// property (iterations independent of the grid), and what it refuses.
#include <gtest/gtest.h>

#include <Eigen/SparseCore>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "lubrication/struct_multigrid.h"

namespace tribo::lubrication {
namespace {

// −∇·(k∇) on the box by the 5-point rule with unit spacing, k per node and face values by the
// harmonic mean; Dirichlet 0 beyond i = −1, ni and (unless periodic) j = −1, nj.
SparseMatrix five_point(const BoxGrid& box, const std::vector<double>& k) {
  const int n = box.ni * box.nj;
  std::vector<Eigen::Triplet<double, int>> t;
  auto at = [&](int i, int j) { return j * box.ni + i; };
  for (int j = 0; j < box.nj; ++j)
    for (int i = 0; i < box.ni; ++i) {
      const int u = at(i, j);
      double diag = 0;
      const int d[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
      for (const auto& e : d) {
        int ni = i + e[0], nj = j + e[1];
        if (box.periodic_j) nj = (nj + box.nj) % box.nj;
        const bool inside = ni >= 0 && ni < box.ni && nj >= 0 && nj < box.nj;
        const double k_face = inside ? 2.0 / (1.0 / k[u] + 1.0 / k[at(ni, nj)]) : k[u];
        diag += k_face;
        if (inside) t.emplace_back(u, at(ni, nj), -k_face);
      }
      t.emplace_back(u, u, diag);
    }
  SparseMatrix a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

// With k ≡ 1 the operator's eigenvectors are known: v = sin(π(i+1)/(ni+1)) · (sin(π(j+1)/(nj+1))
// or, periodic, cos(2πj/nj)) with λ = 4 sin²(π/(2(ni+1))) + (4 sin²(π/(2(nj+1))) or 4 sin²(π/nj)).
// Solving A x = λ v must return v; the error bound is κ(A)·τ with κ ≤ 8 / λ_min (Gershgorin).
void expect_eigenvector_solved(const BoxGrid& box) {
  const int n = box.ni * box.nj;
  const SparseMatrix a = five_point(box, std::vector<double>(static_cast<std::size_t>(n), 1.0));
  Eigen::VectorXd v(n);
  const double pi = std::numbers::pi;
  for (int j = 0; j < box.nj; ++j)
    for (int i = 0; i < box.ni; ++i)
      v[j * box.ni + i] = std::sin(pi * (i + 1) / (box.ni + 1)) *
                          (box.periodic_j ? std::cos(2 * pi * j / box.nj) : std::sin(pi * (j + 1) / (box.nj + 1)));
  const double sx = std::sin(pi / (2.0 * (box.ni + 1)));
  const double sy = box.periodic_j ? std::sin(pi / box.nj) : std::sin(pi / (2.0 * (box.nj + 1)));
  const double lambda = 4 * sx * sx + 4 * sy * sy;
  const double tolerance = 1e-10;
  auto solver = make_pfmg_solver(box, {tolerance, 100});
  ASSERT_TRUE(solver->analyze(a).ok);
  const LinearSolveStatus f = solver->factorize(a);
  ASSERT_TRUE(f.ok) << f.message;
  Eigen::VectorXd x;
  const LinearSolveStatus s = solver->solve(lambda * v, x);
  ASSERT_TRUE(s.ok) << s.message;
  const double error = (x - v).norm() / v.norm();
  const double bound = 8.0 / (4 * sx * sx) * tolerance;  // λ_min ≥ the x part alone
  std::printf("  %d x %d%s: %d iterations, |x - v|/|v| = %.2e (bound %.2e)\n", box.ni, box.nj,
              box.periodic_j ? " periodic" : "", s.iterations, error, bound);
  EXPECT_LE(s.relative_residual, tolerance);
  EXPECT_LE(error, bound);
}

TEST(StructuredMultigrid, SolvesTheLaplacianEigenvectorOnOddAndEvenBoxes) {
  expect_eigenvector_solved({63, 63, false});
  expect_eigenvector_solved({64, 50, false});
  expect_eigenvector_solved({127, 64, true});
  expect_eigenvector_solved({96, 128, true});
}

// The multigrid property: for a rough conductance field (k varying 8× over a few cells, like
// h³ of a film with ±0.33 relative roughness) the PCG iteration count stays flat from 63² to 511²
// unknowns. BoomerAMG needed 7 on the Reynolds film at every size (bench/README.md); a count that
// grew like the grid (√κ ∝ n for unpreconditioned CG: ≈ 300 at 511²) would fail the bound.
TEST(StructuredMultigrid, IterationsDoNotGrowWithTheGrid) {
  std::vector<int> counts;
  for (const int m : {63, 127, 255, 511}) {
    const BoxGrid box{m, m + 1, false};
    std::vector<double> k(static_cast<std::size_t>(box.ni * box.nj));
    for (int j = 0; j < box.nj; ++j)
      for (int i = 0; i < box.ni; ++i) {
        const double h = 1.0 + 0.33 * std::sin(0.7 * i + 0.3 * j) * std::cos(0.4 * i - 0.9 * j);
        k[static_cast<std::size_t>(j * box.ni + i)] = h * h * h;
      }
    const SparseMatrix a = five_point(box, k);
    auto solver = make_pfmg_solver(box, {1e-10, 100});
    ASSERT_TRUE(solver->analyze(a).ok);
    ASSERT_TRUE(solver->factorize(a).ok);
    Eigen::VectorXd x;
    const LinearSolveStatus s = solver->solve(Eigen::VectorXd::Ones(a.rows()), x);
    ASSERT_TRUE(s.ok) << s.message;
    std::printf("  %d x %d: %d PCG iterations to 1e-10\n", box.ni, box.nj, s.iterations);
    counts.push_back(s.iterations);
  }
  for (const int c : counts) EXPECT_LE(c, 15);
  EXPECT_LE(counts.back() - counts.front(), 3);
}

TEST(StructuredMultigrid, TakesBoxesItCanCoarsen) {
  EXPECT_TRUE(pfmg_supports({5, 7, false}));
  EXPECT_TRUE(pfmg_supports({3, 3, false}));
  EXPECT_FALSE(pfmg_supports({2, 7, false}));
  EXPECT_TRUE(pfmg_supports({9, 64, true}));
  EXPECT_FALSE(pfmg_supports({9, 96, true}));  // 96 = 3·2⁵: a period PFMG cannot keep halving
  EXPECT_FALSE(pfmg_supports({9, 2, true}));
}

TEST(StructuredMultigrid, RefusesWhatIsNotAFivePointBoxMatrix) {
  const BoxGrid box{4, 4, false};
  SparseMatrix a = five_point(box, std::vector<double>(16, 1.0));
  auto solver = make_pfmg_solver(box);
  ASSERT_TRUE(solver->analyze(a).ok);
  a.coeffRef(0, 5) = -0.1;  // (0, 0) to (1, 1): a diagonal neighbour
  const LinearSolveStatus s = solver->factorize(a);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.message.find("entry (0, 5)"), std::string::npos) << s.message;
  const SparseMatrix wrong_size = five_point({5, 4, false}, std::vector<double>(20, 1.0));
  EXPECT_FALSE(solver->analyze(wrong_size).ok);
  auto periodic_96 = make_pfmg_solver({9, 96, true});
  const LinearSolveStatus p = periodic_96->analyze(five_point({9, 96, true}, std::vector<double>(9 * 96, 1.0)));
  EXPECT_FALSE(p.ok);
  EXPECT_NE(p.message.find("periodic"), std::string::npos) << p.message;
  Eigen::VectorXd x;
  EXPECT_FALSE(make_pfmg_solver(box)->solve(Eigen::VectorXd::Ones(16), x).ok);  // before factorize()
}

}  // namespace
}  // namespace tribo::lubrication
