// FFT boundary-element contact speed (DESIGN §9): the floor is one FFTW r2c + c2r pair per CG
// iteration. For periodic self-affine Gaussian surfaces (H = 0.8, no roll-off, cut-off at 4
// cells, Rq = 1, E* = 1 — the family of issue 3's ContactMechanics reference point), loaded to
// about 10 % real contact, each benchmark reports
//   iterations           CG iterations to the relative residual 1e-8 (normal_contact.h)
//   per_iter_over_fft    wall time per iteration / wall time of one r2c + c2r pair, same grid
//   per_iter_over_fft_cpu the same ratio in process CPU time (robust on a shared machine)
//   fft_pair_ms          that FFT pair, measured in the same process with the same thread count
//   fft_pairs            half-space evaluations of the solve (1 per iteration + recomputations)
//   peak_rss_MiB         the process' peak resident memory so far (VmHWM)
// Arguments: grid side n, threads. The elastic-plastic case caps the pressure so that the mean
// pressure is 0.6 × hardness (where public FFT codes are reported to stall).
// Run: build/bench/contact_bench --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <string>

#include "contact/fft.h"
#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"

namespace {

using namespace tribo::contact;

double peak_rss_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kib = 0.0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 10, '\n');
  }
  return 0.0;
}

// Process CPU time: on a shared machine it measures the work, where wall time also measures
// the other jobs; for one thread it is the wall time of an idle machine.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct PairTime {
  double wall_s, cpu_s;
};

PairTime fft_pair_time(Eigen::Index n, int threads) {
  RealFft2d fft(n, n, threads);
  fft.real().setRandom();
  const int reps = n >= 1024 ? 5 : 20;
  fft.forward();
  fft.inverse();
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < reps; ++k) {
    fft.forward();
    fft.inverse();
  }
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / reps,
          (cpu_seconds() - c0) / reps};
}

Eigen::ArrayXXd bench_surface(Eigen::Index n) {
  GaussianSurfaceParams p;
  p.grid = n;
  p.size_m = 1.0;
  p.hurst = 0.8;
  p.rms_height_m = 1.0;
  p.cutoff_wavelength_m = 4.0 / static_cast<double>(n);
  p.seed = 1;
  return gaussian_surface(p);
}

void solve_bench(benchmark::State& state, bool plastic) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  const Eigen::ArrayXXd z = bench_surface(n);
  const double slope = surface_statistics(z, 1.0, 1.0).rms_slope;
  const Grid grid = Grid::patch(n, n, 1.0, 1.0);
  ElasticHalfSpace hs(grid, 1.0, true, threads);
  const Eigen::ArrayXXd h = gap_from_heights(z);
  // A ≈ κ W/(E* h'), κ ≈ 2.2: a mean pressure 0.045 E* h' gives ≈ 10 % contact.
  const double load = 0.045 * slope * grid.area_m2();
  NormalContactOptions opt;
  opt.tolerance = 1e-8;
  if (plastic) opt.pressure_cap_Pa = load / grid.area_m2() / 0.6;
  NormalContactResult r;
  double solve_s = 0.0, solve_cpu_s = 0.0;
  for (auto _ : state) {
    const double c0 = cpu_seconds();
    const auto t0 = std::chrono::steady_clock::now();
    r = solve_normal_load(hs, h, load, opt);
    solve_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    solve_cpu_s += cpu_seconds() - c0;
    benchmark::DoNotOptimize(r.real_area_m2);
  }
  if (!r.summary.converged) state.SkipWithError(r.summary.message.c_str());
  const PairTime fft = fft_pair_time(n, threads);
  const double runs = static_cast<double>(state.iterations()) * r.summary.iterations;
  state.counters["iterations"] = r.summary.iterations;
  state.counters["fft_pairs"] = r.summary.fft_pairs;
  state.counters["area_fraction"] = r.area_fraction;
  state.counters["fft_pair_ms"] = 1e3 * fft.wall_s;
  state.counters["per_iter_over_fft"] = solve_s / runs / fft.wall_s;
  state.counters["per_iter_over_fft_cpu"] = solve_cpu_s / runs / fft.cpu_s;
  state.counters["peak_rss_MiB"] = peak_rss_mib();
}

void BM_FftPair(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  omp_set_num_threads(threads);
  RealFft2d fft(n, n, threads);
  fft.real().setRandom();
  for (auto _ : state) {
    fft.forward();
    fft.inverse();
  }
}

void BM_ElasticSolve(benchmark::State& state) { solve_bench(state, false); }
void BM_ElasticPlasticSolve(benchmark::State& state) { solve_bench(state, true); }

void grids(benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
}

BENCHMARK(BM_FftPair)->Apply([](benchmark::internal::Benchmark* b) {
  for (int n : {256, 512, 1024, 2048}) {
    for (int t : {1, 2}) b->Args({n, t});
  }
  b->ArgNames({"n", "threads"})->Unit(benchmark::kMillisecond)->UseRealTime();
});
BENCHMARK(BM_ElasticSolve)->Apply(grids);
BENCHMARK(BM_ElasticPlasticSolve)->Apply(grids);

}  // namespace

BENCHMARK_MAIN();
