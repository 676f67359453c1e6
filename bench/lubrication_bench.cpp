// Reynolds solver cost (DESIGN §9): wall time per solve against grid size, with and without
// mass-conserving cavitation, the share of it spent inside the linear solvers (counter
// `suitesparse_share`: SuiteSparse, or hypre for the multigrid rows), Newton iterations, unknowns
// solved per second of CPU time (`unknowns_per_s`), and the homogenisation loop on 1 vs 2 threads.
// Full film by both backends: direct (CHOLMOD) and multigrid (BoomerAMG-preconditioned CG to
// ‖b − Ap‖₂ ≤ 1e-10‖b‖₂, `pcg_iterations`: Krylov iterations, PCG + GMRES of every Newton step
// for the cavitating rows; the cavitating multigrid rows solve the Newton steps by GMRES with the
// block-triangular preconditioner of lubrication/cavitation_krylov.h, inexact Newton and grid
// sequencing, the WholeAmg rows by GMRES + one V-cycle of the whole matrix to 1e-10 from the full
// film). The first multigrid solve
// of a process also starts MPI (hypre is built with it), ≈ 0.1–0.7 s once; the benchmark's
// warm-up absorbs it.
//
// Film: a textured gap h = h₀(1 + 0.4 cos(2πx/λ) cos(2πy/λ)), h₀ = 1 µm, λ = L/4, L = 1 mm,
// sliding at U = 1 m/s, p = 0 at x = 0 and x = L, periodic in y: every dimple has a converging
// half (pressure) and a diverging half (rupture), so the cavitating solve has work to do.
//   cmake --build build --target lubrication_bench && ./build/bench/lubrication_bench
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "lubrication/ehl_line.h"
#include "lubrication/ehl_roughness.h"
#include "lubrication/ehl_point.h"
#include "lubrication/flow_factors.h"
#include "lubrication/reference/ehl_film.h"
#include "lubrication/reynolds.h"

namespace {

namespace lub = tribo::lubrication;

lub::ReynoldsProblem textured(int n, lub::Cavitation cavitation) {
  lub::ReynoldsProblem pr;
  const double length = 1e-3, wavelength = length / 4;
  pr.grid = tribo::contact::Grid{n + 1, n, length / n, length / n};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double kx = 2 * std::numbers::pi * i * pr.grid.dx_m / wavelength;
      const double ky = 2 * std::numbers::pi * j * pr.grid.dy_m / wavelength;
      pr.gap_m(i, j) = 1e-6 * (1.0 + 0.4 * std::cos(kx) * std::cos(ky));
    }
  pr.sliding_speed_m_per_s = 1.0;
  pr.boundary_y = lub::BoundaryY::periodic;
  pr.cavitation = cavitation;
  return pr;
}

void run(benchmark::State& state, lub::Cavitation cavitation, lub::PressureSolver backend,
         lub::CavitationPreconditioner preconditioner = lub::CavitationPreconditioner::block_triangular,
         bool structured_multigrid = true, bool grid_sequencing = true) {
  const int n = static_cast<int>(state.range(0));
  const lub::ReynoldsProblem pr = textured(n, cavitation);
  lub::ReynoldsOptions options;
  options.pressure_solver = backend;
  options.structured_multigrid = structured_multigrid;
  options.cavitation_preconditioner = preconditioner;
  options.grid_sequencing = grid_sequencing;
  // The earlier whole-matrix AMG path: every Newton step to the full tolerance, from the full film.
  if (preconditioner == lub::CavitationPreconditioner::amg) {
    options.inexact_newton = false;
    options.grid_sequencing = false;
  }
  lub::ReynoldsSolver solver(options);  // symbolic analysis reused after the first iteration
  // Warm-up outside the timing: the first multigrid solve of the process starts MPI and hypre
  // (≈ 0.1–0.7 s; a small full-film solve suffices, the cavitating rows run once).
  if (backend == lub::PressureSolver::multigrid) {
    lub::ReynoldsSolver warm_up(options);
    benchmark::DoNotOptimize(warm_up.solve(textured(32, lub::Cavitation::none)));
  }
  double linear_s = 0, wall_s = 0, iterations = 0, cavitated = 0, pcg_iterations = 0;
  bool converged = true;
  for (auto _ : state) {
    const lub::ReynoldsSolution s = solver.solve(pr);
    linear_s += s.summary.linear_solver_s;
    wall_s += s.summary.wall_s;
    iterations += s.summary.iterations;
    pcg_iterations += s.summary.linear_iterations;
    cavitated = s.cavitated_fraction;
    converged = converged && s.summary.converged;
  }
  const double k = static_cast<double>(state.iterations());
  // (nx − 2) × ny interior nodes carry the unknowns.
  const double unknowns = static_cast<double>((pr.grid.nx - 2) * pr.grid.ny);
  state.counters["unknowns"] = unknowns;
  state.counters["unknowns_per_s"] = benchmark::Counter(unknowns * k, benchmark::Counter::kIsRate);
  state.counters["suitesparse_share"] = linear_s / wall_s;
  state.counters["newton_iterations"] = iterations / k;
  state.counters["pcg_iterations"] = pcg_iterations / k;
  state.counters["cavitated_fraction"] = cavitated;
  state.counters["converged"] = converged ? 1 : 0;
}

void BM_ReynoldsFullFilm(benchmark::State& state) {
  run(state, lub::Cavitation::none, lub::PressureSolver::direct);
}
// Multigrid = PCG + PFMG (the default on this box grid); BoomerAmg = PCG + BoomerAMG, the
// algebraic multigrid the disc domain and non-box grids use.
void BM_ReynoldsFullFilmMultigrid(benchmark::State& state) {
  run(state, lub::Cavitation::none, lub::PressureSolver::multigrid);
}
void BM_ReynoldsFullFilmBoomerAmg(benchmark::State& state) {
  run(state, lub::Cavitation::none, lub::PressureSolver::multigrid, lub::CavitationPreconditioner::block_triangular,
      false);
}
// Newton steps on UMFPACK (direct) or GMRES + BoomerAMG (multigrid): the default block-triangular
// preconditioner with inexact Newton and grid sequencing, and (WholeAmg) one V-cycle of the whole
// reduced matrix with every step to 1e-10 from the full film, the earlier path.
void BM_ReynoldsCavitation(benchmark::State& state) {
  run(state, lub::Cavitation::mass_conserving, lub::PressureSolver::direct);
}
void BM_ReynoldsCavitationMultigrid(benchmark::State& state) {
  run(state, lub::Cavitation::mass_conserving, lub::PressureSolver::multigrid);
}
// The same from the full-film start (no grid sequencing), as on the disc domain.
void BM_ReynoldsCavitationMultigridFullFilmStart(benchmark::State& state) {
  run(state, lub::Cavitation::mass_conserving, lub::PressureSolver::multigrid,
      lub::CavitationPreconditioner::block_triangular, true, false);
}
void BM_ReynoldsCavitationMultigridWholeAmg(benchmark::State& state) {
  run(state, lub::Cavitation::mass_conserving, lub::PressureSolver::multigrid, lub::CavitationPreconditioner::amg);
}

BENCHMARK(BM_ReynoldsFullFilm)->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReynoldsFullFilmMultigrid)
    ->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReynoldsFullFilmBoomerAmg)
    ->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Arg(2048)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReynoldsCavitation)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ReynoldsCavitationMultigrid)
    ->Arg(128)->Arg(256)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ReynoldsCavitationMultigridFullFilmStart)
    ->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_ReynoldsCavitationMultigridWholeAmg)
    ->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);

// Homogenisation: 4 realisations × 2 gap ratios of φ_x, φ_y, Φ_s on 96² cells; realisations are
// spread over OpenMP threads (SuiteSparse itself runs serially with the reference BLAS).
void BM_FlowFactors(benchmark::State& state) {
  lub::HomogenisationOptions o;
  o.surface.kind = tribo::contact::SpectrumKind::gaussian_acf;
  o.surface.grid = 96;
  o.surface.size_m = 1e-3;
  o.surface.rms_height_m = 0.5e-6;
  o.surface.correlation_length_m = 1e-3 / 16;
  o.gap_ratios = {2.0, 4.0};
  o.realisations = 4;
  o.threads = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(lub::flow_factors(o));
}
BENCHMARK(BM_FlowFactors)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// EHL line contact (lubrication/ehl_line.h): the steel rollers of tests/lubrication (R = 10 mm,
// E' = 2.26e11 Pa, mineral oil η0 = 0.04 Pa·s, α = 2.2e-8 1/Pa, u_m = 1 m/s, Roelands and
// Dowson–Higginson) at w = 3e5 N/m (W = 1.3e-4, p_H ≈ 1.04 GPa) and 3e6 N/m (W = 1.3e-3,
// p_H ≈ 3.3 GPa), on N nodes; counters: Newton iterations and continuation steps. Each Newton step
// factorises the dense (N + 1)² Jacobian: O(N³).
lub::PiezoviscousLubricant roller_oil() {
  lub::PiezoviscousLubricant oil;
  oil.viscosity_Pa_s = 0.04;
  oil.pressure_viscosity_per_Pa = 2.2e-8;
  return oil;
}
void BM_EhlLine(benchmark::State& state) {
  const double w = static_cast<double>(state.range(1));
  const lub::PiezoviscousLubricant oil = roller_oil();
  lub::EhlLineOptions o;
  o.nodes = static_cast<int>(state.range(0));
  lub::EhlLineResult r;
  for (auto _ : state) r = lub::solve_ehl_line({w, 0.01, 2.26e11, 1.0}, oil, o);
  if (!r.converged) state.SkipWithError(r.message.c_str());
  state.counters["newton_iterations"] = r.iterations;
  state.counters["continuation_steps"] = r.continuation_steps;
}
BENCHMARK(BM_EhlLine)->Args({201, 300000})->Args({401, 300000})->Args({401, 3000000})->Args({801, 3000000})
    ->Unit(benchmark::kSecond)->Iterations(1);

// The same rollers at 3e5 N/m with boundary layers (lubrication/ehl_line.h, mixed: a flat stationary
// profile, 5 nm layers) at u_m = 0.5 mm/s, where 0.92 of the load is in contact on 801 nodes — the
// transition, the hardest speed of a Stribeck study — on N nodes, each grid of 801 and more started
// from the answer on a grid half as fine (nested iteration).
void BM_EhlLineMixed(benchmark::State& state) {
  const double w = 3e5;
  const lub::PiezoviscousLubricant oil = roller_oil();
  lub::EhlLineOptions o;
  o.nodes = static_cast<int>(state.range(0));
  const double b = lub::reference::hertz_line_half_width_m(w, 0.01, 2.26e11);
  const lub::EhlRoughness flat = lub::cosine_ridges(-6.0 * b, 2.0 * b, 0.0, 1.0, 4001);
  lub::EhlLineResult r;
  for (auto _ : state) r = lub::solve_ehl_line({w, 0.01, 2.26e11, 5e-4}, flat, oil, o);
  if (!r.converged) state.SkipWithError(r.message.c_str());
  state.counters["newton_iterations"] = r.iterations;
  state.counters["contact_load_share"] = r.contact_load_share;
}
BENCHMARK(BM_EhlLineMixed)->Arg(801)->Arg(1601)->Arg(3201)->Unit(benchmark::kSecond)->Iterations(1);

// EHL point contact (lubrication/ehl_point.h): the ball on a disc of tests/lubrication/ball_on_disc.h
// (R = 9.525 mm, E' = 2.31e11 Pa, η0 = 0.04 Pa·s, α = 2e-8 1/Pa, Roelands and Dowson–Higginson,
// u_m = 0.5 m/s) at W newtons on N × N nodes; counters: Newton iterations, continuation steps and
// the unknowns. The solver as `automatic` picks it: every row here by Newton–Krylov (above 21²),
// each grid started from the solve on one half as fine.
void BM_EhlPoint(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const double load_N = static_cast<double>(state.range(1));
  lub::PiezoviscousLubricant oil;
  oil.viscosity_Pa_s = 0.04;
  oil.pressure_viscosity_per_Pa = 2e-8;
  lub::EhlPointOptions o;
  o.nodes_x = o.nodes_y = n;
  lub::EhlPointResult r;
  for (auto _ : state) r = lub::solve_ehl_point({load_N, 9.525e-3, 2.1e11 / (1.0 - 0.3 * 0.3), 0.5}, oil, o);
  if (!r.converged) state.SkipWithError(r.message.c_str());
  state.counters["newton_iterations"] = r.iterations;
  state.counters["continuation_steps"] = r.continuation_steps;
  state.counters["krylov_iterations"] = r.krylov_iterations;  // 0: the dense LU (automatic up to 21²)
  state.counters["unknowns"] = (n - 2) * (n - 1 - n / 2) + 1;  // the half |Y| ≥ 0 (EhlPointOptions::symmetric_in_y) and H0
}
// Times include the coarser grids' solves that start each grid.
BENCHMARK(BM_EhlPoint)->Args({31, 10})->Args({41, 10})->Args({51, 10})->Args({61, 10})->Args({41, 20})->Args({61, 20})
    ->Args({65, 10})->Args({129, 10})->Args({257, 10})->Args({129, 20})->Args({257, 20})->Args({513, 10})
    ->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
